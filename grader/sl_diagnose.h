/* sl_diagnose: what turns a failed check into a message that names the
 * mistake. sl_grade.c holds the shared core (saying things, stubs, the lookup
 * function of a case, what to fix first); each lab's knowledge sits in a file
 * of its own under grader/diagnose/, function probes in
 * grader/diagnose/probe.c, and measures shared by the visibility checks of
 * several labs in grader/diagnose/visibility.c.
 *
 * Messages go from root cause to symptom. A diagnosis writes the symptom it
 * measured into out->message ("shadow acne on 23% of lit surfaces") and the
 * likely cause into out->cause ("bias too small or missing — ..."); the core
 * joins them, or, when the cause is already known from a failed earlier
 * check or probe, leads with that and keeps the symptom alone. */
#ifndef SL_DIAGNOSE_H
#define SL_DIAGNOSE_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_compare.h"
#include "sl_grade.h"
#include "sl_image.h"
#include "sl_run.h"

/* ---- the core (grader/sl_grade.c) ---- */
void sl_diag_say(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void sl_diag_append(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The likely cause of the symptom in out->message. */
void sl_diag_cause(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Adds a case's hint after the message. */
void sl_diag_hint(sl_check_result *out, const char *hint);
/* "not implemented" for this lab's stubs first, then "needs lab K"; false if no stub is in the way. */
bool sl_diag_explain_missing(const sl_case *c, const sl_case_result *r, sl_check_result *out);
/* The GLSL function that computes visibility for this case, and its TODO. */
void sl_diag_lookup_function(const sl_case *c, const char **function, const char **todo);
/* An image check's verdict from its comparison: few enough pixels off, none
 * NaN, and a mean difference within the check's mean tolerance. When only
 * the mean is off, says so (a small error everywhere) and returns false. */
bool sl_diag_image_passes(const sl_check *k, const sl_compare_stats *st, const char *what, sl_check_result *out);
/* The TODO tag and file of a lab function ("TODO(lab3.2)", "labs/lab3_bias/shaders/bias.glsl"). */
bool sl_diag_stub_location(const char *function, const char **todo, const char **file);

/* ---- shared visibility measures (grader/diagnose/visibility.c) ---- */
/* Acne: on surfaces facing the light (the mask; every pixel without one),
 * the reference's fully lit pixels that are darker here, as a fraction of
 * them, and how many of those differ from a neighbour: self-shadowing comes
 * as a fine moiré, a misplaced shadow as a solid region. */
typedef struct sl_acne {
    double fraction; /* of the reference's lit surface, darkened here */
    double pattern;  /* of those darkened pixels, the ones with a neighbour much brighter or darker */
    double mean;     /* mean visibility here over the reference's lit surface */
} sl_acne;
sl_acne sl_measure_acne(const sl_image *student, const sl_image *reference, const sl_image *lit_mask);
/* A moiré, not a region: the measure says acne. */
bool sl_acne_is_pattern(const sl_acne *acne);

/* ---- lab 1 (grader/diagnose/lab1.c) ---- */
void sl_diagnose_fbo(const sl_case *c, const sl_case_result *r, sl_check_result *out);
void sl_diagnose_depth(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                       sl_check_result *out);

/* ---- lab 2 (grader/diagnose/lab2.c) ---- */
void sl_diagnose_matrices(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                          sl_check_result *out);
/* Lab 2's visibility beyond the core's checks: acne, a solid extra shadow past the far plane. */
bool sl_diagnose_lab2_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);

/* ---- lab 3 (grader/diagnose/lab3.c): true when it named the mistake ---- */
bool sl_diagnose_lab3_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);

/* ---- lab 4 (grader/diagnose/lab4.c) ---- */
bool sl_diagnose_lab4_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);
void sl_diagnose_penumbra(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                          sl_check_result *out);

/* ---- lab 5 (grader/diagnose/lab5.c) ---- */
/* The moments before or after the blur, per channel, and the target's format. */
void sl_diagnose_moments(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out);
/* Light bleeding in the reference's umbra, with and without the reduction. */
void sl_diagnose_bleeding(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                          sl_check_result *out);
/* The moments target's format, when it is the cause (said in out); false when it is fine. */
bool sl_diagnose_lab5_format(const sl_case_result *r, sl_check_result *out);
bool sl_diagnose_lab5_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);
/* ---- lab 6 (grader/diagnose/lab6.c) ---- */
void sl_diagnose_cascade_index(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out);
void sl_diagnose_flicker(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out);
/* ---- lab 7 (grader/diagnose/lab7.c) ---- */
/* sl_lab_builds_on and sl_lab_shows (which labs a lab builds on): sl_params.h */
/* Whether a lab 7 case calls the function `name` that failed its probe. */
bool sl_lab7_case_calls(const sl_case *c, const sl_check *k, const char *name);
void sl_diagnose_cube_face(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                           sl_check_result *out);
bool sl_diagnose_lab7_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);
/* A probe of a lab 7 function: what its failing rows say ("face +Y: the up vector should be
 * (0,0,1)") into text, and the row that shows it; text left empty when there is nothing more specific. */
int sl_lab7_probe_verdict(const sl_check *k, const double *student, const double *expected, uint32_t failing_rows,
                          char *text, size_t text_size);

/* ---- function probes (grader/diagnose/probe.c) ---- */
void sl_diagnose_probe(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                       sl_check_result *out);
/* A probe reference: the outputs of the solution, and the inputs they were made from. */
bool sl_probe_reference_read(const char *path, const sl_check *k, double *outputs, char *err, size_t err_size);
bool sl_probe_reference_write(const char *path, const sl_check *k, const double *outputs, char *err, size_t err_size);

#endif
