/* sl_bench: `shadowlab --bench`. Renders a fixed scene per lab and technique
 * with the build's labs, warms up, then times N frames: per-pass times from
 * GL timer queries, whole-frame wall-clock time (median, min) and fps. A table
 * for people, or --json for scripts. Timing is reported, never judged. */
#ifndef SL_BENCH_H
#define SL_BENCH_H

#include <stddef.h>
#include <stdio.h>

#include "sl_scene.h"

/* The benchmark's plain-GL row (plain-gl-3x3): the same scene drawn by a
 * shadow-mapping program as a tutorial writes it, timed in the same run. That
 * program answers labs 1-4, so it lives with the solutions
 * (solutions/bench/sl_bench_baseline.c) and only a staff build's viewer hands
 * it over, before sl_bench_main; elsewhere the row is left out. */
typedef struct sl_bench_plain_gl {
    /* NULL with a reason in err when it cannot be made */
    void *(*create)(const sl_scene *scene, int map_size, int pcf_radius, char *err, size_t err_size);
    /* one frame into framebuffer 0; pass_ms: the depth and camera passes of the frame before */
    void (*draw)(void *program, const sl_scene *scene, int width, int height, double pass_ms[2]);
    void (*destroy)(void *program);
} sl_bench_plain_gl;
void sl_bench_set_plain_gl(const sl_bench_plain_gl *program);

/* Runs the benchmark with the command line of `shadowlab --bench ...`;
 * returns the process exit status. */
int sl_bench_main(int argc, char **argv);
/* The benchmark's options, for the viewer's --help. */
void sl_bench_usage(FILE *f);

#endif
