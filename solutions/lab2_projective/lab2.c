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
 */
#include <math.h>

#include "shadowlab.h"

/* The light camera's up vector: world up, unless the light looks (almost) straight along it. */
static void light_up_vector(const vec3 direction, vec3 up) {
    if (fabsf(direction[1]) > 0.99f) glm_vec3_copy((vec3){0, 0, 1}, up);
    else glm_vec3_copy((vec3){0, 1, 0}, up);
}

/* 1. ---------------------------------------------------------------------- */
sl_status lab2_light_view(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest) {
    vec3 eye, target, up, dir;
    glm_vec3_copy((float *)light->direction, dir);
    light_up_vector(dir, up);
    switch (light->type) {
    case SL_LIGHT_DIRECTIONAL: {
        /* A sun has no position: put the camera outside the scene, looking at its centre. */
        glm_vec3_center((float *)scene_bounds->min, (float *)scene_bounds->max, target);
        float radius = glm_vec3_distance((float *)scene_bounds->min, (float *)scene_bounds->max) / 2;
        glm_vec3_scale(dir, -2 * radius, eye);
        glm_vec3_add(target, eye, eye);
        break;
    }
    case SL_LIGHT_SPOT:
        glm_vec3_copy((float *)light->position, eye);
        glm_vec3_add(eye, dir, target);
        break;
    default:
        return SL_FAILED; /* point lights need six cameras: lab 7 */
    }
    glm_lookat(eye, target, up, dest);
    return SL_OK;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab2_light_projection(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest) {
    if (light->type == SL_LIGHT_SPOT) {
        /* The cone's half-angle is half the field of view; the map is square. */
        glm_perspective(glm_rad(2 * light->spot_angle_deg), 1.0f, light->near, light->far, dest);
        return SL_OK;
    }
    if (light->type != SL_LIGHT_DIRECTIONAL) return SL_FAILED;
    /* Tight fit: the scene box's 8 corners in light view space bound the ortho box. */
    vec3 lo = {1e30f, 1e30f, 1e30f}, hi = {-1e30f, -1e30f, -1e30f};
    for (int i = 0; i < 8; i++) {
        vec3 corner = {
            i & 1 ? scene_bounds->max[0] : scene_bounds->min[0],
            i & 2 ? scene_bounds->max[1] : scene_bounds->min[1],
            i & 4 ? scene_bounds->max[2] : scene_bounds->min[2],
        };
        vec3 v;
        glm_mat4_mulv3(light_view, corner, 1.0f, v);
        glm_vec3_minv(lo, v, lo);
        glm_vec3_maxv(hi, v, hi);
    }
    /* The camera looks down -z: near is -max z, far is -min z; pad depth by 1%
     * so the farthest corner is not clipped by rounding. */
    float pad = 0.01f * (hi[2] - lo[2]);
    glm_ortho(lo[0], hi[0], lo[1], hi[1], -hi[2] - pad, -lo[2] + pad, dest);
    return SL_OK;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab2_shadow_matrix(mat4 light_projection, mat4 light_view, mat4 dest) {
    /* W maps clip space [-1,1] to texture space [0,1]: scale by 1/2, then add 1/2. */
    mat4 bias = {
        {0.5f, 0.0f, 0.0f, 0.0f},
        {0.0f, 0.5f, 0.0f, 0.0f},
        {0.0f, 0.0f, 0.5f, 0.0f},
        {0.5f, 0.5f, 0.5f, 1.0f}, /* column 3: the translation */
    };
    mat4 view_projection;
    glm_mat4_mul(light_projection, light_view, view_projection);
    glm_mat4_mul(bias, view_projection, dest);
    return SL_OK;
}
