#include "sl_renderer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Calls lab N's function fn through the renderer's table, recording what it returned. */
#define _SL_CALL_LAB(r, N, fn, ...) (_sl_enter(#fn), _sl_lab_result((r), #fn, (r)->fns[N]->fn(__VA_ARGS__)))

static bool _sl_build(sl_program *p, const sl_renderer *r, const char *vs, const char *fs, const char *defines,
                      char *err, size_t err_size) {
    sl_shader_desc desc = {
        .vertex_path = vs,
        .fragment_path = fs,
        .search_dirs = {r->labs_dir, r->shaders_dir},
        .defines = defines,
    };
    return sl_program_build(p, &desc, err, err_size);
}

static void _sl_path(char *out, size_t n, const char *dir, const char *file) { snprintf(out, n, "%s/%s", dir, file); }

/* The camera-pass fragment shader of each lab: it includes that lab's GLSL and the labs' before it. */
static const char *const _sl_scene_fragment[SL_RENDERER_MAX_LAB + 1] = {
    [2] = "scene.frag", [3] = "scene_bias.frag", [4] = "scene_filter.frag",
};

/* Builds lab `lab`'s camera-pass programs once; a failure is kept per lab
 * instead of stopping everything. */
static bool _sl_scene_ready(sl_renderer *r, int lab) {
    if (!r->scene_built[lab]) {
        r->scene_built[lab] = true;
        char vs[SL_PATH_MAX * 2], fs[SL_PATH_MAX * 2];
        _sl_path(vs, sizeof vs, r->shaders_dir, "scene.vert");
        _sl_path(fs, sizeof fs, r->shaders_dir, _sl_scene_fragment[lab]);
        char *err = r->shader_errors[lab];
        if (_sl_build(&r->scene_programs[lab][0], r, vs, fs, NULL, err, sizeof r->shader_errors[lab]))
            _sl_build(&r->scene_programs[lab][1], r, vs, fs, "#define SL_HARDWARE_COMPARE 1", err,
                      sizeof r->shader_errors[lab]);
    }
    return r->scene_programs[lab][0].id && r->scene_programs[lab][1].id;
}

bool sl_renderer_init(sl_renderer *r, const sl_renderer_desc *desc, char *err, size_t err_size) {
    memset(r, 0, sizeof *r);
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) r->fns[lab] = &sl_build_lab_functions;
    const char *labs = desc && desc->labs_dir ? desc->labs_dir : getenv("SHADOWLAB_LABS");
    if (!labs || !*labs) labs = sl_build_labs_dir;
    snprintf(r->labs_dir, sizeof r->labs_dir, "%s", labs);
    const char *fw = desc && desc->framework_dir ? desc->framework_dir : sl_framework_dir();
    snprintf(r->shaders_dir, sizeof r->shaders_dir, "%s/shaders", fw);

    char vs[SL_PATH_MAX * 2], fs[SL_PATH_MAX * 2];
    _sl_path(vs, sizeof vs, r->shaders_dir, "plain.vert");
    _sl_path(fs, sizeof fs, r->shaders_dir, "plain.frag");
    if (!_sl_build(&r->plain_program, r, vs, fs, NULL, err, err_size)) return false;
    _sl_path(vs, sizeof vs, r->shaders_dir, "debug_quad.vert");
    _sl_path(fs, sizeof fs, r->shaders_dir, "debug_quad.frag");
    if (!_sl_build(&r->debug_program, r, vs, fs, NULL, err, err_size)) return false;
    _sl_path(vs, sizeof vs, r->labs_dir, "lab1_depth_fbo/shaders/depth.vert");
    _sl_path(fs, sizeof fs, r->labs_dir, "lab1_depth_fbo/shaders/depth.frag");
    _sl_build(&r->depth_program, r, vs, fs, NULL, r->shader_errors[1], sizeof r->shader_errors[1]);
    glGenVertexArrays(1, &r->empty_vao);
    return true;
}

bool sl_renderer_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    typedef struct { sl_program *program; int lab; } watched;
    watched programs[4 + 2 * SL_RENDERER_MAX_LAB];
    int n = 0;
    programs[n++] = (watched){&r->depth_program, 1};
    programs[n++] = (watched){&r->plain_program, 0};
    programs[n++] = (watched){&r->debug_program, 0};
    for (int lab = 2; lab <= SL_RENDERER_MAX_LAB; lab++)
        for (int v = 0; v < 2 && r->scene_built[lab]; v++) programs[n++] = (watched){&r->scene_programs[lab][v], lab};
    bool ok = true;
    *reloaded = false;
    for (int i = 0; i < n; i++) {
        char e[8192];
        int lab = programs[i].lab;
        if (sl_program_reload_if_changed(programs[i].program, e, sizeof e)) {
            *reloaded = true;
            if (lab) r->shader_errors[lab][0] = '\0';
        } else if (e[0]) {
            if (lab) snprintf(r->shader_errors[lab], sizeof r->shader_errors[lab], "%s", e);
            if (ok) snprintf(err, err_size, "%s", e);
            ok = false;
        }
    }
    return ok;
}

static void _sl_destroy_meshes(sl_renderer *r) {
    for (int i = 0; i < r->mesh_count; i++) sl_mesh_destroy(&r->meshes[i]);
    r->mesh_count = 0;
}

void sl_renderer_destroy(sl_renderer *r) {
    _sl_destroy_meshes(r);
    if (r->shadow_map_attempted && r->shadow_map_status == SL_OK) {
        _sl_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->shadow_map);
        if (sl_lab_call_hook) sl_lab_call_hook(NULL);
    }
    if (r->second_map_attempted && r->second_map_status == SL_OK) {
        _sl_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->second_map);
        if (sl_lab_call_hook) sl_lab_call_hook(NULL);
    }
    sl_program_destroy(&r->depth_program);
    for (int lab = 0; lab <= SL_RENDERER_MAX_LAB; lab++) {
        sl_program_destroy(&r->scene_programs[lab][0]);
        sl_program_destroy(&r->scene_programs[lab][1]);
    }
    sl_program_destroy(&r->plain_program);
    sl_program_destroy(&r->debug_program);
    if (r->empty_vao) glDeleteVertexArrays(1, &r->empty_vao);
    memset(r, 0, sizeof *r);
}

bool sl_renderer_set_scene(sl_renderer *r, const sl_scene *scene, char *err, size_t err_size) {
    _sl_destroy_meshes(r);
    for (int i = 0; i < scene->object_count; i++) {
        const sl_object *o = &scene->objects[i];
        sl_mesh_data data;
        switch (o->shape) {
        case SL_SHAPE_PLANE: data = sl_mesh_plane(o->size[0], o->size[1], o->subdivisions); break;
        case SL_SHAPE_BOX: data = sl_mesh_box(o->size[0], o->size[1], o->size[2]); break;
        case SL_SHAPE_SPHERE: data = sl_mesh_sphere(o->size[0], 48, 24); break;
        case SL_SHAPE_CYLINDER: data = sl_mesh_cylinder(o->size[0], o->size[1], 48); break;
        case SL_SHAPE_TORUS: data = sl_mesh_torus(o->size[0], o->size[1], 48, 24); break;
        default: data = (sl_mesh_data){0}; break;
        }
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

/* GL state the labs may change, put back so one pass cannot leak into the next. */
static void _sl_reset_state(GLuint target, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0, 0);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

static void _sl_light_matrices(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    sl_frame_info *info = &r->info;
    sl_light light = scene->light;
    sl_aabb bounds = scene->bounds;
    info->lab2_ready = false;
    if (p->lab >= 2) {
        mat4 view, proj, shadow;
        glm_mat4_identity(view);
        glm_mat4_identity(proj);
        glm_mat4_identity(shadow);
        bool ok = _SL_CALL_LAB(r, 2, lab2_light_view, &light, &bounds, view) &&
                  _SL_CALL_LAB(r, 2, lab2_light_projection, &light, &bounds, view, proj) &&
                  _SL_CALL_LAB(r, 2, lab2_shadow_matrix, proj, view, shadow);
        if (ok) {
            glm_mat4_copy(view, info->light_view);
            glm_mat4_copy(proj, info->light_projection);
            glm_mat4_copy(shadow, info->shadow_matrix);
            info->lab2_ready = true;
            return;
        }
    }
    /* Lab 1 alone (or lab 2 not done yet): a loose light camera so the depth map can be seen. */
    sl_light_default_matrices(&light, &bounds, info->light_view, info->light_projection);
    glm_mat4_identity(info->shadow_matrix);
}

static void _sl_draw_objects(sl_renderer *r, const sl_scene *scene, const sl_program *prog, bool colours) {
    GLint u_model = sl_program_uniform(prog, "u_model");
    GLint u_normal = sl_program_uniform(prog, "u_normal_matrix");
    GLint u_color = sl_program_uniform(prog, "u_albedo");
    for (int i = 0; i < r->mesh_count && i < scene->object_count; i++) {
        const sl_object *o = &scene->objects[i];
        glUniformMatrix4fv(u_model, 1, GL_FALSE, (const float *)o->model);
        if (colours) {
            mat3 normal;
            mat4 inv;
            glm_mat4_inv((vec4 *)o->model, inv);
            glm_mat4_transpose(inv);
            glm_mat4_pick3(inv, normal);
            glUniformMatrix3fv(u_normal, 1, GL_FALSE, (const float *)normal);
            glUniform3fv(u_color, 1, o->color);
        }
        sl_mesh_draw(&r->meshes[i]);
    }
}

/* Returns the highest lab the depth pass used (0: no map, 1, or 3 with lab 3's state). */
static int _sl_depth_pass_labs(sl_renderer *r, const sl_scene *scene, const sl_render_params *p);

/* Lab 3's extension: the second surface's depths, into a second map made with
 * lab 1's own functions. The depth program is still bound. */
static void _sl_second_depth_pass(sl_renderer *r, const sl_scene *scene, int size) {
    if (r->second_map_attempted && r->second_map_status == SL_OK && r->second_map.size != size) {
        _sl_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->second_map);
        r->second_map_attempted = false;
    }
    if (!r->second_map_attempted) {
        memset(&r->second_map, 0, sizeof r->second_map);
        _sl_enter("lab1_create_shadow_map");
        r->second_map_status = r->fns[1]->lab1_create_shadow_map(size, &r->second_map);
        r->second_map_attempted = true;
    }
    if (!_sl_lab_result(r, "lab1_create_shadow_map", r->second_map_status)) return;
    if (!_SL_CALL_LAB(r, 1, lab1_begin_depth_pass, &r->second_map)) return;
    if (!_SL_CALL_LAB(r, 3, lab3_second_depth_state)) return;
    _sl_draw_objects(r, scene, &r->depth_program, false);
    r->info.second_map_ready = true;
}

static int _sl_depth_pass(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    int used = _sl_depth_pass_labs(r, scene, p);
    /* Lab 3's stub is asked even when an earlier lab stops the pass, so the
     * grader can say which of a lab's own functions are not done yet. */
    if (used == 0 && p->lab >= 3) {
        _SL_CALL_LAB(r, 3, lab3_depth_pass_state, &p->bias);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    return used;
}

static int _sl_depth_pass_labs(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    sl_frame_info *info = &r->info;
    int size = p->shadow_map_size > 0 ? p->shadow_map_size : 1024;
    if (r->shadow_map_attempted && r->shadow_map_status == SL_OK && r->shadow_map.size != size) {
        _sl_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->shadow_map);
        r->shadow_map_attempted = false;
    }
    if (!r->shadow_map_attempted) {
        memset(&r->shadow_map, 0, sizeof r->shadow_map);
        _sl_enter("lab1_create_shadow_map");
        r->shadow_map_status = r->fns[1]->lab1_create_shadow_map(size, &r->shadow_map);
        r->shadow_map_attempted = true;
        if (r->shadow_map_status == SL_OK && glIsTexture(r->shadow_map.depth_texture)) {
            glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &r->lab1_min_filter);
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &r->lab1_mag_filter);
        }
    }
    info->shadow_map = r->shadow_map; /* even on failure: the grader inspects what was made */
    if (!_sl_lab_result(r, "lab1_create_shadow_map", r->shadow_map_status)) return 0;
    if (!r->depth_program.id) {
        info->shader_error = r->shader_errors[1];
        info->shader_error_lab = 1;
        return 0;
    }
    if (!_SL_CALL_LAB(r, 1, lab1_begin_depth_pass, &r->shadow_map)) return 0;
    int used = 1;
    if (p->lab >= 3 && _SL_CALL_LAB(r, 3, lab3_depth_pass_state, &p->bias)) used = 3;
    mat4 view_proj;
    glm_mat4_mul(info->light_projection, info->light_view, view_proj);
    glUseProgram(r->depth_program.id);
    glUniformMatrix4fv(sl_program_uniform(&r->depth_program, "u_light_view_projection"), 1, GL_FALSE,
                       (const float *)view_proj);
    _sl_draw_objects(r, scene, &r->depth_program, false);
    info->shadow_map_ready = true;
    if (used == 3 && p->bias.mode == SL_BIAS_MIDPOINT) _sl_second_depth_pass(r, scene, size);
    return used;
}

/* The world size of one shadow-map texel: for a spot light, per unit of distance. */
static float _sl_texel_size(const sl_frame_info *info, const sl_light *light, int map_size) {
    float scale = light->type == SL_LIGHT_DIRECTIONAL ? 2.0f / info->light_projection[0][0]
                                                        : 2.0f * tanf(glm_rad(light->spot_angle_deg));
    return scale / (float)(map_size > 0 ? map_size : 1);
}

static void _sl_scene_pass(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, int depth_lab, int width,
                           int height) {
    sl_frame_info *info = &r->info;
    /* The highest lab whose code can run this frame. */
    int lab = 0;
    if (info->shadow_map_ready && info->lab2_ready) {
        lab = p->lab < SL_RENDERER_MAX_LAB ? p->lab : SL_RENDERER_MAX_LAB;
        if (depth_lab < 3 && lab > 2) lab = 2;
    }
    if (lab >= 4) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        if (!_SL_CALL_LAB(r, 4, lab4_configure_shadow_texture, r->shadow_map.depth_texture, p->filter.mode)) lab = 3;
    } else if (p->lab >= 4 && !(info->shadow_map_ready && info->lab2_ready)) {
        /* asked anyway, on no texture, to learn whether it is still a stub (see _sl_depth_pass) */
        glBindTexture(GL_TEXTURE_2D, 0);
        _SL_CALL_LAB(r, 4, lab4_configure_shadow_texture, 0, p->filter.mode);
    } else if (info->shadow_map_ready && r->lab1_min_filter) {
        /* lab 4 may have changed the filtering in an earlier frame: back to lab 1's */
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, r->lab1_min_filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, r->lab1_mag_filter);
    }
    for (int l = 2; l <= lab; l++) {
        if (_sl_scene_ready(r, l)) continue;
        if (!info->shader_error) {
            info->shader_error = r->shader_errors[l];
            info->shader_error_lab = l;
        }
        lab = l - 1;
    }
    bool hardware = lab >= 4 ? p->filter.mode == SL_FILTER_HARDWARE : p->compare == SL_COMPARE_HARDWARE;
    bool midpoint = lab == 3 && p->bias.mode == SL_BIAS_MIDPOINT && info->second_map_ready;
    if (midpoint) hardware = false; /* the midpoint is compared by hand, on two sampler2Ds */
    const sl_program *prog = lab >= 2 ? &r->scene_programs[lab][hardware] : &r->plain_program;
    info->lab_in_use = lab >= 2 ? lab : (info->shadow_map_ready ? 1 : 0);

    /* background: sky; lit in the visibility image; not a lit surface in the mask */
    if (p->output == SL_OUTPUT_SHADED) glClearColor(0.55f, 0.62f, 0.70f, 1);
    else if (p->output == SL_OUTPUT_VISIBILITY) glClearColor(1, 1, 1, 1);
    else glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(prog->id);
    mat4 view, proj;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, height > 0 ? (float)width / (float)height : 1, proj);
    glUniformMatrix4fv(sl_program_uniform(prog, "u_view"), 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(sl_program_uniform(prog, "u_projection"), 1, GL_FALSE, (const float *)proj);
    glUniformMatrix4fv(sl_program_uniform(prog, "u_shadow_matrix"), 1, GL_FALSE, (const float *)info->shadow_matrix);
    const sl_light *l = &scene->light;
    glUniform1i(sl_program_uniform(prog, "u_light_type"), (int)l->type);
    glUniform3fv(sl_program_uniform(prog, "u_light_position"), 1, l->position);
    glUniform3fv(sl_program_uniform(prog, "u_light_direction"), 1, l->direction);
    vec3 radiance;
    glm_vec3_scale((float *)l->color, l->intensity, radiance);
    glUniform3fv(sl_program_uniform(prog, "u_light_radiance"), 1, radiance);
    glUniform1f(sl_program_uniform(prog, "u_spot_cos"), cosf(glm_rad(l->spot_angle_deg)));
    glUniform1i(sl_program_uniform(prog, "u_shadows"), lab >= 2 ? 1 : 0);
    glUniform1i(sl_program_uniform(prog, "u_output"), (int)p->output);
    /* lab 2: constant bias; lab 3: the chosen mode */
    glUniform1f(sl_program_uniform(prog, "u_depth_bias"), p->bias.constant);
    /* midpoint without its second map (not implemented): lab 2's constant bias instead */
    sl_bias_mode mode = p->bias.mode == SL_BIAS_MIDPOINT && !midpoint ? SL_BIAS_CONSTANT : p->bias.mode;
    glUniform1i(sl_program_uniform(prog, "u_bias_mode"), (int)mode);
    glUniform1i(sl_program_uniform(prog, "u_second_map"), 1);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, midpoint ? r->second_map.depth_texture : 0);
    if (midpoint) glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glActiveTexture(GL_TEXTURE0);
    glUniform1f(sl_program_uniform(prog, "u_slope_bias"), p->bias.slope);
    glUniform1f(sl_program_uniform(prog, "u_max_bias"), p->bias.max_bias);
    glUniform1f(sl_program_uniform(prog, "u_normal_offset"), p->bias.normal_offset);
    glUniform1f(sl_program_uniform(prog, "u_texel_size"), _sl_texel_size(info, l, p->shadow_map_size));
    /* lab 4 */
    glUniform1i(sl_program_uniform(prog, "u_filter_mode"), (int)p->filter.mode);
    glUniform1i(sl_program_uniform(prog, "u_grid_radius"), p->filter.grid_radius);
    glUniform1f(sl_program_uniform(prog, "u_poisson_radius"), p->filter.poisson_radius);
    float near_width = l->type == SL_LIGHT_DIRECTIONAL ? 2.0f / info->light_projection[0][0]
                                                       : 2.0f * l->near * tanf(glm_rad(l->spot_angle_deg));
    glUniform1f(sl_program_uniform(prog, "u_light_size_uv"), l->size / near_width);
    glUniform1f(sl_program_uniform(prog, "u_light_near"), l->near);
    glUniform1f(sl_program_uniform(prog, "u_light_far"), l->far);
    glUniform1i(sl_program_uniform(prog, "u_shadow_map"), 0);
    glActiveTexture(GL_TEXTURE0);
    if (lab >= 2) {
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        /* Compare mode is texture state: set it for the sampler type this program declares. */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, hardware ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    } else {
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    _sl_draw_objects(r, scene, prog, true);
}

static void _sl_debug_view(sl_renderer *r, const sl_light *light, int width, int height) {
    if (!r->info.shadow_map_ready) return;
    int side = (width < height ? width : height) / 3;
    glViewport(width - side - 8, 8, side, side);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(r->debug_program.id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glUniform1i(sl_program_uniform(&r->debug_program, "u_texture"), 0);
    glUniform1i(sl_program_uniform(&r->debug_program, "u_perspective"), light->type != SL_LIGHT_DIRECTIONAL);
    glUniform1f(sl_program_uniform(&r->debug_program, "u_near"), light->near);
    glUniform1f(sl_program_uniform(&r->debug_program, "u_far"), light->far);
    glBindVertexArray(r->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
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
    _sl_light_matrices(r, scene, params);
    _sl_reset_state(0, width, height);
    int depth_lab = _sl_depth_pass(r, scene, params);
    _sl_reset_state(target, width, height);
    _sl_scene_pass(r, scene, params, depth_lab, width, height);
    if (params->show_shadow_map) _sl_debug_view(r, &scene->light, width, height);
    glBindVertexArray(0);
    glUseProgram(0);
}

bool sl_capture_framebuffer(GLuint framebuffer, int width, int height, int channels, sl_image *out) {
    static const GLenum formats[5] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
    if (channels < 1 || channels > 4) return false;
    *out = sl_image_alloc(width, height, channels);
    if (!out->data) return false;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, formats[channels], GL_FLOAT, out->data);
    sl_image_flip_rows(out);
    return true;
}

bool sl_capture_depth_texture(GLuint texture, sl_image *out, char *err, size_t err_size) {
    *out = (sl_image){0};
    if (!texture || !glIsTexture(texture)) {
        snprintf(err, err_size, "depth_texture (%u) is not a texture name", texture);
        return false;
    }
    GLint w = 0, h = 0, fmt = 0;
    glBindTexture(GL_TEXTURE_2D, texture);
    while (glGetError() != GL_NO_ERROR) {}
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    if (glGetError() != GL_NO_ERROR || w <= 0 || h <= 0) {
        snprintf(err, err_size, "depth_texture (%u) is not a 2D texture with storage", texture);
        return false;
    }
    GLint depth_bits = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
    if (depth_bits == 0) {
        snprintf(err, err_size, "depth_texture has internal format %s (0x%x), not a depth format",
                 sl_gl_enum_name((GLenum)fmt), fmt);
        return false;
    }
    *out = sl_image_alloc(w, h, 1);
    if (!out->data) return false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out->data);
    sl_image_flip_rows(out);
    return true;
}
