/* Attack (compile time): probes with __has_include where the solution of lab 6
 * might be (the Gradescope image's fixed path, paths relative to this file at
 * every depth, the compiler's working folder, the project's absolute path) and
 * includes the first it finds. Stubs where none can be seen. */
#include "shadowlab.h"

#if __has_include("/autograder/source/solutions/lab6_cascades/lab6.c")
#include "/autograder/source/solutions/lab6_cascades/lab6.c"
#elif __has_include("../../solutions/lab6_cascades/lab6.c")
#include "../../solutions/lab6_cascades/lab6.c"
#elif __has_include("../../../solutions/lab6_cascades/lab6.c")
#include "../../../solutions/lab6_cascades/lab6.c"
#elif __has_include("../../../../solutions/lab6_cascades/lab6.c")
#include "../../../../solutions/lab6_cascades/lab6.c"
#elif __has_include("../../../../../solutions/lab6_cascades/lab6.c")
#include "../../../../../solutions/lab6_cascades/lab6.c"
#elif __has_include("/proc/self/cwd/../../solutions/lab6_cascades/lab6.c")
#include "/proc/self/cwd/../../solutions/lab6_cascades/lab6.c"
#elif __has_include("@SOURCE_DIR@/solutions/lab6_cascades/lab6.c")
#include "@SOURCE_DIR@/solutions/lab6_cascades/lab6.c"
#else
sl_status lab6_split_distances(float near, float far, int count, float lambda, float splits[SL_MAX_CASCADES + 1]) {
    return SL_NOT_IMPLEMENTED;
}
sl_status lab6_slice_sphere(mat4 inv_view_projection, float near, float far, float split_near, float split_far,
                            vec4 dest) {
    return SL_NOT_IMPLEMENTED;
}
sl_status lab6_cascade_matrices(const sl_light *light, vec4 sphere, float caster_margin, int map_size, mat4 light_view,
                                mat4 light_projection) {
    return SL_NOT_IMPLEMENTED;
}
#endif
