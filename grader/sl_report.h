/* sl_report: the grade as people and course systems read it — the terminal
 * table ending in "Score: X/Y", a JSON report with student/reference/diff
 * images, and Gradescope / PrairieLearn results files. */
#ifndef SL_REPORT_H
#define SL_REPORT_H

#include <stdbool.h>
#include <stdio.h>

#include "sl_case.h"
#include "sl_grade.h"
#include "sl_run.h"

#define SL_SUBMISSION_NOTES_MAX 16

struct cJSON;

typedef struct sl_graded_case {
    const sl_case *c;
    const sl_case_result *result;
    const sl_reference *references; /* one per check */
    sl_check_result checks[SL_CASE_MAX_CHECKS];
} sl_graded_case;

/* How bonus points (extension checks) count, the same in every report a grade writes:
 * apart: the score counts the regular checks only; the bonus is its own number and
 *        never fills a lost point (a real mistake always shows in the score);
 * fill:  the bonus fills lost points, up to the maximum;
 * add:   the bonus is added, past the maximum if the student has it (extra credit). */
typedef enum { SL_BONUS_APART, SL_BONUS_FILL, SL_BONUS_ADD } sl_bonus_policy;
const char *sl_bonus_policy_name(sl_bonus_policy policy);
bool sl_bonus_policy_parse(const char *name, sl_bonus_policy *policy);
/* The one number a student gets under a policy: score and max leave bonus checks out. */
double sl_bonus_total(sl_bonus_policy policy, double score, double max, double bonus);

typedef struct sl_grade_report {
    sl_graded_case *cases;
    int case_count;
    char problems[32][1200]; /* case files that could not be read, and the like */
    int problem_count;
    double seconds;
    int jobs;
    char options[640];       /* the options that decide the grade ("--lab 1-2 --hidden --seed 4711"; "": none) */
    const char *seed;        /* --hidden's seed, or NULL */
    const char *labs_kind, *labs_dir;
    char sandbox[320];       /* the sandbox level the runners got, in words */
    const char *self_check;  /* the runners had no sandbox: what the header says to the student (else NULL) */
    char backend[32], renderer[160]; /* what the runners rendered with (as the first runner said) */
    bool interrupted;        /* stopped early: the score is incomplete */
    int cases_finished;      /* cases that ran to their end */
    char case_set[160];      /* which cases, when not the public ones ("hidden variants, seed 42") */
    bool hidden;             /* hidden variants (--hidden): Gradescope shows their tests after the due date */
    const char *not_built;   /* the compiler's first error, when the submission did not build */
    const char *lab_not_built[SL_LAB_MAX + 1]; /* graded per lab: each lab's first error, when that lab did not build */
    /* How the submission was staged (shadowlab-grade --submission-summary, written by
     * shadowlab-stage): notes said first in every report, and the summary for results.json. */
    char submission_notes[SL_SUBMISSION_NOTES_MAX][1600];
    int submission_note_count;
    bool no_lab_file;        /* the submission held no lab file: every lab is the handout's stub */
    sl_bonus_policy bonus_policy; /* how the bonus counts in the total (--bonus) */
    struct cJSON *submission_summary;
} sl_grade_report;

/* Reads a submission summary (shadowlab-stage --summary FILE) into the report: its notes and
 * whether a lab file was found. False with "FILE: ..." in err when it cannot be read. */
bool sl_report_load_submission(sl_grade_report *report, const char *path, char *err, size_t err_size);
void sl_report_free_submission(sl_grade_report *report);

/* score and max_score leave bonus checks out; bonus is what they earned. */
void sl_report_totals(const sl_grade_report *report, double *score, double *max_score, double *bonus);
/* The total under the report's bonus policy. */
double sl_report_total(const sl_grade_report *report);
/* "Score: 55/57 (+2 bonus)" (apart), "Score: 57/57 (55 + 2 bonus)" (add, fill), with
 * "(incomplete: ...)" when interrupted. */
void sl_report_score_line(const sl_grade_report *report, char *out, size_t out_size);
/* Every check that is not a bonus passed. */
bool sl_report_full_marks(const sl_grade_report *report);
void sl_report_print(const sl_grade_report *report, FILE *out, bool color);
/* DIR/results.json, DIR/report.html (student | reference | diff for every
 * failed image check) and DIR/images/<case>.<check>.{student,reference,diff}.png */
bool sl_report_write_dir(const sl_grade_report *report, const char *dir, char *err, size_t err_size);
/* JUnit XML: one test suite per lab, one test case per check. */
bool sl_report_write_junit(const sl_grade_report *report, const char *path, char *err, size_t err_size);
bool sl_report_write_gradescope(const sl_grade_report *report, const char *path, char *err, size_t err_size);
bool sl_report_write_prairielearn(const sl_grade_report *report, const char *path, char *err, size_t err_size);

#endif
