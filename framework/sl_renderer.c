#define _POSIX_C_SOURCE 200809L
#include "sl_renderer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sl_technique.h"

#ifndef SL_FRAMEWORK_DIR
#define SL_FRAMEWORK_DIR "framework"
#endif

void (*sl_lab_call_hook)(const char *function);

const char *sl_framework_dir(void) {
    const char *env = getenv("SHADOWLAB_FRAMEWORK");
    return env && *env ? env : SL_FRAMEWORK_DIR;
}

static void _sl_enter(const char *function) {
    if (sl_lab_call_hook) sl_lab_call_hook(function);
}

/* Records the outcome of one lab call; true if the step may go on. */
static bool _sl_lab_result(sl_renderer *r, const char *function, sl_status status) {
    if (sl_lab_call_hook) sl_lab_call_hook(NULL);
    if (status == SL_OK) return true;
    if (status == SL_NOT_IMPLEMENTED) {
        sl_frame_info *info = &r->info;
        for (int i = 0; i < info->not_implemented_count; i++)
            if (strcmp(info->not_implemented[i], function) == 0) return false;
        if (info->not_implemented_count < SL_MAX_NOT_IMPLEMENTED)
            info->not_implemented[info->not_implemented_count++] = function;
    } else if (!r->info.failed) {
        r->info.failed = function;
    }
    return false;
}

void sl_renderer_lab_enter(const char *function) { _sl_enter(function); }

static bool _sl_note(sl_frame_info *info, int lab, const char *function, sl_stop_reason reason) {
    for (int i = 0; i < info->stop_count; i++)
        if (info->stops[i].lab == lab) return true; /* one reason per lab: its first */
    if (info->stop_count >= SL_MAX_FRAME_STOPS) return true;
    info->stops[info->stop_count++] = (sl_frame_stop){.lab = lab, .function = function, .reason = reason};
    return true;
}

/* Lab functions are named labN_...: whose they are. */
static bool _sl_is_labs(const char *function, int lab) {
    char prefix[16];
    snprintf(prefix, sizeof prefix, "lab%d_", lab);
    return function && strncmp(function, prefix, strlen(prefix)) == 0;
}

bool sl_renderer_note_stop(sl_renderer *r, int lab) {
    sl_frame_info *info = &r->info;
    for (int i = 0; i < info->not_implemented_count; i++)
        if (_sl_is_labs(info->not_implemented[i], lab))
            return _sl_note(info, lab, info->not_implemented[i], SL_STOP_NOT_IMPLEMENTED);
    if (_sl_is_labs(info->failed, lab)) return _sl_note(info, lab, info->failed, SL_STOP_FAILED);
    if (info->shader_error && info->shader_error_lab == lab) return _sl_note(info, lab, NULL, SL_STOP_SHADERS);
    return false;
}

void sl_renderer_note_off(sl_renderer *r, int lab, sl_stop_reason reason) { _sl_note(&r->info, lab, NULL, reason); }

bool sl_renderer_lab_result(sl_renderer *r, const char *function, sl_status status) {
    return _sl_lab_result(r, function, status);
}

static void _sl_path(char *out, size_t n, const char *dir, const char *file) { snprintf(out, n, "%s/%s", dir, file); }

bool sl_renderer_init(sl_renderer *r, const sl_renderer_desc *desc, char *err, size_t err_size) {
    memset(r, 0, sizeof *r);
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) r->fns[lab] = &sl_build_lab_functions;
    const char *labs = desc && desc->labs_dir ? desc->labs_dir : getenv("SHADOWLAB_LABS");
    if (!labs || !*labs) labs = sl_build_labs_dir;
    snprintf(r->labs_dir, sizeof r->labs_dir, "%s", labs);
    const char *fw = desc && desc->framework_dir ? desc->framework_dir : sl_framework_dir();
    snprintf(r->shaders_dir, sizeof r->shaders_dir, "%s/shaders", fw);
    /* Programs are built later, by the frames that use them: only check the framework's files are there. */
    char path[SL_PATH_MAX * 2];
    _sl_path(path, sizeof path, r->shaders_dir, "scene.vert");
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, err_size, "%s: cannot read the framework's shaders (is the framework folder right?)", path);
        return false;
    }
    fclose(f);
    glGenVertexArrays(1, &r->empty_vao);
    return true;
}

void sl_renderer_program_stats(const sl_renderer *r, sl_program_stats *out) {
    *out = (sl_program_stats){0};
    /* the programs each technique keeps in its module */
    for (int lab = 0; lab <= SL_LAB_COUNT; lab++) {
        const sl_technique *t = sl_technique_of(lab);
        if (t && t->program_stats) t->program_stats(r, out);
    }
}

bool sl_renderer_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    *reloaded = false;
    bool ok = true;
    /* the programs each technique keeps in its module; the first error is reported */
    for (int lab = 0; lab <= SL_LAB_COUNT; lab++) {
        const sl_technique *t = sl_technique_of(lab);
        char technique_err[sizeof r->shader_errors[0]] = "";
        if (!t || !t->reload_changed || t->reload_changed(r, reloaded, technique_err, sizeof technique_err)) continue;
        if (ok) snprintf(err, err_size, "%s", technique_err);
        ok = false;
    }
    return ok;
}

static void _sl_destroy_meshes(sl_renderer *r) {
    for (int i = 0; i < r->mesh_count; i++) sl_mesh_destroy(&r->meshes[i]);
    r->mesh_count = 0;
}

void sl_renderer_destroy(sl_renderer *r) {
    _sl_destroy_meshes(r);
    for (int lab = SL_LAB_COUNT; lab >= 0; lab--) {
        const sl_technique *t = sl_technique_of(lab);
        if (t && t->destroy) t->destroy(r);
    }
    if (r->empty_vao) glDeleteVertexArrays(1, &r->empty_vao);
    if (r->timer_queries[0]) glDeleteQueries(SL_MAX_PASSES + 1, r->timer_queries);
    memset(r, 0, sizeof *r);
}

bool sl_renderer_set_scene(sl_renderer *r, const sl_scene *scene, char *err, size_t err_size) {
    _sl_destroy_meshes(r);
    for (int i = 0; i < scene->object_count; i++) {
        const sl_object *o = &scene->objects[i];
        sl_mesh_data data = sl_mesh_for_object(o);
        bool ok = sl_mesh_upload(&r->meshes[i], &data);
        sl_mesh_data_free(&data);
        if (!ok) {
            snprintf(err, err_size, "%s: could not build the mesh of object %d", scene->name, i);
            return false;
        }
        r->mesh_count = i + 1;
    }
    return true;
}

const sl_frame_info *sl_renderer_info(const sl_renderer *r) { return &r->info; }

void sl_renderer_set_light_camera(sl_renderer *r, const float *view, const float *projection) {
    r->light_camera_given = view && projection;
    if (!r->light_camera_given) return;
    memcpy(r->light_camera_view, view, sizeof r->light_camera_view);
    memcpy(r->light_camera_projection, projection, sizeof r->light_camera_projection);
}

void sl_renderer_set_timing(sl_renderer *r, bool enabled) {
    if (enabled && !r->timer_queries[0]) glGenQueries(SL_MAX_PASSES + 1, r->timer_queries);
    r->timing = enabled;
    r->timer_count = 0;
}

/* A timestamp after the pass just drawn; the first one of a frame (name NULL) marks its start. */
static void _sl_timer_mark(sl_renderer *r, const char *finished_pass) {
    if (!r->timing) return;
    if (!finished_pass) {
        r->timer_count = 0;
        glQueryCounter(r->timer_queries[0], GL_TIMESTAMP);
    } else if (r->timer_count < SL_MAX_PASSES) {
        r->timer_names[r->timer_count++] = finished_pass;
        glQueryCounter(r->timer_queries[r->timer_count], GL_TIMESTAMP);
    }
}

void sl_renderer_timer_mark(sl_renderer *r, const char *finished_pass) { _sl_timer_mark(r, finished_pass); }

bool sl_renderer_frame_timing(sl_renderer *r, sl_frame_timing *out) {
    *out = (sl_frame_timing){0};
    if (!r->timing || r->timer_count == 0) return false;
    GLuint64 stamps[SL_MAX_PASSES + 1];
    for (int i = 0; i <= r->timer_count; i++) glGetQueryObjectui64v(r->timer_queries[i], GL_QUERY_RESULT, &stamps[i]);
    for (int i = 0; i < r->timer_count; i++) {
        /* timestamps from different rasteriser threads can be a hair out of order */
        double ms = stamps[i + 1] > stamps[i] ? (double)(stamps[i + 1] - stamps[i]) * 1e-6 : 0.0;
        out->passes[out->pass_count++] = (sl_pass_time){r->timer_names[i], ms};
    }
    return true;
}

/* GL state the labs may change, put back so one pass cannot leak into the next. */
void sl_renderer_reset_state(GLuint target, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0, 0);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

void sl_renderer_draw_objects(sl_renderer *r, const sl_scene *scene, GLint model, GLint normal_matrix, GLint albedo) {
    for (int i = 0; i < r->mesh_count && i < scene->object_count; i++) {
        const sl_object *o = &scene->objects[i];
        glUniformMatrix4fv(model, 1, GL_FALSE, (const float *)o->model);
        if (normal_matrix >= 0 || albedo >= 0) {
            mat3 normal;
            mat4 inv;
            glm_mat4_inv((vec4 *)o->model, inv);
            glm_mat4_transpose(inv);
            glm_mat4_pick3(inv, normal);
            glUniformMatrix3fv(normal_matrix, 1, GL_FALSE, (const float *)normal);
            glUniform3fv(albedo, 1, o->color);
        }
        sl_mesh_draw(&r->meshes[i]);
    }
}

void sl_renderer_draw(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                      int width, int height) {
    sl_frame_info *info = &r->info;
    info->not_implemented_count = 0;
    info->failed = NULL;
    info->shader_error = NULL;
    info->shader_error_lab = 0;
    info->shadow_map_ready = false;
    info->second_map_ready = false;
    info->lab_in_use = 0;
    info->lab_asked = params->lab;
    info->stop_count = 0;
    info->cube_frame = info->cube_matrices_ready = info->cube_map_ready = info->cube_layered = info->cube_layered_attached = false;
    r->frame_count++;
    _sl_timer_mark(r, NULL);
    /* A technique that takes the frame draws it (lab 6's cascades; lab 7's cube map for a point light);
     * else the one that draws every other frame (lab 1's shadow map, which labs 2-5 add to). */
    const sl_technique *drawing = NULL;
    for (int lab = 0; lab <= SL_LAB_COUNT && !drawing; lab++) {
        const sl_technique *t = sl_technique_of(lab);
        if (t && t->takes_frame && t->takes_frame(r, scene, params)) drawing = t;
    }
    for (int lab = 0; lab <= SL_LAB_COUNT && !drawing; lab++) {
        const sl_technique *t = sl_technique_of(lab);
        if (t && !t->takes_frame && t->draw_frame) drawing = t;
    }
    if (drawing) drawing->draw_frame(r, scene, params, target, width, height);
    glBindVertexArray(0);
    glUseProgram(0);
}
