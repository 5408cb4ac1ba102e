/* sl_archive_path: an archive entry's path made safe to write under a folder
 * (no absolute path, drive letter or '..'), shared by the archive reader and
 * the zip's own records, which read the same names. */
#ifndef SL_ARCHIVE_PATH_H
#define SL_ARCHIVE_PATH_H

#include <stdbool.h>
#include <stddef.h>

#define SL_ARCHIVE_PATH_MAX 1024

bool sl_archive_clean_path(const char *raw, char *out, size_t out_size, const char **why);

#endif
