/* shadowlab-runner: runs lab code for one grading case. Started by
 * shadowlab-grade, never by hand; all of it lives in sl_runner.c. */
#include "sl_runner.h"

int main(int argc, char **argv) { return sl_runner_main(argc, argv); }
