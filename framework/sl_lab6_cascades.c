#define _POSIX_C_SOURCE 200809L
#include "sl_lab6_cascades.h"
#include "sl_lab6_viewer.h"
#include "sl_overlay.h"
#include "sl_probe_calls.h"
#include "sl_technique.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Calls lab N's function through the renderer's table, recorded as the renderer records its own calls. */
#define _SL_LAB6_CALL(r, N, fn, ...)                                                                              \
    (sl_renderer_lab_enter(#fn), sl_renderer_lab_result((r), #fn, (r)->fns[N]->fn(__VA_ARGS__)))

typedef struct _sl_lab6_program {
    sl_program program;
    bool attempted;
} _sl_lab6_program;

struct _sl_lab6 {
    GLuint texture, framebuffer;
    int size;
    _sl_lab6_program depth;      /* lab 1's depth shaders */
    _sl_lab6_program scene[3];   /* the camera pass, per light type */
    _sl_lab6_program plain[3];   /* no shadows: a stub or a shader error */
    _sl_lab6_program debug;      /* one layer of the array, in the overlay */
    _sl_lab6_program lines;      /* the frozen frustum's slices and light boxes */
    GLuint line_vao, line_buffer;
    int builds;      /* programs built (sl_renderer_program_stats) */
    double build_ms;
};

/* What lab 6 keeps between frames: made by its first frame. */
static struct _sl_lab6 *_sl_lab6_state(sl_renderer *r) {
    if (!r->technique_state[6]) r->technique_state[6] = calloc(1, sizeof(struct _sl_lab6));
    return r->technique_state[6];
}

static void _sl_lab6_destroy(sl_renderer *r) {
    struct _sl_lab6 *s = r->technique_state[6];
    if (!s) return;
    if (s->texture) glDeleteTextures(1, &s->texture);
    if (s->framebuffer) glDeleteFramebuffers(1, &s->framebuffer);
    sl_program_destroy(&s->depth.program);
    sl_program_destroy(&s->debug.program);
    sl_program_destroy(&s->lines.program);
    if (s->line_vao) glDeleteVertexArrays(1, &s->line_vao);
    if (s->line_buffer) glDeleteBuffers(1, &s->line_buffer);
    for (int i = 0; i < 3; i++) {
        sl_program_destroy(&s->scene[i].program);
        sl_program_destroy(&s->plain[i].program);
    }
    free(s);
    r->technique_state[6] = NULL;
}

static bool _sl_lab6_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    struct _sl_lab6 *s = r->technique_state[6];
    if (!s) return true;
    struct {
        _sl_lab6_program *p;
        int lab;
    } watched[] = {{&s->depth, 1}, {&s->scene[0], 6}, {&s->scene[1], 6}, {&s->scene[2], 6}};
    bool ok = true;
    for (size_t i = 0; i < sizeof watched / sizeof watched[0]; i++) {
        _sl_lab6_program *p = watched[i].p;
        if (!p->attempted) continue;
        char e[sizeof r->shader_errors[0]];
        if (sl_program_reload_if_changed(&p->program, e, sizeof e)) {
            r->shader_errors[watched[i].lab][0] = '\0';
            *reloaded = true;
        } else if (e[0]) {
            snprintf(r->shader_errors[watched[i].lab], sizeof r->shader_errors[0], "%s", e);
            if (ok) snprintf(err, err_size, "%s", e);
            ok = false;
        }
    }
    return ok;
}

static void _sl_lab6_program_stats(const sl_renderer *r, sl_program_stats *out) {
    const struct _sl_lab6 *s = r->technique_state[6];
    if (!s) return;
    out->builds += s->builds;
    out->build_ms += s->build_ms;
    const _sl_lab6_program *all[] = {&s->depth, &s->scene[0], &s->scene[1], &s->scene[2], &s->plain[0],
                                     &s->plain[1], &s->plain[2], &s->debug, &s->lines};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) out->cached += all[i]->program.id != 0;
}

/* The camera the cascades of this frame are fitted to: params' frozen one, or the scene's. */
static const sl_camera *_sl_lab6_fit_camera(const sl_scene *scene, const sl_render_params *params) {
    return params->cascades.use_camera ? &params->cascades.camera : &scene->camera;
}

/* Builds p once from two files (the vertex shader under vs_dir, the fragment shader under fs_dir);
 * a failure goes to the renderer's shader errors of `lab`. NULL if it does not compile. */
static sl_program *_sl_lab6_build(sl_renderer *r, _sl_lab6_program *p, const char *vs_dir, const char *vs,
                                    const char *fs_dir, const char *fs, const char *defines, int lab) {
    if (!p->attempted) {
        char vs_path[SL_PATH_MAX * 2], fs_path[SL_PATH_MAX * 2];
        snprintf(vs_path, sizeof vs_path, "%s/%s", vs_dir, vs);
        snprintf(fs_path, sizeof fs_path, "%s/%s", fs_dir, fs);
        sl_shader_desc desc = {
            .vertex_path = vs_path,
            .fragment_path = fs_path,
            .search_dirs = {r->labs_dir, r->shaders_dir},
            .defines = defines,
        };
        p->attempted = true;
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        sl_program_build(&p->program, &desc, r->shader_errors[lab], sizeof r->shader_errors[lab]);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        struct _sl_lab6 *s = r->technique_state[6];
        s->builds++;
        s->build_ms += (double)(t1.tv_sec - t0.tv_sec) * 1e3 + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-6;
    }
    return p->program.id ? &p->program : NULL;
}

/* The depth texture array (one layer per cascade) and the framebuffer its layers are attached to in turn. */
static bool _sl_lab6_targets(struct _sl_lab6 *s, int size) {
    if (s->texture && s->size == size) return true;
    if (s->texture) glDeleteTextures(1, &s->texture);
    if (!s->framebuffer) glGenFramebuffers(1, &s->framebuffer);
    glGenTextures(1, &s->texture);
    glBindTexture(GL_TEXTURE_2D_ARRAY, s->texture);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, SL_MAX_CASCADES, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* beyond a cascade's square: the border's depth 1.0, nothing in front, lit */
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    static const float border[4] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, s->texture, 0, 0);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    s->size = size;
    return complete;
}

static void _sl_lab6_draw_objects(sl_renderer *r, const sl_scene *scene, GLuint program, bool colours) {
    GLint model = glGetUniformLocation(program, "u_model");
    GLint normal_matrix = colours ? glGetUniformLocation(program, "u_normal_matrix") : -1;
    GLint albedo = colours ? glGetUniformLocation(program, "u_albedo") : -1;
    sl_renderer_draw_objects(r, scene, model, normal_matrix, albedo);
}

/* The shimmer demo: moves the light box so that the sphere's centre lands exactly
 * on the middle of the map, as it does before snapping. Snapping moved it by a
 * fraction of a texel, in the projection or in the view; this takes that away in
 * either case, so the demo works with any correct lab code. */
static void _sl_lab6_unsnap(const vec4 sphere, mat4 light_view, mat4 light_projection) {
    mat4 view_projection, shift;
    vec4 centre = {sphere[0], sphere[1], sphere[2], 1}, ndc;
    glm_mat4_mul(light_projection, light_view, view_projection);
    glm_mat4_mulv(view_projection, centre, ndc);
    if (!(fabsf(ndc[3]) > 1e-12f)) return;
    glm_translate_make(shift, (vec3){-ndc[0] / ndc[3], -ndc[1] / ndc[3], 0});
    glm_mat4_mul(shift, light_projection, light_projection);
}

/* Lab 6's C functions and lab 2's shadow matrix, for every cascade; false if one of them is not done.
 * Every function is asked even after one fails, so the grader can name each stub. */
static bool _sl_lab6_matrices(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, float aspect) {
    sl_frame_info *info = &r->info;
    const sl_camera *cam = _sl_lab6_fit_camera(scene, p);
    int count = p->cascades.count < 1 ? 1 : p->cascades.count > SL_MAX_CASCADES ? SL_MAX_CASCADES : p->cascades.count;
    float far = p->cascades.max_distance > cam->near && p->cascades.max_distance < cam->far ? p->cascades.max_distance
                                                                                            : cam->far;
    int size = p->shadow_map_size > 0 ? p->shadow_map_size : 1024;
    mat4 view, proj, view_proj, inv;
    sl_camera_view(cam, view);
    sl_camera_projection(cam, aspect, proj);
    glm_mat4_mul(proj, view, view_proj);
    glm_mat4_inv(view_proj, inv);
    glm_mat4_copy(view, info->cascade_fit_view);
    info->cascade_count = count;
    float splits[SL_MAX_CASCADES + 1] = {0};
    bool ok = _SL_LAB6_CALL(r, 6, lab6_split_distances, cam->near, far, count, p->cascades.lambda, splits);
    if (!ok) /* uniform splits, so the functions asked next get sensible inputs */
        for (int i = 0; i <= count; i++) splits[i] = cam->near + (far - cam->near) * (float)i / (float)count;
    memcpy(info->cascade_splits, splits, sizeof splits);
    sl_light light = scene->light;
    for (int i = 0; i < count; i++) {
        vec4 sphere = {0, 0, 0, 1};
        mat4 lv, lp, shadow;
        glm_mat4_identity(lv);
        glm_mat4_identity(lp);
        glm_mat4_identity(shadow);
        ok &= _SL_LAB6_CALL(r, 6, lab6_slice_sphere, inv, cam->near, cam->far, splits[i], splits[i + 1], sphere);
        vec4 fitted; /* the sphere as fitted, whatever lab6_cascade_matrices does to its argument */
        glm_vec4_copy(sphere, fitted);
        ok &= _SL_LAB6_CALL(r, 6, lab6_cascade_matrices, &light, sphere, p->cascades.caster_margin, size, lv, lp);
        if (ok && p->cascades.unsnapped) _sl_lab6_unsnap(fitted, lv, lp);
        ok &= _SL_LAB6_CALL(r, 2, lab2_shadow_matrix, lp, lv, shadow);
        glm_vec4_copy(sphere, info->cascade_spheres[i]);
        glm_mat4_copy(lv, info->cascade_view[i]);
        glm_mat4_copy(lp, info->cascade_projection[i]);
        glm_mat4_copy(shadow, info->cascade_shadow_matrix[i]);
        if (!ok) return false;
    }
    return ok;
}

/* One depth pass per cascade, into its layer, with lab 1's depth shaders. */
static bool _sl_lab6_depth_passes(sl_renderer *r, const sl_scene *scene, const sl_render_params *p) {
    sl_frame_info *info = &r->info;
    struct _sl_lab6 *s = _sl_lab6_state(r);
    int size = p->shadow_map_size > 0 ? p->shadow_map_size : 1024;
    if (!s || !_sl_lab6_targets(s, size)) return false;
    sl_program *depth = _sl_lab6_build(r, &s->depth, r->labs_dir, "lab1_depth_fbo/shaders/depth.vert", r->labs_dir,
                                         "lab1_depth_fbo/shaders/depth.frag", NULL, 1);
    if (!depth) {
        info->shader_error = r->shader_errors[1];
        info->shader_error_lab = 1;
        return false;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glUseProgram(depth->id);
    GLint lvp = glGetUniformLocation(depth->id, "u_light_view_projection");
    for (int i = 0; i < info->cascade_count; i++) {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, s->texture, 0, i);
        glClear(GL_DEPTH_BUFFER_BIT);
        mat4 vp;
        glm_mat4_mul(info->cascade_projection[i], info->cascade_view[i], vp);
        glUniformMatrix4fv(lvp, 1, GL_FALSE, (const float *)vp);
        _sl_lab6_draw_objects(r, scene, depth->id, false);
    }
    sl_renderer_timer_mark(r, "cascades");
    info->cascade_texture = s->texture;
    return true;
}

static void _sl_lab6_camera_pass(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, bool shadows,
                                 GLuint target, int width, int height) {
    sl_frame_info *info = &r->info;
    struct _sl_lab6 *s = _sl_lab6_state(r);
    sl_renderer_reset_state(target, width, height);
    if (p->output == SL_OUTPUT_SHADED) glClearColor(0.55f, 0.62f, 0.70f, 1);
    else if (p->output == SL_OUTPUT_VISIBILITY) glClearColor(1, 1, 1, 1);
    else if (p->output == SL_OUTPUT_CASCADE_INDEX) glClearColor(-1, -1, -1, 1); /* no surface, no cascade */
    else glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!s) return;
    int type = (int)scene->light.type;
    if (type < 0 || type > 2) type = 0;
    char defines[96];
    snprintf(defines, sizeof defines, "#define SL_LIGHT_TYPE %d\n#define SL_LAB 6\n", type);
    sl_program *prog = NULL;
    if (shadows) {
        prog = _sl_lab6_build(r, &s->scene[type], r->shaders_dir, "plain.vert", r->shaders_dir,
                                "scene_cascades.frag", defines, 6);
        if (!prog && !s->scene[type].program.id) {
            info->shader_error = r->shader_errors[6];
            info->shader_error_lab = 6;
        }
    }
    bool shadowed = prog != NULL;
    if (!prog)
        prog = _sl_lab6_build(r, &s->plain[type], r->shaders_dir, "plain.vert", r->shaders_dir, "plain.frag",
                                defines, 0);
    if (!prog) return;
    GLuint id = prog->id;
    glUseProgram(id);
    mat4 view, proj;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, height > 0 ? (float)width / (float)height : 1, proj);
    glUniformMatrix4fv(glGetUniformLocation(id, "u_view"), 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(glGetUniformLocation(id, "u_projection"), 1, GL_FALSE, (const float *)proj);
    const sl_light *l = &scene->light;
    glUniform3fv(glGetUniformLocation(id, "u_light_position"), 1, l->position);
    glUniform3fv(glGetUniformLocation(id, "u_light_direction"), 1, l->direction);
    vec3 radiance;
    glm_vec3_scale((float *)l->color, l->intensity, radiance);
    glUniform3fv(glGetUniformLocation(id, "u_light_radiance"), 1, radiance);
    glUniform1f(glGetUniformLocation(id, "u_spot_cos"), cosf(glm_rad(l->spot_angle_deg)));
    glUniform1i(glGetUniformLocation(id, "u_output"), (int)p->output);
    glUniform1i(glGetUniformLocation(id, "u_shadows"), shadowed ? 1 : 0);
    if (shadowed) {
        int count = info->cascade_count;
        float split_far[4] = {0, 0, 0, 0}, split_near[4] = {0, 0, 0, 0}, texel[4] = {0, 0, 0, 0},
              depth_scale[4] = {0, 0, 0, 0};
        int size = p->shadow_map_size > 0 ? p->shadow_map_size : 1024;
        for (int i = 0; i < count; i++) {
            split_far[i] = info->cascade_splits[i + 1];
            split_near[i] = info->cascade_splits[i];
            /* the world size of a texel and of the depth range, from the projection lab 6 built */
            float sx = info->cascade_projection[i][0][0], sz = info->cascade_projection[i][2][2];
            texel[i] = sx != 0 ? 2.0f / sx / (float)size : 0;
            depth_scale[i] = fabsf(sz) * 0.5f; /* depth units per world unit along the light */
        }
        glUniform1i(glGetUniformLocation(id, "u_cascade_count"), count);
        glUniform4fv(glGetUniformLocation(id, "u_split_far"), 1, split_far);
        glUniform4fv(glGetUniformLocation(id, "u_split_near"), 1, split_near);
        glUniform1f(glGetUniformLocation(id, "u_blend_band"), p->cascades.blend_band);
        glUniform4fv(glGetUniformLocation(id, "u_texel_world"), 1, texel);
        glUniform4fv(glGetUniformLocation(id, "u_depth_per_world"), 1, depth_scale);
        glUniformMatrix4fv(glGetUniformLocation(id, "u_cascade_matrix"), count, GL_FALSE,
                           (const float *)info->cascade_shadow_matrix);
        glUniformMatrix4fv(glGetUniformLocation(id, "u_fit_view"), 1, GL_FALSE, (const float *)info->cascade_fit_view);
        glUniform1i(glGetUniformLocation(id, "u_show_cascades"), p->cascades.show_cascades ? 1 : 0);
        glUniform3fv(glGetUniformLocation(id, "u_cascade_colours"), SL_MAX_CASCADES, &sl_cascade_colours[0][0]);
        glUniform1i(glGetUniformLocation(id, "u_cascades"), 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, s->texture);
        info->lab_in_use = 6;
    }
    _sl_lab6_draw_objects(r, scene, id, true);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    sl_renderer_timer_mark(r, "camera");
}

/* The 12 edges of a box given by its 8 corners (bit 0: x, bit 1: y, bit 2: z), as line vertices. */
static int _sl_lab6_box_edges(vec3 corners[8], float *out) {
    int n = 0;
    for (int a = 0; a < 8; a++)
        for (int bit = 1; bit < 8; bit <<= 1) {
            int b = a | bit;
            if (b == a) continue;
            for (int k = 0; k < 3; k++) out[n * 3 + k] = corners[a][k];
            for (int k = 0; k < 3; k++) out[n * 3 + 3 + k] = corners[b][k];
            n += 2;
        }
    return n; /* 24 vertices */
}

/* The classic demo, seen from the scene's camera: each cascade's slice of the
 * frozen camera's frustum and its light box, in the cascade's colour. */
static void _sl_lab6_frustum_lines(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, float aspect) {
    struct _sl_lab6 *s = r->technique_state[6];
    sl_frame_info *info = &r->info;
    sl_program *prog = _sl_lab6_build(r, &s->lines, r->shaders_dir, "lines.vert", r->shaders_dir, "lines.frag",
                                      NULL, 0);
    if (!prog) return;
    if (!s->line_vao) {
        glGenVertexArrays(1, &s->line_vao);
        glGenBuffers(1, &s->line_buffer);
        glBindVertexArray(s->line_vao);
        glBindBuffer(GL_ARRAY_BUFFER, s->line_buffer);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), NULL);
    }
    const sl_camera *frozen = &p->cascades.camera;
    mat4 view, proj, vp, inv;
    sl_camera_view(frozen, view);
    sl_camera_projection(frozen, aspect, proj);
    glm_mat4_mul(proj, view, vp);
    glm_mat4_inv(vp, inv);
    const float (*colours)[3] = sl_cascade_colours;
    float vertices[SL_MAX_CASCADES][2][24 * 3];
    int counts[SL_MAX_CASCADES][2];
    for (int i = 0; i < info->cascade_count; i++) {
        vec3 slice[8], box[8];
        for (int c = 0; c < 8; c++) {
            /* the slice: along each frustum edge at the cascade's split depths */
            vec4 n = {(c & 1) ? 1.f : -1.f, (c & 2) ? 1.f : -1.f, -1, 1}, f = {n[0], n[1], 1, 1}, wn, wf;
            glm_mat4_mulv(inv, n, wn);
            glm_mat4_mulv(inv, f, wf);
            float d = info->cascade_splits[i + ((c & 4) ? 1 : 0)];
            float t = (d - frozen->near) / (frozen->far - frozen->near);
            for (int k = 0; k < 3; k++) slice[c][k] = wn[k] / wn[3] + (wf[k] / wf[3] - wn[k] / wn[3]) * t;
            /* the light box: the corners of the cascade's NDC cube, back to the world */
            mat4 light_vp, light_inv;
            glm_mat4_mul(info->cascade_projection[i], info->cascade_view[i], light_vp);
            glm_mat4_inv(light_vp, light_inv);
            vec4 ndc = {(c & 1) ? 1.f : -1.f, (c & 2) ? 1.f : -1.f, (c & 4) ? 1.f : -1.f, 1}, w;
            glm_mat4_mulv(light_inv, ndc, w);
            for (int k = 0; k < 3; k++) box[c][k] = w[k] / w[3];
        }
        counts[i][0] = _sl_lab6_box_edges(slice, vertices[i][0]);
        counts[i][1] = _sl_lab6_box_edges(box, vertices[i][1]);
    }
    mat4 scene_view, scene_proj;
    sl_camera_view(&scene->camera, scene_view);
    sl_camera_projection(&scene->camera, aspect, scene_proj);
    glUseProgram(prog->id);
    glUniformMatrix4fv(glGetUniformLocation(prog->id, "u_view"), 1, GL_FALSE, (const float *)scene_view);
    glUniformMatrix4fv(glGetUniformLocation(prog->id, "u_projection"), 1, GL_FALSE, (const float *)scene_proj);
    GLint colour = glGetUniformLocation(prog->id, "u_albedo");
    glBindVertexArray(s->line_vao);
    glBindBuffer(GL_ARRAY_BUFFER, s->line_buffer);
    glDisable(GL_DEPTH_TEST); /* the boxes reach under the ground: show them whole */
    for (int i = 0; i < info->cascade_count; i++)
        for (int which = 0; which < 2; which++) {
            float dim = which ? 0.55f : 1.0f; /* light boxes darker than the slices */
            glUniform3f(colour, colours[i][0] * dim, colours[i][1] * dim, colours[i][2] * dim);
            glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(counts[i][which] * 3 * sizeof(float)), vertices[i][which],
                         GL_STREAM_DRAW);
            glDrawArrays(GL_LINES, 0, counts[i][which]);
        }
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(0);
    sl_renderer_timer_mark(r, "frustum lines");
}

static void _sl_lab6_debug_view(sl_renderer *r, int width, int height);

static void _sl_lab6_draw_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                                int width, int height) {
    sl_frame_info *info = &r->info;
    info->cascades_ready = false;
    info->cascade_texture = 0;
    float aspect = height > 0 ? (float)width / (float)height : 1;
    bool ok = _sl_lab6_matrices(r, scene, params, aspect);
    if (ok) ok = _sl_lab6_depth_passes(r, scene, params);
    info->cascades_ready = ok;
    _sl_lab6_camera_pass(r, scene, params, ok, target, width, height);
    /* what stopped the cascades: lab 6's functions or shaders, lab 2's shadow matrix, lab 1's depth shaders */
    if (info->lab_in_use != 6 && !sl_renderer_note_stop(r, 6) && !sl_renderer_note_stop(r, 2))
        sl_renderer_note_stop(r, 1);
    if (ok && params->cascades.use_camera && params->cascades.show_frustum)
        _sl_lab6_frustum_lines(r, scene, params, aspect);
    if (ok && params->show_shadow_map) _sl_lab6_debug_view(r, width, height);
}

/* Where the debug view puts layer `layer` of `count`: its top-left corner from the frame's top-left, and its
 * side, in pixels (and the overlay's labels). */
static void _sl_lab6_layer_rect(int width, int height, int count, int layer, int *x, int *y, int *side) {
    *side = (width < height ? width : height) / 4;
    *x = width - (count - layer) * (*side + 6) - 2;
    *y = height - 8 - *side;
}

/* The cascades' layers side by side along the bottom of the picture. */
static void _sl_lab6_debug_view(sl_renderer *r, int width, int height) {
    struct _sl_lab6 *s = r->technique_state[6];
    if (!s || !r->info.cascades_ready) return;
    sl_program *prog = _sl_lab6_build(r, &s->debug, r->shaders_dir, "debug_quad.vert", r->shaders_dir,
                                        "debug_layer.frag", NULL, 0);
    if (!prog) return;
    int count = r->info.cascade_count;
    glDisable(GL_DEPTH_TEST);
    glUseProgram(prog->id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, s->texture);
    glUniform1i(glGetUniformLocation(prog->id, "u_layers"), 0);
    glBindVertexArray(r->empty_vao);
    for (int i = 0; i < count; i++) {
        int x, y, side;
        _sl_lab6_layer_rect(width, height, count, i, &x, &y, &side);
        glViewport(x, height - y - side, side, side);
        glUniform1i(glGetUniformLocation(prog->id, "u_layer"), i);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    sl_renderer_timer_mark(r, "debug view");
}

/* The cascades' colours with their view depths (K), and each layer's number in the debug view (M). */
static void _sl_lab6_overlay_labels(sl_overlay *ov, const sl_frame_info *info, const sl_render_params *p, int width,
                                    int height) {
    if (!info->cascades_ready) return;
    if (p->cascades.show_cascades) {
        sl_overlay_panel(ov, SL_OVERLAY_TOP_RIGHT, "cascades (K), view depth");
        for (int i = 0; i < info->cascade_count && i < SL_MAX_CASCADES; i++)
            sl_overlay_line(ov, sl_cascade_colours[i], SL_OVERLAY_SWATCH SL_OVERLAY_SWATCH " %d: %.1f - %.1f", i,
                            (double)info->cascade_splits[i], (double)info->cascade_splits[i + 1]);
    }
    if (p->show_shadow_map) {
        int s = sl_overlay_scale_for(ov, width, height);
        for (int i = 0; i < info->cascade_count && i < SL_MAX_CASCADES; i++) {
            int x, y, side;
            _sl_lab6_layer_rect(width, height, info->cascade_count, i, &x, &y, &side);
            sl_overlay_label(ov, x + s, y + s, sl_cascade_colours[i], "%d", i);
        }
    }
}

static bool _sl_lab6_takes_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params) {
    (void)r;
    (void)scene;
    return params->lab == 6;
}

/* Lab 6 draws a frame of its own whenever it is asked, whatever the light. */
const sl_technique sl_lab6_technique = {
    .name = "cascades",
    .lab = 6,
    .takes_frame = _sl_lab6_takes_frame,
    .draw_frame = _sl_lab6_draw_frame,
    .overlay_labels = _sl_lab6_overlay_labels,
    .reload_changed = _sl_lab6_reload_changed,
    .program_stats = _sl_lab6_program_stats,
    .destroy = _sl_lab6_destroy,
    .probes = sl_lab6_probes,
    /* the viewer's side: sl_lab6_viewer.c */
    .keys = sl_lab6_keys,
    .key_pressed = sl_lab6_key_pressed,
    .key_state = sl_lab6_key_state,
    .settings_text = sl_lab6_settings_text,
    .maps_text = sl_lab6_maps_text,
    .overlay_lines = sl_lab6_overlay_lines,
    .own_bias = true,
    .frozen_text = "frustum frozen, seen from above (Z)",
    .frozen_lines = sl_lab6_frozen_lines,
    .freeze = sl_lab6_freeze,
    .fit_camera = sl_lab6_fit_camera,
};
