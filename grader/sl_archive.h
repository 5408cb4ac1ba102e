/* sl_archive: reading the archives students and course platforms upload
 * (.zip, .tar, .tar.gz/.tgz, .tar.bz2, .tar.xz, .tar.zst), through libarchive,
 * without trusting them. An entry's path is cleaned ('\' is a
 * separator, "." and empty parts dropped) and said to be unsafe when it would
 * leave the archive's folder (absolute, a drive letter, ".."). Data is read in
 * bounded amounts, whatever the header claims. Nothing here follows a link:
 * links, devices, FIFOs and sockets are entries of their own kind, to refuse.
 *
 * Listing:
 *     sl_archive *a = sl_archive_open(fd, "alice.zip", err, sizeof err);
 *     sl_archive_entry e;
 *     int r;
 *     while ((r = sl_archive_next(a, &e)) > 0)
 *         printf("%s %lld %s\n", sl_archive_kind_name(e.kind), e.size, e.path);
 *     if (r < 0) fprintf(stderr, "%s\n", sl_archive_error(a));   // names the archive, and the entry
 *     sl_archive_close(a);
 * Extracting (regular files and folders only, nothing outside the folder):
 *     sl_archive_extract(fd, "alice.zip", dir_fd, &(sl_archive_limits){0}, on_refused, on_mismatch, ctx,
 *                        err, sizeof err);   // SL_ARCHIVE_EXTRACTED when every file is as recorded
 */
#ifndef SL_ARCHIVE_H
#define SL_ARCHIVE_H

#include <stdbool.h>

#include "sl_archive_path.h"
#include <stddef.h>
#include <stdint.h>


typedef enum sl_archive_kind {
    SL_ARCHIVE_FILE,
    SL_ARCHIVE_FOLDER,
    SL_ARCHIVE_SYMLINK,
    SL_ARCHIVE_HARDLINK, /* another entry's data under a second name */
    SL_ARCHIVE_DEVICE,
    SL_ARCHIVE_FIFO,
    SL_ARCHIVE_SOCKET,
    SL_ARCHIVE_OTHER,
} sl_archive_kind;

typedef struct sl_archive_entry {
    char path[SL_ARCHIVE_PATH_MAX]; /* cleaned, '/'-separated, UTF-8 where the archive says so */
    char raw_path[SL_ARCHIVE_PATH_MAX]; /* as the archive wrote it (cut to fit) */
    sl_archive_kind kind;
    long long size;                 /* what the header claims, -1 if it says nothing: never trusted */
    char link_target[256];          /* symlinks and hard links, as written (cut to fit) */
    const char *unsafe;             /* NULL, or why the path must not be used ("a '..' in the path", ...) */
} sl_archive_entry;

typedef struct sl_archive sl_archive;

/* Reads the archive from fd (an open regular file, left open: the caller
 * closes it; reading starts from offset 0). name is used in messages. NULL
 * with "NAME: ..." in err when it is no archive this reader knows. */
sl_archive *sl_archive_open(int fd, const char *name, char *err, size_t err_size);
/* The next entry: 1, 0 at the end, -1 on an error (a corrupt or cut archive):
 * sl_archive_error then names the archive and the last good entry. */
int sl_archive_next(sl_archive *a, sl_archive_entry *entry);
/* The current entry's data, at most cap bytes into buf; *more says whether
 * the data went on past cap, and the next call goes on from the byte after
 * the last one given (reads in a loop give the whole data, nothing dropped).
 * -1 on an error (sl_archive_error). */
long long sl_archive_read(sl_archive *a, void *buf, size_t cap, bool *more);
/* Bytes unpacked from the archive so far (the decompressed stream): bounds an
 * archive that unpacks to far more than it weighs. */
unsigned long long sl_archive_unpacked_bytes(sl_archive *a);
const char *sl_archive_error(const sl_archive *a);
void sl_archive_close(sl_archive *a);

const char *sl_archive_kind_name(sl_archive_kind kind); /* "file", "folder", "symbolic link", ... */
/* Whether a file name looks like an archive this reader takes (.zip, .tar, .tgz, .tar.gz, ...). */
bool sl_archive_name_is_archive(const char *name);
/* Cleans a path as sl_archive_next does: false (with *why) when it must not
 * be used; true with an empty out for the archive's own folder ("./"). */

/* Limits for sl_archive_extract; zero means the default. */
typedef struct sl_archive_limits {
    long long max_file_bytes;  /* default 64 MiB */
    long long max_total_bytes; /* default 1 GiB: the sum of what is written */
    unsigned long long max_unpacked_bytes; /* default 2 GiB: all the archive unpacks to, skipped entries included */
    int max_entries;           /* default 100000 */
} sl_archive_limits;

/* Called with an entry's path and a reason: for each entry not extracted
 * ("a symbolic link (to /etc/passwd)", "a '..' in the path", "more than 64
 * MiB", ...), and for each file whose extraction does not match the
 * archive's records ("extracted as 168892 bytes, CRC-32 ..., where the zip's
 * central directory records 168894 bytes, CRC-32 ..."). */
typedef void (*sl_archive_note_fn)(void *context, const char *path, const char *why);

typedef enum sl_archive_outcome {
    SL_ARCHIVE_EXTRACTED,   /* every file written is as the archive records it */
    SL_ARCHIVE_DAMAGED,     /* the archive is corrupt, cut short, past a limit or contradicts itself */
    SL_ARCHIVE_MISMATCH,    /* a sound archive, extracted wrong: a file written differs from its records */
    SL_ARCHIVE_NOT_WRITTEN, /* the folder could not be written (disk full, permissions, memory) */
} sl_archive_outcome;

/* Extracts the archive's regular files and folders under dir_fd (an open
 * folder): never a link, a device or a path outside it; each folder made
 * 0755 and file 0644, an existing name never replaced (the second entry of
 * a name is refused). Entries not extracted go to refused (may be NULL).
 * Each file written is read back, and its size and CRC-32 checked against
 * the archive's records: a zip's central directory, read with code of ours
 * (sl_zip_records.h) before anything is written, and every file it records
 * must have been read; a tar's headers (sizes: tar has no CRC). A file that
 * does not match goes to mismatched (may be NULL) and the outcome is
 * SL_ARCHIVE_MISMATCH; a zip whose data fails its own CRC, or whose records
 * contradict each other, is SL_ARCHIVE_DAMAGED. Anything but
 * SL_ARCHIVE_EXTRACTED comes with err naming the archive (what was extracted
 * before a stop stays). */
sl_archive_outcome sl_archive_extract(int fd, const char *name, int dir_fd, const sl_archive_limits *limits,
                                      sl_archive_note_fn refused, sl_archive_note_fn mismatched, void *context,
                                      char *err, size_t err_size);

/* Whether the archive read is a zip (known once sl_archive_next gave an entry). */
bool sl_archive_is_zip(const sl_archive *a);
struct sl_zip_records;
/* Whether size bytes of CRC-32 crc, read or written as the entry path, are
 * what the archive records: the zip's records when there are some (NULL
 * otherwise), else header_size, what a tar header claims (-1: nothing to
 * check). False with what saying both ("N bytes, CRC-32 X, where the zip's
 * central directory records M bytes, CRC-32 Y"). */
bool sl_archive_matches_records(const struct sl_zip_records *records, const char *path, long long header_size,
                                long long size, uint32_t crc, char *what, size_t what_size);

#endif
