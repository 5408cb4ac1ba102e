/* sl_bench: `shadowlab --bench`. Renders a fixed scene per lab and technique
 * with the build's labs, warms up, then times N frames: per-pass times from
 * GL timer queries, whole-frame wall-clock time (median, min) and fps. A table
 * for people, or --json for scripts. Timing is reported, never judged. */
#ifndef SL_BENCH_H
#define SL_BENCH_H

#include <stdio.h>

/* Runs the benchmark with the command line of `shadowlab --bench ...`;
 * returns the process exit status. */
int sl_bench_main(int argc, char **argv);
/* The benchmark's options, for the viewer's --help. */
void sl_bench_usage(FILE *f);

#endif
