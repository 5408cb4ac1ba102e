#include "sl_context.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

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

struct sl_context {
    sl_backend backend;
    int width, height;
    OSMesaContext osmesa;
    unsigned char *osmesa_buffer;
    GLFWwindow *window;
};

static void _sl_set_err(char *err, size_t n, const char *msg) {
    if (err && n) snprintf(err, n, "%s", msg);
}

static sl_gl_proc _sl_osmesa_get_proc(const char *name) { return (sl_gl_proc)OSMesaGetProcAddress(name); }
static sl_gl_proc _sl_glfw_get_proc(const char *name) { return (sl_gl_proc)glfwGetProcAddress(name); }

static char _sl_glfw_last_error[256];
static void _sl_glfw_error(int code, const char *description) {
    snprintf(_sl_glfw_last_error, sizeof _sl_glfw_last_error, "GLFW error %d: %s", code, description);
}

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
        _sl_set_err(err, n, "OSMesa could not create a GL 3.3 core context (is libosmesa6 installed?)");
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

static bool _sl_create_glfw(sl_context *ctx, const sl_context_desc *desc, char *err, size_t n) {
    glfwSetErrorCallback(_sl_glfw_error);
    if (!glfwInit()) {
        if (err && n)
            snprintf(err, n, "cannot open a window (%s). No display? Use xvfb-run, or the headless grader",
                     _sl_glfw_last_error[0] ? _sl_glfw_last_error : "glfwInit failed");
        return false;
    }
    /* Forward-compatible core 3.3 runs on Linux, Windows and macOS (which stops at 4.1). */
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_RESIZABLE, desc->resizable ? GLFW_TRUE : GLFW_FALSE);
    ctx->window = glfwCreateWindow(ctx->width, ctx->height, desc->title ? desc->title : "shadowlab", NULL, NULL);
    if (!ctx->window) {
        if (err && n)
            snprintf(err, n, "cannot create a GL 3.3 core window (%s)",
                     _sl_glfw_last_error[0] ? _sl_glfw_last_error : "glfwCreateWindow failed");
        return false;
    }
    glfwMakeContextCurrent(ctx->window);
    glfwSwapInterval(1);
    return sl_gl_load(_sl_glfw_get_proc, err, n);
}

sl_context *sl_context_create(const sl_context_desc *desc, char *err, size_t err_size) {
    sl_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        _sl_set_err(err, err_size, "out of memory");
        return NULL;
    }
    ctx->backend = desc->backend;
    ctx->width = desc->width > 0 ? desc->width : 512;
    ctx->height = desc->height > 0 ? desc->height : 512;
    bool ok = ctx->backend == SL_BACKEND_GLFW ? _sl_create_glfw(ctx, desc, err, err_size)
                                              : _sl_create_osmesa(ctx, err, err_size);
    if (!ok) {
        sl_context_destroy(ctx);
        return NULL;
    }
    return ctx;
}

void sl_context_destroy(sl_context *ctx) {
    if (!ctx) return;
    if (ctx->osmesa) OSMesaDestroyContext(ctx->osmesa);
    free(ctx->osmesa_buffer);
    if (ctx->backend == SL_BACKEND_GLFW) {
        if (ctx->window) glfwDestroyWindow(ctx->window);
        glfwTerminate();
    }
    free(ctx);
}

sl_backend sl_context_backend(const sl_context *ctx) { return ctx->backend; }

void sl_context_framebuffer_size(const sl_context *ctx, int *width, int *height) {
    if (ctx->window) {
        glfwGetFramebufferSize(ctx->window, width, height);
    } else {
        *width = ctx->width;
        *height = ctx->height;
    }
}

void sl_context_end_frame(sl_context *ctx) {
    if (ctx->window) {
        glfwSwapBuffers(ctx->window);
        glfwPollEvents();
    } else {
        glFinish();
    }
}

bool sl_context_should_close(const sl_context *ctx) {
    return ctx->window ? glfwWindowShouldClose(ctx->window) != 0 : false;
}

void *sl_context_window(const sl_context *ctx) { return ctx->window; }

const char *sl_context_renderer_name(void) {
    const GLubyte *name = glGetString(GL_RENDERER);
    return name ? (const char *)name : "unknown renderer";
}
