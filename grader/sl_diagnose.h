/* sl_diagnose: what turns a failed check into a message that names the
 * mistake. sl_diag.c holds what every diagnosis uses (saying things, stubs),
 * sl_grade.c what to fix first; each lab's
 * knowledge sits in a file of its own under grader/diagnose/, registered in
 * the diagnosis table (at the end of this header), function probes in
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
#include "sl_diag.h"
#include "sl_image.h"
#include "sl_run.h"

/* ---- evidence: what a case runs, what a failed probe explains (grader/diagnose/runs.c) ----
 * The rules (grader/diagnose/README.md): a message names a function as the cause
 * only when (a) its probe failed, (b) the check's case runs it, on inputs like
 * a failing row's, and (c) what the failing rows predict is what the capture
 * shows; a bonus function never answers for a regular check. */
/* A lab function a message may name: a probe's, or one without a probe (a shader file, a C function). */
typedef struct sl_lab_function {
    const char *name; /* "pcf_grid", "depth.vert" */
    int lab;
    const char *todo; /* "lab4.3" for a probe's; "TODO(lab1.4)" for the others */
    bool bonus;
} sl_lab_function;
int sl_lab_function_count(void);
sl_lab_function sl_lab_function_at(int i); /* probe functions first, in sl_probe_at order */
/* Whether check k of case c runs `function` as the framework draws that case
 * (filter, bias and compare modes; the lab's passes; the extensions the case
 * turns on). Labs answer for their own cases, earlier labs' code included. */
bool sl_case_runs(const sl_case *c, const sl_check *k, const char *function);
/* Whether the situation of row `row` of a probe check can occur in case c: a
 * mode the case is in, a radius it uses, w != 1 only under a perspective light. */
bool sl_case_meets_row(const sl_case *c, const sl_check *probe, int row);
/* What a failed probe predicts for case c (1 << sl_symptom): its failing rows' predictions, over the rows the case meets. */
uint32_t sl_probe_failure_predicts(const sl_case *c, const sl_probe_failure *failure);
/* Whether a prediction meets measured symptoms: a direction in common (too dark, too light, narrower or
 * wider penumbrae), and a gross symptom only for a gross mistake; symptoms without a direction: any. */
bool sl_prediction_meets(uint32_t predicts, uint32_t symptoms);
/* (a), (b) and (c) together, for a failure of a function of lab c->lab or of a lab it builds on
 * (never an earlier lab's under --isolate). */
bool sl_probe_failure_explains(const sl_case *c, const sl_check *k, const sl_probe_failure *failure, uint32_t symptoms,
                               bool isolated);
/* (b) alone, for a function with or without a probe; never a bonus function for a regular check. */
bool sl_function_may_be_blamed(const sl_case *c, const sl_check *k, const char *function, bool isolated);
/* The step of its lab a student must have done for case c to pass, by the TODO tags of the lab's
 * functions its regular checks run: a case of probes alone, the first (its functions are the steps'
 * own, one by one), a case of pictures, the last; 0 where none is known (lab 0). */
int sl_case_step(const sl_case *c);
/* The path the framework takes for case c, in a few words ("pcf_grid() with radius 1"); empty when there is nothing to say. */
void sl_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
/* The GLSL function that computes visibility for case c ("pcf_grid()"), and its TODO ("lab4.3"): its lab's
 * lookup_function; "the shadow lookup" and "" for a lab that draws none. */
void sl_case_lookup_function(const sl_case *c, const char **function, const char **todo);
/* Per lab (grader/diagnose/labN.c): sl_case_runs for that lab's cases, and its path. */
bool sl_lab1_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab2_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab3_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab4_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab5_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab6_case_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_lab7_case_runs(const sl_case *c, const sl_check *k, const char *function);
void sl_lab2_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
void sl_lab3_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
void sl_lab4_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
void sl_lab5_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
void sl_lab6_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
void sl_lab7_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n);
bool sl_lab4_meets_row(const sl_case *c, const sl_check *probe, int row);
/* Lab 2's lookup for case c (its compare mode), which lab 3 draws through outside its midpoint mode. */
void sl_lab2_lookup_function(const sl_case *c, const char **function, const char **todo);
/* Shared by labs 1-4 (lab1.c, lab2.c, lab3.c): the depth pass (lab 1's map, from lab 2 on lab 2's
 * light camera, from lab 3 on lab 3's state), a check of the camera's picture, lab 3's biased lookup. */
bool sl_depth_pass_runs(const sl_case *c, const sl_check *k, const char *function);
bool sl_camera_check(const sl_check *k);
bool sl_biased_lookup_runs(const sl_case *c, const char *function);

/* ---- shared visibility measures (grader/diagnose/visibility.c) ---- */
/* The symptoms every failed capture is measured for, the same way: darker or
 * lighter than the reference's 3x3 neighbourhood by more than `threshold`
 * (too_dark, too_light); for a visibility (`soft`), less or more soft area
 * (0.1 < v < 0.9) than the reference's (narrow_penumbra, wide_penumbra), and
 * gross when lit and shadowed (across 0.5) are exchanged over most of the
 * reference's shadow or a quarter of its lit area. Higher values are
 * lighter (a depth map: farther). On the mask's pixels, if there is a mask. */
uint32_t sl_measure_symptoms(const sl_image *student, const sl_image *reference, const sl_image *mask, double threshold,
                             bool soft);
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
/* The moments target, when it is the cause (said in out): its format, a clear to (0, 0), its mipmaps
 * (made for the wrong texture, or not read); false when it is fine. */
bool sl_diagnose_lab5_format(const sl_case *c, const sl_case_result *r, sl_check_result *out);
bool sl_diagnose_lab5_visibility(const sl_case *c, const sl_image *student, const sl_image *reference,
                                 const sl_image *lit_mask, sl_check_result *out);
/* ---- lab 6 (grader/diagnose/lab6.c) ---- */
void sl_diagnose_cascade_index(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out);
void sl_diagnose_flicker(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out);
/* ---- lab 7 (grader/diagnose/lab7.c) ---- */
/* sl_lab_builds_on and sl_lab_shows (which labs a lab builds on): sl_params.h */
/* Whether the runner drew lab 7's cube map in one layered pass (its "path" capture). */
bool sl_lab7_drawn_layered(const sl_case_result *r);
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

/* ---- functions judged by their contract, not by the solution's numbers ---- */
/* True when the probe's function has a contract of its own (lab 6: lab6_cascade_matrices; lab 7:
 * lab7_face_view): *broken then holds the rows that break it, text what breaks (empty when none does), and
 * *shown the row that shows it best. `expected`: the solution's outputs for the same rows (NULL: not
 * known), which lab 7 reads each face's orientation from. */
bool sl_lab6_probe_contract(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                            char *text, size_t text_size, int *shown);
bool sl_lab7_probe_contract(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                            char *text, size_t text_size, int *shown);

/* ---- function probes (grader/diagnose/probe.c) ---- */
void sl_diagnose_probe(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                       sl_check_result *out);
/* A probe reference: the outputs of the solution, and the inputs they were made from. */
bool sl_probe_reference_read(const char *path, const sl_check *k, double *outputs, char *err, size_t err_size);
bool sl_probe_reference_write(const char *path, const sl_check *k, const double *outputs, char *err, size_t err_size);

/* ---- the diagnosis table (grader/diagnose/table.c) ----
 * Each lab registers what it knows in one descriptor at the end of its file
 * (diagnose/labN.c); the core, the evidence and the probes read the table and
 * never name a lab. Zero (NULL) means the lab has nothing of that kind. */
struct sl_verdict_rows;
typedef void (*sl_check_diagnosis_fn)(const sl_case *c, const sl_check *k, const sl_case_result *r,
                                      const sl_reference *ref, sl_check_result *out);
/* A check kind the lab diagnoses itself (its pictures or numbers measured its own way). */
typedef struct sl_check_diagnosis {
    sl_check_kind kind;
    sl_check_diagnosis_fn diagnose;
} sl_check_diagnosis;
#define SL_LAB_MAX_CHECK_KINDS 4
/* What a lab knows of one of its probe functions' rows, beyond the shared readings (verdict.c, runs.c). */
typedef struct sl_function_verdict {
    const char *function; /* the probe's name: "lab3_depth_pass_state" */
    /* The mistake the failing rows show, in a few words into text, and the row that shows it (-1: none);
     * asked before the lab's rows_verdict. */
    int (*verdict)(const struct sl_verdict_rows *rows, char *text, size_t text_size);
    /* What one failing row predicts a picture shows (1 << sl_symptom); NULL: the shared reading. */
    uint32_t (*row_predicts)(const struct sl_verdict_rows *rows, int row);
    /* A row's "mode" input is this setting of the case (lab 3's bias mode, lab 4's filter mode): a case
     * meets the row only in that mode. NULL: the mode is the function's own. */
    int (*case_mode)(const sl_case *c);
    /* Outputs (1 << output) that matter only to a filter reading past the map's edge (lab 1's wrap modes
     * and border): a row differing in these alone shows only in a case whose lab's filters_past_edge says
     * so. 0: every output shows. */
    uint16_t edge_outputs;
} sl_function_verdict;
#define SL_LAB_MAX_FUNCTION_VERDICTS 4
#define SL_LAB_MAX_UNPROBED 5
typedef struct sl_lab_diagnoses {
    int lab;
    sl_check_diagnosis checks[SL_LAB_MAX_CHECK_KINDS]; /* up to the first without a diagnose */
    /* A visibility check of the lab's cases, after the core's own measures: true when it named the mistake. */
    bool (*visibility)(const sl_case *c, const sl_image *student, const sl_image *reference, const sl_image *lit_mask,
                       sl_check_result *out);
    /* Before a failed visibility check of the lab's cases is measured: a capture that already explains it
     * (said in out), or false. */
    bool (*capture_explains)(const sl_case *c, const sl_case_result *r, sl_check_result *out);
    /* sl_case_runs and sl_case_path for the lab's cases (runs.c); a row's settings (sl_case_meets_row). */
    bool (*case_runs)(const sl_case *c, const sl_check *k, const char *function);
    void (*case_path)(const sl_case *c, const sl_case_result *r, char *out, size_t n);
    bool (*meets_row)(const sl_case *c, const sl_check *probe, int row);
    /* The GLSL function that computes visibility for the lab's case c ("pcf_grid()", "point_shadow()"), and
     * its TODO ("lab4.3"); NULL: its cases draw no lookup (lab 1). */
    void (*lookup_function)(const sl_case *c, const char **function, const char **todo);
    /* Lab code without a probe of its own that a message may name as a candidate (files and C functions:
     * "depth.vert", "lab5_begin_blur_pass"), ended by one without a name. */
    sl_lab_function unprobed[SL_LAB_MAX_UNPROBED];
    /* The lab's probe functions judged by their own rows (verdict.c asks by the probe's name): up to the
     * first without a function. */
    sl_function_verdict functions[SL_LAB_MAX_FUNCTION_VERDICTS];
    /* The lab's lookup averages samples around the point (a filter): shadows far too faint, where the
     * reference has them, mean most samples land off the map, rather than a lookup that returns 1.0. */
    bool filtered_lookup;
    /* Whether case c reads the shadow map through a filter that reads past the map's edge, where a
     * wrap mode and border matter (the lab's cases; NULL: never). */
    bool (*filters_past_edge)(const sl_case *c);
    /* Whether case c takes the path of the lab's case `failed` (a failed check of it can be behind
     * c's): the settings the lab's code branches on (lab 1: a moving light; lab 3: the bias mode).
     * NULL: the same light's kind is enough. */
    bool (*same_path)(const sl_case *failed, const sl_case *c);
    /* Probes of the lab's functions: a contract of their own (probe.c), a verdict read from the check's numbers
     * before the shared ones (probe.c), a verdict from the rows after them (verdict.c). */
    bool (*probe_contract)(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                           char *text, size_t text_size, int *shown);
    int (*probe_verdict)(const sl_check *k, const double *student, const double *expected, uint32_t failing_rows,
                         char *text, size_t text_size);
    int (*rows_verdict)(const struct sl_verdict_rows *rows, char *text, size_t text_size);
} sl_lab_diagnoses;
extern const sl_lab_diagnoses sl_lab1_diagnoses;
extern const sl_lab_diagnoses sl_lab2_diagnoses;
extern const sl_lab_diagnoses sl_lab3_diagnoses;
extern const sl_lab_diagnoses sl_lab4_diagnoses;
extern const sl_lab_diagnoses sl_lab5_diagnoses;
extern const sl_lab_diagnoses sl_lab6_diagnoses;
extern const sl_lab_diagnoses sl_lab7_diagnoses;
/* Lab `lab`'s descriptor, or NULL. */
const sl_lab_diagnoses *sl_lab_diagnoses_of(int lab);
/* The i-th descriptor of the table, in the labs' order; NULL past its end. */
const sl_lab_diagnoses *sl_lab_diagnoses_at(int i);
/* What the lab of probe function f registered for it by name (its functions), or NULL. */
const sl_function_verdict *sl_function_verdict_of(const sl_probe_function *f);
/* The diagnosis a lab registered for checks of that kind, or NULL. */
sl_check_diagnosis_fn sl_check_diagnosis_of(sl_check_kind kind);

#endif
