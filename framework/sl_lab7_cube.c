#include "sl_lab7_cube.h"

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

/* The programs lab 7 draws with, each built the first time a frame needs it. */
typedef struct _sl_cube_program {
    sl_program program;
    bool attempted;
    GLuint located; /* the program id the locations below belong to */
    GLint model, normal_matrix, albedo, view, projection, light_view_projection, face_view_projection, light_position,
        light_far, light_radiance, light_direction, output, shadows, cube_map, cube_bias, soft_radius, spot_cos;
} _sl_cube_program;

enum {
    _SL_DEPTH_SIX,     /* cube_depth.vert + cube_depth.frag */
    _SL_DEPTH_LAYERED, /* + cube_depth.geom */
    _SL_CAMERA_PLAIN,  /* scene_cube.frag without shadows */
    _SL_CAMERA_HARD,   /* point_shadow */
    _SL_CAMERA_SOFT,   /* point_shadow_soft */
    _SL_CROSS,         /* the faces as a cross */
    _SL_PROGRAM_COUNT
};

struct _sl_lab7 {
    _sl_cube_program programs[_SL_PROGRAM_COUNT];
    bool used[_SL_PROGRAM_COUNT]; /* by the last frame: rebuilt at once when their files change */
    sl_cube_map map;
    sl_status map_status;
    bool map_attempted;
};

/* Lab 7 casts from a point light only: asked for on a spot or a sun, labs 1-4 draw (and the frame says why). */
static bool _sl_lab7_takes_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params) {
    if (params->lab != 7) return false;
    if (scene->light.type == SL_LIGHT_POINT) return true;
    sl_renderer_note_off(r, 7, SL_STOP_NO_POINT_LIGHT);
    return false;
}

/* What lab 7 keeps between frames: made by its first frame. */
static struct _sl_lab7 *_sl_state(sl_renderer *r) {
    if (!r->technique_state[7]) r->technique_state[7] = calloc(1, sizeof(struct _sl_lab7));
    return r->technique_state[7];
}

/* Builds program `which` if no frame has tried yet; NULL if it does not compile (error in shader_errors[7]). */
static _sl_cube_program *_sl_program(sl_renderer *r, int which) {
    struct _sl_lab7 *s = r->technique_state[7];
    _sl_cube_program *p = &s->programs[which];
    s->used[which] = true;
    if (!p->attempted) {
        p->attempted = true;
        char vs[SL_PATH_MAX * 2], fs[SL_PATH_MAX * 2], gs[SL_PATH_MAX * 2];
        const char *defines = "#define SL_LIGHT_TYPE 2\n";
        bool lab = which == _SL_DEPTH_SIX || which == _SL_DEPTH_LAYERED;
        if (lab) {
            snprintf(vs, sizeof vs, "%s/lab7_cube/shaders/cube_depth.vert", r->labs_dir);
            snprintf(fs, sizeof fs, "%s/lab7_cube/shaders/cube_depth.frag", r->labs_dir);
            snprintf(gs, sizeof gs, "%s/lab7_cube/shaders/cube_depth.geom", r->labs_dir);
        } else if (which == _SL_CROSS) {
            snprintf(vs, sizeof vs, "%s/debug_quad.vert", r->shaders_dir);
            snprintf(fs, sizeof fs, "%s/cube_cross.frag", r->shaders_dir);
        } else {
            snprintf(vs, sizeof vs, "%s/plain.vert", r->shaders_dir);
            snprintf(fs, sizeof fs, "%s/scene_cube.frag", r->shaders_dir);
            defines = which == _SL_CAMERA_PLAIN  ? "#define SL_LIGHT_TYPE 2\n#define SL_CUBE_SHADOWS 0\n"
                      : which == _SL_CAMERA_HARD ? "#define SL_LIGHT_TYPE 2\n#define SL_CUBE_SHADOWS 1\n"
                                                   "#define SL_CUBE_SOFT 0\n"
                                                 : "#define SL_LIGHT_TYPE 2\n#define SL_CUBE_SHADOWS 1\n"
                                                   "#define SL_CUBE_SOFT 1\n";
        }
        sl_shader_desc desc = {
            .vertex_path = vs,
            .fragment_path = fs,
            .geometry_path = which == _SL_DEPTH_LAYERED ? gs : NULL,
            .search_dirs = {r->labs_dir, r->shaders_dir},
            .defines = defines,
        };
        /* The plain pass must work whatever lab 7's GLSL says: its errors are the framework's. */
        int owner = which == _SL_CAMERA_PLAIN || which == _SL_CROSS ? 0 : 7;
        sl_program_build(&p->program, &desc, r->shader_errors[owner], sizeof r->shader_errors[owner]);
    }
    if (!p->program.id) return NULL;
    if (p->located == p->program.id) return p;
    GLuint id = p->located = p->program.id;
#define _SL_LOC(field, name) p->field = glGetUniformLocation(id, name)
    _SL_LOC(model, "u_model");
    _SL_LOC(normal_matrix, "u_normal_matrix");
    _SL_LOC(albedo, "u_albedo");
    _SL_LOC(view, "u_view");
    _SL_LOC(projection, "u_projection");
    _SL_LOC(light_view_projection, "u_light_view_projection");
    _SL_LOC(face_view_projection, "u_face_view_projection");
    _SL_LOC(light_position, "u_light_position");
    _SL_LOC(light_far, "u_light_far");
    _SL_LOC(light_radiance, "u_light_radiance");
    _SL_LOC(light_direction, "u_light_direction");
    _SL_LOC(output, "u_output");
    _SL_LOC(shadows, "u_shadows");
    _SL_LOC(cube_map, "u_cube_map");
    _SL_LOC(cube_bias, "u_cube_bias");
    _SL_LOC(soft_radius, "u_soft_radius");
    _SL_LOC(spot_cos, "u_spot_cos");
#undef _SL_LOC
    return p;
}

#define _SL_CALL(r, fn, ...) \
    (sl_renderer_lab_enter(#fn), sl_renderer_lab_result((r), #fn, (r)->fns[7]->fn(__VA_ARGS__)))

/* Step 1: the face matrices. */
static bool _sl_face_matrices(sl_renderer *r, const sl_light *light) {
    sl_frame_info *info = &r->info;
    mat4 projection, views[6];
    glm_mat4_identity(projection);
    bool ok = _SL_CALL(r, lab7_face_projection, light->near, light->far, projection);
    vec3 position;
    glm_vec3_copy((float *)light->position, position);
    for (int f = 0; f < 6 && ok; f++) {
        glm_mat4_identity(views[f]);
        ok = _SL_CALL(r, lab7_face_view, position, f, views[f]);
    }
    if (!ok) return false;
    glm_mat4_copy(projection, info->cube_projection);
    for (int f = 0; f < 6; f++) glm_mat4_copy(views[f], info->cube_views[f]);
    info->cube_matrices_ready = true;
    return true;
}

/* Step 2: the cube map, made once per size. */
static bool _sl_cube_map(sl_renderer *r, int size) {
    struct _sl_lab7 *s = r->technique_state[7];
    if (s->map_attempted && s->map_status == SL_OK && s->map.size != size) {
        sl_renderer_lab_enter("lab7_destroy_cube_map");
        r->fns[7]->lab7_destroy_cube_map(&s->map);
        sl_renderer_lab_enter(NULL);
        s->map_attempted = false;
    }
    if (!s->map_attempted) {
        memset(&s->map, 0, sizeof s->map);
        sl_renderer_lab_enter("lab7_create_cube_map");
        s->map_status = r->fns[7]->lab7_create_cube_map(size, &s->map);
        s->map_attempted = true;
    }
    r->info.cube_map = s->map; /* even on failure: the grader inspects what was made */
    return sl_renderer_lab_result(r, "lab7_create_cube_map", s->map_status);
}

/* Back faces are culled in the depth passes, before the lab's begin (which may change it): every
 * mesh is closed, so the nearest surface along a ray from the light is a front face, and the
 * fragment shader, which writes gl_FragDepth and so runs for every fragment (no early depth
 * test), runs on half as many. The stored distances are the same; the pass is about 30% cheaper. */
static void _sl_depth_pass_culling(void) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
}

/* Step 2: the depth passes, layered when asked for (or on "auto") and the lab does it, else six. */
static bool _sl_depth_passes(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    sl_frame_info *info = &r->info;
    const sl_light *light = &scene->light;
    struct _sl_lab7 *s = r->technique_state[7];
    mat4 view_projection[6];
    for (int f = 0; f < 6; f++) glm_mat4_mul(info->cube_projection, info->cube_views[f], view_projection[f]);
    vec3 position;
    glm_vec3_copy((float *)light->position, position);
    if (p->cube.pass != SL_CUBE_PASS_SIX) {
        /* Asked directly: a lab that renders six passes answers SL_NOT_IMPLEMENTED here, which is no mistake. */
        _sl_depth_pass_culling();
        sl_renderer_lab_enter("lab7_begin_cube_pass");
        sl_status layered = r->fns[7]->lab7_begin_cube_pass(&s->map, SL_CUBE_ALL_FACES);
        sl_renderer_lab_enter(NULL);
        if (layered == SL_FAILED) return sl_renderer_lab_result(r, "lab7_begin_cube_pass", layered);
        if (layered == SL_OK) {
            /* what the lab attached: a message can then tell a layered pass from an SL_OK that attached nothing */
            GLint attached_layered = 0;
            glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                  GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &attached_layered);
            while (glGetError() != GL_NO_ERROR) {}
            info->cube_layered_attached = attached_layered != 0;
            _sl_cube_program *prog = _sl_program(r, _SL_DEPTH_LAYERED);
            if (!prog) {
                info->shader_error = r->shader_errors[7];
                info->shader_error_lab = 7;
                return false;
            }
            mat4 identity = GLM_MAT4_IDENTITY_INIT;
            glUseProgram(prog->program.id);
            glUniformMatrix4fv(prog->light_view_projection, 1, GL_FALSE, (const float *)identity);
            glUniformMatrix4fv(prog->face_view_projection, 6, GL_FALSE, (const float *)view_projection);
            glUniform3fv(prog->light_position, 1, position);
            glUniform1f(prog->light_far, light->far);
            sl_renderer_draw_objects(r, scene, prog->model, -1, -1);
            info->cube_layered = true;
            sl_renderer_timer_mark(r, "cube layered");
            return true;
        }
    }
    _sl_cube_program *prog = NULL;
    for (int f = 0; f < 6; f++) {
        _sl_depth_pass_culling();
        if (!_SL_CALL(r, lab7_begin_cube_pass, &s->map, f)) return false;
        if (!prog) {
            prog = _sl_program(r, _SL_DEPTH_SIX);
            if (!prog) {
                info->shader_error = r->shader_errors[7];
                info->shader_error_lab = 7;
                return false;
            }
            glUseProgram(prog->program.id);
            glUniform3fv(prog->light_position, 1, position);
            glUniform1f(prog->light_far, light->far);
        }
        glUniformMatrix4fv(prog->light_view_projection, 1, GL_FALSE, (const float *)view_projection[f]);
        sl_renderer_draw_objects(r, scene, prog->model, -1, -1);
    }
    sl_renderer_timer_mark(r, "cube 6-pass");
    return true;
}

/* Step 3: the camera pass. */
static void _sl_camera_pass(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, int width, int height) {
    sl_frame_info *info = &r->info;
    struct _sl_lab7 *s = r->technique_state[7];
    _sl_cube_program *prog = NULL;
    bool shadows = info->cube_map_ready;
    if (shadows) {
        prog = _sl_program(r, p->cube.soft ? _SL_CAMERA_SOFT : _SL_CAMERA_HARD);
        if (!prog && !info->shader_error) {
            info->shader_error = r->shader_errors[7];
            info->shader_error_lab = 7;
        }
    }
    if (!prog) {
        shadows = false;
        prog = _sl_program(r, _SL_CAMERA_PLAIN);
        if (!prog && !info->shader_error) {
            info->shader_error = r->shader_errors[0];
            info->shader_error_lab = 0;
        }
    }
    info->lab_in_use = shadows ? 7 : 0;
    if (p->output == SL_OUTPUT_SHADED) glClearColor(0.55f, 0.62f, 0.70f, 1);
    else if (p->output == SL_OUTPUT_VISIBILITY) glClearColor(1, 1, 1, 1);
    else glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!prog) return;
    const sl_light *l = &scene->light;
    mat4 view, projection;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, height > 0 ? (float)width / (float)height : 1, projection);
    glUseProgram(prog->program.id);
    glUniformMatrix4fv(prog->view, 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(prog->projection, 1, GL_FALSE, (const float *)projection);
    glUniform3fv(prog->light_position, 1, l->position);
    glUniform3fv(prog->light_direction, 1, l->direction);
    vec3 radiance;
    glm_vec3_scale((float *)l->color, l->intensity, radiance);
    glUniform3fv(prog->light_radiance, 1, radiance);
    glUniform1f(prog->spot_cos, 0);
    glUniform1i(prog->output, (int)p->output);
    glUniform1f(prog->light_far, l->far);
    glUniform1f(prog->cube_bias, p->cube.bias);
    glUniform1f(prog->soft_radius, p->cube.soft_radius);
    glUniform1i(prog->cube_map, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, shadows ? s->map.depth_cube : 0);
    if (shadows) {
        /* the lookup compares by hand: the texture returns distances, not comparison results */
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    }
    sl_renderer_draw_objects(r, scene, prog->model, prog->normal_matrix, prog->albedo);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    sl_renderer_timer_mark(r, "camera");
}

/* The cross's cells: a side of half what fits 4 x 3 cells in the frame, 8 pixels off the lower right corner. */
static int _sl_cross_cell(int width, int height) { return (width / 4 < height / 3 ? width / 4 : height / 3) / 2; }

/* Where the cross (params.show_shadow_map) puts face `face` (0..5: +x -x +y -y +z -z) in a width x
 * height frame: its top-left corner from the frame's top-left, and its side, in pixels (face labels). */
static void _sl_lab7_cross_face_rect(int width, int height, int face, int *x, int *y, int *side) {
    /* cube_cross.frag's net, cells counted from the cross's lower left: -X -Z +X +Z across the middle row,
     * +Y above -Z, -Y below it */
    static const int cells[6][2] = {{2, 1}, {0, 1}, {1, 2}, {1, 0}, {3, 1}, {1, 1}};
    int cell = _sl_cross_cell(width, height), f = face >= 0 && face < 6 ? face : 0;
    *side = cell;
    *x = width - 4 * cell - 8 + cells[f][0] * cell;
    *y = height - 8 - (cells[f][1] + 1) * cell;
}

/* The six faces as a cross in the lower right corner. */
static void _sl_cross_view(sl_renderer *r, int width, int height) {
    if (!r->info.cube_map_ready) return;
    _sl_cube_program *prog = _sl_program(r, _SL_CROSS);
    if (!prog) return;
    int cell = _sl_cross_cell(width, height);
    glViewport(width - 4 * cell - 8, 8, 4 * cell, 3 * cell);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(prog->program.id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, ((struct _sl_lab7 *)r->technique_state[7])->map.depth_cube);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glUniform1i(prog->cube_map, 0);
    glBindVertexArray(r->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    sl_renderer_timer_mark(r, "debug view");
}

static void _sl_lab7_draw_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, GLuint target,
                                int width, int height) {
    sl_frame_info *info = &r->info;
    info->cube_frame = true;
    struct _sl_lab7 *s = _sl_state(r);
    if (!s) return;
    memset(s->used, 0, sizeof s->used);
    int size = p->cube.map_size > 0 ? p->cube.map_size : 512;
    sl_renderer_reset_state(0, width, height);
    bool ready = _sl_face_matrices(r, &scene->light);
    /* The map's stubs are asked even without matrices, so the grader can say which of them are not done yet. */
    bool map = _sl_cube_map(r, size);
    if (ready && map) info->cube_map_ready = _sl_depth_passes(r, scene, p);
    else if (map) _SL_CALL(r, lab7_begin_cube_pass, &s->map, 0);
    sl_renderer_reset_state(target, width, height);
    _sl_camera_pass(r, scene, p, width, height);
    if (info->lab_in_use != 7) sl_renderer_note_stop(r, 7);
    if (p->show_shadow_map) _sl_cross_view(r, width, height);
}

static bool _sl_lab7_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    struct _sl_lab7 *s = r->technique_state[7];
    if (!s) return true;
    bool ok = true;
    for (int i = 0; i < _SL_PROGRAM_COUNT; i++) {
        _sl_cube_program *p = &s->programs[i];
        if (!p->attempted) continue;
        if (!p->program.id) {
            /* never compiled: try again, so a fix switches the lab back on */
            p->attempted = false;
            if (s->used[i]) *reloaded = true;
            continue;
        }
        if (!s->used[i]) continue;
        char e[4096];
        if (sl_program_reload_if_changed(&p->program, e, sizeof e)) {
            *reloaded = true;
        } else if (e[0]) {
            if (ok) snprintf(err, err_size, "%s", e);
            ok = false;
        }
    }
    return ok;
}

/* Lab 7's programs: how many were built (first builds only) and how many are held now. */
static void _sl_lab7_program_stats(const sl_renderer *r, sl_program_stats *out) {
    const struct _sl_lab7 *s = r->technique_state[7];
    if (!s) return;
    for (int i = 0; i < _SL_PROGRAM_COUNT; i++) {
        out->builds += s->programs[i].attempted;
        out->cached += s->programs[i].program.id != 0;
    }
}

static void _sl_lab7_destroy(sl_renderer *r) {
    struct _sl_lab7 *s = r->technique_state[7];
    if (!s) return;
    if (s->map_attempted && s->map_status == SL_OK) {
        sl_renderer_lab_enter("lab7_destroy_cube_map");
        r->fns[7]->lab7_destroy_cube_map(&s->map);
        sl_renderer_lab_enter(NULL);
    }
    for (int i = 0; i < _SL_PROGRAM_COUNT; i++) sl_program_destroy(&s->programs[i].program);
    free(s);
    r->technique_state[7] = NULL;
}

/* The faces' names on the cross (M). */
static void _sl_lab7_overlay_labels(sl_overlay *ov, const sl_frame_info *info, const sl_render_params *p, int width,
                                    int height) {
    if (!info->cube_frame || !info->cube_map_ready || !p->show_shadow_map) return;
    static const float white[3] = {1, 1, 1};
    static const char *const faces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    int s = sl_overlay_scale_for(ov, width, height);
    for (int f = 0; f < 6; f++) {
        int x, y, side;
        _sl_lab7_cross_face_rect(width, height, f, &x, &y, &side);
        sl_overlay_label(ov, x + 2 * s, y + 2 * s, white, "%s", faces[f]);
    }
}

/* Lab 7 draws a frame of its own for a point light. */
/* ---- The viewer: lab 7's keys and what the title and overlay say of it ---- */
enum { _SL_LAB7_KEY_SOFT, _SL_LAB7_KEY_CUBE_PASS, _SL_LAB7_KEY_CUBE_BIAS, _SL_LAB7_KEY_LIGHT_HEIGHT };

static const sl_technique_key _sl_lab7_keys[] = {
    {{GLFW_KEY_S}, "S", "lookup", "soft (20 directions) or hard lookup", _SL_LAB7_KEY_SOFT},
    {{GLFW_KEY_L}, "L", "faces", "faces drawn in: auto, six passes, one layered pass", _SL_LAB7_KEY_CUBE_PASS},
    {{GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET}, "[ ]", "cube bias", "the cube lookup's bias halve, double",
     _SL_LAB7_KEY_CUBE_BIAS},
    {{GLFW_KEY_PAGE_UP, GLFW_KEY_PAGE_DOWN}, "PgUp PgDn", "light height", "the point light up, down",
     _SL_LAB7_KEY_LIGHT_HEIGHT},
    {{0}, NULL, NULL, NULL, 0},
};

static void _sl_lab7_key_pressed(sl_view_context *c, const sl_technique_key *k, int code, bool up) {
    sl_cube_settings *cube = &c->params->cube;
    switch (k->id) {
    case _SL_LAB7_KEY_SOFT:
        /* soft or hard, each with the bias it needs unless the bias was changed by hand */
        cube->soft = !cube->soft;
        if (cube->soft && cube->bias == SL_CUBE_HARD_BIAS) cube->bias = SL_CUBE_SOFT_BIAS;
        else if (!cube->soft && cube->bias == SL_CUBE_SOFT_BIAS) cube->bias = SL_CUBE_HARD_BIAS;
        break;
    case _SL_LAB7_KEY_CUBE_PASS: cube->pass = (sl_cube_pass)((cube->pass + 1) % SL_CUBE_PASS_COUNT); break;
    case _SL_LAB7_KEY_CUBE_BIAS: cube->bias = up ? (cube->bias > 0 ? cube->bias * 2 : 0.0005f) : cube->bias * 0.5f; break;
    case _SL_LAB7_KEY_LIGHT_HEIGHT:
        if (c->scene->light.type == SL_LIGHT_POINT) c->scene->light.position[1] += code == GLFW_KEY_PAGE_UP ? 0.2f : -0.2f;
        break;
    }
}

static void _sl_lab7_key_state(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n) {
    const sl_cube_settings *cube = &c->params->cube;
    const sl_frame_info *info = c->info;
    switch (k->id) {
    case _SL_LAB7_KEY_SOFT: snprintf(out, n, "%s", cube->soft ? "soft" : "hard"); break;
    case _SL_LAB7_KEY_CUBE_PASS:
        /* auto says which it took */
        snprintf(out, n, "%s%s", sl_cube_pass_name(cube->pass),
                 cube->pass != SL_CUBE_PASS_AUTO || !info || !info->cube_frame ? ""
                 : info->cube_layered ? " (layered)" : " (six)");
        break;
    case _SL_LAB7_KEY_CUBE_BIAS: snprintf(out, n, "%.4f", cube->bias); break;
    case _SL_LAB7_KEY_LIGHT_HEIGHT: snprintf(out, n, "y %.1f", (double)c->scene->light.position[1]); break;
    }
}

/* The cube map's settings for a point light; with another light lab 4's, which then draw. */
static void _sl_lab7_settings_text(const sl_view_context *c, char *out, size_t n) {
    const sl_cube_settings *cube = &c->params->cube;
    if (c->scene->light.type == SL_LIGHT_POINT) {
        snprintf(out, n, "cube map %d, bias %.4f, %s, %s", cube->map_size, cube->bias,
                 cube->soft ? "soft (20 directions)" : "hard", c->info->cube_layered ? "one layered pass" : "six passes");
        return;
    }
    const sl_technique *filtering = sl_technique_of(4);
    out[0] = '\0';
    if (filtering && filtering->settings_text) filtering->settings_text(c, out, n);
}

static bool _sl_lab7_maps_text(const sl_view_context *c, char *out, size_t n) {
    if (!c->info->cube_frame) return false;
    snprintf(out, n, "cube map: 6 faces of %dx%d", c->params->cube.map_size, c->params->cube.map_size);
    return true;
}

static void _sl_lab7_overlay_lines(sl_overlay *ov, const sl_view_context *c) {
    const sl_cube_settings *cube = &c->params->cube;
    sl_overlay_line(ov, NULL, "lookup: %s, bias %.4f (distance / far)", cube->soft ? "soft, 20 directions" : "hard",
                    cube->bias);
    sl_overlay_line(ov, NULL, "faces: %s", c->info->cube_layered ? "one layered pass" : "six passes");
}

/* The benchmark asked for one layered pass and the build's lab7_begin_cube_pass drew six. */
static void _sl_lab7_frame_shortfall(const sl_frame_info *info, const sl_render_params *params, char *out, size_t n) {
    out[0] = '\0';
    if (params->cube.pass == SL_CUBE_PASS_LAYERED && info->cube_map_ready && !info->cube_layered)
        snprintf(out, n, "drew six passes: these labs' lab7_begin_cube_pass has no layered pass (SL_CUBE_ALL_FACES)");
}

const sl_technique sl_lab7_technique = {
    .name = "cube maps",
    .lab = 7,
    .takes_frame = _sl_lab7_takes_frame,
    .draw_frame = _sl_lab7_draw_frame,
    .overlay_labels = _sl_lab7_overlay_labels,
    .reload_changed = _sl_lab7_reload_changed,
    .program_stats = _sl_lab7_program_stats,
    .destroy = _sl_lab7_destroy,
    .probes = sl_lab7_probes,
    .keys = _sl_lab7_keys,
    .key_pressed = _sl_lab7_key_pressed,
    .key_state = _sl_lab7_key_state,
    .settings_text = _sl_lab7_settings_text,
    .maps_text = _sl_lab7_maps_text,
    .overlay_lines = _sl_lab7_overlay_lines,
    .default_for_lights = 1u << SL_LIGHT_POINT,
    .frame_shortfall = _sl_lab7_frame_shortfall,
};
