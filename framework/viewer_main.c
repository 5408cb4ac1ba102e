/* shadowlab: the viewer. All of it lives in the framework (sl_viewer.c). */
#include "sl_viewer.h"
#ifdef SL_BENCH_PLAIN_GL
#include "sl_bench_baseline.h" /* staff builds: the benchmark's plain-GL row (solutions/bench/) */
#endif
#ifdef SL_STAFF_LIGHT_CAMERA
#include "sl_light_camera.h" /* staff builds: lab 1's light camera for any light (solutions/framework/) */
#endif

int main(int argc, char **argv) {
#ifdef SL_STAFF_LIGHT_CAMERA
    sl_light_camera_compute_with(sl_light_camera_compute);
#endif
#ifdef SL_BENCH_PLAIN_GL
    sl_bench_set_plain_gl(&sl_bench_baseline_program);
#endif
    return sl_viewer_main(argc, argv);
}
