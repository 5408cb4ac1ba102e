#include "sl_backend.h"

#include <string.h>

const char *sl_backend_name(sl_backend backend) {
    switch (backend) {
    case SL_BACKEND_DEFAULT_HEADLESS: return "default-headless";
    case SL_BACKEND_OSMESA: return "osmesa";
    case SL_BACKEND_EGL: return "egl";
    case SL_BACKEND_GLFW: return "glfw";
    case SL_BACKEND_WINDOW: return "window";
    }
    return "unknown";
}

bool sl_backend_parse(const char *name, sl_backend *out) {
    if (!name) return false;
    if (strcmp(name, "osmesa") == 0) *out = SL_BACKEND_OSMESA;
    else if (strcmp(name, "egl") == 0) *out = SL_BACKEND_EGL;
    else if (strcmp(name, "window") == 0) *out = SL_BACKEND_WINDOW;
    else return false;
    return true;
}

bool sl_backend_available(sl_backend backend) {
    switch (backend) {
    case SL_BACKEND_DEFAULT_HEADLESS: return true;
#ifdef SL_HAVE_OSMESA
    case SL_BACKEND_OSMESA: return true;
#endif
#ifdef SL_HAVE_EGL
    case SL_BACKEND_EGL: return true;
#endif
    case SL_BACKEND_GLFW: return true;
    case SL_BACKEND_WINDOW: return true;
    default: return false;
    }
}

sl_backend sl_backend_default_headless(void) {
#if defined(SL_HAVE_OSMESA)
    return SL_BACKEND_OSMESA;
#elif defined(SL_HAVE_EGL)
    return SL_BACKEND_EGL;
#else
    return SL_BACKEND_WINDOW;
#endif
}

const char *sl_backend_choices(void) {
#if defined(SL_HAVE_OSMESA) && defined(SL_HAVE_EGL)
    return "osmesa, egl or window";
#elif defined(SL_HAVE_OSMESA)
    return "osmesa or window";
#elif defined(SL_HAVE_EGL)
    return "egl or window";
#else
    return "window (this build has no headless GL)";
#endif
}
