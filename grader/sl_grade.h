/* sl_grade: turns what a case's child captured into points and a one-line
 * reason that names the likely mistake, against the case's references. */
#ifndef SL_GRADE_H
#define SL_GRADE_H

#include <stdbool.h>
#include <stdint.h>

#include "sl_case.h"
#include "sl_diag.h"
#include "sl_image.h"
#include "sl_manifest.h"
#include "sl_probe.h"
#include "sl_reference.h"
#include "sl_reference_cache.h"
#include "sl_run.h"

/* The types a check's diagnosis reads and writes (sl_reference, sl_check_result,
 * sl_probe_failure) are sl_diag.h's, below the diagnoses and this module. */

typedef struct sl_lab_failure {
    bool failed;
    int lab;
    char where[200];     /* "lab1_depth_boxes / depth" */
    char summary[512];
    const sl_case *c;    /* the failed check, and what its capture showed */
    const sl_check *k;
    uint32_t symptoms;
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
    /* functions (1 << sl_probe index) whose every probe check was graded and passed: ruled out */
    uint64_t probes_passed;
    /* of those, the functions whose every probe check ran generic rows too (sl_probe_generic.h) */
    uint64_t probes_generic;
    const sl_lab_failure *lab_failures; /* the earlier labs' failed checks, in lab order; NULL: unknown */
    int lab_failure_count;
    bool isolated;  /* --isolate: the solutions stand in for the other labs, whose failures do not show here */
    /* Staff grading's experiment on this check (sl_experiment.h), when it answered: its lead
     * replaces the probes' lead and candidates; the function it names (none: ""), the cause. */
    const char *experiment_lead;
    const char *experiment_function;
    const sl_probe_failure *experiment_probe; /* that function's failed probe, if it failed one: NULL */
} sl_grade_context;

/* Grades one check; context may be NULL (nothing known besides this check). */
void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    const sl_grade_context *context, sl_check_result *out);
/* Whether the case's runner took far more CPU time than the solutions' (a shader loop that does not
 * end): the grader's own measure, on the references' renderer (c->reference_cpu_seconds is 0 elsewhere). */
bool sl_grade_too_slow(const sl_case *c, const sl_case_result *r);
/* Whether a check is graded from numbers the runner sends alone, with no reference (the
 * framebuffer's state): lab code can send any number, so such a check explains, never earns. */
bool sl_check_is_state(const sl_check *k);
/* After every check of case c is graded (results: one per check): a state check that passed keeps
 * its points only when the case's pictures prove the state was used (every other regular check of
 * the case passed); otherwise it fails, saying which picture does not back it. */
void sl_grade_require_evidence(const sl_case *c, sl_check_result *results);
/* After experiments have said their checks again: a state check not backed by its picture quotes that
 * picture's check as it now reads. */
void sl_grade_quote_evidence(const sl_case *c, sl_check_result *results);
/* A graded probe check's failure, for the context of later checks; false if it passed. */
bool sl_probe_failure_of(const sl_case *c, const sl_check *k, const sl_check_result *result, sl_probe_failure *out);

#endif
