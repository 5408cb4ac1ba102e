/* sl_context: a GL 3.3 core context from one of two backends, with every GL
 * entry point loaded through that backend (see sl_gl.h).
 *   SL_BACKEND_OSMESA  headless, software (llvmpipe); the grader's default
 *   SL_BACKEND_GLFW    a window (X11 on Linux); the viewer's default */
#ifndef SL_CONTEXT_H
#define SL_CONTEXT_H

#include <stdbool.h>
#include <stddef.h>

typedef enum sl_backend { SL_BACKEND_OSMESA = 0, SL_BACKEND_GLFW } sl_backend;

typedef struct sl_context_desc {
    sl_backend backend;  /* default OSMesa */
    int width, height;   /* default 512 x 512 */
    const char *title;   /* window title (GLFW) */
    bool resizable;      /* GLFW only */
} sl_context_desc;

typedef struct sl_context sl_context;

/* NULL on failure, with the reason in err. */
sl_context *sl_context_create(const sl_context_desc *desc, char *err, size_t err_size);
void sl_context_destroy(sl_context *ctx);

sl_backend sl_context_backend(const sl_context *ctx);
/* Size of the default framebuffer in pixels. */
void sl_context_framebuffer_size(const sl_context *ctx, int *width, int *height);
/* Finishes the frame: swaps and polls events (GLFW), or glFinish (OSMesa). */
void sl_context_end_frame(sl_context *ctx);
bool sl_context_should_close(const sl_context *ctx);
/* The GLFWwindow, or NULL for OSMesa. */
void *sl_context_window(const sl_context *ctx);
const char *sl_context_renderer_name(void); /* GL_RENDERER of the current context */

#endif
