/* sl_runner: the grader's runner, the only process that runs lab code while
 * grading. It reads one sl_job on fd 0, renders the case's frames through the
 * renderer, and writes what it saw to fd 3 (see sl_protocol.h). The grader
 * starts one per case, inside a sandbox (grader/sl_sandbox.h), and trusts
 * nothing it says: the runner holds no reference and no solution it could
 * hand over, so the only way to earn points is to render the right picture. */
#ifndef SL_RUNNER_H
#define SL_RUNNER_H

int sl_runner_main(int argc, char **argv);

#endif
