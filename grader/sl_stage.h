/* sl_stage: a student's submission, as uploaded, made into a labs tree the
 * project's CMake builds (scripts/grade-submission; the tool is
 * shadowlab-stage). The submission is a folder or an archive (.zip, .tar,
 * .tar.gz, ...), in one of three layouts (a labs/ folder, the lab folders, the
 * lab files loose), possibly inside one top folder and beside what macOS and
 * Windows add (__MACOSX/, ._*, .DS_Store, Thumbs.db, desktop.ini).
 *
 * Two processes. A child reads the submission: as uid 65534 when this runs as
 * root, in a mount namespace where the folders named `hidden` are empty where
 * the system allows one, with no file writes, no new processes and bounded
 * time and memory. It walks folders one name at a time from open descriptors
 * and never through a link (openat2 RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS
 * where the kernel has it, O_NOFOLLOW on every step), and refuses by name
 * symbolic links, hard links (a file with several names may be another
 * file's content: copy submissions with cp -R, unzip or tar, which make
 * none), devices, FIFOs, sockets and archive paths that leave the archive.
 * A lab file read from an archive is checked against the archive's records
 * (sl_archive_matches_records: a zip's CRC-32 and size, a tar header's size);
 * one that does not match is left out and said as the tool's fault
 * (SL_STAGE_MISMATCH). It sends the lab files it chose over a pipe. The
 * parent, which reads no file the submission names, checks every name it is
 * sent against the handout's (a lab's labN.c, files under a lab's shaders/),
 * applies the limits again, normalises the text (sl_text: byte-order mark,
 * CRLF, CR), names bytes that are not text, writes the files over the stubs
 * in the stage, and writes a summary (JSON) that shadowlab-grade
 * --submission-summary turns into notes in every report. */
#ifndef SL_STAGE_H
#define SL_STAGE_H

#include "sl_stage_desc.h"

/* Stages the submission; returns one of the statuses (sl_stage_desc.h). */
int sl_stage_run(const sl_stage_desc *desc);

#endif
