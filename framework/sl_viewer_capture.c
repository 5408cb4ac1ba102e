#define _POSIX_C_SOURCE 200809L
#include "sl_viewer_capture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>

/* --screenshot FILE.gif: every frame goes into the animation. */
bool _sl_viewer_is_gif(const char *path) {
    size_t n = path ? strlen(path) : 0;
    return n > 4 && strcasecmp(path + n - 4, ".gif") == 0;
}

bool _sl_viewer_add_frame(_sl_viewer *v, GLuint target, int width, int height, const char *path) {
    char err[1024] = "";
    sl_image shot = {0};
    glFinish();
    if (!v->animation) v->animation = sl_animation_open(path, 10, err, sizeof err);
    bool ok = v->animation && sl_capture_framebuffer(target, width, height, 3, &shot) &&
              sl_animation_add(v->animation, &shot, err, sizeof err);
    if (!ok) fprintf(stderr, "shadowlab: cannot save the animation: %s\n", err[0] ? err : "cannot read the frame");
    sl_image_free(&shot);
    return ok;
}

/* --mark-changes: remembers the first frame, then marks every pixel a later frame
 * differs on (more than 0.1 summed over R, G, B: a shadow edge that moved, not
 * noise). False if a frame cannot be read or has another size. */
bool _sl_viewer_mark_changes(_sl_viewer *v, GLuint target, int width, int height) {
    sl_image frame;
    glFinish();
    if (!sl_capture_framebuffer(target, width, height, 3, &frame)) return false;
    if (!v->first_frame.data) {
        v->first_frame = frame;
        v->changed = calloc((size_t)width * (size_t)height, 1);
        return v->changed != NULL;
    }
    bool same_size = frame.width == v->first_frame.width && frame.height == v->first_frame.height;
    for (size_t i = 0; same_size && i < (size_t)width * (size_t)height; i++) {
        float d = 0;
        for (int c = 0; c < 3; c++) d += fabsf(frame.data[i * 3 + c] - v->first_frame.data[i * 3 + c]);
        if (d > 0.1f) v->changed[i] = 1;
    }
    sl_image_free(&frame);
    return same_size;
}

/* Puts an image (top-down RGB floats, the frame's size) into framebuffer `target`. */
static void _sl_show_image(const sl_image *img, GLuint target) {
    sl_image flipped = sl_image_alloc(img->width, img->height, 3);
    if (!flipped.data) return;
    memcpy(flipped.data, img->data, sizeof(float) * 3 * (size_t)img->width * (size_t)img->height);
    sl_image_flip_rows(&flipped);
    GLuint texture, fbo;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, img->width, img->height, 0, GL_RGB, GL_FLOAT, flipped.data);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, img->width, img->height, 0, 0, img->width, img->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, 0);
    sl_image_free(&flipped);
}

/* The first frame with the pixels that changed painted red, into `path`; with
 * the overlay, the last frame's overlay drawn over it (the marks are the
 * scene's, never the overlay's changing text). */
bool _sl_viewer_save_changes(_sl_viewer *v, const char *path, int frames, bool overlay, mat4 camera, GLuint target) {
    char err[1024] = "";
    sl_image *img = &v->first_frame;
    size_t count = 0, n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        if (v->changed[i]) {
            img->data[i * 3] = 1, img->data[i * 3 + 1] = 0.05f, img->data[i * 3 + 2] = 0.05f;
            count++;
        }
    if (overlay && v->overlay) {
        _sl_show_image(img, target);
        sl_overlay_draw(v->overlay, camera, target, img->width, img->height);
        sl_image shot;
        glFinish();
        if (sl_capture_framebuffer(target, img->width, img->height, 3, &shot)) {
            sl_image_free(img);
            *img = shot;
        }
    }
    bool ok = sl_image_write(path, img, err, sizeof err);
    if (ok) printf("shadowlab: saved %s: %zu pixels (%.3f%%) changed over %d frames, in red\n", path, count,
                   n ? 100.0 * (double)count / (double)n : 0.0, frames);
    else fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
    return ok;
}

bool _sl_viewer_save(GLuint target, int width, int height, const char *path) {
    sl_image shot;
    char err[1024] = "";
    glFinish();
    bool ok = sl_capture_framebuffer(target, width, height, 3, &shot) && sl_image_write(path, &shot, err, sizeof err);
    if (ok) printf("shadowlab: saved %s (%dx%d)\n", path, width, height);
    else fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
    sl_image_free(&shot);
    return ok;
}

bool _sl_viewer_screenshot_dir_make(const char *dir) {
    struct stat st;
    if (mkdir(dir, 0777) != 0 && (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))) {
        fprintf(stderr, "shadowlab: cannot make the screenshots' folder %s\n", dir);
        return false;
    }
    return true;
}

/* The X key: shadowlab-001.png, -002 ... never overwriting. The names are the viewer's own: a
 * --serve page asks for a screenshot with the key and nothing else. */
void _sl_viewer_screenshot_key(_sl_viewer *v, GLuint target, int width, int height) {
    char path[4200];
    const char *dir = v->screenshot_dir;
    for (int tries = 0; tries < 1000; tries++) {
        snprintf(path, sizeof path, "%s%sshadowlab-%03d.png", dir ? dir : "", dir ? "/" : "", ++v->screenshot_count);
        FILE *f = fopen(path, "r");
        if (!f) break;
        fclose(f);
    }
    _sl_viewer_save(target, width, height, path);
}

