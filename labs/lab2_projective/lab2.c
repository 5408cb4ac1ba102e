/* Lab 2: projective lookup — find each pixel in the shadow map and compare.
 *
 * Goal: the light's camera (view Lv, projection Lp), the bias matrix W, and the
 * shadow coordinate s = W * Lp * Lv * M * p that turns a world point into
 * shadow-map texture coordinates and a depth (Williams 1978; Everitt et al.
 * 2001). Read README.md in this folder first.
 *
 *   1. lab2_light_view         where the light's camera sits     (TODO lab2.1)
 *   2. lab2_light_projection   what it sees: ortho fit or cone   (TODO lab2.2)
 *   3. lab2_shadow_matrix      W * Lp * Lv                       (TODO lab2.3)
 *   4. shaders/shadow_coord.glsl   s per vertex                  (TODO lab2.4)
 *   5. shaders/shadow_lookup.glsl  divide, outside test, compare (TODO lab2.5, lab2.6)
 *
 * The grader compares your matrices with the reference: follow the recipe in
 * README.md exactly (eye position, up vector, fit, padding).
 */
#include <math.h>

#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab2_light_view(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest) {
    /* TODO(lab2.1): the light's view matrix with glm_lookat(eye, target, up, dest).
     *   up: (0,1,0), or (0,0,1) when |light->direction[1]| > 0.99
     *   SL_LIGHT_DIRECTIONAL: target = centre of scene_bounds, r = half its
     *       diagonal, eye = target - 2 r * light->direction
     *   SL_LIGHT_SPOT: eye = light->position, target = eye + light->direction
     *   other types: return SL_FAILED (point lights come in lab 7) */
    (void)light;
    (void)scene_bounds;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab2_light_projection(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest) {
    /* TODO(lab2.2): the light's projection.
     *   SL_LIGHT_SPOT: glm_perspective with a field of view of twice the cone's
     *       half-angle (light->spot_angle_deg, in degrees), aspect 1,
     *       light->near, light->far
     *   SL_LIGHT_DIRECTIONAL: fit glm_ortho to the scene: transform the 8 corners
     *       of scene_bounds by light_view, take their min and max x, y, z;
     *       left/right = x range, bottom/top = y range; the camera looks down
     *       -z, so near = -max z and far = -min z, each padded outwards by 1% of
     *       (max z - min z)
     *   other types: return SL_FAILED */
    (void)light;
    (void)scene_bounds;
    (void)light_view;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab2_shadow_matrix(mat4 light_projection, mat4 light_view, mat4 dest) {
    /* TODO(lab2.3): dest = W * light_projection * light_view, where the bias
     * matrix W maps clip space [-1,1] to texture space [0,1] (scale 0.5, then
     * translate 0.5, on x, y and z). cglm matrices are column-major: mat4 m =
     * {{column 0}, {column 1}, ...}; glm_mat4_mul(a, b, dest) is dest = a * b. */
    (void)light_projection;
    (void)light_view;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}
