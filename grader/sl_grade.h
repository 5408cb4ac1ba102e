/* sl_grade: turns what a case's child captured into points and a one-line
 * reason that names the likely mistake, against the case's references. */
#ifndef SL_GRADE_H
#define SL_GRADE_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_image.h"
#include "sl_run.h"

typedef struct sl_reference {
    bool needed, loaded;
    char path[1100];
    char error[600];
    sl_image image;
    double numbers[48];
    int number_count;
} sl_reference;

typedef struct sl_check_result {
    double points, max_points;
    bool bonus;             /* max_points do not count towards the maximum score */
    bool passed;
    bool reference_problem; /* a missing or corrupt reference: staff must fix it */
    char message[2048];
    sl_image diff;          /* failed image checks */
} sl_check_result;

/* Loads the reference of one check, if it needs one. Missing or corrupt files
 * come back with loaded = false and an error naming the file. */
void sl_reference_load(sl_reference *ref, const char *references_dir, const sl_case *c, const sl_check *k);
void sl_reference_free(sl_reference *ref);
/* Writes the capture a check needs as its reference (solutions builds only). */
bool sl_reference_write(const char *references_dir, const sl_case *c, const sl_check *k, const sl_case_result *r,
                        char *err, size_t err_size);

/* mkdir -p */
bool sl_mkdirs(const char *path);

void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    sl_check_result *out);

#endif
