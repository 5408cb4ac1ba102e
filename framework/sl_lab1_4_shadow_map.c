/* sl_lab1_4_shadow_map: labs 1-4's technique, the shadow-map frame (see sl_renderer.h for its steps), and
 * the camera pass lab 5 draws with its moments. Lab 1's descriptor (sl_lab1_technique, in the table of
 * sl_technique.h) draws every frame no other technique takes; labs 2-4 add their steps to it, and the
 * frame steps down to the highest lab whose code runs. The programs it draws with: sl_lab1_4_programs.c. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_renderer.h"
#include "sl_probe_calls.h"
#include "sl_lab1_4_programs.h"
#include "sl_lab1_4_viewer.h"
#include "sl_technique.h"

/* Calls lab N's function fn through the renderer's table, recording what it returned. */
#define _SL_CALL_LAB(r, N, fn, ...) \
    (sl_renderer_lab_enter(#fn), sl_renderer_lab_result((r), #fn, (r)->fns[N]->fn(__VA_ARGS__)))

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
    /* Lab 1 alone (or lab 2 not done yet): a loose light camera so the depth map can be seen; the one the
     * grader gave in a lab 1 case's job. */
    if (r->light_camera_given) {
        glm_mat4_copy(r->light_camera_view, info->light_view);
        glm_mat4_copy(r->light_camera_projection, info->light_projection);
    } else {
        sl_light_default_matrices(&light, &bounds, info->light_view, info->light_projection);
    }
    glm_mat4_identity(info->shadow_matrix);
}

static void _sl_draw_objects(sl_renderer *r, const sl_scene *scene, const sl_lab1_4_uniforms *u, bool colours) {
    sl_renderer_draw_objects(r, scene, u->model, colours ? u->normal_matrix : -1, colours ? u->albedo : -1);
}

/* Returns the highest lab the depth pass used (0: no map, 1, or 3 with lab 3's state). */
static int _sl_depth_pass_labs(sl_renderer *r, const sl_scene *scene, const sl_render_params *p);

/* Lab 3's extension: the second surface's depths, into a second map made with
 * lab 1's own functions. The depth program is still bound. */
static void _sl_second_depth_pass(sl_renderer *r, const sl_scene *scene, const sl_lab1_4_uniforms *u, int size) {
    if (r->second_map_attempted && r->second_map_status == SL_OK && r->second_map.size != size) {
        sl_renderer_lab_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->second_map);
        r->second_map_attempted = false;
    }
    if (!r->second_map_attempted) {
        memset(&r->second_map, 0, sizeof r->second_map);
        sl_renderer_lab_enter("lab1_create_shadow_map");
        r->second_map_status = r->fns[1]->lab1_create_shadow_map(size, &r->second_map);
        r->second_map_attempted = true;
    }
    if (!sl_renderer_lab_result(r, "lab1_create_shadow_map", r->second_map_status)) return;
    if (!_SL_CALL_LAB(r, 1, lab1_begin_depth_pass, &r->second_map)) return;
    if (!_SL_CALL_LAB(r, 3, lab3_second_depth_state)) return;
    _sl_draw_objects(r, scene, u, false);
    r->info.second_map_ready = true;
    sl_renderer_timer_mark(r, "second depth");
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
        sl_renderer_lab_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->shadow_map);
        r->shadow_map_attempted = false;
    }
    if (!r->shadow_map_attempted) {
        memset(&r->shadow_map, 0, sizeof r->shadow_map);
        sl_renderer_lab_enter("lab1_create_shadow_map");
        r->shadow_map_status = r->fns[1]->lab1_create_shadow_map(size, &r->shadow_map);
        r->shadow_map_attempted = true;
        if (r->shadow_map_status == SL_OK && glIsTexture(r->shadow_map.depth_texture)) {
            glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &r->lab1_min_filter);
            glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &r->lab1_mag_filter);
        }
    }
    info->shadow_map = r->shadow_map; /* even on failure: the grader inspects what was made */
    if (!sl_renderer_lab_result(r, "lab1_create_shadow_map", r->shadow_map_status)) return 0;
    sl_lab1_4_slot *depth = sl_lab1_4_depth_program(r);
    if (!depth) {
        info->shader_error = r->shader_errors[1];
        info->shader_error_lab = 1;
        return 0;
    }
    const sl_lab1_4_uniforms *u = sl_lab1_4_uniforms_of(depth);
    if (!_SL_CALL_LAB(r, 1, lab1_begin_depth_pass, &r->shadow_map)) return 0;
    int used = 1;
    if (p->lab >= 3 && _SL_CALL_LAB(r, 3, lab3_depth_pass_state, &p->bias)) used = 3;
    mat4 view_proj;
    glm_mat4_mul(info->light_projection, info->light_view, view_proj);
    glUseProgram(depth->program.id);
    glUniformMatrix4fv(u->light_view_projection, 1, GL_FALSE, (const float *)view_proj);
    _sl_draw_objects(r, scene, u, false);
    info->shadow_map_ready = true;
    sl_renderer_timer_mark(r, "depth");
    if (used == 3 && p->bias.mode == SL_BIAS_MIDPOINT) _sl_second_depth_pass(r, scene, u, size);
    return used;
}

/* The world size of one shadow-map texel: for a spot light, per unit of distance. */
static float _sl_texel_size(const sl_frame_info *info, const sl_light *light, int map_size) {
    float scale = light->type == SL_LIGHT_DIRECTIONAL ? 2.0f / info->light_projection[0][0]
                                                        : 2.0f * tanf(glm_rad(light->spot_angle_deg));
    return scale / (float)(map_size > 0 ? map_size : 1);
}

/* What lab `lab`'s camera-pass program is compiled for, this frame. */
static sl_lab1_4_variant_key _sl_variant_for(const sl_renderer *r, const sl_scene *scene, const sl_render_params *p,
                                       int lab) {
    bool midpoint = lab == 3 && p->bias.mode == SL_BIAS_MIDPOINT && r->info.second_map_ready;
    sl_lab1_4_variant_key key = {.lab = lab, .light_type = (int)scene->light.type};
    if (lab < 2) return key; /* no shadows: plain.frag */
    key.hardware = lab >= 4 ? lab == 4 && p->filter.mode == SL_FILTER_HARDWARE
                            : p->compare == SL_COMPARE_HARDWARE && !midpoint;
    /* midpoint without its second map (not implemented): lab 2's constant bias instead */
    if (lab >= 3) key.bias_mode = p->bias.mode == SL_BIAS_MIDPOINT && !midpoint ? SL_BIAS_CONSTANT : p->bias.mode;
    if (lab == 4) {
        key.filter_mode = p->filter.mode;
        key.grid_radius = p->filter.mode == SL_FILTER_GRID ? p->filter.grid_radius : 0;
    }
    return key;
}

/* The camera-pass program of the highest lab, at most *lab, that has one: built now, or the
 * last version that compiled (hot reload). A lab's program includes the GLSL of the labs
 * before it, so when one fails, the error names the earliest lab whose GLSL fails. */
static sl_lab1_4_slot *_sl_camera_program(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, int *lab) {
    for (; *lab >= 2; (*lab)--) {
        sl_lab1_4_variant_key key = _sl_variant_for(r, scene, p, *lab);
        sl_lab1_4_slot *slot = sl_lab1_4_variant_program(r, &key);
        if (slot) return slot;
        if (r->info.shader_error) continue;
        int failed = *lab;
        for (int l = 2; l < *lab && failed == *lab; l++) {
            sl_lab1_4_variant_key lower = _sl_variant_for(r, scene, p, l);
            sl_lab1_4_slot *lower_slot = sl_lab1_4_variant_program(r, &lower);
            if (!lower_slot || !lower_slot->compiles) failed = l;
        }
        r->info.shader_error = r->shader_errors[failed];
        r->info.shader_error_lab = failed;
        sl_renderer_note_stop(r, failed);
    }
    return NULL;
}

/* The highest lab up to `lab` with a camera pass of a shadow map (lab 7's
 * cube maps draw their own frame: a later lab on a spot or sun is the labs' before). */
static int _sl_planar_lab(int lab) {
    if (lab > SL_RENDERER_MAX_LAB) lab = SL_RENDERER_MAX_LAB;
    while (lab > 2 && !sl_lab1_4_has_camera_pass(lab)) lab--;
    return lab;
}

/* The camera pass of lab `lab`, whose technique's passes made what it reads (lab 5's moments), can draw
 * this frame: lab 2's matrices are there and its shaders compile. */
static bool _sl_technique_camera_draws(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, int lab) {
    if (!r->info.lab2_ready) return false;
    sl_lab1_4_variant_key key = _sl_variant_for(r, scene, p, lab);
    return sl_lab1_4_variant_program(r, &key) != NULL;
}

/* depth_lab: the highest lab lab 1's depth pass used; technique_lab: the lab whose technique's own passes
 * feed its camera pass this frame (0: none). */
static void _sl_scene_pass(sl_renderer *r, const sl_scene *scene, const sl_render_params *p, int depth_lab,
                           int technique_lab, int width, int height) {
    sl_frame_info *info = &r->info;
    /* The highest lab whose code can run this frame. */
    int lab = 0;
    if (technique_lab) {
        lab = technique_lab; /* VSM reads its moments and lab 2's matrices only: no lab 1 map, no lab 3 state */
    } else if (info->shadow_map_ready && info->lab2_ready) {
        /* labs 6 and 7 draw in their own modules; asked for otherwise (a light they do not cast from), labs 1-4 draw */
        lab = _sl_planar_lab(p->lab > 5 ? 4 : p->lab);
        /* lab 5 without its moments (or VSM switched off): lab 4's filters; with them, its camera
         * pass's shaders do not compile, and _sl_camera_program says so as it steps down */
        if (lab == 5 && !info->moments_ready) {
            lab = 4;
            if (p->vsm_off) sl_renderer_note_off(r, 5, SL_STOP_SWITCHED_OFF);
            else sl_renderer_note_stop(r, 5);
        }
        if (depth_lab < 3 && lab > 2) {
            lab = 2;
            sl_renderer_note_stop(r, 3);
        }
    } else if (p->lab >= 1) { /* no map to look up: lab 1's or lab 2's step stopped */
        if (!info->shadow_map_ready) sl_renderer_note_stop(r, 1);
        if (p->lab >= 2 && !info->lab2_ready) sl_renderer_note_stop(r, 2);
    }
    if (lab == 4) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        if (!_SL_CALL_LAB(r, 4, lab4_configure_shadow_texture, r->shadow_map.depth_texture, p->filter.mode)) {
            lab = 3;
            sl_renderer_note_stop(r, 4);
        }
    } else if (p->lab >= 4 && lab != 5 && !(info->shadow_map_ready && info->lab2_ready)) {
        /* asked anyway, on no texture, to learn whether it is still a stub (see _sl_depth_pass) */
        glBindTexture(GL_TEXTURE_2D, 0);
        _SL_CALL_LAB(r, 4, lab4_configure_shadow_texture, 0, p->filter.mode);
    } else if (info->shadow_map_ready && r->lab1_min_filter) {
        /* lab 4 may have changed the filtering in an earlier frame: back to lab 1's */
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, r->lab1_min_filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, r->lab1_mag_filter);
    }
    sl_lab1_4_slot *slot = lab >= 2 ? _sl_camera_program(r, scene, p, &lab) : NULL;
    if (!slot) {
        sl_lab1_4_variant_key plain = _sl_variant_for(r, scene, p, 0);
        slot = sl_lab1_4_variant_program(r, &plain);
        if (!slot && !info->shader_error) {
            info->shader_error = r->shader_errors[0];
            info->shader_error_lab = 0;
        }
    }
    bool hardware = lab >= 4 ? lab == 4 && p->filter.mode == SL_FILTER_HARDWARE : p->compare == SL_COMPARE_HARDWARE;
    bool midpoint = lab == 3 && p->bias.mode == SL_BIAS_MIDPOINT && info->second_map_ready;
    if (midpoint) hardware = false; /* the midpoint is compared by hand, on two sampler2Ds */
    info->lab_in_use = lab >= 2 ? lab : (info->shadow_map_ready ? 1 : 0);

    /* background: sky; lit in the visibility image; not a lit surface in the mask */
    if (p->output == SL_OUTPUT_SHADED) glClearColor(0.55f, 0.62f, 0.70f, 1);
    else if (p->output == SL_OUTPUT_VISIBILITY) glClearColor(1, 1, 1, 1);
    else glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!slot) return;
    const sl_lab1_4_uniforms *u = sl_lab1_4_uniforms_of(slot);
    glUseProgram(slot->program.id);
    mat4 view, proj;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, height > 0 ? (float)width / (float)height : 1, proj);
    glUniformMatrix4fv(u->view, 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(u->projection, 1, GL_FALSE, (const float *)proj);
    glUniformMatrix4fv(u->shadow_matrix, 1, GL_FALSE, (const float *)info->shadow_matrix);
    const sl_light *l = &scene->light;
    glUniform3fv(u->light_position, 1, l->position);
    glUniform3fv(u->light_direction, 1, l->direction);
    vec3 radiance;
    glm_vec3_scale((float *)l->color, l->intensity, radiance);
    glUniform3fv(u->light_radiance, 1, radiance);
    glUniform1f(u->spot_cos, cosf(glm_rad(l->spot_angle_deg)));
    glUniform1i(u->shadows, lab >= 2 ? 1 : 0);
    glUniform1i(u->output, (int)p->output);
    /* lab 2: constant bias; lab 3: the chosen mode (compiled into the program) */
    glUniform1f(u->depth_bias, p->bias.constant);
    glUniform1i(u->second_map, 1);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, midpoint ? r->second_map.depth_texture : 0);
    if (midpoint) glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glActiveTexture(GL_TEXTURE0);
    glUniform1f(u->slope_bias, p->bias.slope);
    glUniform1f(u->max_bias, p->bias.max_bias);
    glUniform1f(u->normal_offset, p->bias.normal_offset);
    glUniform1f(u->texel_size, _sl_texel_size(info, l, p->shadow_map_size));
    /* lab 4 (the filter and the grid radius are compiled into the program) */
    glUniform1f(u->poisson_radius, p->filter.poisson_radius);
    float near_width = l->type == SL_LIGHT_DIRECTIONAL ? 2.0f / info->light_projection[0][0]
                                                       : 2.0f * l->near * tanf(glm_rad(l->spot_angle_deg));
    glUniform1f(u->light_size_uv, l->size / near_width);
    glUniform1f(u->light_near, l->near);
    glUniform1f(u->light_far, l->far);
    glUniform1i(u->shadow_map, 0);
    /* lab 5: the blurred, mipmapped moments on unit 2 */
    glUniform1i(u->moments, 2);
    glUniform1f(u->min_variance, p->vsm.min_variance);
    glUniform1f(u->bleeding, p->vsm.bleeding);
    glActiveTexture(GL_TEXTURE2);
    const sl_technique *technique = sl_technique_of(lab);
    glBindTexture(GL_TEXTURE_2D, technique && technique->camera_texture ? technique->camera_texture(r) : 0);
    glActiveTexture(GL_TEXTURE0);
    if (lab >= 2) {
        glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
        /* Compare mode is texture state: set it for the sampler type this program declares. */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, hardware ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    } else {
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    _sl_draw_objects(r, scene, u, true);
    sl_renderer_timer_mark(r, "camera");
}

static void _sl_debug_view(sl_renderer *r, const sl_light *light, int width, int height) {
    if (!r->info.shadow_map_ready) return;
    sl_lab1_4_slot *slot = sl_lab1_4_debug_program(r);
    if (!slot) return;
    const sl_lab1_4_uniforms *u = sl_lab1_4_uniforms_of(slot);
    int side = (width < height ? width : height) / 3;
    glViewport(width - side - 8, 8, side, side);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(slot->program.id);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r->shadow_map.depth_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glUniform1i(u->texture, 0);
    glUniform1i(u->perspective, light->type != SL_LIGHT_DIRECTIONAL);
    glUniform1f(u->near, light->near);
    glUniform1f(u->far, light->far);
    glBindVertexArray(r->empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    sl_renderer_timer_mark(r, "debug view");
}

static void _sl_lab1_destroy(sl_renderer *r) {
    if (r->shadow_map_attempted && r->shadow_map_status == SL_OK) {
        sl_renderer_lab_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->shadow_map);
        sl_renderer_lab_enter(NULL);
    }
    if (r->second_map_attempted && r->second_map_status == SL_OK) {
        sl_renderer_lab_enter("lab1_destroy_shadow_map");
        r->fns[1]->lab1_destroy_shadow_map(&r->second_map);
        sl_renderer_lab_enter(NULL);
    }
    sl_lab1_4_programs_destroy(r);
}

/* The shadow-map frame: lab 2's matrices, the passes of the asked lab's technique before its camera pass
 * (lab 5's moments), lab 1's depth pass with lab 3's state, the camera pass of the highest lab that can
 * draw, and the debug view. */
static void _sl_lab1_draw_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                                int width, int height) {
    sl_frame_info *info = &r->info;
    if (!sl_lab1_4_programs_ready(r)) return;
    _sl_light_matrices(r, scene, params);
    sl_renderer_reset_state(0, width, height);
    info->moments_ready = false;
    const sl_technique *asked = sl_technique_of(params->lab);
    bool passes = asked && asked->depth_passes && asked->depth_passes(r, scene, params);
    /* VSM needs neither lab 1's map nor lab 3's depth-pass state: the depth pass runs
     * only for labs 1-4, and for lab 5 when its moments are not there (lab 4 draws instead) */
    int technique_lab = passes && _sl_technique_camera_draws(r, scene, params, params->lab) ? params->lab : 0;
    int depth_lab = 0;
    if (!technique_lab) {
        sl_renderer_reset_state(0, width, height);
        depth_lab = _sl_depth_pass(r, scene, params);
    }
    sl_renderer_reset_state(target, width, height);
    _sl_scene_pass(r, scene, params, depth_lab, technique_lab, width, height);
    const sl_technique *drawn = sl_technique_of(info->lab_in_use);
    if (params->show_shadow_map && drawn && drawn->debug_view) drawn->debug_view(r, width, height);
    else if (params->show_shadow_map) _sl_debug_view(r, &scene->light, width, height);
}

/* Lab 1's technique draws every frame no other technique takes: labs 2-4 add their steps to it. */
const sl_technique sl_lab1_technique = {
    .name = "depth map",
    .lab = 1,
    .draw_frame = _sl_lab1_draw_frame,
    .reload_changed = sl_lab1_4_reload_changed,
    .program_stats = sl_lab1_4_program_stats,
    .destroy = _sl_lab1_destroy,
    .probes = sl_lab1_probes,
    /* the viewer's side: sl_lab1_4_viewer.c (also labs 2-4's descriptors) */
    .settings_text = sl_lab1_settings_text,
    .drawing_text = sl_lab1_drawing_text,
};
