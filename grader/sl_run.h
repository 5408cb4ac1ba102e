/* sl_run: runs each case in a child process with a time limit, so a crash, a
 * hang or a shader error in lab code costs that case only.
 *
 * The child makes its own OSMesa context, draws the case's frames through the
 * renderer, and streams back what it saw (captures, stubs not implemented, the
 * lab function it was in) over a pipe. The parent never touches GL or lab code. */
#ifndef SL_RUN_H
#define SL_RUN_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_image.h"
#include "sl_labs.h"

#define SL_RUN_MAX_CAPTURES 8
#define SL_RUN_MAX_NUMBERS 64

typedef struct sl_capture {
    char name[32];
    bool is_image;
    sl_image image;
    double numbers[SL_RUN_MAX_NUMBERS];
    int number_count;
} sl_capture;

typedef struct sl_case_result {
    bool finished;        /* the child reported every capture */
    bool timed_out;
    int signal;           /* that ended the child, or 0 */
    int exit_code;
    char error[8192];     /* setup or shader compile error, with file:line */
    char capture_error[512]; /* a capture that could not be taken, and why */
    char crashed_in[64];  /* lab function running when the child died */
    char not_implemented[16][64];
    int not_implemented_count;
    char failed[64];      /* lab function that returned SL_FAILED */
    sl_capture captures[SL_RUN_MAX_CAPTURES];
    int capture_count;
    double seconds;
    char output_tail[2048]; /* the end of what lab code printed */
} sl_case_result;

typedef struct sl_run_options {
    int jobs;              /* children at once; default 2 */
    double timeout;        /* seconds, overrides each case's own; 0 = the case's */
    const char *labs_dir;  /* NULL = the build's */
    /* --isolate: each case runs its own lab from this build and the other labs
     * from the solutions, with shaders from isolation_dirs[case's lab] */
    bool isolate;
    const char *isolation_dirs[SL_LAB_COUNT + 1];
} sl_run_options;

void sl_run_cases(const sl_case *cases, int count, const sl_run_options *options, sl_case_result *results);
const sl_capture *sl_result_capture(const sl_case_result *r, const char *name);
void sl_case_result_free(sl_case_result *r);

#endif
