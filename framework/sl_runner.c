#define _GNU_SOURCE
#include "sl_runner.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "sl_context.h"
#include "sl_capture.h"
#include "sl_probe_pass.h"
#include "sl_protocol.h"
#include "sl_renderer.h"
#include "sl_technique.h"

static void _sl_write_all(const void *data, size_t n) {
    const char *p = data;
    while (n > 0) {
        ssize_t w = write(SL_CHANNEL_FD, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) _exit(3); /* the grader is gone */
        p += w;
        n -= (size_t)w;
    }
}

static void _sl_send(sl_message_type type, const char *name, const void *payload, size_t payload_length) {
    size_t name_length = name ? strlen(name) : 0;
    if (name_length > SL_MSG_NAME_MAX) name_length = SL_MSG_NAME_MAX;
    sl_message_header h = {(uint32_t)type, (uint32_t)name_length, payload_length};
    _sl_write_all(&h, sizeof h);
    if (name_length) _sl_write_all(name, name_length);
    if (payload_length) _sl_write_all(payload, payload_length);
}

static void _sl_send_text(sl_message_type type, const char *name, const char *text) {
    size_t n = strlen(text);
    _sl_send(type, name, text, n < SL_MSG_TEXT_MAX ? n : SL_MSG_TEXT_MAX);
}

static void _sl_send_image(int kind, const sl_image *img) {
    size_t n = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
    size_t bytes = SL_IMAGE_HEADER_BYTES + n * sizeof(float);
    char *buf = malloc(bytes);
    if (!buf) {
        _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(kind), "out of memory for the capture");
        return;
    }
    int32_t dims[3] = {img->width, img->height, img->channels};
    memcpy(buf, dims, sizeof dims);
    memcpy(buf + sizeof dims, img->data, n * sizeof(float));
    _sl_send(SL_MSG_IMAGE, sl_capture_name(kind), buf, bytes);
    free(buf);
}

static void _sl_send_numbers(int kind, const double *v, int count) {
    _sl_send(SL_MSG_NUMBERS, sl_capture_name(kind), v, (size_t)count * sizeof(double));
}

/* Where the runner is, for the grader's message if it hangs or crashes: the
 * lab function it is in, or else, while a case's frames are drawn, "drawing_labN"
 * (GL work, the lab shaders' included, is done there: a shader loop that does
 * not end stops the runner in a draw, a readback or glFinish). */
static char _sl_draw_stage[32];
/* The lab function running now ("" between them), for the errors GL reports meanwhile. */
static char _sl_running[SL_MSG_NAME_MAX + 1];
static void _sl_stage_hook(const char *function) {
    snprintf(_sl_running, sizeof _sl_running, "%s", function ? function : "");
    _sl_send(SL_MSG_STAGE, function ? function : _sl_draw_stage, NULL, 0);
}

/* ---- what GL says about a lab function's calls ----
 * The first error GL's debug output (KHR_debug, which Mesa has in every context) reports while each lab
 * function runs, in GL's own words ("GL_INVALID_VALUE in glTexImage2D(border=1)"): a message can then
 * say which call went wrong and why. Sent once the case is done; errors outside lab functions are the
 * framework's, never reported as the student's. */
typedef struct _sl_gl_error {
    char function[SL_MSG_NAME_MAX + 1];
    char text[SL_MSG_GL_ERROR_MAX];
} _sl_gl_error;
static _sl_gl_error _sl_gl_errors[SL_MSG_GL_ERRORS];
static int _sl_gl_error_count;

static void APIENTRY _sl_gl_debug(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                  const GLchar *message, const void *user) {
    (void)source, (void)id, (void)severity, (void)user;
    if (type != GL_DEBUG_TYPE_ERROR || !_sl_running[0] || !message) return;
    for (int i = 0; i < _sl_gl_error_count; i++)
        if (strcmp(_sl_gl_errors[i].function, _sl_running) == 0) return; /* its first error only */
    if (_sl_gl_error_count == SL_MSG_GL_ERRORS) return;
    _sl_gl_error *e = &_sl_gl_errors[_sl_gl_error_count++];
    snprintf(e->function, sizeof e->function, "%s", _sl_running);
    int n = length >= 0 && length < (GLsizei)sizeof e->text ? (int)length : (int)sizeof e->text - 1;
    snprintf(e->text, sizeof e->text, "%.*s", n, message);
}

static void _sl_gl_debug_start(const sl_context *ctx) {
    PFNGLDEBUGMESSAGECALLBACKPROC callback =
        (PFNGLDEBUGMESSAGECALLBACKPROC)sl_context_proc(ctx, "glDebugMessageCallback");
    if (!callback) return; /* a GL without debug output: messages keep to what they measure */
    while (glGetError() != GL_NO_ERROR) {}
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS); /* reported inside the call, while its function still runs */
    callback(_sl_gl_debug, NULL);
    while (glGetError() != GL_NO_ERROR) {}
}

static void _sl_gl_debug_send(void) {
    for (int i = 0; i < _sl_gl_error_count; i++)
        _sl_send(SL_MSG_GL_ERROR, _sl_gl_errors[i].function, _sl_gl_errors[i].text, strlen(_sl_gl_errors[i].text));
}

/* What the FBO check needs to know about lab 1's framebuffer and texture. */
static void _sl_capture_fbo(const sl_shadow_map *map, int requested_size) {
    double v[SL_FBO_NUMBERS] = {0};
    while (glGetError() != GL_NO_ERROR) {}
    bool is_fbo = map->framebuffer && glIsFramebuffer(map->framebuffer);
    v[9] = requested_size;
    if (is_fbo) {
        GLint type = 0, name = 0, color_type = 0, draw = 0, read = 0;
        glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
        v[0] = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type == GL_TEXTURE)
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &color_type);
        glGetIntegerv(GL_DRAW_BUFFER, &draw);
        glGetIntegerv(GL_READ_BUFFER, &read);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        v[1] = type;
        v[2] = (GLuint)name == map->depth_texture && name != 0;
        v[6] = draw;
        v[7] = read;
        v[8] = color_type;
    }
    if (map->depth_texture && glIsTexture(map->depth_texture)) {
        GLint w = 0, h = 0, bits = 0;
        glBindTexture(GL_TEXTURE_2D, map->depth_texture);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
        v[3] = bits;
        v[4] = w;
        v[5] = h;
    }
    while (glGetError() != GL_NO_ERROR) {}
    _sl_send_numbers(SL_CAPTURE_FBO, v, SL_FBO_NUMBERS);
}

static bool _sl_wants(const sl_job *job, int capture) { return (job->captures >> capture) & 1u; }

/* The camera's image is drawn into 32-bit floats, never 8-bit colour: NaN
 * and small systematic errors reach the grader as they are. */
typedef struct _sl_float_target {
    GLuint framebuffer, colour, depth;
} _sl_float_target;

static bool _sl_float_target_make(_sl_float_target *t, int width, int height) {
    glGenTextures(1, &t->colour);
    glBindTexture(GL_TEXTURE_2D, t->colour);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenRenderbuffers(1, &t->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, t->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glGenFramebuffers(1, &t->framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, t->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->colour, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, t->depth);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return complete;
}

static void _sl_float_target_free(_sl_float_target *t) {
    glDeleteFramebuffers(1, &t->framebuffer);
    glDeleteRenderbuffers(1, &t->depth);
    glDeleteTextures(1, &t->colour);
}

/* Draws one more frame with `output` and sends it as capture `kind`. */
static void _sl_capture_output(sl_renderer *r, const sl_job *job, sl_scene *scene, sl_render_params *p, GLuint target,
                               sl_output output, sl_capture_kind kind, int channels, bool redraw) {
    p->output = output;
    if (redraw) sl_renderer_draw(r, scene, p, target, job->width, job->height);
    sl_image img;
    if (sl_capture_framebuffer(target, job->width, job->height, channels, &img)) {
        _sl_send_image(kind, &img);
        sl_image_free(&img);
    } else {
        _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(kind), "out of memory for the capture");
    }
}

/* Stubs that returned SL_NOT_IMPLEMENTED, each named once. */
typedef struct _sl_missing {
    const char *names[32];
    int count;
} _sl_missing;

static void _sl_missing_add(_sl_missing *m, const char *name) {
    for (int i = 0; i < m->count; i++)
        if (strcmp(m->names[i], name) == 0) return;
    if (m->count < 32) m->names[m->count++] = name;
}

/* Lab 5's captures: the moments before the blur (a frame with radius 0),
 * then, from a frame as the case asks, the moments the camera pass read and
 * the target's format, and the visibility without light-bleeding reduction
 * (a frame with amount 0). Every frame after the first asks every lab 5
 * stub, so the stubs the last frame recorded are all of them. */
static void _sl_capture_lab5(sl_renderer *r, const sl_job *job, sl_scene *scene, sl_render_params *p, GLuint fb) {
    char err[512];
    const sl_frame_info *info = sl_renderer_info(r);
    uint32_t lab5 = (1u << SL_CAPTURE_MOMENTS) | (1u << SL_CAPTURE_MOMENTS_BLURRED) |
                    (1u << SL_CAPTURE_MOMENTS_TARGET) | (1u << SL_CAPTURE_VISIBILITY_UNREDUCED) |
                    (1u << SL_CAPTURE_MOMENTS_PASSES);
    if (!(job->captures & lab5)) return;
    sl_render_params q = *p;
    q.output = SL_OUTPUT_VISIBILITY;
    for (int pass = 0; pass < 2; pass++) {
        int kind = pass == 0 ? SL_CAPTURE_MOMENTS : SL_CAPTURE_MOMENTS_BLURRED;
        q.vsm.blur_radius = pass == 0 ? 0 : p->vsm.blur_radius; /* 0: the moments pass alone */
        if (pass == 0 && !_sl_wants(job, kind)) continue;
        r->keep_pass_outputs = pass == 1 && _sl_wants(job, SL_CAPTURE_MOMENTS_PASSES);
        sl_renderer_draw(r, scene, &q, fb, job->width, job->height);
        r->keep_pass_outputs = false;
        if (pass == 1 && _sl_wants(job, SL_CAPTURE_MOMENTS_PASSES) && info->vsm_passes && info->vsm_passes->data)
            _sl_send_image(SL_CAPTURE_MOMENTS_PASSES, info->vsm_passes);
        if (!_sl_wants(job, kind) || !info->moments_ready) continue;
        sl_image img;
        if (sl_vsm_capture_moments(info->moments_target.moments[0], &img, err, sizeof err)) {
            _sl_send_image(kind, &img);
            sl_image_free(&img);
        } else {
            _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(kind), err);
        }
    }
    if (_sl_wants(job, SL_CAPTURE_MOMENTS_TARGET) && info->moments_target.framebuffer[0] + info->moments_target.moments[0]) {
        double v[SL_MOMENTS_TARGET_NUMBERS];
        sl_vsm_describe_target(&info->moments_target, v);
        for (int i = 0; i < 2; i++) {
            v[14 + i] = info->vsm_blur_read[i];
            v[16 + i] = info->vsm_blur_drew[i];
        }
        _sl_send_numbers(SL_CAPTURE_MOMENTS_TARGET, v, SL_MOMENTS_TARGET_NUMBERS);
    }
    if (_sl_wants(job, SL_CAPTURE_VISIBILITY_UNREDUCED)) {
        q.vsm.bleeding = 0;
        _sl_capture_output(r, job, scene, &q, fb, SL_OUTPUT_VISIBILITY, SL_CAPTURE_VISIBILITY_UNREDUCED, 1, true);
    }
    p->output = SL_OUTPUT_VISIBILITY;
}

/* The case's frames and their captures; false when the case must stop (said why). */
static bool _sl_render_case(const sl_job *job, _sl_missing *missing) {
    char err[8192];
    sl_renderer r;
    sl_renderer_desc rd = {.labs_dir = job->labs_dir, .framework_dir = job->framework_dir};
    snprintf(_sl_draw_stage, sizeof _sl_draw_stage, "drawing_lab%d", job->params.lab);
    _sl_stage_hook(NULL);
    sl_scene scene = job->scene;
    _sl_float_target target = {0};
    if (!_sl_float_target_make(&target, job->width, job->height)) {
        _sl_send_text(SL_MSG_ERROR, NULL, "this GL cannot render into a 32-bit float framebuffer");
        return false;
    }
    if (!sl_renderer_init(&r, &rd, err, sizeof err) || !sl_renderer_set_scene(&r, &scene, err, sizeof err)) {
        _sl_send_text(SL_MSG_ERROR, NULL, err);
        return false;
    }
    sl_render_params p = job->params;
    p.output = SL_OUTPUT_VISIBILITY;
    /* lab 6's flicker: every frame's visibility, stacked top to bottom */
    sl_image flicker = {0};
    bool want_flicker = _sl_wants(job, SL_CAPTURE_FLICKER);
    if (want_flicker) flicker = sl_image_alloc(job->width, job->height * job->frame_count, 1);
    for (int f = 0; f < job->frame_count; f++) {
        scene.light = job->frame_lights[f];
        if (job->light_cameras_given)
            sl_renderer_set_light_camera(&r, &job->frame_light_cameras[f][0][0], &job->frame_light_cameras[f][1][0]);
        if (job->camera_path) { /* lab 6: the cascades follow the path; the picture's camera stays */
            p.cascades.use_camera = true;
            p.cascades.camera = job->frame_cameras[f];
        }
        sl_renderer_draw(&r, &scene, &p, target.framebuffer, job->width, job->height);
        glFinish();
        sl_image frame;
        if (want_flicker && flicker.data && sl_capture_framebuffer(target.framebuffer, job->width, job->height, 1, &frame)) {
            memcpy(flicker.data + (size_t)f * (size_t)job->width * (size_t)job->height, frame.data,
                   (size_t)job->width * (size_t)job->height * sizeof(float));
            sl_image_free(&frame);
        }
    }
    const sl_frame_info *info = sl_renderer_info(&r);
    if (info->shader_error && info->shader_error_lab <= job->lab) {
        /* A lab's shaders this case needs do not compile: the case fails on that alone. */
        _sl_send_text(SL_MSG_ERROR, NULL, info->shader_error);
        return false;
    }
    /* The visibility frame is the one just drawn; the others need a frame of their own. */
    GLuint fb = target.framebuffer;
    if (_sl_wants(job, SL_CAPTURE_VISIBILITY))
        _sl_capture_output(&r, job, &scene, &p, fb, SL_OUTPUT_VISIBILITY, SL_CAPTURE_VISIBILITY, 1, false);
    if (_sl_wants(job, SL_CAPTURE_LIT_MASK))
        _sl_capture_output(&r, job, &scene, &p, fb, SL_OUTPUT_LIT_MASK, SL_CAPTURE_LIT_MASK, 1, true);
    if (_sl_wants(job, SL_CAPTURE_IMAGE))
        _sl_capture_output(&r, job, &scene, &p, fb, SL_OUTPUT_SHADED, SL_CAPTURE_IMAGE, 3, true);
    _sl_capture_lab5(&r, job, &scene, &p, fb);
    if (_sl_wants(job, SL_CAPTURE_CASCADE_INDEX))
        _sl_capture_output(&r, job, &scene, &p, fb, SL_OUTPUT_CASCADE_INDEX, SL_CAPTURE_CASCADE_INDEX, 1, true);
    if (want_flicker) {
        if (flicker.data) _sl_send_image(SL_CAPTURE_FLICKER, &flicker);
        else _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(SL_CAPTURE_FLICKER), "out of memory for the capture");
        sl_image_free(&flicker);
    }
    for (int i = 0; i < info->not_implemented_count; i++) _sl_missing_add(missing, info->not_implemented[i]);
    if (info->failed) _sl_send(SL_MSG_FAILED, info->failed, NULL, 0);
    if (_sl_wants(job, SL_CAPTURE_FBO) && info->shadow_map.framebuffer + info->shadow_map.depth_texture > 0)
        _sl_capture_fbo(&info->shadow_map, p.shadow_map_size);
    if (_sl_wants(job, SL_CAPTURE_DEPTH_MAP) && info->shadow_map_ready) {
        sl_image img;
        if (sl_capture_depth_texture(info->shadow_map.depth_texture, &img, err, sizeof err)) {
            _sl_send_image(SL_CAPTURE_DEPTH_MAP, &img);
            sl_image_free(&img);
        } else {
            _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(SL_CAPTURE_DEPTH_MAP), err);
        }
    }
    for (int face = 0; face < 6; face++) {
        if (!_sl_wants(job, SL_CAPTURE_CUBE_FACE + face) || !info->cube_map_ready) continue;
        sl_image img;
        if (sl_capture_cube_face(info->cube_map.depth_cube, face, &img, err, sizeof err)) {
            _sl_send_image(SL_CAPTURE_CUBE_FACE + face, &img);
            sl_image_free(&img);
        } else {
            _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(SL_CAPTURE_CUBE_FACE + face), err);
        }
    }
    if (_sl_wants(job, SL_CAPTURE_PATH)) {
        /* which way the framework drew: a message can then say which code ran (a layered pass, another lab's) */
        /* the layered pass: 1, or 2 where the lab answered SL_OK without attaching the whole cube map */
        double path[SL_PATH_NUMBERS] = {info->lab_in_use,
                                        info->cube_layered ? (info->cube_layered_attached ? 1 : 2) : 0};
        _sl_send_numbers(SL_CAPTURE_PATH, path, SL_PATH_NUMBERS);
    }
    if (_sl_wants(job, SL_CAPTURE_MATRICES) && info->lab2_ready) {
        double m[SL_MATRICES_NUMBERS];
        for (int i = 0; i < 16; i++) {
            m[i] = ((const float *)info->light_view)[i];
            m[16 + i] = ((const float *)info->light_projection)[i];
            m[32 + i] = ((const float *)info->shadow_matrix)[i];
        }
        _sl_send_numbers(SL_CAPTURE_MATRICES, m, SL_MATRICES_NUMBERS);
    }
    /* One more frame, timed once every shader is compiled, after every capture:
     * a shader loop that does not end shows as a frame hundreds of times slower. */
    struct timespec t0, t1;
    p.output = SL_OUTPUT_VISIBILITY;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0); /* every thread's: llvmpipe renders on several */
    sl_renderer_draw(&r, &scene, &p, fb, job->width, job->height);
    glFinish();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    double render_seconds = (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9;
    _sl_send(SL_MSG_RENDER_TIME, NULL, &render_seconds, sizeof render_seconds);
    sl_renderer_destroy(&r);
    _sl_float_target_free(&target);
    _sl_draw_stage[0] = '\0';
    _sl_stage_hook(NULL);
    return true;
}

/* Each probe table: the function called on every row, the outputs sent as numbers. */
static void _sl_run_probes(const sl_job *job, _sl_missing *missing) {
    static double outputs[SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS];
    for (int k = 0; k < SL_JOB_MAX_PROBES; k++) {
        const sl_probe_table *t = &job->probes[k];
        if (!t->function[0] || !_sl_wants(job, (sl_capture_kind)(SL_CAPTURE_PROBE + k))) continue;
        const char *name = t->function; /* terminated when the job was read */
        char err[8192];
        bool not_implemented = false;
        _sl_stage_hook(name);
        bool ok = sl_probe_pass_run(t, job->labs_dir, job->framework_dir, outputs, &not_implemented, err, sizeof err);
        _sl_stage_hook(NULL);
        if (not_implemented) _sl_missing_add(missing, name);
        if (ok) _sl_send(SL_MSG_NUMBERS, sl_capture_name(SL_CAPTURE_PROBE + k), outputs,
                         (size_t)t->rows * (size_t)t->output_count * sizeof(double));
        else _sl_send_text(SL_MSG_CAPTURE_ERROR, sl_capture_name(SL_CAPTURE_PROBE + k), err);
    }
}

/* Object names of different kinds never coincide here: GL hands out each kind's names from 1, so a
 * texture's name passed where a framebuffer's belongs (or the reverse) would often name the right object
 * by luck. Reserved, never bound: no object is made. */
static void _sl_separate_object_names(void) {
    enum { _SL_RESERVED = 100 };
    GLuint names[4 * _SL_RESERVED];
    glGenTextures(_SL_RESERVED, names);
    glGenRenderbuffers(2 * _SL_RESERVED, names);
    glGenBuffers(3 * _SL_RESERVED, names);
    glGenVertexArrays(4 * _SL_RESERVED, names);
}

static int _sl_run_job(const sl_job *job) {
    char err[8192];
    /* software_only: llvmpipe even where EGL finds a GPU, as the references were rendered */
    sl_context_desc cd = {.backend = (sl_backend)job->backend, .width = job->width, .height = job->height,
                          .software_only = true};
    sl_context *ctx = sl_context_create(&cd, err, sizeof err);
    if (!ctx) {
        _sl_send_text(SL_MSG_ERROR, NULL, err);
        return 1;
    }
    char hello[512];
    snprintf(hello, sizeof hello, "%s\n%s", sl_backend_name(sl_context_backend(ctx)), sl_context_renderer_name());
    _sl_send_text(SL_MSG_HELLO, NULL, hello);
    _sl_separate_object_names();
    _sl_gl_debug_start(ctx);
    sl_lab_call_hook = _sl_stage_hook;
    _sl_missing missing = {0};
    if (job->frame_count > 0 && !_sl_render_case(job, &missing)) return 1;
    _sl_run_probes(job, &missing);
    for (int i = 0; i < missing.count; i++) _sl_send(SL_MSG_NOT_IMPLEMENTED, missing.names[i], NULL, 0);
    _sl_gl_debug_send();
    sl_lab_call_hook = NULL;
    sl_context_destroy(ctx);
    _sl_send(SL_MSG_DONE, NULL, NULL, 0);
    return 0;
}

static bool _sl_read_job(sl_job *job, char *err, size_t n) {
    size_t have = 0;
    while (have < sizeof *job) {
        ssize_t got = read(0, (char *)job + have, sizeof *job - have);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) {
            snprintf(err, n, "the job ended after %zu of %zu bytes", have, sizeof *job);
            return false;
        }
        have += (size_t)got;
    }
    if (job->magic != SL_JOB_MAGIC || job->version != SL_PROTOCOL_VERSION || job->size != sizeof *job) {
        snprintf(err, n, "the grader and this runner were built from different versions (rebuild both)");
        return false;
    }
    job->labs_dir[sizeof job->labs_dir - 1] = '\0';
    job->framework_dir[sizeof job->framework_dir - 1] = '\0';
    for (int k = 0; k < SL_JOB_MAX_PROBES; k++) job->probes[k].function[SL_PROBE_NAME_MAX - 1] = '\0';
    if (job->lab == 0 && !sl_technique_of(0)) {
        snprintf(err, n, "the case grades the technique a build adds (lab 0), and this runner's build adds none");
        return false;
    }
    if (job->frame_count < 0 || job->frame_count > SL_JOB_MAX_FRAMES || job->width < 1 || job->height < 1 ||
        job->width > SL_IMAGE_SIDE_MAX || job->height > SL_IMAGE_SIDE_MAX) {
        snprintf(err, n, "the job is malformed");
        return false;
    }
    return true;
}

int sl_runner_main(int argc, char **argv) {
    (void)argv;
    if (argc != 1 || isatty(0)) {
        fprintf(stderr, "shadowlab-runner runs one grading case for shadowlab-grade, which starts it; "
                        "run shadowlab-grade instead.\n");
        return 2;
    }
#ifdef SIGPIPE /* not on Windows */
    signal(SIGPIPE, SIG_DFL);
#endif
    static sl_job job; /* large: not on the stack */
    char err[256];
    if (!_sl_read_job(&job, err, sizeof err)) {
        _sl_send_text(SL_MSG_ERROR, NULL, err);
        _exit(1);
    }
    if (_sl_run_job(&job) != 0) _exit(1);
    /* DONE is sent: wait until the grader has checked this process and closes
     * fd 0, then leave at once, so no lab destructor or atexit handler runs. */
    char byte;
    while (read(0, &byte, 1) < 0 && errno == EINTR) {}
    _exit(0);
}
