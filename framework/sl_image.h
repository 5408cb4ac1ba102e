/* sl_image: float images in memory, and their files (PNG for colour and
 * visibility, OpenEXR for float buffers) through OpenImageIO, which lives in
 * a module loaded on the first read or write (see sl_image_io.h). If the
 * module is missing, reads and writes fail with a message naming it.
 *
 * Pixels are floats, interleaved, row 0 is the TOP row (as in image files;
 * GL read-backs are flipped on capture). */
#ifndef SL_IMAGE_H
#define SL_IMAGE_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sl_image {
    int width, height, channels;
    float *data; /* width * height * channels */
} sl_image;

/* Zero-filled image; data is NULL if the allocation failed. */
sl_image sl_image_alloc(int width, int height, int channels);
void sl_image_free(sl_image *image);
static inline float *sl_image_pixel(const sl_image *image, int x, int y) {
    return image->data + ((size_t)y * (size_t)image->width + (size_t)x) * (size_t)image->channels;
}

/* Writes by extension: .png (8 bits per channel, values clamped to [0,1]),
 * .exr (32-bit float). On failure returns false with a message naming the file. */
bool sl_image_write(const char *path, const sl_image *image, char *err, size_t err_size);

/* Reads any format OpenImageIO reads, converted to float. A missing or corrupt
 * file returns false with a message naming the file and the reason. */
bool sl_image_read(const char *path, sl_image *out, char *err, size_t err_size);

/* An animated GIF written one frame at a time (slide figures: frames of the
 * viewer), so a long animation never holds more than one frame in memory.
 * Every frame must have the first one's size and 1 or 3 channels (0..1,
 * clamped). On failure each returns false / NULL with a message naming the
 * file; close frees the animation whatever it returns. */
typedef struct sl_animation sl_animation;
sl_animation *sl_animation_open(const char *path, int fps, char *err, size_t err_size);
bool sl_animation_add(sl_animation *animation, const sl_image *frame, char *err, size_t err_size);
bool sl_animation_close(sl_animation *animation, char *err, size_t err_size);

/* 8-bit pixels as GL reads them back: `channels` (3 or 4) bytes a pixel,
 * rows `stride` bytes apart, row 0 at the bottom when bottom_up. */
typedef struct sl_pixels {
    const unsigned char *data;
    int width, height, channels;
    size_t stride;
    bool bottom_up;
} sl_pixels;

/* Compresses pixels into an image file in memory: format "jpg" (quality
 * 1-100; the alpha channel is dropped) or "png". *out is malloc()ed: free()
 * it. On failure returns false with the reason. The live frames of the
 * browser viewer (sl_serve.h). */
bool sl_image_encode(const sl_pixels *pixels, const char *format, int quality, unsigned char **out, size_t *out_size,
                     char *err, size_t err_size);

/* Reverses the row order in place (GL's bottom-up <-> files' top-down). */
void sl_image_flip_rows(sl_image *image);

#ifdef __cplusplus
}
#endif
#endif
