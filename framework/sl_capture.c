/* sl_capture: read-backs of what a frame drew, as top-down images and numbers (the grader's runner,
 * the viewer's --case). */
#include "sl_capture.h"

#include <stdio.h>
#include <string.h>

#include "sl_gl.h"

bool sl_capture_framebuffer(GLuint framebuffer, int width, int height, int channels, sl_image *out) {
    static const GLenum formats[5] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
    if (channels < 1 || channels > 4) return false;
    *out = sl_image_alloc(width, height, channels);
    if (!out->data) return false;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, formats[channels], GL_FLOAT, out->data);
    sl_image_flip_rows(out);
    return true;
}

bool sl_capture_depth_texture(GLuint texture, sl_image *out, char *err, size_t err_size) {
    *out = (sl_image){0};
    if (!texture || !glIsTexture(texture)) {
        snprintf(err, err_size, "depth_texture (%u) is not a texture name", texture);
        return false;
    }
    GLint w = 0, h = 0, fmt = 0;
    glBindTexture(GL_TEXTURE_2D, texture);
    while (glGetError() != GL_NO_ERROR) {}
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    if (glGetError() != GL_NO_ERROR || w <= 0 || h <= 0) {
        snprintf(err, err_size, "depth_texture (%u) is not a 2D texture with storage", texture);
        return false;
    }
    GLint depth_bits = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
    if (depth_bits == 0) {
        snprintf(err, err_size, "depth_texture has internal format %s (0x%x), not a depth format",
                 sl_gl_enum_name((GLenum)fmt), fmt);
        return false;
    }
    *out = sl_image_alloc(w, h, 1);
    if (!out->data) return false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out->data);
    sl_image_flip_rows(out);
    return true;
}

bool sl_capture_cube_face(GLuint cube, int face, sl_image *out, char *err, size_t err_size) {
    *out = (sl_image){0};
    if (!cube || !glIsTexture(cube) || face < 0 || face > 5) {
        snprintf(err, err_size, "depth_cube (%u) is not a texture name", cube);
        return false;
    }
    while (glGetError() != GL_NO_ERROR) {}
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    if (glGetError() != GL_NO_ERROR) {
        snprintf(err, err_size, "depth_cube (%u) is not a GL_TEXTURE_CUBE_MAP (was it first bound to another target?)",
                 cube);
        return false;
    }
    GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
    GLint w = 0, h = 0, fmt = 0, depth_bits = 0;
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
    if (glGetError() != GL_NO_ERROR || w <= 0 || h <= 0) {
        snprintf(err, err_size, "face %s of depth_cube has no storage (glTexImage2D for each of the six faces)",
                 sl_cube_face_name(face));
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        return false;
    }
    if (depth_bits == 0) {
        snprintf(err, err_size, "face %s of depth_cube has internal format %s (0x%x), not a depth format",
                 sl_cube_face_name(face), sl_gl_enum_name((GLenum)fmt), fmt);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        return false;
    }
    *out = sl_image_alloc(w, h, 1);
    if (!out->data) return false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(target, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out->data);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    sl_image_flip_rows(out);
    return true;
}

bool sl_vsm_capture_moments(GLuint texture, sl_image *out, char *err, size_t err_size) {
    *out = (sl_image){0};
    if (!texture || !glIsTexture(texture)) {
        snprintf(err, err_size, "moments[0] (%u) is not a texture name", texture);
        return false;
    }
    GLint w = 0, h = 0;
    glBindTexture(GL_TEXTURE_2D, texture);
    while (glGetError() != GL_NO_ERROR) {}
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    if (glGetError() != GL_NO_ERROR || w <= 0 || h <= 0 || w > 4096 || h > 4096) {
        snprintf(err, err_size, "moments[0] (%u) is not a 2D texture with storage", texture);
        return false;
    }
    *out = sl_image_alloc(w, h, 2);
    if (!out->data) return false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, out->data);
    sl_image_flip_rows(out);
    return true;
}

void sl_vsm_describe_target(const sl_moments_target *t, double out[SL_MOMENTS_TARGET_NUMBERS]) {
    memset(out, 0, sizeof(double) * SL_MOMENTS_TARGET_NUMBERS);
    while (glGetError() != GL_NO_ERROR) {}
    if (t->framebuffer[0] && glIsFramebuffer(t->framebuffer[0])) {
        GLint depth_type = 0;
        glBindFramebuffer(GL_FRAMEBUFFER, t->framebuffer[0]);
        out[0] = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &depth_type);
        out[7] = depth_type;
        /* the moments pass writes into what is attached here: the blur reads moments[0] */
        GLint colour_type = 0, colour = 0;
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &colour_type);
        if (colour_type == GL_TEXTURE)
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &colour);
        out[13] = colour_type == GL_TEXTURE && (GLuint)colour == t->moments[0];
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    /* the blur's first pass draws into framebuffer[1]: incomplete, it writes nothing */
    if (t->framebuffer[1] && glIsFramebuffer(t->framebuffer[1])) {
        glBindFramebuffer(GL_FRAMEBUFFER, t->framebuffer[1]);
        out[12] = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    if (t->moments[0] && glIsTexture(t->moments[0])) {
        GLint format = 0, w = 0, h = 0, red = 0, green = 0, type = 0;
        glBindTexture(GL_TEXTURE_2D, t->moments[0]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &red);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &green);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &type);
        out[1] = format;
        out[2] = w;
        out[3] = h;
        out[4] = red;
        out[5] = green;
        out[6] = type == GL_FLOAT;
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    /* the mipmaps: where they were made (level 1's width, 0 when it has none), and how each target is filtered */
    for (int i = 0; i < 2; i++) {
        if (!t->moments[i] || !glIsTexture(t->moments[i])) continue;
        GLint level1 = 0, min_filter = 0;
        glBindTexture(GL_TEXTURE_2D, t->moments[i]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &level1);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min_filter);
        out[8 + 2 * i] = level1;
        out[9 + 2 * i] = min_filter;
        if (i == 0) { /* the camera pass magnifies moments[0] near the light: its mag filter */
            GLint mag_filter = 0;
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag_filter);
            out[18] = mag_filter;
        }
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    /* what each blur pass read and drew into: the renderer's record, filled in by the caller */
    for (int i = 14; i < 18; i++) out[i] = -2;
    while (glGetError() != GL_NO_ERROR) {}
}
