/* Attack (compile time): the solution's lab 2, #included by its absolute path
 * (a student who knows where the course keeps its files). Where the compiler
 * cannot see it, the stubs below are compiled instead, so the build never
 * fails: the test is what the grade says. */
#include "shadowlab.h"

#if __has_include("@SOURCE_DIR@/solutions/lab2_projective/lab2.c")
#include "@SOURCE_DIR@/solutions/lab2_projective/lab2.c"
#else
sl_status lab2_light_view(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest) { return SL_NOT_IMPLEMENTED; }
sl_status lab2_light_projection(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest) {
    return SL_NOT_IMPLEMENTED;
}
sl_status lab2_shadow_matrix(mat4 light_projection, mat4 light_view, mat4 dest) { return SL_NOT_IMPLEMENTED; }
#endif
