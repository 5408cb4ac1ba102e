#include "sl_lab5_vsm.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_renderer.h"
#include "sl_shader.h"
#include "sl_overlay.h"
#include "sl_probe_calls.h"
#include "sl_technique.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

typedef struct _sl_vsm_program {
    sl_program program;
    bool attempted;
    GLint model, light_view_projection, light_near, light_far; /* the moments pass */
    GLint moments, direction;                                   /* the blur */
    GLint texture, channel;                                     /* the debug view */
} _sl_vsm_program;

#define _SL_MAX_BLUR_RADIUS 32

typedef struct _sl_lab5 { /* lab 5's targets and programs, one per renderer */
    sl_moments_target target;
    sl_status target_status;
    bool target_attempted;
    /* the moments pass per light type (its depth is linearised for spot lights), the blur per
     * radius (compiled in: its loop unrolls), the debug view */
    _sl_vsm_program moments[3], blur[_SL_MAX_BLUR_RADIUS + 1], debug;
    sl_image passes; /* what each pass drew, stacked (the renderer's keep_pass_outputs) */
} _sl_lab5;

#define _SL_LAB5 5

/* Calls lab 5's fn through the renderer's table, recording what it returned. */
#define _SL_CALL_LAB5(r, fn, ...) \
    (sl_renderer_lab_enter(#fn), sl_renderer_lab_result((r), #fn, (r)->fns[_SL_LAB5]->fn(__VA_ARGS__)))

/* What lab 5 keeps between frames: made by its first frame. */
static _sl_lab5 *_sl_vsm_state(const sl_renderer *r) { return r->technique_state[_SL_LAB5]; }

static _sl_lab5 *_sl_vsm_of(sl_renderer *r) {
    if (!r->technique_state[_SL_LAB5]) r->technique_state[_SL_LAB5] = calloc(1, sizeof(_sl_lab5));
    return _sl_vsm_state(r);
}

static _sl_vsm_program *_sl_vsm_build(sl_renderer *r, _sl_vsm_program *s, const char *vs, const char *fs,
                                      const char *defines) {
    if (!s->attempted) {
        char v[SL_PATH_MAX * 2], f[SL_PATH_MAX * 2];
        snprintf(v, sizeof v, "%s/%s", r->shaders_dir, vs);
        snprintf(f, sizeof f, "%s/%s", r->shaders_dir, fs);
        sl_shader_desc desc = {.vertex_path = v, .fragment_path = f, .search_dirs = {r->labs_dir, r->shaders_dir},
                               .defines = defines};
        s->attempted = true;
        sl_program_build(&s->program, &desc, r->shader_errors[_SL_LAB5], sizeof r->shader_errors[_SL_LAB5]);
    }
    if (!s->program.id) return NULL;
    const sl_program *p = &s->program;
    s->model = sl_program_uniform(p, "u_model");
    s->light_view_projection = sl_program_uniform(p, "u_light_view_projection");
    s->light_near = sl_program_uniform(p, "u_light_near");
    s->light_far = sl_program_uniform(p, "u_light_far");
    s->moments = sl_program_uniform(p, "u_moments");
    s->direction = sl_program_uniform(p, "u_direction");
    s->texture = sl_program_uniform(p, "u_texture");
    s->channel = sl_program_uniform(p, "u_channel");
    return s;
}

static void _sl_vsm_shader_failed(sl_renderer *r) {
    sl_frame_info *info = &r->info;
    if (info->shader_error) return;
    info->shader_error = r->shader_errors[_SL_LAB5];
    info->shader_error_lab = _SL_LAB5;
}

/* Which of the target's two (texture or framebuffer) names `name` is: 0, 1, -1 another, -2 none. */
static int _sl_vsm_which(const GLuint pair[2], GLint name) {
    return name == 0 ? -2 : (GLuint)name == pair[0] ? 0 : (GLuint)name == pair[1] ? 1 : -1;
}

/* Pass `stage` (0 the moments, 1 and 2 the blur's) drew into the bound framebuffer: keep a copy of it, so
 * the grader can tell which pass departs first. Reads the framebuffer lab code bound, whatever it is. */
static void _sl_vsm_keep_pass(sl_renderer *r, _sl_lab5 *v, int stage) {
    int size = v->target.size;
    if (!r->keep_pass_outputs || size <= 0 || size * 3 > 4096) return;
    if (v->passes.width != size || v->passes.height != 3 * size) {
        sl_image_free(&v->passes);
        v->passes = sl_image_alloc(size, 3 * size, 2);
    }
    if (!v->passes.data) return;
    float *rows = v->passes.data + (size_t)stage * size * size * 2;
    if (stage == 0)
        for (size_t i = 0; i < (size_t)size * 3 * size * 2; i++) v->passes.data[i] = NAN; /* passes not run */
    GLint draw = 0, read = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    if (!draw) return; /* the window's framebuffer: nothing of the target's */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, (GLuint)draw);
    if (glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        sl_image one = sl_image_alloc(size, size, 2);
        if (one.data) {
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, size, size, GL_RG, GL_FLOAT, one.data);
            sl_image_flip_rows(&one);
            memcpy(rows, one.data, sizeof(float) * size * size * 2);
        }
        sl_image_free(&one);
    }
    while (glGetError() != GL_NO_ERROR) {}
    glBindFramebuffer(GL_READ_FRAMEBUFFER, (GLuint)read);
}

/* Lab 5's own stubs are all asked, even when an earlier one stops the passes,
 * so the grader can name every function that is not done yet. */
static void _sl_vsm_ask_stubs(sl_renderer *r, _sl_lab5 *v, int from) {
    sl_moments_target none = {0};
    const sl_moments_target *t = v->target_status == SL_OK ? &v->target : &none;
    GLint fb = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fb);
    if (from <= 2) _SL_CALL_LAB5(r, lab5_begin_moments_pass, t);
    if (from <= 4) _SL_CALL_LAB5(r, lab5_begin_blur_pass, t, 0);
    if (from <= 6) _SL_CALL_LAB5(r, lab5_filter_moments, t);
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fb);
}

/* Labs 1-4's frame with lab 5 asked: the moments, unless VSM is switched off (lab 4's filter alone, as
 * fast as in lab 4). */
static bool _sl_lab5_depth_passes(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    if (p->vsm_off) return false;
    _sl_lab5 *v = _sl_vsm_of(r);
    sl_frame_info *info = &r->info;
    if (!v) return false;
    int size = p->vsm.map_size > 0 ? p->vsm.map_size : p->shadow_map_size > 0 ? p->shadow_map_size : 1024;
    if (v->target_attempted && v->target_status == SL_OK && v->target.size != size) {
        sl_renderer_lab_enter("lab5_destroy_moments_target");
        r->fns[_SL_LAB5]->lab5_destroy_moments_target(&v->target);
        sl_renderer_lab_enter(NULL);
        v->target_attempted = false;
    }
    if (!v->target_attempted) {
        memset(&v->target, 0, sizeof v->target);
        sl_renderer_lab_enter("lab5_create_moments_target");
        v->target_status = r->fns[_SL_LAB5]->lab5_create_moments_target(size, &v->target);
        v->target_attempted = true;
    }
    info->moments_target = v->target; /* even on failure: the grader inspects what was made */
    if (!sl_renderer_lab_result(r, "lab5_create_moments_target", v->target_status)) {
        _sl_vsm_ask_stubs(r, v, 2);
        return false;
    }
    /* 1. the moments pass */
    int type = scene->light.type >= 0 && scene->light.type < 3 ? (int)scene->light.type : 0;
    char defines[64];
    snprintf(defines, sizeof defines, "#define SL_LIGHT_TYPE %d\n", type);
    _sl_vsm_program *m = _sl_vsm_build(r, &v->moments[type], "moments.vert", "moments.frag", defines);
    if (!m) {
        _sl_vsm_shader_failed(r);
        return false;
    }
    if (!_SL_CALL_LAB5(r, lab5_begin_moments_pass, &v->target)) {
        _sl_vsm_ask_stubs(r, v, 4);
        return false;
    }
    mat4 view_proj;
    glm_mat4_mul(info->light_projection, info->light_view, view_proj);
    glUseProgram(m->program.id);
    glUniformMatrix4fv(m->light_view_projection, 1, GL_FALSE, (const float *)view_proj);
    glUniform1f(m->light_near, scene->light.near);
    glUniform1f(m->light_far, scene->light.far);
    sl_renderer_draw_objects(r, scene, m->model, -1, -1);
    for (int i = 0; i < 2; i++) info->vsm_blur_read[i] = info->vsm_blur_drew[i] = -2;
    info->vsm_passes = r->keep_pass_outputs ? &v->passes : NULL;
    _sl_vsm_keep_pass(r, v, 0);
    sl_renderer_timer_mark(r, "moments");
    /* 2. the blur, horizontal then vertical */
    int radius = p->vsm.blur_radius < _SL_MAX_BLUR_RADIUS ? p->vsm.blur_radius : _SL_MAX_BLUR_RADIUS;
    if (radius > 0) {
        snprintf(defines, sizeof defines, "#define SL_BLUR_RADIUS %d\n", radius);
        _sl_vsm_program *b = _sl_vsm_build(r, &v->blur[radius], "debug_quad.vert", "blur.frag", defines);
        if (!b) {
            _sl_vsm_shader_failed(r);
            return false;
        }
        for (int direction = 0; direction < 2; direction++) {
            if (!_SL_CALL_LAB5(r, lab5_begin_blur_pass, &v->target, direction)) {
                _sl_vsm_ask_stubs(r, v, 6);
                return false;
            }
            glUseProgram(b->program.id);
            glUniform1i(b->moments, 0);
            glUniform2f(b->direction, direction == 0 ? 1.0f : 0.0f, direction == 0 ? 0.0f : 1.0f);
            glBindVertexArray(r->empty_vao);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            GLint read = 0, drew = 0;
            GLint unit = GL_TEXTURE0; /* unit 0, which the blur's u_moments names, whichever is active */
            glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
            glActiveTexture(GL_TEXTURE0);
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &read);
            glActiveTexture((GLenum)unit);
            glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drew);
            info->vsm_blur_read[direction] = _sl_vsm_which(v->target.moments, read);
            info->vsm_blur_drew[direction] = _sl_vsm_which(v->target.framebuffer, drew);
            _sl_vsm_keep_pass(r, v, 1 + direction);
        }
        sl_renderer_timer_mark(r, "blur");
    }
    /* 3. mipmaps and trilinear filtering */
    glActiveTexture(GL_TEXTURE0);
    if (!_SL_CALL_LAB5(r, lab5_filter_moments, &v->target)) return false;
    sl_renderer_timer_mark(r, "mipmaps");
    info->moments_ready = true;
    return true;
}

static GLuint _sl_lab5_camera_texture(const sl_renderer *r) {
    const _sl_lab5 *v = _sl_vsm_state(r);
    return v && r->info.moments_ready ? v->target.moments[0] : 0;
}

static void _sl_lab5_debug_view(sl_renderer *r, int width, int height) {
    _sl_lab5 *v = _sl_vsm_state(r);
    if (!v || !r->info.moments_ready) return;
    _sl_vsm_program *d = _sl_vsm_build(r, &v->debug, "debug_quad.vert", "moments_debug.frag", NULL);
    if (!d) return;
    int side = (width < height ? width : height) / 3;
    glDisable(GL_DEPTH_TEST);
    glUseProgram(d->program.id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, v->target.moments[0]);
    glUniform1i(d->texture, 0);
    glBindVertexArray(r->empty_vao);
    for (int channel = 0; channel < 2; channel++) {
        /* the mean on the left, the second moment on the right, in the lower right corner */
        glViewport(width - (2 - channel) * (side + 8), 8, side, side);
        glUniform1i(d->channel, channel);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
}

/* Every program of the module, by index: the moments passes, the debug view, the blurs. */
static _sl_vsm_program *_sl_vsm_program_at(_sl_lab5 *v, int i) {
    return i < 3 ? &v->moments[i] : i == 3 ? &v->debug : &v->blur[i - 4];
}

static bool _sl_lab5_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    _sl_lab5 *v = _sl_vsm_state(r);
    if (!v) return true;
    bool ok = true;
    for (int i = 0; i < 4 + _SL_MAX_BLUR_RADIUS + 1; i++) {
        _sl_vsm_program *s = _sl_vsm_program_at(v, i);
        if (!s->attempted) continue;
        if (!s->program.id) {
            s->attempted = false; /* never compiled: try again on the next frame */
            continue;
        }
        char e[4096] = "";
        if (sl_program_reload_if_changed(&s->program, e, sizeof e)) {
            *reloaded = true;
        } else if (e[0]) {
            if (ok) snprintf(err, err_size, "%s", e);
            ok = false;
        }
    }
    return ok;
}

static void _sl_lab5_destroy(sl_renderer *r) {
    _sl_lab5 *v = _sl_vsm_state(r);
    if (!v) return;
    if (v->target_attempted && v->target_status == SL_OK) {
        sl_renderer_lab_enter("lab5_destroy_moments_target");
        r->fns[_SL_LAB5]->lab5_destroy_moments_target(&v->target);
        sl_renderer_lab_enter(NULL);
    }
    for (int i = 0; i < 4 + _SL_MAX_BLUR_RADIUS + 1; i++) sl_program_destroy(&_sl_vsm_program_at(v, i)->program);
    sl_image_free(&v->passes);
    r->info.vsm_passes = NULL;
    free(v);
    r->technique_state[_SL_LAB5] = NULL;
}

/* Lab 5 draws within labs 1-4's frame: its moments before the camera pass, which reads them. */
/* ---- The viewer: lab 5's keys and what the title and overlay say of it ---- */
enum { _SL_LAB5_KEY_VSM, _SL_LAB5_KEY_BLUR, _SL_LAB5_KEY_BLEEDING, _SL_LAB5_KEY_MIN_VARIANCE };

static const sl_technique_key _sl_lab5_keys[] = {
    {{GLFW_KEY_P}, "P", "VSM", "VSM or lab 4's filter on the same scene", _SL_LAB5_KEY_VSM},
    {{GLFW_KEY_R, GLFW_KEY_T}, "R T", "blur radius", "blur radius of the moments down, up", _SL_LAB5_KEY_BLUR},
    {{GLFW_KEY_K, GLFW_KEY_L}, "K L", "bleeding reduction", "light-bleeding reduction down, up", _SL_LAB5_KEY_BLEEDING},
    {{GLFW_KEY_N, GLFW_KEY_J}, "N J", "min variance", "minimum variance halve, double", _SL_LAB5_KEY_MIN_VARIANCE},
    {{0}, NULL, NULL, NULL, 0},
};

static void _sl_lab5_key_pressed(sl_view_context *c, const sl_technique_key *k, int code, bool up) {
    (void)code;
    sl_vsm_settings *vsm = &c->params->vsm;
    switch (k->id) {
    case _SL_LAB5_KEY_VSM: c->params->vsm_off = !c->params->vsm_off; break;
    case _SL_LAB5_KEY_BLUR: vsm->blur_radius = up ? (vsm->blur_radius < 32 ? vsm->blur_radius + 1 : 32)
                                                  : (vsm->blur_radius > 0 ? vsm->blur_radius - 1 : 0); break;
    case _SL_LAB5_KEY_BLEEDING: vsm->bleeding = glm_clamp(vsm->bleeding + (up ? 0.05f : -0.05f), 0, 0.95f); break;
    case _SL_LAB5_KEY_MIN_VARIANCE: vsm->min_variance = glm_clamp(vsm->min_variance * (up ? 2.0f : 0.5f), 1e-7f, 0.01f); break;
    }
}

static void _sl_lab5_key_state(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n) {
    const sl_render_params *p = c->params;
    switch (k->id) {
    case _SL_LAB5_KEY_VSM: snprintf(out, n, "%s", p->vsm_off ? "off, lab 4's filter" : "on"); break;
    case _SL_LAB5_KEY_BLUR: snprintf(out, n, "%d", p->vsm.blur_radius); break;
    case _SL_LAB5_KEY_BLEEDING: snprintf(out, n, "%.2f", p->vsm.bleeding); break;
    case _SL_LAB5_KEY_MIN_VARIANCE: snprintf(out, n, "%.1e", p->vsm.min_variance); break;
    }
}

/* VSM's settings; with VSM off (P), lab 4's, which then draw. */
static void _sl_lab5_settings_text(const sl_view_context *c, char *out, size_t n) {
    const sl_render_params *p = c->params;
    if (!p->vsm_off) {
        snprintf(out, n, "VSM: blur %d, bleeding %.2f, min variance %.1e", p->vsm.blur_radius, p->vsm.bleeding,
                 p->vsm.min_variance);
        return;
    }
    const sl_technique *filtering = sl_technique_of(4);
    out[0] = '\0';
    if (filtering && filtering->settings_text) filtering->settings_text(c, out, n);
    snprintf(out + strlen(out), n - strlen(out), " (VSM off: P)");
}

static void _sl_lab5_overlay_lines(sl_overlay *ov, const sl_view_context *c) {
    const sl_render_params *p = c->params;
    int moments = p->vsm.map_size > 0 ? p->vsm.map_size : p->shadow_map_size;
    sl_overlay_line(ov, NULL, "VSM: moments %dx%d, blur radius %d", moments, moments, p->vsm.blur_radius);
    sl_overlay_line(ov, NULL, "bleeding reduction %.2f, min variance %.1e", p->vsm.bleeding, p->vsm.min_variance);
}

const sl_technique sl_lab5_technique = {
    .name = "VSM",
    .lab = 5,
    .depth_passes = _sl_lab5_depth_passes,
    .camera_texture = _sl_lab5_camera_texture,
    .debug_view = _sl_lab5_debug_view,
    .reload_changed = _sl_lab5_reload_changed,
    .destroy = _sl_lab5_destroy,
    .keys = _sl_lab5_keys,
    .key_pressed = _sl_lab5_key_pressed,
    .key_state = _sl_lab5_key_state,
    .panel_keys = {"F", "- ="},
    .settings_text = _sl_lab5_settings_text,
    .switched_off_text = "switched off with P",
    .overlay_lines = _sl_lab5_overlay_lines,
    .probes = sl_lab5_probes,
};
