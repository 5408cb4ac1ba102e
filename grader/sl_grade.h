/* sl_grade: turns what a case's child captured into points and a one-line
 * reason that names the likely mistake, against the case's references. */
#ifndef SL_GRADE_H
#define SL_GRADE_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_image.h"
#include "sl_manifest.h"
#include "sl_run.h"

typedef struct sl_reference {
    bool needed, loaded;
    char path[1100];
    char error[600];
    sl_image image;
    double numbers[SL_RUN_MAX_NUMBERS]; /* matrices (48), or a probe's rows x outputs */
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

/* Loads the reference of one check, if it needs one. A missing, corrupt or
 * changed file (against the manifest: NULL means the manifest itself could
 * not be read, `manifest_error` says why), or one that does not fit the case
 * (another image size), comes back with loaded = false and an error naming
 * the file: a problem for the staff, not the student. */
void sl_reference_load(sl_reference *ref, const char *references_dir, const sl_manifest *manifest,
                       const char *manifest_error, const sl_case *c, const sl_check *k);
void sl_reference_free(sl_reference *ref);
/* Writes the capture a check needs as its reference (from the solutions'
 * runner) and records it in the manifest. */
bool sl_reference_write(const char *references_dir, sl_manifest *manifest, const sl_case *c, const sl_check *k,
                        const sl_case_result *r, char *err, size_t err_size);

void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    sl_check_result *out);

#endif
