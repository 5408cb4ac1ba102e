/* context_backends: an offscreen backend makes a GL 3.3 core context, draws
 * into framebuffer 0 with colour and depth, and reads the picture back.
 *   context_backends osmesa|egl|window   exit 0 pass, 1 fail, 77 not in this build
 *                                        (window: needs a display, e.g. xvfb-run)
 *   context_backends names          backend names and parsing */
#include <stdio.h>
#include <string.h>

#include "sl_context.h"
#include "sl_gl.h"

static int failures;
#define CHECK(cond, ...)                                                   \
    do {                                                                   \
        if (!(cond)) {                                                     \
            failures++;                                                    \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);          \
            fprintf(stderr, __VA_ARGS__);                                  \
            fputc('\n', stderr);                                           \
        }                                                                  \
    } while (0)

static int _names(void) {
    sl_backend b = SL_BACKEND_GLFW;
    CHECK(sl_backend_parse("osmesa", &b) && b == SL_BACKEND_OSMESA, "osmesa parses");
    CHECK(sl_backend_parse("window", &b) && b == SL_BACKEND_WINDOW, "window parses");
    CHECK(sl_backend_parse("egl", &b) && b == SL_BACKEND_EGL, "egl parses");
    CHECK(!sl_backend_parse("glfw", &b) && !sl_backend_parse("EGL", &b) && !sl_backend_parse("", &b) &&
              !sl_backend_parse(NULL, &b) && b == SL_BACKEND_EGL,
          "only offscreen names parse, and a failed parse leaves the value alone");
    CHECK(strcmp(sl_backend_name(SL_BACKEND_OSMESA), "osmesa") == 0 && strcmp(sl_backend_name(SL_BACKEND_EGL), "egl") == 0,
          "names round-trip");
    sl_backend d = sl_backend_default_headless();
    CHECK(sl_backend_available(d) && d != SL_BACKEND_GLFW, "the default is built in and offscreen");
    CHECK(sl_backend_available(SL_BACKEND_OSMESA) == (d == SL_BACKEND_OSMESA), "OSMesa is the default where built");
    CHECK(sl_backend_available(SL_BACKEND_OSMESA) || sl_backend_available(SL_BACKEND_EGL) || d == SL_BACKEND_WINDOW,
          "the hidden window is the default without headless GL");
    CHECK(sl_backend_available(SL_BACKEND_WINDOW) && strcmp(sl_backend_name(SL_BACKEND_WINDOW), "window") == 0,
          "every build has the hidden window");
    printf("default: %s; this build has %s\n", sl_backend_name(d), sl_backend_choices());
    return failures ? 1 : 0;
}

static GLuint _program(void) {
    static const char *vs = "#version 330 core\n"
                            "uniform float u_depth;\n"
                            "void main() {\n"
                            "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
                            "  gl_Position = vec4(p, u_depth, 1.0);\n"
                            "}\n";
    static const char *fs = "#version 330 core\n"
                            "uniform vec4 u_color;\n"
                            "out vec4 colour;\n"
                            "void main() { colour = u_color; }\n";
    GLuint program = glCreateProgram();
    const char *sources[2] = {vs, fs};
    GLenum kinds[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    for (int i = 0; i < 2; i++) {
        GLuint shader = glCreateShader(kinds[i]);
        glShaderSource(shader, 1, &sources[i], NULL);
        glCompileShader(shader);
        glAttachShader(program, shader);
        glDeleteShader(shader);
    }
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    CHECK(linked, "the test program links");
    return program;
}

static void _full_screen(GLuint program, float depth, float r, float g, float b) {
    glUniform1f(glGetUniformLocation(program, "u_depth"), depth);
    glUniform4f(glGetUniformLocation(program, "u_color"), r, g, b, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

static int _draw_and_read(sl_backend backend) {
    if (!sl_backend_available(backend)) {
        printf("%s: not in this build, skipped\n", sl_backend_name(backend));
        return 77;
    }
    enum { W = 64, H = 48 };
    char err[2048];
    sl_context_desc desc = {.backend = backend, .width = W, .height = H};
    sl_context *ctx = sl_context_create(&desc, err, sizeof err);
    if (!ctx) {
        fprintf(stderr, "FAIL: %s: %s\n", sl_backend_name(backend), err);
        return 1;
    }
    printf("%s: %s, %s\n", sl_backend_name(backend), sl_context_renderer_name(), (const char *)glGetString(GL_VERSION));
    CHECK(sl_context_backend(ctx) == backend, "the backend asked for");
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    CHECK(major * 10 + minor >= 33 && (profile & GL_CONTEXT_CORE_PROFILE_BIT), "GL %d.%d core", major, minor);
    int w = 0, h = 0;
    sl_context_framebuffer_size(ctx, &w, &h);
    CHECK(w == W && h == H, "framebuffer size %dx%d", w, h);
    CHECK((backend == SL_BACKEND_EGL || backend == SL_BACKEND_WINDOW) == (sl_context_default_framebuffer(ctx) != 0),
          "EGL and the hidden window have a framebuffer object for 0");
    CHECK(sl_context_window(ctx) == NULL && !sl_context_should_close(ctx), "offscreen: no window to show or close");

    /* A framebuffer of one's own, then back to 0: 0 must be the context's picture again. */
    GLuint other = 0, texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGenFramebuffers(1, &other);
    glBindFramebuffer(GL_FRAMEBUFFER, other);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    GLint bound = -1;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    CHECK((GLuint)bound == other, "a framebuffer object reports its own name (%d)", bound);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    CHECK(bound == 0, "framebuffer 0 reports 0 (%d)", bound);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
    CHECK(bound == 0, "read framebuffer 0 reports 0 (%d)", bound);
    CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE, "framebuffer 0 is complete");

    /* Colour and depth: grey clear, a blue left half in front, a red full screen behind it. */
    GLuint program = _program();
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glUseProgram(program);
    glViewport(0, 0, W, H);
    glClearColor(0.5f, 0.5f, 0.5f, 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W / 2, H);
    _full_screen(program, -0.5f, 0, 0, 1);
    glDisable(GL_SCISSOR_TEST);
    _full_screen(program, 0.5f, 1, 0, 0);
    glFinish();
    CHECK(glGetError() == GL_NO_ERROR, "no GL error while drawing");

    static unsigned char pixels[H][W][4];
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    const unsigned char *left = pixels[H / 2][W / 4], *right = pixels[H / 2][3 * W / 4];
    CHECK(left[0] == 0 && left[1] == 0 && left[2] == 255, "left half blue (the depth test kept it): %d %d %d", left[0],
          left[1], left[2]);
    CHECK(right[0] == 255 && right[1] == 0 && right[2] == 0, "right half red: %d %d %d", right[0], right[1], right[2]);
    glDeleteFramebuffers(1, &other);
    glDeleteTextures(1, &texture);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    sl_context_destroy(ctx);
    return failures ? 1 : 0;
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: context_backends osmesa|egl|window|names\n");
        return 2;
    }
    if (strcmp(argv[1], "names") == 0) return _names();
    sl_backend backend;
    if (!sl_backend_parse(argv[1], &backend)) {
        fprintf(stderr, "context_backends: unknown backend %s\n", argv[1]);
        return 2;
    }
    return _draw_and_read(backend);
}
