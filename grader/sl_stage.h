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
 * It sends the lab files it chose over a pipe. The parent, which reads no
 * file the submission names, checks every name it is sent against the
 * handout's (a lab's labN.c, files under a lab's shaders/), applies the
 * limits again, normalises the text (sl_text: byte-order mark, CRLF, CR),
 * names bytes that are not text, writes the files over the stubs in the
 * stage, and writes a summary (JSON) that shadowlab-grade --submission-summary
 * turns into notes in every report. */
#ifndef SL_STAGE_H
#define SL_STAGE_H

#include <stdio.h>

/* Exit statuses of shadowlab-stage (and sl_stage_run's results). */
enum {
    SL_STAGE_TAKEN = 0,       /* lab files were staged */
    SL_STAGE_PROBLEM = 2,     /* could not stage: a staff-side problem (arguments, the stage, unreadable files) */
    SL_STAGE_NO_LAB_FILE = 3, /* no lab file in the submission: the stage holds the stubs only */
};

/* Zero means the default for every number. */
typedef struct sl_stage_desc {
    const char *submission;       /* a folder or an archive */
    const char *stage;            /* a labs tree holding the handout's stubs: the lab files go over them */
    const char *summary;          /* where the JSON summary goes (NULL: none) */
    const char *const *hidden;    /* folders the reading process must not see */
    int hidden_count;
    unsigned user;                /* when root: the uid and gid that read the submission (default 65534) */
    int max_files;                /* lab files taken, default 256 */
    long long max_file_bytes;     /* per file, default 1 MiB */
    long long max_total_bytes;    /* all lab files, default 16 MiB */
    int max_entries;              /* folder and archive entries looked at, default 20000 */
    int max_depth;                /* folders deep, default 16 */
    unsigned long long max_unpacked_bytes; /* what an archive may unpack to, default 512 MiB */
    double timeout;               /* seconds, default 120 */
    FILE *log;                    /* lines for people (default stdout) */
    const char *log_prefix;       /* before each line (default "shadowlab-stage: ") */
} sl_stage_desc;

/* Stages the submission; returns one of the statuses above. */
int sl_stage_run(const sl_stage_desc *desc);

#endif
