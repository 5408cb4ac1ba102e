/* sl_diag: what a check's diagnosis reads and writes, and how it says what
 * it found: the check's result (its message, the likely cause, the lab
 * function that cause names), the reference it was compared with, a failed
 * probe; where a stub's TODO is. Below the diagnoses (sl_diagnose.h) and the
 * grade (sl_grade.h), which both use it, so neither calls back into the other. */
#ifndef SL_DIAG_H
#define SL_DIAG_H

#include <stdbool.h>
#include <stdint.h>

#include "sl_case.h"
#include "sl_compare.h"
#include "sl_image.h"
#include "sl_probe.h"
#include "sl_run.h"

typedef struct sl_reference {
    bool needed, loaded;
    char path[1100];
    char error[600];
    sl_image image;
    /* The surfaces facing the light, as the solutions drew them (lit_mask.exr), for the checks that
     * measure only there; no data for the others. The runner's own mask is its word: never used. */
    sl_image lit_mask;
    double numbers[SL_RUN_MAX_NUMBERS]; /* matrices (48), or a probe's rows x outputs */
    int number_count;
} sl_reference;

typedef struct sl_check_result {
    double points, max_points;
    bool bonus;             /* max_points do not count towards the maximum score */
    bool passed;
    /* Not the submission's doing, staff must fix it: a missing or corrupt
     * reference, or a case the machine could not run (r->staff_error). */
    bool reference_problem;
    char message[2048];
    sl_image diff;          /* failed image checks */
    /* What other checks may quote: the mistake in a few words ("the shadow
     * matrix multiplies Lv * Lp"), for a later check of the case or an image
     * check of the same lab to lead with. */
    char summary[512];
    uint32_t symptoms;      /* 1 << sl_symptom: what the capture shows (a hint is shown for its own only) */
    uint32_t failing_rows;  /* probe checks: 1 << row for each row that differs */
    bool stub;              /* probe checks: the function still returns what its stub returns */
    /* probe checks: what each failing row's mistake can show in a picture (1 << sl_symptom), from
     * the row's outputs, or the verdict's when it named the mistake (grader/diagnose/probe.c) */
    uint32_t row_predicts[SL_PROBE_MAX_ROWS];
    uint16_t row_outputs[SL_PROBE_MAX_ROWS]; /* probe checks: 1 << output for each output of a row that differs */
    char cause[1024];       /* while a check is diagnosed: the likely cause of the symptom in message */
    char blamed[64];        /* while a check is diagnosed: the lab function the cause names (sl_diag_cause_in) */
    bool settled;           /* the message needs no lead: a stub, a run that failed, a capture missing */
    /* A failed check's diagnosis, the same for every student it fits: the
     * mistake in a few words (the summary; a probe's with its function; for a
     * check led by an earlier failure, that lead) with its numbers taken out
     * ("shadow acne on …% of lit surfaces"), and an id made from that text
     * ("shadow-acne-on-of-lit-surfaces-3fa2c1"; "follows-..." for a lead).
     * The class report counts students per id. */
    char diagnosis[72];
    char diagnosis_text[320];
    /* The mistake behind a failed check, when the evidence names a lab
     * function: that function and the kind of cause (SL_CAUSE_*). Checks that
     * fail through one mistake carry the same pair whatever their wording (a
     * probe's verdict, a lead, a crash in it), so the class report counts it
     * once. Empty when nothing names a function. */
    char cause_function[64];
    const char *cause_kind;
    /* The shader file whose GLSL compile error stopped the check before it could run
     * ("labs/lab3_bias/shaders/bias.glsl"), or "": a report quotes the compiler once per file. */
    char not_compiled[160];
} sl_check_result;

/* The kinds of cause a failed check names (results.json's "cause": {"function", "kind"}). */
#define SL_CAUSE_WRONG "wrong"     /* the function gives wrong results (its probe, a lead, a blame on evidence) */
#define SL_CAUSE_STUB "stub"       /* the function is not implemented */
#define SL_CAUSE_CRASH "crash"     /* the runner died in the function */
#define SL_CAUSE_TIMEOUT "timeout" /* the runner was stopped in the function */
/* Sets out's cause: the function's name alone ("pcf_grid()" -> "pcf_grid"). */
void sl_diag_set_cause(sl_check_result *out, const char *function, const char *kind);

/* A function probe that failed. A check whose case runs the function leads
 * with it only on evidence (grader/diagnose/README.md): the case runs it on
 * inputs like a failing row's, and what those rows predict is what the
 * check's capture shows. */
typedef struct sl_probe_failure {
    int function;            /* sl_probe_at index */
    char where[200];         /* "lab4_probes / pcf_grid" */
    char summary[512];       /* what is wrong with it */
    bool stub;               /* not implemented yet */
    uint32_t failing_modes;  /* functions whose first input is a mode: 1 << mode of each failing row */
    const sl_check *check;   /* the probe check: its rows' inputs */
    uint32_t failing_rows;   /* 1 << row */
    uint32_t row_predicts[SL_PROBE_MAX_ROWS]; /* what each failing row's mistake can show (1 << sl_symptom) */
    uint16_t row_outputs[SL_PROBE_MAX_ROWS];  /* 1 << output for each output of a row that differs */
} sl_probe_failure;

/* A failed check of a lab (not a bonus one), for the later labs that build on it. */
void sl_diag_say(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void sl_diag_append(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The likely cause of the symptom in out->message. */
void sl_diag_cause(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A likely cause that names a lab function (a probe's, or "depth.vert"): the core
 * keeps it only on evidence (runs.c): the case runs that function, and its probe,
 * when it was graded, failed in a way that explains the symptoms; otherwise the
 * message says the function was ruled out and lists the candidates instead. */
void sl_diag_cause_in(sl_check_result *out, const char *function, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Adds a case's hint after the message, unless the message already says it word for word. */
void sl_diag_hint(sl_check_result *out, const char *hint);
/* "not implemented" for this lab's stubs first, then "needs lab K"; false if no stub is in the way. */
bool sl_diag_explain_missing(const sl_case *c, const sl_case_result *r, sl_check_result *out);
/* Appends what GL's debug output reported while `function` ran (its first error), where it reported one. */
void sl_diag_gl_error(sl_check_result *out, const sl_case_result *r, const char *function);
/* An image check's verdict from its comparison: few enough pixels off, none
 * NaN, and a mean difference within the check's mean tolerance. When only
 * the mean is off, says so (a small error everywhere) and returns false. */
bool sl_diag_image_passes(const sl_check *k, const sl_compare_stats *st, const char *what, sl_check_result *out);
/* A check that measures a difference (`what`: "flicker", "light bleeding")
 * and found none may be looking at a picture that is dark everywhere: says
 * so and returns true when the student's picture lost too much of the
 * reference's light (sl_visibility_lit_lost; frames stacked, a mask of one). Called only where
 * the difference itself was met: a failed one keeps its own message. */
bool sl_diag_lit_lost(const sl_image *student, const sl_image *reference, const sl_image *mask, const char *what,
                      sl_check_result *out);
/* A runner's error that is a GLSL compile error ("GLSL compile error in MAIN:" and the compiler's lines):
 * the check was not reached. Says "not reached: FILE did not compile:" with the compiler's lines (a
 * candidate list on one line), FILE the first error's when it is a lab file, else MAIN; sets
 * out->not_compiled and settles the check. False (out untouched) for any other error. */
bool sl_diag_compile_error(sl_check_result *out, const char *error);
/* A report quotes each compile error once: the first check (in the report's order) that FILE stopped
 * keeps the compiler's lines, each later one says "not reached: FILE did not compile (see above)". */
typedef struct sl_compile_errors_said {
    char files[32][160];
    int count;
} sl_compile_errors_said;
void sl_diag_compile_error_once(sl_check_result *out, sl_compile_errors_said *said);
/* The TODO tag and file of a lab function ("TODO(lab3.2)", "labs/lab3_bias/shaders/bias.glsl"). */
bool sl_diag_stub_location(const char *function, const char **todo, const char **file);

/* The lab of a lab function by its name ("lab4_configure_shadow_texture": 4); 0 for a GLSL one. */
int sl_diag_function_lab(const char *function);
/* A GL enum's name ("GL_CLAMP_TO_EDGE"), "unknown GL enum" for others. */
const char *sl_diag_enum_name(unsigned value);

/* Where the graded code and the handout's stubs are (set once per grade), for a diagnosis that
 * reads a function's text: whether a function that answers as its stub does is still the stub. */
void sl_diag_set_sources(const char *graded_tree, const char *stubs_tree);
/* Whether `function`'s definition in `file` (a path under the labs tree) is the handout's, up to
 * comments and white space: 1 it is, 0 it was written, -1 unknown (no sources set, a file missing). */
int sl_diag_still_the_stub(const char *file, const char *function);

#endif
