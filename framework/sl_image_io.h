/* sl_image_io: the interface between sl_image.c and the image file module
 * (libshadowlab_image.so, built from sl_image_oiio.cpp with OpenImageIO).
 *
 * Why a module: OpenImageIO brings in some 260 shared libraries, which cost a
 * quarter of a second at every start of every program linked with it. Only
 * reading and writing files needs it, so sl_image.c loads the module with
 * dlopen() on the first read or write, and programs that never touch an
 * image file (shadowlab --help, a grading child) start without it.
 *
 * The module exports one function, SL_IMAGE_IO_ENTRY, returning a table of
 * functions. Images the module reads are allocated with calloc(), so
 * sl_image_free() frees them. */
#ifndef SL_IMAGE_IO_H
#define SL_IMAGE_IO_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* sl_image.h's types, by name only: the interface stands below both sides
 * (sl_image.c loads the module, the module reads and writes sl_image.h's images). */
struct sl_image;
struct sl_animation;
struct sl_pixels;

/* Raised whenever the table or the meaning of its functions changes, so a
 * module left over from another build is refused rather than misused. */
#define SL_IMAGE_IO_VERSION 3
#define SL_IMAGE_IO_ENTRY "sl_image_io_module"
/* The module's file name; sl_image.c looks for it next to the executable. */
#ifdef _WIN32
#define SL_IMAGE_IO_MODULE "libshadowlab_image.dll"
#else
#define SL_IMAGE_IO_MODULE "libshadowlab_image.so" /* CMake names modules .so on macOS too */
#endif

typedef struct sl_image_io_api {
    int version;        /* SL_IMAGE_IO_VERSION */
    size_t struct_size; /* sizeof(sl_image_io_api) */
    /* Same contracts as sl_image_write and sl_image_read (sl_image.h). */
    bool (*write)(const char *path, const struct sl_image *image, char *err, size_t err_size);
    bool (*read)(const char *path, struct sl_image *out, char *err, size_t err_size);
    /* Same contracts as sl_animation_open, _add and _close (sl_image.h). */
    struct sl_animation *(*animation_open)(const char *path, int fps, char *err, size_t err_size);
    bool (*animation_add)(struct sl_animation *animation, const struct sl_image *frame, char *err, size_t err_size);
    bool (*animation_close)(struct sl_animation *animation, char *err, size_t err_size);
    /* Same contract as sl_image_encode (sl_image.h); the bytes are malloc()ed. */
    bool (*encode)(const struct sl_pixels *pixels, const char *format, int quality, unsigned char **out, size_t *out_size,
                   char *err, size_t err_size);
} sl_image_io_api;

typedef const sl_image_io_api *(*sl_image_io_entry_fn)(void);

#ifdef __cplusplus
}
#endif
#endif
