/* Lab 6: cascaded shadow maps — one map per slice of the camera's frustum.
 *
 * Goal: a sun over a long scene. One map over all of it gives the nearest
 * metre a handful of texels (perspective aliasing); cascades give each slice
 * of the view its own map. Here: where the slices end (the practical split
 * scheme, Zhang et al. 2006), each slice's light camera (a bounding sphere, so
 * its size never changes as the camera turns) moved by whole texels (so
 * shadows do not shimmer as the camera moves: Microsoft, "Common Techniques to
 * Improve Shadow Depth Maps"; Valient, ShaderX6), and in shaders/cascades.glsl
 * the choice of cascade per pixel. Read README.md in this folder first.
 *
 *   1. lab6_split_distances   practical split scheme               (TODO lab6.1)
 *   2. lab6_slice_sphere      bounding sphere of a frustum slice   (TODO lab6.2)
 *   3. lab6_cascade_matrices  light view + ortho, texel snapping   (TODO lab6.3)
 *   4. shaders/cascades.glsl  cascade_index                        (TODO lab6.4)
 *   5. shaders/cascades.glsl  cascade_compare                      (TODO lab6.5)
 */
#include <math.h>

#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab6_split_distances(float near, float far, int count, float lambda, float splits[SL_MAX_CASCADES + 1]) {
    if (count < 1 || count > SL_MAX_CASCADES || near <= 0 || far <= near) return SL_FAILED;
    /* C_i = lambda * C_log + (1 - lambda) * C_uniform: the logarithmic split
     * keeps every slice's texels the same size on screen, but gives the first
     * slice almost nothing; the uniform one wastes texels near the camera. */
    for (int i = 0; i <= count; i++) {
        float t = (float)i / (float)count;
        float logarithmic = near * powf(far / near, t);
        float uniform = near + (far - near) * t;
        splits[i] = lambda * logarithmic + (1 - lambda) * uniform;
    }
    splits[0] = near; /* exact ends, whatever the rounding */
    splits[count] = far;
    return SL_OK;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab6_slice_sphere(mat4 inv_view_projection, float near, float far, float split_near, float split_far,
                            vec4 dest) {
    /* The frustum's corners: NDC (+-1, +-1, -1) on the near plane and (+-1, +-1, +1)
     * on the far one (GL's depth range), back to world space. */
    vec3 corners[8];
    for (int i = 0; i < 4; i++) {
        float x = (i & 1) ? 1.0f : -1.0f, y = (i & 2) ? 1.0f : -1.0f;
        vec4 n = {x, y, -1, 1}, f = {x, y, 1, 1}, wn, wf;
        glm_mat4_mulv(inv_view_projection, n, wn);
        glm_mat4_mulv(inv_view_projection, f, wf);
        /* view depth grows linearly along each edge from the near to the far corner */
        float a = (split_near - near) / (far - near), b = (split_far - near) / (far - near);
        for (int k = 0; k < 3; k++) {
            float cn = wn[k] / wn[3], cf = wf[k] / wf[3];
            corners[i][k] = cn + (cf - cn) * a;
            corners[4 + i][k] = cn + (cf - cn) * b;
        }
    }
    /* A sphere around the slice: its centre the corners' mean, its radius the
     * farthest corner. The slice's shape is fixed in the camera's frame, so the
     * radius is the same whichever way the camera looks. */
    vec3 centre = {0, 0, 0};
    for (int i = 0; i < 8; i++) glm_vec3_add(centre, corners[i], centre);
    glm_vec3_scale(centre, 1.0f / 8.0f, centre);
    float radius = 0;
    for (int i = 0; i < 8; i++) radius = fmaxf(radius, glm_vec3_distance(centre, corners[i]));
    dest[0] = centre[0];
    dest[1] = centre[1];
    dest[2] = centre[2];
    dest[3] = radius;
    return SL_OK;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab6_cascade_matrices(const sl_light *light, vec4 sphere, float caster_margin, int map_size, mat4 light_view,
                                mat4 light_projection) {
    if (map_size < 1) return SL_FAILED;
    vec3 dir, up, centre = {sphere[0], sphere[1], sphere[2]}, eye;
    float radius = sphere[3];
    glm_vec3_normalize_to((float *)light->direction, dir);
    /* as in lab 2: world up, unless the light looks (almost) straight along it */
    if (fabsf(dir[1]) > 0.99f) glm_vec3_copy((vec3){0, 0, 1}, up);
    else glm_vec3_copy((vec3){0, 1, 0}, up);
    /* The camera steps back from the centre by the radius and the margin, so
     * casters up to caster_margin beyond the sphere, towards the light, are in range. */
    glm_vec3_scale(dir, -(radius + caster_margin), eye);
    glm_vec3_add(centre, eye, eye);
    glm_lookat(eye, centre, up, light_view);
    glm_ortho(-radius, radius, -radius, radius, 0.0f, 2 * radius + caster_margin, light_projection);
    /* Texel snapping: where the world's origin lands in the map, in texels,
     * rounded to a whole texel; the projection moves by the difference. Every
     * world point then keeps its place on the texel grid from frame to frame. */
    mat4 view_projection;
    glm_mat4_mul(light_projection, light_view, view_projection);
    float half = (float)map_size / 2;
    float x = view_projection[3][0] * half, y = view_projection[3][1] * half; /* the origin's NDC, in texels */
    light_projection[3][0] += (roundf(x) - x) / half;
    light_projection[3][1] += (roundf(y) - y) / half;
    return SL_OK;
}
