/* sl_context: a GL 3.3 core context from one of four backends, with every GL
 * entry point loaded through that backend (see sl_gl.h).
 *   SL_BACKEND_OSMESA  headless, software (llvmpipe). Mesa removed OSMesa in
 *                      25.1, so newer systems do not have it.
 *   SL_BACKEND_EGL     headless, no display and no surface: a GPU through
 *                      EGL_EXT_platform_device where there is one, else llvmpipe
 *                      (EGL_MESA_platform_surfaceless or Mesa's software device).
 *   SL_BACKEND_GLFW    a window (X11 on Linux); the viewer's default.
 *   SL_BACKEND_WINDOW  offscreen like the headless ones, in a hidden GLFW
 *                      window that only holds the context: macOS (4.1 core),
 *                      Windows, or Linux with a display (Xvfb). Needs a
 *                      desktop session or a display; the default where the
 *                      build has no headless backend.
 * Which headless backends exist is decided at build time: ask
 * sl_backend_available() (sl_backend.h).
 *
 * Framebuffer 0. Code draws into and reads from framebuffer 0 as "the
 * context's own picture" (the window, the OSMesa buffer). EGL without a surface
 * has no such framebuffer, and a hidden window's is not to be relied on (a
 * window never shown owns no pixels), so these two backends make one: a
 * framebuffer object of the context's size (RGBA8 colour, depth 24 / stencil
 * 8), bound at creation. So that every caller, the labs included, keeps
 * meaning "the context's picture" by 0 on every backend, they load
 * glBindFramebuffer so that binding 0 binds that object, and glGetIntegerv
 * reports it as 0 for GL_{DRAW_,READ_,}FRAMEBUFFER_BINDING. Code that needs the
 * real name (e.g. to attach or query it) gets it from
 * sl_context_default_framebuffer(). Differences that remain there: the
 * colour buffer is GL_COLOR_ATTACHMENT0, not GL_BACK/GL_FRONT, for
 * glDrawBuffer, glReadBuffer and attachment queries.
 *
 * One context at a time per process: the GL entry points are process-wide. */
#ifndef SL_CONTEXT_H
#define SL_CONTEXT_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_backend.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sl_context_desc {
    sl_backend backend;  /* default: sl_backend_default_headless() */
    int width, height;   /* default 512 x 512 */
    const char *title;   /* window title (GLFW) */
    bool resizable;      /* GLFW only */
    /* EGL: only Mesa's software device (llvmpipe), even where a GPU is
     * present, so pictures match references rendered in software. The
     * surfaceless platform is tried only if that device fails. */
    bool software_only;
} sl_context_desc;

typedef struct sl_context sl_context;

/* NULL on failure, with the reason in err. The context is current on return. */
sl_context *sl_context_create(const sl_context_desc *desc, char *err, size_t err_size);
void sl_context_destroy(sl_context *ctx);

/* An entry point of the context's GL beyond the loader's 3.3 core (an extension's), or NULL. */
typedef void (*sl_context_gl_fn)(void);
sl_context_gl_fn sl_context_proc(const sl_context *ctx, const char *name);
/* The backend in use (never SL_BACKEND_DEFAULT_HEADLESS). */
sl_backend sl_context_backend(const sl_context *ctx);
/* Size of the default framebuffer in pixels. */
void sl_context_framebuffer_size(const sl_context *ctx, int *width, int *height);
/* The GL name of the default framebuffer: the framebuffer object of the EGL
 * and hidden-window backends, 0 for the others. Binding 0 binds it anyway
 * (see the top). */
unsigned sl_context_default_framebuffer(const sl_context *ctx);
/* Finishes the frame: swaps and polls events (a window), or glFinish (offscreen). */
void sl_context_end_frame(sl_context *ctx);
bool sl_context_should_close(const sl_context *ctx);
/* The GLFWwindow of a visible window, or NULL for the offscreen backends
 * (the hidden window's included). */
void *sl_context_window(const sl_context *ctx);
const char *sl_context_renderer_name(void); /* GL_RENDERER of the current context */

#ifdef __cplusplus
}
#endif

#endif
