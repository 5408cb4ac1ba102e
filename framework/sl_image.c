/* sl_image: float images in memory here; their files through the image module
 * (sl_image_io.h), loaded on the first read or write. */
#define _POSIX_C_SOURCE 200809L /* pthread_once */
#include "sl_image.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_image_io.h"
#include "sl_platform.h"

static bool _sl_image_size(int width, int height, int channels, size_t *count) {
    if (width <= 0 || height <= 0 || channels <= 0) return false;
    size_t w = (size_t)width, h = (size_t)height, c = (size_t)channels;
    if (w > SIZE_MAX / h || w * h > SIZE_MAX / c || w * h * c > SIZE_MAX / sizeof(float)) return false;
    *count = w * h * c;
    return true;
}

sl_image sl_image_alloc(int width, int height, int channels) {
    sl_image image = {0, 0, 0, NULL};
    size_t count = 0;
    if (!_sl_image_size(width, height, channels, &count)) return image;
    image.data = calloc(count, sizeof(float));
    if (image.data) {
        image.width = width;
        image.height = height;
        image.channels = channels;
    }
    return image;
}

void sl_image_free(sl_image *image) {
    if (!image) return;
    free(image->data);
    *image = (sl_image){0, 0, 0, NULL};
}

void sl_image_flip_rows(sl_image *image) {
    if (!image || !image->data || image->width <= 0 || image->height <= 1 || image->channels <= 0) return;
    size_t row = (size_t)image->width * (size_t)image->channels;
    /* Swap in place, element by element, so flipping needs no allocation. */
    for (int top = 0, bottom = image->height - 1; top < bottom; top++, bottom--) {
        float *a = image->data + (size_t)top * row;
        float *b = image->data + (size_t)bottom * row;
        for (size_t i = 0; i < row; i++) {
            float t = a[i];
            a[i] = b[i];
            b[i] = t;
        }
    }
}

/* ---- the image module ---------------------------------------------------- */

static pthread_once_t _sl_image_io_once = PTHREAD_ONCE_INIT;
static const sl_image_io_api *_sl_image_io;
static char _sl_image_io_error[1536];

/* Tries one place. Returns false only when the module is not there, so a
 * module that is there but broken (e.g. OpenImageIO missing) is reported as such. */
static bool _sl_image_io_try(const char *path) {
    if (!sl_platform_is_file(path)) return false;
    /* Never closed: OpenImageIO keeps threads and static state for the process's life. */
    char why[1024];
    void *module = sl_platform_module_open(path, why, sizeof why);
    if (!module) {
        snprintf(_sl_image_io_error, sizeof _sl_image_io_error, "the image module %s does not load: %s", SL_IMAGE_IO_MODULE,
                 why);
        return true;
    }
    sl_image_io_entry_fn entry = (sl_image_io_entry_fn)sl_platform_module_function(module, SL_IMAGE_IO_ENTRY);
    const sl_image_io_api *api = entry ? entry() : NULL;
    if (!api || api->version != SL_IMAGE_IO_VERSION || api->struct_size != sizeof *api || !api->read || !api->write ||
        !api->animation_open || !api->animation_add || !api->animation_close || !api->encode) {
        snprintf(_sl_image_io_error, sizeof _sl_image_io_error,
                 "the image module %s is from another build of shadowlab (rebuild it: cmake --build build)", path);
        return true;
    }
    _sl_image_io = api;
    return true;
}

/* Next to the executable, then in ../lib beside its folder (an installed
 * layout, and build/bin -> build/lib), then in this build's lib folder. */
static void _sl_image_io_load(void) {
    char exe_dir[1024] = "";
    if (!sl_platform_executable_dir(exe_dir, sizeof exe_dir)) exe_dir[0] = '\0';
    char places[3][1200];
    int count = 0;
    if (exe_dir[0]) {
        snprintf(places[count++], sizeof places[0], "%s/%s", exe_dir, SL_IMAGE_IO_MODULE);
        snprintf(places[count++], sizeof places[0], "%s/../lib/%s", exe_dir, SL_IMAGE_IO_MODULE);
    }
    snprintf(places[count++], sizeof places[0], "%s/%s", SL_IMAGE_IO_BUILD_DIR, SL_IMAGE_IO_MODULE);
    for (int i = 0; i < count; i++)
        if (_sl_image_io_try(places[i])) return;
    snprintf(_sl_image_io_error, sizeof _sl_image_io_error,
             "the image module %s is missing: it was not next to the program (%s), in %s/../lib, nor in %s. "
             "Build it (cmake --build build) and keep it beside the programs",
             SL_IMAGE_IO_MODULE, exe_dir[0] ? exe_dir : "unknown folder", exe_dir[0] ? exe_dir : "", SL_IMAGE_IO_BUILD_DIR);
}

static const sl_image_io_api *_sl_image_io_get(const char *path, char *err, size_t err_size) {
    pthread_once(&_sl_image_io_once, _sl_image_io_load);
    if (!_sl_image_io && err && err_size)
        snprintf(err, err_size, "%s: cannot read or write image files: %s", path ? path : "(null)", _sl_image_io_error);
    return _sl_image_io;
}

bool sl_image_write(const char *path, const sl_image *image, char *err, size_t err_size) {
    const sl_image_io_api *io = _sl_image_io_get(path, err, err_size);
    return io && io->write(path, image, err, err_size);
}

bool sl_image_read(const char *path, sl_image *out, char *err, size_t err_size) {
    if (out) *out = (sl_image){0, 0, 0, NULL};
    const sl_image_io_api *io = _sl_image_io_get(path, err, err_size);
    return io && io->read(path, out, err, err_size);
}

bool sl_image_encode(const sl_pixels *pixels, const char *format, int quality, unsigned char **out, size_t *out_size,
                     char *err, size_t err_size) {
    *out = NULL;
    *out_size = 0;
    const sl_image_io_api *io = _sl_image_io_get(format, err, err_size);
    return io && io->encode(pixels, format, quality, out, out_size, err, err_size);
}

sl_animation *sl_animation_open(const char *path, int fps, char *err, size_t err_size) {
    const sl_image_io_api *io = _sl_image_io_get(path, err, err_size);
    return io ? io->animation_open(path, fps, err, err_size) : NULL;
}

/* Only reached with an animation the module made, so the module is loaded. */
bool sl_animation_add(sl_animation *animation, const sl_image *frame, char *err, size_t err_size) {
    if (!animation || !_sl_image_io) {
        if (err && err_size) snprintf(err, err_size, "no animation to add a frame to");
        return false;
    }
    return _sl_image_io->animation_add(animation, frame, err, err_size);
}

bool sl_animation_close(sl_animation *animation, char *err, size_t err_size) {
    if (!animation || !_sl_image_io) return animation == NULL;
    return _sl_image_io->animation_close(animation, err, err_size);
}
