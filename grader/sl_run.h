/* sl_run: runs each case's runner (the process with the lab code) in the
 * sandbox, under a deadline the grader keeps, and takes its results apart as
 * hostile input: every length is bounded, a capture must be one the case
 * asked for and come once, nothing may follow DONE, and the runner must
 * still be the runner executable when it says DONE. A crash, a hang, a
 * shader error or a malformed stream costs that case only. */
#ifndef SL_RUN_H
#define SL_RUN_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_case_result.h"
#include "sl_image.h"
#include "sl_params.h"
#include "sl_sandbox.h"

/* Which runner executable and which lab sources a case of one lab uses. */
typedef struct sl_runner_setup {
    const char *runner;                     /* NULL: no runner for this lab */
    const char *lab_dirs[SL_LAB_COUNT + 1]; /* the tree each lab's folder comes from */
    const char *labs_tree;                  /* one tree holding every lab's folder */
} sl_runner_setup;

typedef struct sl_run_options {
    int jobs;              /* runners at once; default 2 */
    double timeout;        /* seconds, overrides each case's own; 0 = the case's */
    unsigned long long memory_bytes; /* address space per runner; 0 = each case's own */
    int backend;           /* sl_backend */
    const sl_sandbox *sandbox;
    const char *framework_dir;
    /* by the case's lab; setups[0] serves every lab without a setup of its own */
    sl_runner_setup setups[SL_LAB_MAX + 1];
    const char *const *environment; /* the runner's, NULL-terminated */
    /* Optional: called as each case ends (not for cases cut short by `stop`),
     * with how many have ended so far; for progress lines. */
    void (*case_ended)(const sl_case *c, const sl_case_result *r, int ended, int total, void *context);
    void *case_ended_context;
} sl_run_options;

/* Runs every case; returns false if interrupted (the results of cases not
 * finished say so). `stop` is polled: set it from a signal handler. */
bool sl_run_cases(const sl_case *cases, int count, const sl_run_options *options, sl_case_result *results,
                  volatile int *stop);

/* Test hook: parses a stream as if a runner of case `c` had sent it. */
void sl_run_parse_stream(const sl_case *c, const void *data, size_t size, sl_case_result *r);

#endif
