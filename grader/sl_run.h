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
#include "sl_image.h"
#include "sl_params.h"
#include "sl_sandbox.h"

#define SL_RUN_MAX_CAPTURES 16
#define SL_RUN_MAX_NUMBERS (SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS)

typedef struct sl_capture {
    char name[32];
    bool is_image;
    sl_image image;
    double numbers[SL_RUN_MAX_NUMBERS];
    int number_count;
} sl_capture;

typedef struct sl_case_result {
    bool started;
    bool finished;        /* DONE arrived, the runner was the runner, and it exited cleanly */
    bool timed_out;
    bool interrupted;     /* the grader was stopped (SIGINT/SIGTERM) before this case ended */
    /* The grading machine, not lab code, stopped the case (no process or
     * pipe for the runner, no memory for its results, starved of CPU by
     * other processes): it could not be graded, and says why. */
    char staff_error[512];
    int signal;           /* that ended the runner, or 0 */
    int exit_code;
    char error[8192];     /* set-up or shader compile error, with file:line */
    char protocol_error[256]; /* the runner's stream broke the rules: the case fails */
    char capture_error[512];  /* a capture that could not be taken, and why */
    char crashed_in[64];  /* lab function running when the runner died */
    char not_implemented[16][64];
    int not_implemented_count;
    char failed[64];      /* lab function that returned SL_FAILED */
    sl_capture captures[SL_RUN_MAX_CAPTURES];
    int capture_count;
    double seconds;       /* wall clock, start to end */
    double cpu_seconds;   /* the runner's CPU time (user + system) */
    double render_seconds; /* CPU time of one frame with every shader compiled, as the runner measured it */
    char backend[32];     /* what the runner said it rendered with */
    char renderer[160];
    char output_tail[2048]; /* the end of what lab code printed, control characters removed */
    long long output_dropped; /* bytes of output before that tail */
} sl_case_result;

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
const sl_capture *sl_result_capture(const sl_case_result *r, const char *name);
void sl_case_result_free(sl_case_result *r);

/* Test hook: parses a stream as if a runner of case `c` had sent it. */
void sl_run_parse_stream(const sl_case *c, const void *data, size_t size, sl_case_result *r);

#endif
