/* sl_zip_records: what a zip says of its own files, read from its central
 * directory with code of ours (not libarchive's, which extracts them), to
 * check an extraction against: each file's CRC-32 and uncompressed size.
 * Each record's local header is read too: a zip whose central directory and
 * local headers (or data descriptors) disagree on a file's CRC-32 or sizes
 * contradicts itself, and is said to be damaged.
 *     sl_zip_records *r = sl_zip_records_read(fd, 100000, err, sizeof err);
 *     int count;
 *     const sl_zip_record *const *rec = sl_zip_records_find(r, "labs/lab1.c", &count);
 *     // count records of that cleaned path (a zip may name a path twice)
 *     sl_zip_records_free(r);
 */
#ifndef SL_ZIP_RECORDS_H
#define SL_ZIP_RECORDS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct sl_zip_record {
    char *path;         /* cleaned as sl_archive_clean_path does; NULL when unsafe */
    char *unicode_path; /* from an Info-ZIP Unicode Path field, cleaned; NULL when none */
    uint32_t crc32;
    unsigned long long size;        /* uncompressed */
    unsigned long long packed_size; /* compressed */
    bool is_file;       /* not a folder, nor a link or device of a Unix zip */
} sl_zip_record;

typedef struct sl_zip_records sl_zip_records;

/* Reads the zip in fd (an open regular file; read with pread, the offset
 * left alone). NULL with err ("no central directory (cut short?)", "the
 * central directory says ... but the local header ...") when the zip's own
 * records cannot be read or contradict each other: the zip is damaged.
 * max_records bounds the work on a hostile file. */
sl_zip_records *sl_zip_records_read(int fd, int max_records, char *err, size_t err_size);
int sl_zip_records_count(const sl_zip_records *r);
const sl_zip_record *sl_zip_records_at(const sl_zip_records *r, int i);
/* The records whose path or unicode_path is `path` (*count of them, 0: none). */
const sl_zip_record *const *sl_zip_records_find(const sl_zip_records *r, const char *path, int *count);
void sl_zip_records_free(sl_zip_records *r);

#endif
