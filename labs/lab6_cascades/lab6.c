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
    /* TODO(lab6.1): fill splits[0..count] with the practical split scheme
     * (Zhang et al. 2006), for i = 0..count and m = count:
     *     C_i = lambda * near * (far / near)^(i / m)
     *         + (1 - lambda) * (near + (far - near) * i / m)
     * so splits[0] = near and splits[count] = far; lambda = 0 is uniform,
     * 1 logarithmic. README.md, "Where the cascades end". */
    (void)near;
    (void)far;
    (void)count;
    (void)lambda;
    (void)splits;
    return SL_NOT_IMPLEMENTED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab6_slice_sphere(mat4 inv_view_projection, float near, float far, float split_near, float split_far,
                            vec4 dest) {
    /* TODO(lab6.2): the bounding sphere of the frustum's slice between view
     * depths split_near and split_far:
     *   - the frustum's 8 corners: NDC (+-1, +-1, -1) and (+-1, +-1, +1) times
     *     inv_view_projection, divided by w (near corners and far corners);
     *   - the slice's 8 corners: along each edge from near corner to far
     *     corner, at t = (split - near) / (far - near) for both splits;
     *   - centre = the mean of the 8 slice corners, radius = the largest
     *     distance from it to a corner. dest = {x, y, z, radius}.
     * cglm 0.8.8: write this yourself; glm_aabb_sphere is not a bounding
     * sphere of the corners (README.md, "cglm caveats"). */
    (void)inv_view_projection;
    (void)near;
    (void)far;
    (void)split_near;
    (void)split_far;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab6_cascade_matrices(const sl_light *light, vec4 sphere, float caster_margin, int map_size, mat4 light_view,
                                mat4 light_projection) {
    /* TODO(lab6.3): one cascade's light camera around sphere = {x, y, z, r}:
     *   - light_view: glm_lookat from centre - dir * (r + caster_margin) to
     *     the centre, dir = light->direction normalised, up as in lab 2
     *     (world Y, or Z when the light is almost vertical);
     *   - light_projection: glm_ortho(-r, r, -r, r, 0, 2 r + caster_margin);
     *   - texel snapping: take the world origin's x and y in the projection's
     *     NDC, times map_size / 2 (that is, in texels), and add
     *     (round(v) - v) / (map_size / 2) to light_projection[3][0] and [3][1].
     * README.md, "Shadows that stand still". */
    (void)light;
    (void)sphere;
    (void)caster_margin;
    (void)map_size;
    (void)light_view;
    (void)light_projection;
    return SL_NOT_IMPLEMENTED;
}
