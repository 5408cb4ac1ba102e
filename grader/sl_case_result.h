/* sl_case_result: what one case's runner gave back (sl_run.h runs it):
 * how it ended, what it said of itself, and its captures, images or
 * numbers. */
#ifndef SL_CASE_RESULT_H
#define SL_CASE_RESULT_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_image.h"
#include "sl_protocol.h"

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
    char capture_error[512];  /* a capture that could not be taken, and why (the last one said) */
    /* each probe's own, since one shader error stops every probe of its file: probe k's why, or "" */
    char probe_errors[SL_JOB_MAX_PROBES][4096];
    char crashed_in[64];  /* lab function running when the runner died */
    char not_implemented[16][64];
    int not_implemented_count;
    char failed[64];      /* lab function that returned SL_FAILED */
    /* the first error GL reported while a lab function ran, in GL's words, for each function it named */
    char gl_error_function[SL_MSG_GL_ERRORS][64];
    char gl_error[SL_MSG_GL_ERRORS][SL_MSG_GL_ERROR_MAX];
    int gl_error_count;
    sl_capture captures[SL_RUN_MAX_CAPTURES];
    int capture_count;
    double seconds;       /* wall clock, start to end */
    double cpu_seconds;   /* the runner's CPU time (user + system) */
    double render_seconds; /* CPU time of one frame with every shader compiled, as the runner said: shown, never graded */
    char backend[32];     /* what the runner said it rendered with */
    char renderer[160];
    char output_tail[2048]; /* the end of what lab code printed, control characters removed */
    long long output_dropped; /* bytes of output before that tail */
} sl_case_result;

/* The capture of that name, or NULL. */
const sl_capture *sl_result_capture(const sl_case_result *r, const char *name);
/* What GL reported while `function` ran (its first error, in GL's words), or NULL. */
const char *sl_result_gl_error(const sl_case_result *r, const char *function);
/* Frees the captures' images. */
void sl_case_result_free(sl_case_result *r);

#endif
