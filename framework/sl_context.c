#include "sl_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_platform.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#ifdef SL_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

#ifdef SL_HAVE_OSMESA
/* GL/osmesa.h pulls in GL/gl.h, whose prototypes clash with sl_gl.h's names;
 * these are the few OSMesa declarations needed (Mesa's osmesa.h, 11.2). */
typedef struct osmesa_context *OSMesaContext;
typedef void (*OSMESAproc)(void);
extern OSMesaContext OSMesaCreateContextAttribs(const int *attribList, OSMesaContext sharelist);
extern GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
extern void OSMesaDestroyContext(OSMesaContext ctx);
extern OSMESAproc OSMesaGetProcAddress(const char *funcName);
enum {
    SL_OSMESA_RGBA = GL_RGBA,
    SL_OSMESA_FORMAT = 0x22,
    SL_OSMESA_DEPTH_BITS = 0x30,
    SL_OSMESA_STENCIL_BITS = 0x31,
    SL_OSMESA_PROFILE = 0x33,
    SL_OSMESA_CORE_PROFILE = 0x34,
    SL_OSMESA_CONTEXT_MAJOR_VERSION = 0x36,
    SL_OSMESA_CONTEXT_MINOR_VERSION = 0x37,
};
#endif

struct sl_context {
    sl_backend backend;
    int width, height;
#ifdef SL_HAVE_OSMESA
    OSMesaContext osmesa;
    unsigned char *osmesa_buffer;
#endif
#ifdef SL_HAVE_EGL
    EGLDisplay egl_display;
    EGLContext egl_context;
#endif
    /* EGL and the hidden window: the framebuffer object that stands in for 0 */
    GLuint offscreen_framebuffer, offscreen_color, offscreen_depth_stencil;
    GLFWwindow *window;
};

static void _sl_set_err(char *err, size_t n, const char *msg) {
    if (err && n) snprintf(err, n, "%s", msg);
}

/* ---- OSMesa -------------------------------------------------------------- */

#ifdef SL_HAVE_OSMESA
static sl_gl_proc _sl_osmesa_get_proc(const char *name) { return (sl_gl_proc)OSMesaGetProcAddress(name); }

static bool _sl_create_osmesa(sl_context *ctx, char *err, size_t n) {
    const int attribs[] = {
        SL_OSMESA_FORMAT, SL_OSMESA_RGBA,
        SL_OSMESA_DEPTH_BITS, 24,
        SL_OSMESA_STENCIL_BITS, 8,
        SL_OSMESA_PROFILE, SL_OSMESA_CORE_PROFILE,
        SL_OSMESA_CONTEXT_MAJOR_VERSION, 3,
        SL_OSMESA_CONTEXT_MINOR_VERSION, 3,
        0,
    };
    ctx->osmesa = OSMesaCreateContextAttribs(attribs, NULL);
    if (!ctx->osmesa) {
        _sl_set_err(err, n, "OSMesa could not create a GL 3.3 core context (is libosmesa6 installed? "
                            "--backend egl renders without it)");
        return false;
    }
    ctx->osmesa_buffer = calloc((size_t)ctx->width * (size_t)ctx->height, 4);
    if (!ctx->osmesa_buffer) {
        _sl_set_err(err, n, "out of memory for the OSMesa frame buffer");
        return false;
    }
    if (!OSMesaMakeCurrent(ctx->osmesa, ctx->osmesa_buffer, GL_UNSIGNED_BYTE, ctx->width, ctx->height)) {
        _sl_set_err(err, n, "OSMesaMakeCurrent failed");
        return false;
    }
    return sl_gl_load(_sl_osmesa_get_proc, err, n);
}
#endif

/* ---- the offscreen framebuffer (EGL, the hidden window) ------------------ */

/* The stand-in for framebuffer 0 (see sl_context.h): EGL without a surface has
 * no framebuffer of its own, and a hidden window's may not be drawn at all (a
 * window not shown owns no pixels) or be another size (macOS's Retina
 * scaling). One context at a time, like the GL entry points themselves. */
static GLuint _sl_offscreen_fbo;
static PFNGLBINDFRAMEBUFFERPROC _sl_offscreen_bind_framebuffer_gl;
static PFNGLGETINTEGERVPROC _sl_offscreen_get_integerv_gl;

static void APIENTRY _sl_offscreen_bind_framebuffer(GLenum target, GLuint framebuffer) {
    _sl_offscreen_bind_framebuffer_gl(target, framebuffer ? framebuffer : _sl_offscreen_fbo);
}

static void APIENTRY _sl_offscreen_get_integerv(GLenum pname, GLint *data) {
    _sl_offscreen_get_integerv_gl(pname, data);
    if ((pname == GL_DRAW_FRAMEBUFFER_BINDING || pname == GL_READ_FRAMEBUFFER_BINDING) && data &&
        (GLuint)*data == _sl_offscreen_fbo)
        *data = 0; /* GL_FRAMEBUFFER_BINDING is GL_DRAW_FRAMEBUFFER_BINDING */
}

/* Makes the stand-in (RGBA8, depth 24 / stencil 8, the context's size), binds
 * it, and loads the entries that make 0 mean it. GL is loaded already. */
static bool _sl_offscreen_create(sl_context *ctx, const char *backend, char *err, size_t n) {
    glGenFramebuffers(1, &ctx->offscreen_framebuffer);
    glGenRenderbuffers(1, &ctx->offscreen_color);
    glGenRenderbuffers(1, &ctx->offscreen_depth_stencil);
    glBindRenderbuffer(GL_RENDERBUFFER, ctx->offscreen_color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, ctx->width, ctx->height);
    glBindRenderbuffer(GL_RENDERBUFFER, ctx->offscreen_depth_stencil);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, ctx->width, ctx->height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->offscreen_framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ctx->offscreen_color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              ctx->offscreen_depth_stencil);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        if (err && n)
            snprintf(err, n, "%s: the %dx%d default framebuffer is incomplete (%s)", backend, ctx->width, ctx->height,
                     sl_gl_enum_name(status));
        return false;
    }
    glViewport(0, 0, ctx->width, ctx->height);
    _sl_offscreen_fbo = ctx->offscreen_framebuffer;
    _sl_offscreen_bind_framebuffer_gl = _sl_glBindFramebuffer;
    _sl_glBindFramebuffer = _sl_offscreen_bind_framebuffer;
    _sl_offscreen_get_integerv_gl = _sl_glGetIntegerv;
    _sl_glGetIntegerv = _sl_offscreen_get_integerv;
    return true;
}

/* While the context is still current. */
static void _sl_offscreen_destroy(sl_context *ctx) {
    if (ctx->offscreen_framebuffer) {
        GLuint renderbuffers[2] = {ctx->offscreen_color, ctx->offscreen_depth_stencil};
        glDeleteRenderbuffers(2, renderbuffers);
        glDeleteFramebuffers(1, &ctx->offscreen_framebuffer);
    }
    if (_sl_offscreen_fbo && _sl_offscreen_fbo == ctx->offscreen_framebuffer) {
        /* Undo the redirection: the next context loads its own entry points. */
        if (_sl_glBindFramebuffer == _sl_offscreen_bind_framebuffer)
            _sl_glBindFramebuffer = _sl_offscreen_bind_framebuffer_gl;
        if (_sl_glGetIntegerv == _sl_offscreen_get_integerv) _sl_glGetIntegerv = _sl_offscreen_get_integerv_gl;
        _sl_offscreen_fbo = 0;
    }
    ctx->offscreen_framebuffer = 0;
}

/* ---- EGL ----------------------------------------------------------------- */

#ifdef SL_HAVE_EGL
static sl_gl_proc _sl_egl_get_proc(const char *name) { return (sl_gl_proc)eglGetProcAddress(name); }

/* Whole-word match in a space-separated extension string. */
static bool _sl_has_extension(const char *list, const char *name) {
    size_t len = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += len)
        if ((p == list || p[-1] == ' ') && (p[len] == ' ' || p[len] == '\0')) return true;
    return false;
}

static const char *_sl_egl_error_name(EGLint code) {
    switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error";
    }
}

/* Appends "what: why" to the list of attempts that failed, for the final message. */
static void _sl_egl_note(char *tried, size_t n, const char *what, const char *why) {
    size_t used = strlen(tried);
    if (used + 1 < n) snprintf(tried + used, n - used, "%s%s: %s", used ? "; " : "", what, why);
}

/* Makes a 3.3 core context on an initialised display current, without a surface. */
static bool _sl_egl_try_display(sl_context *ctx, EGLDisplay display, char *why, size_t n) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        snprintf(why, n, "eglInitialize failed (%s)", _sl_egl_error_name(eglGetError()));
        return false;
    }
    ctx->egl_display = display;
    const char *extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!_sl_has_extension(extensions, "EGL_KHR_surfaceless_context")) {
        snprintf(why, n, "no EGL_KHR_surfaceless_context");
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        snprintf(why, n, "no desktop OpenGL (eglBindAPI: %s)", _sl_egl_error_name(eglGetError()));
        return false;
    }
    /* No surface is ever made, so no config is needed where the driver allows it. */
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!_sl_has_extension(extensions, "EGL_KHR_no_config_context") &&
        !_sl_has_extension(extensions, "EGL_MESA_configless_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &count) || count < 1) {
            snprintf(why, n, "no EGL config for desktop OpenGL");
            return false;
        }
    }
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 3,
        EGL_CONTEXT_MINOR_VERSION, 3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_NONE,
    };
    ctx->egl_context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
    if (ctx->egl_context == EGL_NO_CONTEXT) {
        snprintf(why, n, "no GL 3.3 core context (%s)", _sl_egl_error_name(eglGetError()));
        return false;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx->egl_context)) {
        snprintf(why, n, "eglMakeCurrent failed (%s)", _sl_egl_error_name(eglGetError()));
        return false;
    }
    return true;
}

static void _sl_egl_release(sl_context *ctx) {
    if (ctx->egl_display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(ctx->egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (ctx->egl_context != EGL_NO_CONTEXT) eglDestroyContext(ctx->egl_display, ctx->egl_context);
    eglTerminate(ctx->egl_display);
    ctx->egl_context = EGL_NO_CONTEXT;
    ctx->egl_display = EGL_NO_DISPLAY;
}

/* Tries the displays in order of preference: GPU devices, software devices
 * (llvmpipe), then Mesa's surfaceless platform. software_only, or Mesa's
 * LIBGL_ALWAYS_SOFTWARE variable, skips GPU devices. */
static bool _sl_egl_open(sl_context *ctx, bool software_only, char *tried, size_t tried_size) {
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!client || !get_platform_display || !_sl_has_extension(client, "EGL_EXT_platform_base")) {
        _sl_egl_note(tried, tried_size, "EGL", "no EGL_EXT_platform_base");
        return false;
    }
    char why[256];
    const char *always_software = getenv("LIBGL_ALWAYS_SOFTWARE");
    bool skip_gpus = software_only || (always_software && *always_software && strcmp(always_software, "0") != 0);
    PFNEGLQUERYDEVICESEXTPROC query_devices = (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
    PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string =
        (PFNEGLQUERYDEVICESTRINGEXTPROC)eglGetProcAddress("eglQueryDeviceStringEXT");
    EGLDeviceEXT devices[16];
    EGLint device_count = 0;
    if (_sl_has_extension(client, "EGL_EXT_platform_device") && query_devices && query_device_string &&
        !query_devices(16, devices, &device_count))
        device_count = 0;
    for (int pass = 0; pass < 2; pass++) {
        bool want_software = pass == 1;
        for (EGLint i = 0; i < device_count; i++) {
            const char *device_extensions = query_device_string(devices[i], EGL_EXTENSIONS);
            bool software = _sl_has_extension(device_extensions, "EGL_MESA_device_software");
            if (software != want_software || (!software && skip_gpus)) continue;
            char what[64];
            snprintf(what, sizeof what, "EGL device %d (%s)", (int)i, software ? "software" : "GPU");
            EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], NULL);
            if (display != EGL_NO_DISPLAY && _sl_egl_try_display(ctx, display, why, sizeof why)) return true;
            _sl_egl_note(tried, tried_size, what, display == EGL_NO_DISPLAY ? "no display" : why);
            _sl_egl_release(ctx);
        }
    }
    if (_sl_has_extension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        if (display != EGL_NO_DISPLAY && _sl_egl_try_display(ctx, display, why, sizeof why)) return true;
        _sl_egl_note(tried, tried_size, "EGL surfaceless", display == EGL_NO_DISPLAY ? "no display" : why);
        _sl_egl_release(ctx);
    }
    if (!tried[0]) _sl_egl_note(tried, tried_size, "EGL", "no device and no surfaceless platform");
    return false;
}

static bool _sl_create_egl(sl_context *ctx, bool software_only, char *err, size_t n) {
    ctx->egl_display = EGL_NO_DISPLAY;
    ctx->egl_context = EGL_NO_CONTEXT;
    char tried[1024] = "";
    if (!_sl_egl_open(ctx, software_only, tried, sizeof tried)) {
        if (err && n)
            snprintf(err, n, "EGL could not create a GL 3.3 core context without a display (%s). "
                             "Is Mesa's EGL driver installed (libegl-mesa0; scripts/install-deps.sh)?", tried);
        return false;
    }
    if (!sl_gl_load(_sl_egl_get_proc, err, n)) return false;
    return _sl_offscreen_create(ctx, "EGL", err, n);
}

static void _sl_destroy_egl(sl_context *ctx) {
    if (ctx->egl_context != EGL_NO_CONTEXT) _sl_offscreen_destroy(ctx);
    _sl_egl_release(ctx);
}
#endif

/* ---- GLFW ---------------------------------------------------------------- */

static sl_gl_proc _sl_glfw_get_proc(const char *name) { return (sl_gl_proc)glfwGetProcAddress(name); }

static char _sl_glfw_last_error[256];
static void _sl_glfw_error(int code, const char *description) {
    snprintf(_sl_glfw_last_error, sizeof _sl_glfw_last_error, "GLFW error %d: %s", code, description);
}

/* A window, or with `hidden` a window never shown that only holds the
 * context: the picture is then the offscreen framebuffer's. */
static bool _sl_create_glfw(sl_context *ctx, const sl_context_desc *desc, bool hidden, char *err, size_t n) {
    glfwSetErrorCallback(_sl_glfw_error);
    /* A hidden window's display may refuse a connection for a moment (a
     * virtual X server resets itself when its last client leaves, and a busy
     * machine makes that moment long): a few tries, about 6 s in all, before
     * saying so. With no display named at all, no try would help. */
    bool up = glfwInit();
    const char *x11 = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
    bool named = (x11 && x11[0]) || (wayland && wayland[0]);
    for (double wait = 0.1; !up && hidden && named && wait < 4; wait *= 2) {
        sl_platform_sleep(wait);
        up = glfwInit();
    }
    if (!up) {
        if (err && n)
            snprintf(err, n, hidden ? "cannot open even a hidden window (%s): --backend window needs a desktop "
                                      "session or a display (xvfb-run on Linux)"
                                    : "cannot open a window (%s). No display? Add --headless (with --frames and "
                                      "--screenshot) to render without one, or run under xvfb-run",
                     _sl_glfw_last_error[0] ? _sl_glfw_last_error : "glfwInit failed");
        return false;
    }
    /* Forward-compatible core 3.3 runs on Linux, Windows and macOS (which
     * gives 4.1 for it: its only core profile). */
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_RESIZABLE, desc->resizable && !hidden ? GLFW_TRUE : GLFW_FALSE);
    if (hidden) {
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
    }
    /* A hidden window's own size does not matter: it is never drawn into. */
    ctx->window = glfwCreateWindow(hidden ? 64 : ctx->width, hidden ? 64 : ctx->height,
                                   desc->title ? desc->title : "shadowlab", NULL, NULL);
    if (!ctx->window) {
        if (err && n)
            snprintf(err, n, "cannot create a GL 3.3 core %swindow (%s)", hidden ? "hidden " : "",
                     _sl_glfw_last_error[0] ? _sl_glfw_last_error : "glfwCreateWindow failed");
        return false;
    }
    glfwMakeContextCurrent(ctx->window);
    if (!hidden) glfwSwapInterval(1);
    if (!sl_gl_load(_sl_glfw_get_proc, err, n)) return false;
    return !hidden || _sl_offscreen_create(ctx, "the hidden window", err, n);
}

/* ---- the context --------------------------------------------------------- */

sl_context *sl_context_create(const sl_context_desc *desc, char *err, size_t err_size) {
    sl_backend backend = desc->backend == SL_BACKEND_DEFAULT_HEADLESS ? sl_backend_default_headless() : desc->backend;
    if (!sl_backend_available(backend)) {
        if (err && err_size)
            snprintf(err, err_size, "this build has no %s backend (its development package was not installed "
                                    "when it was configured); try --backend %s",
                     sl_backend_name(backend), sl_backend_name(sl_backend_default_headless()));
        return NULL;
    }
    sl_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        _sl_set_err(err, err_size, "out of memory");
        return NULL;
    }
    ctx->backend = backend;
    ctx->width = desc->width > 0 ? desc->width : 512;
    ctx->height = desc->height > 0 ? desc->height : 512;
    bool ok = false;
    switch (backend) {
    case SL_BACKEND_GLFW: ok = _sl_create_glfw(ctx, desc, false, err, err_size); break;
    case SL_BACKEND_WINDOW: ok = _sl_create_glfw(ctx, desc, true, err, err_size); break;
#ifdef SL_HAVE_OSMESA
    case SL_BACKEND_OSMESA: ok = _sl_create_osmesa(ctx, err, err_size); break;
#endif
#ifdef SL_HAVE_EGL
    case SL_BACKEND_EGL: ok = _sl_create_egl(ctx, desc->software_only, err, err_size); break;
#endif
    default: break;
    }
    if (!ok) {
        sl_context_destroy(ctx);
        return NULL;
    }
    return ctx;
}

void sl_context_destroy(sl_context *ctx) {
    if (!ctx) return;
#ifdef SL_HAVE_OSMESA
    if (ctx->osmesa) OSMesaDestroyContext(ctx->osmesa);
    free(ctx->osmesa_buffer);
#endif
#ifdef SL_HAVE_EGL
    if (ctx->backend == SL_BACKEND_EGL) _sl_destroy_egl(ctx);
#endif
    if (ctx->backend == SL_BACKEND_GLFW || ctx->backend == SL_BACKEND_WINDOW) {
        if (ctx->window) {
            if (ctx->backend == SL_BACKEND_WINDOW && glfwGetCurrentContext() == ctx->window) _sl_offscreen_destroy(ctx);
            glfwDestroyWindow(ctx->window);
        }
        glfwTerminate();
    }
    free(ctx);
}

sl_backend sl_context_backend(const sl_context *ctx) { return ctx->backend; }

sl_context_gl_fn sl_context_proc(const sl_context *ctx, const char *name) {
    switch (ctx->backend) {
#ifdef SL_HAVE_OSMESA
    case SL_BACKEND_OSMESA: return _sl_osmesa_get_proc(name);
#endif
#ifdef SL_HAVE_EGL
    case SL_BACKEND_EGL: return _sl_egl_get_proc(name);
#endif
    case SL_BACKEND_GLFW:
    case SL_BACKEND_WINDOW: return _sl_glfw_get_proc(name);
    default: return NULL;
    }
}

void sl_context_framebuffer_size(const sl_context *ctx, int *width, int *height) {
    if (ctx->backend == SL_BACKEND_GLFW) {
        glfwGetFramebufferSize(ctx->window, width, height);
    } else {
        *width = ctx->width;
        *height = ctx->height;
    }
}

unsigned sl_context_default_framebuffer(const sl_context *ctx) { return ctx->offscreen_framebuffer; }

void sl_context_end_frame(sl_context *ctx) {
    if (ctx->backend == SL_BACKEND_GLFW) {
        glfwSwapBuffers(ctx->window);
        glfwPollEvents();
    } else {
        glFinish();
    }
}

bool sl_context_should_close(const sl_context *ctx) {
    return ctx->backend == SL_BACKEND_GLFW ? glfwWindowShouldClose(ctx->window) != 0 : false;
}

void *sl_context_window(const sl_context *ctx) { return ctx->backend == SL_BACKEND_GLFW ? ctx->window : NULL; }

const char *sl_context_renderer_name(void) {
    const GLubyte *name = glGetString(GL_RENDERER);
    return name ? (const char *)name : "unknown renderer";
}
