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
 *
 * Each function returns SL_OK when it is done, SL_FAILED if something went
 * wrong, and SL_NOT_IMPLEMENTED until you write it.
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    /* TODO(lab1.1): make the depth texture, size x size texels, and store
     * everything in *map (depth_texture, size):
     *   - glGenTextures / glBindTexture(GL_TEXTURE_2D, ...)
     *   - glTexImage2D with a depth internal format (GL_DEPTH_COMPONENT24),
     *     format GL_DEPTH_COMPONENT and no data (NULL)
     *   - GL_NEAREST min and mag filters (README: why not GL_LINEAR)
     *   - wrap GL_CLAMP_TO_BORDER with border colour 1.0: outside the map is lit
     *
     * TODO(lab1.2): make the framebuffer and store it in map->framebuffer:
     *   - glGenFramebuffers / glBindFramebuffer(GL_FRAMEBUFFER, ...)
     *   - glFramebufferTexture2D(..., GL_DEPTH_ATTACHMENT, ...)
     *   - no colour: glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE)
     *   - glCheckFramebufferStatus must say GL_FRAMEBUFFER_COMPLETE;
     *     return SL_FAILED if it does not
     *   - bind framebuffer 0 again before you return SL_OK */
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab1_begin_depth_pass(const sl_shadow_map *map) {
    /* TODO(lab1.3): get GL ready to draw depth into the map. The framework
     * draws the objects right after this returns SL_OK.
     *   - bind map->framebuffer
     *   - set the viewport to the map's size (not the window's!)
     *   - enable the depth test (GL_LESS) and depth writes
     *   - clear the depth buffer: last frame's depths must not survive */
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

/* 4. ---------------------------------------------------------------------- */
void lab1_destroy_shadow_map(sl_shadow_map *map) {
    /* TODO(lab1.5): delete the framebuffer and the texture, zero the fields. */
    (void)map;
}
