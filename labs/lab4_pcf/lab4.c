/* Lab 4: PCF & PCSS — soft shadow edges by filtering comparisons.
 *
 * Goal: set the shadow map's filtering for each filter (here), and write the
 * filters in shaders/pcf.glsl: hardware 2x2 PCF, an N x N grid, a rotated
 * Poisson disk, and percentage-closer soft shadows (Reeves et al. 1987;
 * Fernando 2005). Read README.md in this folder first.
 *
 *   1. lab4_configure_shadow_texture   filtering per mode     (TODO lab4.1)
 *   2. shaders/pcf.glsl   pcf_hardware                        (TODO lab4.2)
 *   3. shaders/pcf.glsl   pcf_grid                            (TODO lab4.3)
 *   4. shaders/pcf.glsl   pcf_poisson                         (TODO lab4.4)
 *   5. shaders/pcf.glsl   pcss                                (TODO lab4.5)
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab4_configure_shadow_texture(GLuint depth_texture, sl_filter_mode mode) {
    /* TODO(lab4.1): set depth_texture's GL_TEXTURE_MIN_FILTER and
     * GL_TEXTURE_MAG_FILTER for `mode`:
     *   - SL_FILTER_HARDWARE: GL_LINEAR. With GL_TEXTURE_COMPARE_MODE on (the
     *     framework sets it for sampler2DShadow), the texture unit then filters
     *     the four comparison RESULTS: 2x2 PCF for free.
     *   - every other mode: GL_NEAREST (the shader compares exact depths)
     * Bind it first: glBindTexture(GL_TEXTURE_2D, depth_texture). */
    (void)depth_texture;
    (void)mode;
    return SL_NOT_IMPLEMENTED;
}
