/* Lab 3: bias & culling — get rid of shadow acne without detaching shadows.
 *
 * Goal: the depth pass's part of the cures (polygon offset, front-face culling)
 * here, and the lookup's part (slope-scaled bias, normal offset) in
 * shaders/bias.glsl. Read README.md in this folder first.
 *
 *   1. lab3_depth_pass_state      polygon offset or culling, per mode  (TODO lab3.1)
 *   2. shaders/bias.glsl          slope_scaled_bias                    (TODO lab3.2)
 *   3. shaders/bias.glsl          normal_offset_position               (TODO lab3.3)
 *   Extension (optional, bonus points): midpoint shadow maps
 *   4. lab3_second_depth_state    state of the second-depth pass       (TODO lab3.4)
 *   5. shaders/midpoint.glsl      midpoint_compare                     (TODO lab3.5)
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab3_depth_pass_state(const sl_bias_settings *bias) {
    /* TODO(lab3.1): set the depth pass's state for bias->mode. The map's
     * framebuffer is bound and lab 1 has cleared it; the framework draws the
     * objects right after this returns SL_OK.
     *   - first switch both cures off (GL_POLYGON_OFFSET_FILL, GL_CULL_FACE):
     *     the previous frame may have used another mode
     *   - SL_BIAS_POLYGON_OFFSET: enable GL_POLYGON_OFFSET_FILL and call
     *     glPolygonOffset(bias->polygon_offset_factor, bias->polygon_offset_units)
     *   - SL_BIAS_FRONT_FACE_CULLING: enable GL_CULL_FACE, cull GL_FRONT faces
     *   - every other mode: nothing more (their bias is in the lookup) */
    (void)bias;
    return SL_NOT_IMPLEMENTED;
}

/* Extension (optional, bonus) ----------------------------------------------- */
sl_status lab3_second_depth_state(void) {
    /* TODO(lab3.4, extension): the framework runs a second depth pass into a
     * second map (made with your lab 1 functions) and calls this right after
     * lab1_begin_depth_pass. Set the state that makes the map keep the SECOND
     * surface along each light ray instead of the first. README.md, "Extension". */
    return SL_NOT_IMPLEMENTED;
}
