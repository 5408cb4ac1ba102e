/* Lab 7: cube-map shadows — a point light casts shadows in every direction.
 *
 * Goal: a depth cube map whose texels hold the distance from the light to the
 * nearest surface (divided by the light's far plane), rendered face by face
 * with a 90-degree camera at the light, and the lookup that compares a
 * fragment's own distance with it (Gerasimov 2004, "Omnidirectional shadow
 * mapping"). Read README.md in this folder first.
 *
 *   1. lab7_create_cube_map    the depth cube map and its framebuffer  (TODO lab7.1)
 *   2. lab7_begin_cube_pass    one face (or all six, layered) as target (TODO lab7.2)
 *   3. lab7_face_view          each face's camera: axis and up vector   (TODO lab7.3)
 *   4. lab7_face_projection    90 degrees, aspect 1                     (TODO lab7.4)
 *   5. shaders/cube_depth.frag store distance / far                     (TODO lab7.5)
 *   6. shaders/point_shadow.glsl  point_shadow: the lookup              (TODO lab7.6)
 *   7. shaders/point_shadow.glsl  point_shadow_soft: 20 directions      (TODO lab7.7)
 *   8. lab7_destroy_cube_map   give both back                           (TODO lab7.8)
 *   Optional: one layered pass with shaders/cube_depth.geom (README, "Six passes or one").
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab7_create_cube_map(int size, sl_cube_map *map) {
    /* TODO(lab7.1): the depth cube map and its framebuffer.
     *   - glGenTextures, glBindTexture(GL_TEXTURE_CUBE_MAP, ...), then storage
     *     for each face f = 0..5: glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f,
     *     0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
     *     GL_UNSIGNED_INT, NULL)
     *   - GL_NEAREST filters, GL_CLAMP_TO_EDGE on S, T and R
     *   - a framebuffer with a face as its depth attachment and no colour
     *     (glDrawBuffer/glReadBuffer(GL_NONE)); return SL_FAILED unless
     *     glCheckFramebufferStatus says GL_FRAMEBUFFER_COMPLETE
     * Keep size in map->size. Lab 1's lab1_create_shadow_map is the 2D version. */
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab7_begin_cube_pass(const sl_cube_map *map, int face) {
    /* TODO(lab7.2): make face `face` (0..5, GL's order +X, -X, +Y, -Y, +Z, -Z)
     * the depth target: bind map->framebuffer, attach that face with
     * glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
     * GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, map->depth_cube, 0), then the
     * viewport (the face's size), the depth test with writes on, and clear.
     * face == SL_CUBE_ALL_FACES asks for one layered pass instead: return
     * SL_NOT_IMPLEMENTED for it and the framework renders six passes (the
     * README's "Six passes or one" shows the layered way). */
    (void)map;
    (void)face;
    return SL_NOT_IMPLEMENTED;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab7_face_view(vec3 light_position, int face, mat4 dest) {
    /* TODO(lab7.3): glm_lookat(eye, target, up, dest) with the eye at the
     * light, looking down face `face`'s axis (+X, -X, +Y, -Y, +Z, -Z), and the
     * up vector that matches how texture() reads that face (README: the table
     * of face orientations; the ±Y faces are the ones people get wrong). */
    (void)light_position;
    (void)face;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}

/* 4. ---------------------------------------------------------------------- */
sl_status lab7_face_projection(float near, float far, mat4 dest) {
    /* TODO(lab7.4): one perspective projection for all six faces:
     * glm_perspective(field of view in radians, aspect, near, far, dest).
     * Which field of view and aspect make six frusta fill every direction,
     * edge to edge? */
    (void)near;
    (void)far;
    (void)dest;
    return SL_NOT_IMPLEMENTED;
}

/* 8. ---------------------------------------------------------------------- */
void lab7_destroy_cube_map(sl_cube_map *map) {
    /* TODO(lab7.8): delete the framebuffer and the texture, and zero map's fields. */
    (void)map;
}
