/* Lab 5: variance shadow maps — a shadow map that can be filtered like colour.
 *
 * Goal: store two moments of the depth (depth and depth^2) in a float colour
 * target, blur them with a separable Gaussian, mipmap them, and look them up
 * with Chebyshev's inequality (Donnelly & Lauritzen 2006), with a minimum
 * variance and light-bleeding reduction (Lauritzen 2007, GPU Gems 3 ch. 8).
 * Read README.md in this folder first.
 *
 *   1. lab5_create_moments_target   two RG32F targets, a depth buffer (TODO lab5.1)
 *   2. lab5_begin_moments_pass      bind, clear to "far", depth test  (TODO lab5.2)
 *   3. shaders/moments.glsl   compute_moments                         (TODO lab5.3)
 *   4. lab5_begin_blur_pass         ping-pong between the targets     (TODO lab5.4)
 *   5. shaders/blur.glsl      blur_moments                            (TODO lab5.5)
 *   6. lab5_filter_moments          mipmaps, trilinear filtering      (TODO lab5.6)
 *   7. shaders/vsm.glsl       chebyshev_upper_bound                   (TODO lab5.7)
 *   8. shaders/vsm.glsl       reduce_light_bleeding                   (TODO lab5.8)
 */
#include "shadowlab.h"

/* 1. ---------------------------------------------------------------------- */
sl_status lab5_create_moments_target(int size, sl_moments_target *target) {
    /* TODO(lab5.1): README.md, "What to do", step 1, and "Precision: why GL_RG32F".
     * For i = 0 and 1:
     *   - a texture moments[i], size x size, internal format GL_RG32F (32-bit
     *     floats: the variance is a small difference of two large numbers),
     *     GL_LINEAR filtering, GL_CLAMP_TO_EDGE on both axes;
     *   - a framebuffer framebuffer[i] with moments[i] as GL_COLOR_ATTACHMENT0.
     * framebuffer[0] also needs a depth buffer for the moments pass's depth
     * test: a renderbuffer `depth` (GL_DEPTH_COMPONENT24) as its
     * GL_DEPTH_ATTACHMENT. Set target->size; return SL_FAILED if a
     * framebuffer is not complete (glCheckFramebufferStatus). */
    (void)size;
    (void)target;
    return SL_NOT_IMPLEMENTED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab5_begin_moments_pass(const sl_moments_target *target) {
    /* TODO(lab5.2): as lab1_begin_depth_pass, on framebuffer[0]: bind it,
     * viewport size x size, depth test on (GL_LESS, writes on), then clear
     * colour AND depth. The clear colour is the moments of "nothing in
     * front": (1, 1) (depth 1 and 1^2). */
    (void)target;
    return SL_NOT_IMPLEMENTED;
}

/* 4. ---------------------------------------------------------------------- */
sl_status lab5_begin_blur_pass(const sl_moments_target *target, int direction) {
    /* TODO(lab5.4): README.md, "Separable blur". Ping-pong:
     *   direction 0 (horizontal): read moments[0], write framebuffer[1]
     *   direction 1 (vertical):   read moments[1], write framebuffer[0]
     * Bind the framebuffer to write, set the viewport to size x size, switch
     * the depth test off (a full-screen pass), and bind the texture to read
     * on texture unit 0 (glActiveTexture(GL_TEXTURE0)). The framework then
     * draws one full-screen triangle with shaders/blur.glsl. */
    (void)target;
    (void)direction;
    return SL_NOT_IMPLEMENTED;
}

/* 6. ---------------------------------------------------------------------- */
sl_status lab5_filter_moments(const sl_moments_target *target) {
    /* TODO(lab5.6): the blurred moments are in moments[0]. Bind it, build its
     * mipmaps (glGenerateMipmap) and set GL_TEXTURE_MIN_FILTER to
     * GL_LINEAR_MIPMAP_LINEAR (trilinear), GL_TEXTURE_MAG_FILTER to GL_LINEAR:
     * unlike a depth map, moments may be averaged (README.md, "Why moments
     * can be filtered"). */
    (void)target;
    return SL_NOT_IMPLEMENTED;
}

/* ------------------------------------------------------------------------- */
void lab5_destroy_moments_target(sl_moments_target *target) {
    /* Deletes what lab5_create_moments_target made (nothing yet). */
    glDeleteFramebuffers(2, target->framebuffer);
    glDeleteTextures(2, target->moments);
    glDeleteRenderbuffers(1, &target->depth);
    *target = (sl_moments_target){0};
}
