/* shadowlab, the viewer of a student build that also carries the solutions'
 * lab code (key U, --solutions): that code is compiled a second time with
 * every lab function renamed (see "Viewer: student vs solutions" in the top
 * CMakeLists.txt), so both sets live in this one program. */
#include "sl_viewer.h"
#ifdef SL_BENCH_PLAIN_GL
#include "sl_bench_baseline.h" /* staff builds: the benchmark's plain-GL row (solutions/bench/) */
#endif
#ifdef SL_STAFF_LIGHT_CAMERA
#include "sl_light_camera.h" /* staff builds: lab 1's light camera for any light (solutions/framework/) */
#endif

extern const sl_lab_functions sl_second_lab_functions;

int main(int argc, char **argv) {
#ifdef SL_STAFF_LIGHT_CAMERA
    sl_light_camera_compute_with(sl_light_camera_compute);
#endif
#ifdef SL_BENCH_PLAIN_GL
    sl_bench_set_plain_gl(&sl_bench_baseline_program);
#endif
    sl_viewer_set_second_labs(&sl_second_lab_functions, SL_SECOND_LABS_DIR, "solutions");
    return sl_viewer_main(argc, argv);
}
