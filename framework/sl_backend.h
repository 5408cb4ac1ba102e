/* sl_backend: the GL backends by name, and which ones this build has.
 * No GL here, so the grader (which links no GL and no lab code) can parse and
 * check a backend before it asks a runner to create a context with it
 * (sl_context.h). Which headless backends exist is decided at build time
 * (SL_HAVE_OSMESA, SL_HAVE_EGL). */
#ifndef SL_BACKEND_H
#define SL_BACKEND_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sl_backend {
    SL_BACKEND_DEFAULT_HEADLESS = 0, /* resolved by sl_backend_default_headless() */
    SL_BACKEND_OSMESA,               /* headless, llvmpipe; gone from Mesa 25.1 on */
    SL_BACKEND_EGL,                  /* headless, no display or surface; a GPU or llvmpipe */
    SL_BACKEND_GLFW,                 /* a window; the viewer's default */
    SL_BACKEND_WINDOW,               /* offscreen in a hidden GLFW window: where no headless GL exists
                                        (macOS, Windows, a build with -DSL_OSMESA=OFF -DSL_EGL=OFF) */
} sl_backend;

/* "osmesa", "egl", "glfw", "window", or "default-headless". */
const char *sl_backend_name(sl_backend backend);
/* Parses an offscreen backend's name: "osmesa", "egl" or "window". Returns
 * false on anything else and leaves *out alone. Availability is not checked
 * here. */
bool sl_backend_parse(const char *name, sl_backend *out);
/* Whether this build has the backend compiled in (the library may still fail
 * at run time, e.g. no EGL driver: sl_context_create then says why). */
bool sl_backend_available(sl_backend backend);
/* OSMesa where this build has it (what the references were rendered with),
 * else EGL, else a hidden window (a build with no headless GL). */
sl_backend sl_backend_default_headless(void);
/* The offscreen backends this build has, for messages: "osmesa, egl or window". */
const char *sl_backend_choices(void);

#ifdef __cplusplus
}
#endif
#endif
