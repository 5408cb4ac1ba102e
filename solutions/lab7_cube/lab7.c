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
    map->size = size;
    glGenTextures(1, &map->depth_cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, map->depth_cube);
    /* Six square faces of depth: 24 bits hold distance / far to better than 1e-7. */
    for (int face = 0; face < 6; face++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, 0, GL_DEPTH_COMPONENT24, size, size, 0,
                     GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    /* NEAREST: distances must not be averaged before the comparison. */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* A direction near a face's edge must not fetch from beyond it. */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);

    /* The framebuffer: depth only. Which face it renders into is chosen per pass. */
    glGenFramebuffers(1, &map->framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X, map->depth_cube, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return status == GL_FRAMEBUFFER_COMPLETE ? SL_OK : SL_FAILED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab7_begin_cube_pass(const sl_cube_map *map, int face) {
    /* Six passes: this solution attaches one face per pass. (The layered
     * alternative attaches the whole cube with glFramebufferTexture here and
     * lets cube_depth.geom choose gl_Layer: README, "Six passes or one".) */
    if (face == SL_CUBE_ALL_FACES) return SL_NOT_IMPLEMENTED;
    glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face,
                           map->depth_cube, 0);
    glViewport(0, 0, map->size, map->size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    return SL_OK;
}

/* 3. ---------------------------------------------------------------------- */
sl_status lab7_face_view(vec3 light_position, int face, mat4 dest) {
    /* GL's cube map faces (the OpenGL spec's table "Selection of cube map
     * images"): looking down each axis, with the up vector that makes the
     * rendered image line up with how texture() reads the face. */
    static const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const float ups[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    if (face < 0 || face > 5) return SL_FAILED;
    vec3 target, up;
    glm_vec3_add(light_position, (float *)axes[face], target);
    glm_vec3_copy((float *)ups[face], up);
    glm_lookat(light_position, target, up, dest);
    return SL_OK;
}

/* 4. ---------------------------------------------------------------------- */
sl_status lab7_face_projection(float near, float far, mat4 dest) {
    /* 90 degrees and a square: the six frusta meet edge to edge and fill the sphere. */
    glm_perspective(glm_rad(90.0f), 1.0f, near, far, dest);
    return SL_OK;
}

/* 8. ---------------------------------------------------------------------- */
void lab7_destroy_cube_map(sl_cube_map *map) {
    glDeleteFramebuffers(1, &map->framebuffer);
    glDeleteTextures(1, &map->depth_cube);
    map->framebuffer = 0;
    map->depth_cube = 0;
    map->size = 0;
}
