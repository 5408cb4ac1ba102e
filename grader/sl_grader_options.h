/* shadowlab-grade's command line (sl_grader.c): its options, parsed and
 * described, its usage text and its exit statuses. */
#ifndef SL_GRADER_OPTIONS_H
#define SL_GRADER_OPTIONS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "sl_backend.h"
#include "sl_report.h"
#include "sl_sandbox.h"

/* 3: graded, but the submission held no lab file (--submission-summary says so): a status of its own
 * for a gradebook, not a staff-side problem. */
enum { SL_EXIT_FULL = 0, SL_EXIT_FAILED = 1, SL_EXIT_ERROR = 2, SL_EXIT_NO_LAB_FILE = 3 };
#define _SL_MAX_PATTERNS 32

typedef struct _sl_options {
    const char *cases_dir, *refs_dir, *labs_dir, *runners_dir;
    const char *technique_dir; /* the files of the technique the runners' build adds (lab 0): its shaders/ */
    const char *patterns[_SL_MAX_PATTERNS], *excludes[_SL_MAX_PATTERNS];
    int pattern_count, exclude_count;
    const char *report_dir, *gradescope, *prairielearn, *junit;
    uint32_t only_labs; /* 1 << lab of each --lab; 0: every lab */
    uint32_t stub_labs; /* 1 << lab of each --stub-labs: the handout's stubs, unchanged, neither built nor run */
    bool update, list, isolate, strict, hidden, progress, no_reference_cache;
    /* staff grading (--isolate with the solutions): a failed check run again with one function
     * replaced by the solution's (sl_experiment.h); off: the probes' ranking alone */
    bool no_experiments;
    double experiment_budget; /* seconds for every experiment of the grade; 0: the default */
    const char *experiment_builder; /* links a runner with a C function of the solution's (sl_experiment.h) */
    const char *seed, *probe_seed, *not_built, *gradebook, *build_logs, *submission_summary;
    /* with --gradebook: the LMS's roster, its due date (Moodle), and the grades written back in its format */
    const char *roster, *due, *export_format, *export_path, *assignment;
    bool missing_as_zero;
    sl_bonus_policy bonus_policy; /* --bonus: how the bonus counts in every report */
    sl_sandbox_level sandbox_level;
    double timeout, memory_mb;
    int jobs;
    sl_backend backend;
} _sl_options;

/* A lab --stub-labs names: its checks fail as not implemented, and no runner of it starts. */
static inline bool _sl_stub_lab(const _sl_options *o, int lab) {
    return lab > 0 && lab < 32 && ((o->stub_labs >> lab) & 1u);
}

/* 0: go on; otherwise the exit status. */
int _sl_parse(int argc, char **argv, _sl_options *o);

/* The options that decide a grade, as one line for the report and the
 * gradebook ("--lab 1-2 --case lab1_* --hidden --seed 4711"): a second pass
 * with other options says so instead of passing for the first. Where the
 * files come from is named only when it is not this build's own. */
void _sl_describe_options(const _sl_options *o, const char *default_cases, const char *default_refs, char *out,
                          size_t n);

#endif
