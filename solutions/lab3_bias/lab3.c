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
    /* Each mode starts from a clean state: another mode's setting must not leak in. */
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    if (bias->mode == SL_BIAS_POLYGON_OFFSET) {
        /* depth += factor * max slope + units * smallest resolvable depth step */
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(bias->polygon_offset_factor, bias->polygon_offset_units);
    } else if (bias->mode == SL_BIAS_FRONT_FACE_CULLING) {
        /* Only back faces are stored: lit front faces are compared with a far surface. */
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
    }
    return SL_OK;
}

/* Extension ----------------------------------------------------------------- */
sl_status lab3_second_depth_state(void) {
    /* With front faces culled, the first surface a ray meets in this pass is
     * the far side of the object it entered: the second depth. */
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT); /* keep the far side */
    return SL_OK;
}
