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

/* A float RG texture of size x size: full 32-bit floats, because the variance
 * E[x^2] - E[x]^2 is a difference of two nearly equal numbers. */
static GLuint _moments_texture(int size) {
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    /* The blur reads beyond the edge: repeat the edge texels, never wrap around. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

/* 1. ---------------------------------------------------------------------- */
sl_status lab5_create_moments_target(int size, sl_moments_target *target) {
    target->size = size;
    glGenRenderbuffers(1, &target->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, target->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(2, target->framebuffer);
    bool complete = true;
    for (int i = 0; i < 2; i++) {
        target->moments[i] = _moments_texture(size);
        glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer[i]);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target->moments[i], 0);
        /* only the moments pass draws geometry: the blur targets need no depth */
        if (i == 0) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target->depth);
        complete &= glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return complete ? SL_OK : SL_FAILED;
}

/* 2. ---------------------------------------------------------------------- */
sl_status lab5_begin_moments_pass(const sl_moments_target *target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer[0]);
    glViewport(0, 0, target->size, target->size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    /* nothing drawn = nothing in front: the moments of the far plane, (1, 1^2) */
    glClearColor(1.0f, 1.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return SL_OK;
}

/* 4. ---------------------------------------------------------------------- */
sl_status lab5_begin_blur_pass(const sl_moments_target *target, int direction) {
    int from = direction == 0 ? 0 : 1, to = 1 - from;
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer[to]);
    glViewport(0, 0, target->size, target->size);
    /* a full-screen pass: every texel written, none tested */
    glDisable(GL_DEPTH_TEST);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, target->moments[from]);
    return SL_OK;
}

/* 6. ---------------------------------------------------------------------- */
sl_status lab5_filter_moments(const sl_moments_target *target) {
    glBindTexture(GL_TEXTURE_2D, target->moments[0]);
    glGenerateMipmap(GL_TEXTURE_2D);
    /* trilinear: the lookup is filtered too, over as many texels as a pixel covers */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return SL_OK;
}

/* ------------------------------------------------------------------------- */
void lab5_destroy_moments_target(sl_moments_target *target) {
    glDeleteFramebuffers(2, target->framebuffer);
    glDeleteTextures(2, target->moments);
    glDeleteRenderbuffers(1, &target->depth);
    *target = (sl_moments_target){0};
}
