/* Attack: lab 2's light camera taken from the framework. Before lab 2 is
 * done, lab 1's depth maps are drawn with a light camera of the framework's
 * (sl_light_default_matrices), which for a spot light is lab 2's view and
 * projection, and for a sun its view. A runner that held the staff code
 * computing it for any light answered every probe row and every hidden
 * variant's light with it: the staff function itself (a weak reference,
 * NULL where it is not linked), else the framework's public entry point. */
#include "shadowlab.h"
#include "sl_scene.h"

bool sl_light_camera_compute(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection)
    __attribute__((weak));

static void _framework_camera(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection) {
    if (sl_light_camera_compute && sl_light_camera_compute(light, bounds, view, projection)) return;
    sl_light_default_matrices(light, bounds, view, projection);
}

sl_status lab2_light_view(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest) {
    mat4 projection;
    _framework_camera(light, scene_bounds, dest, projection);
    return SL_OK;
}

sl_status lab2_light_projection(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest) {
    (void)light_view;
    mat4 view;
    _framework_camera(light, scene_bounds, view, dest);
    return SL_OK;
}

/* Lab 2's own work, not taken from anywhere: left undone. */
sl_status lab2_shadow_matrix(mat4 light_projection, mat4 light_view, mat4 dest) {
    (void)light_projection;
    (void)light_view;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}
