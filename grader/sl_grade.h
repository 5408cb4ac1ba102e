/* sl_grade: turns what a case's child captured into points and a one-line
 * reason that names the likely mistake, against the case's references. */
#ifndef SL_GRADE_H
#define SL_GRADE_H

#include <stdbool.h>
#include <stdint.h>

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
    /* What other checks may quote: the mistake in a few words ("the shadow
     * matrix multiplies Lv * Lp"), for a later check of the case or an image
     * check of the same lab to lead with. */
    char summary[512];
    uint32_t symptoms;      /* 1 << sl_symptom: what the capture shows (a hint is shown for its own only) */
    uint32_t failing_rows;  /* probe checks: 1 << row for each row that differs */
    bool stub;              /* probe checks: the function still returns what its stub returns */
    char cause[1024];       /* while a check is diagnosed: the likely cause of the symptom in message */
    bool settled;           /* the message needs no lead: a stub, a run that failed, a capture missing */
    /* A failed check's diagnosis, the same for every student it fits: the
     * mistake in a few words (the summary; a probe's with its function; for a
     * check led by an earlier failure, that lead) with its numbers taken out
     * ("shadow acne on …% of lit surfaces"), and an id made from that text
     * ("shadow-acne-on-of-lit-surfaces-3fa2c1"; "follows-..." for a lead).
     * The class report counts students per id. */
    char diagnosis[72];
    char diagnosis_text[320];
} sl_check_result;

/* A function probe that failed: image checks of its lab that call the
 * function lead with it, since their pictures only show its consequences. */
typedef struct sl_probe_failure {
    int function;            /* sl_probe_at index */
    char where[200];         /* "lab4_probes / pcf_grid" */
    char summary[512];       /* what is wrong with it */
    bool stub;               /* not implemented yet */
    uint32_t failing_modes;  /* functions whose first input is a mode: 1 << mode of each failing row */
} sl_probe_failure;

/* A lab's first failed check (not a bonus one), for the later labs that build on it. */
typedef struct sl_lab_failure {
    bool failed;
    char where[200];     /* "lab1_depth_boxes / depth" */
    char summary[512];
} sl_lab_failure;

/* What is known when a check is graded: the checks of its case graded
 * before it (a failed framebuffer or matrices check comes first), the
 * probes that failed (every probe check is graded before any other), and
 * the earlier labs' failures (labs are graded in order). */
typedef struct sl_grade_context {
    const sl_check_result *earlier; /* this case's checks 0 .. earlier_count-1 */
    int earlier_count;
    const sl_probe_failure *probe_failures;
    int probe_failure_count;
    const sl_lab_failure *lab_failures; /* indexed by lab, 1..SL_LAB_MAX; NULL: unknown */
    bool isolated;  /* --isolate: the solutions stand in for the other labs, whose failures do not show here */
} sl_grade_context;

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

/* Grades one check; context may be NULL (nothing known besides this check). */
void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    const sl_grade_context *context, sl_check_result *out);
/* A graded probe check's failure, for the context of later checks; false if it passed. */
bool sl_probe_failure_of(const sl_case *c, const sl_check *k, const sl_check_result *result, sl_probe_failure *out);

#endif
