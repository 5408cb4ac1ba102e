/* Lab 1: depth FBO — render the scene's depth from the light into a texture.
 *
 * Goal: a depth texture attached to a framebuffer with no colour buffer, and a
 * depth-only pass that fills it (Williams 1978: the shadow map is the depth
 * buffer of a camera placed at the light). Read README.md in this folder first.
 *
 *   1. lab1_create_shadow_map   the texture and the framebuffer  (TODO lab1.1, lab1.2)
 *   2. lab1_begin_depth_pass    bind, viewport, depth state, clear (TODO lab1.3)
 *   3. shaders/depth.vert       vertices into the light's clip space (TODO lab1.4)
 *   4. lab1_destroy_shadow_map  give both back                     (TODO lab1.5)
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    map->size = size;

    /* A depth texture: 24-bit depth is exact enough and renderable everywhere. */
    glGenTextures(1, &map->depth_texture);
    glBindTexture(GL_TEXTURE_2D, map->depth_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    /* NEAREST: depths must not be averaged before the comparison (Reeves 1987). */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* Outside the map: the border depth 1.0 (farthest) means "nothing in front", so lit. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glBindTexture(GL_TEXTURE_2D, 0);

    /* A framebuffer with the texture as its only attachment: no colour is drawn. */
    glGenFramebuffers(1, &map->framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map->depth_texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return status == GL_FRAMEBUFFER_COMPLETE ? SL_OK : SL_FAILED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab1_begin_depth_pass(const sl_shadow_map *map) {
    glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
    glViewport(0, 0, map->size, map->size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    return SL_OK;
}

/* 4. ---------------------------------------------------------------------- */
void lab1_destroy_shadow_map(sl_shadow_map *map) {
    glDeleteFramebuffers(1, &map->framebuffer);
    glDeleteTextures(1, &map->depth_texture);
    map->framebuffer = 0;
    map->depth_texture = 0;
    map->size = 0;
}
