/* sl_experiment: blame by experiment, in staff grading. A failed check's
 * case is run again with one of the student's functions of the lab replaced
 * by the solution's (then, where no single one fixes it, two at a time), in
 * the same sandbox, and each run is reduced by the grader's own comparison to
 * one bit: the check passes, or not. Nothing else of an experiment run is
 * kept: its captures, output, exit status and time are dropped, so no report
 * can carry the solution out. Only where the grader holds the solutions
 * (--isolate in a staff build), never in a handout. */
#ifndef SL_EXPERIMENT_H
#define SL_EXPERIMENT_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_diag.h"
#include "sl_report.h"
#include "sl_run.h"

#define SL_EXPERIMENT_MAX_FUNCTIONS 16

typedef enum {
    SL_EXPERIMENT_NONE = 0,  /* no experiment on this check (passed, not eligible, no function differs) */
    SL_EXPERIMENT_SINGLE,    /* replacing one function fixes it (`functions[0]`) */
    SL_EXPERIMENT_PAIR,      /* no single replacement does; one pair does (`functions[0]`, `functions[1]`) */
    SL_EXPERIMENT_OUTSIDE,   /* every shader function differing from the solution's was tried, alone and in pairs: no fix */
    SL_EXPERIMENT_UNFINISHED /* the budget ran out before an answer: the probes' ranking stands */
} sl_experiment_outcome;

typedef struct sl_experiment_verdict {
    sl_experiment_outcome outcome;
    char functions[2][80]; /* as a message names them: "pcf_grid()", "cube_depth.geom" */
    int tried;             /* functions tried alone on this check */
    bool with_c;           /* the lab's C functions were among them */
} sl_experiment_verdict;

typedef struct sl_experiment_budget {
    double seconds;  /* wall time for every experiment of a grade; past it, the probes' ranking */
    int max_runs;    /* case runs at most */
} sl_experiment_budget;

typedef struct sl_experiment_cost {
    int checks;      /* failed checks experimented on */
    int runs;        /* case runs */
    int functions;   /* functions that differ from the solution's, over the labs tried */
    int unmade;      /* experiments that could not be made (a copy, a link): they answered nothing */
    double seconds;
    bool budget_spent;
} sl_experiment_cost;

/* What one experiment needs of a grade: its cases, their first results and
 * references (`graded[i * SL_CASE_MAX_CHECKS + k]`, `refs` the same), the
 * runs' options (per lab setups: the runner and lab trees it ran with), the
 * graded labs tree and the solutions'. */
typedef struct sl_experiment_grade {
    const sl_case *cases;
    int count;
    const sl_graded_case *graded;         /* by case: its run and its checks' first results */
    const sl_reference *refs;             /* case i's check k: refs[i * SL_CASE_MAX_CHECKS + k] */
    const sl_run_options *run;
    const char *graded_tree, *solutions_tree;
    const char *stubs_tree;               /* the handout's: a function left as its stub is not tried */
    const char *work_dir;                 /* a private folder the experiment trees are made in */
    /* Links a runner with some of the lab's C functions the solution's: run as BUILDER LAB F1[,F2],
     * it prints the runner's path (scripts/build-experiment-runner); NULL: shader functions only. */
    const char *builder;
} sl_experiment_grade;

/* Whether check k's failure is one an experiment may explain: a picture or a lab's own
 * measure that ran and failed (not a probe, a state, a stub, a compile error, a run cut short). */
bool sl_experiment_eligible(const sl_check *k, const sl_check_result *result, const sl_case_result *run);

/* Runs the experiments of every eligible failed check; verdicts[i * SL_CASE_MAX_CHECKS + k]. */
void sl_experiments_run(const sl_experiment_grade *g, const sl_experiment_budget *budget,
                        sl_experiment_verdict *verdicts, sl_experiment_cost *cost, volatile int *stop);

/* The message's lead for a verdict, in the grader's voice; "" for none or an unfinished one. */
void sl_experiment_lead(const sl_experiment_verdict *v, char *out, size_t n);

#endif
