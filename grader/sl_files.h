/* sl_files: the grader's output files are written whole or not at all: to a
 * temporary file beside the target, renamed over it when complete. A report
 * is never left half-written, and a failure names the file. */
#ifndef SL_FILES_H
#define SL_FILES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "sl_image.h"

typedef struct sl_atomic_file {
    FILE *f;
    char path[1100];
    char temporary[1200];
} sl_atomic_file;

/* Opens a temporary file for `path`; false with "PATH: cannot write (reason)" in err. */
bool sl_atomic_open(sl_atomic_file *file, const char *path, char *err, size_t err_size);
/* Closes and renames it into place; on any error removes it and says why. */
bool sl_atomic_commit(sl_atomic_file *file, char *err, size_t err_size);
void sl_atomic_abort(sl_atomic_file *file);
/* An image (by extension, see sl_image_write), written the same way. */
bool sl_atomic_write_image(const char *path, const sl_image *image, char *err, size_t err_size);

/* Whether a spreadsheet would take a cell for a formula: it begins with = + - @, a tab or a CR. */
bool sl_csv_formula(const char *text);
/* One CSV field (RFC 4180), preceded by a comma unless first: quoted when it
 * must be, control characters as spaces, and defused for spreadsheets (a
 * cell sl_csv_formula takes for a formula gets a leading '). The gradebook's
 * and the class report's cells go through it. */
void sl_csv_field(FILE *f, const char *text, bool first);

/* mkdir -p */
bool sl_mkdirs(const char *path);

#endif
