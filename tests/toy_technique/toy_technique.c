#include "toy_technique.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "sl_probe.h"
#include "sl_protocol.h"
#include "sl_renderer.h"
#include "sl_shader.h"

/* A build of the toy with a wrong answer passes -DTOY_VISIBILITY=... */
#ifndef TOY_VISIBILITY
#define TOY_VISIBILITY 0.5f
#endif

sl_status toy_visibility(float *visibility) {
    *visibility = TOY_VISIBILITY;
    return SL_OK;
}

/* What its frames keep (the renderer's technique_state[0]): one program. */
typedef struct _toy_state {
    sl_program program;
    bool built, failed;
} _toy_state;

static bool _toy_takes_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params) {
    return params->lab == 0;
}

static _toy_state *_toy_program(sl_renderer *r) {
    _toy_state *s = r->technique_state[0];
    if (!s && !(s = r->technique_state[0] = calloc(1, sizeof *s))) return NULL;
    if (!s->built && !s->failed) {
        /* Its files: in the grader's sandbox, where the grader copied them (its --technique-dir, as
         * SL_TECHNIQUE_FOLDER of the job's labs tree); elsewhere, where its build put them. */
        char vertex[SL_PATH_MAX + 64], fragment[SL_PATH_MAX + 64];
        snprintf(vertex, sizeof vertex, "%s/" SL_TECHNIQUE_FOLDER "/shaders/toy.vert", r->labs_dir);
        snprintf(fragment, sizeof fragment, "%s/" SL_TECHNIQUE_FOLDER "/shaders/toy.frag", r->labs_dir);
        if (access(vertex, R_OK) != 0) {
            snprintf(vertex, sizeof vertex, "%s", TOY_TECHNIQUE_DIR "/shaders/toy.vert");
            snprintf(fragment, sizeof fragment, "%s", TOY_TECHNIQUE_DIR "/shaders/toy.frag");
        }
        sl_shader_desc desc = {.vertex_path = vertex, .fragment_path = fragment};
        s->built = sl_program_build(&s->program, &desc, r->shader_errors[0], sizeof r->shader_errors[0]);
        s->failed = !s->built;
    }
    if (s->failed) {
        r->info.shader_error = r->shader_errors[0];
        r->info.shader_error_lab = 0;
    }
    return s->built ? s : NULL;
}

/* The whole frame: the scene's objects, each pixel the visibility as grey (as red in its debug view), on
 * black. */
static void _toy_draw_frame(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                            int width, int height) {
    sl_renderer_reset_state(target, width, height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    _toy_state *s = _toy_program(r);
    if (!s) return;
    float visibility = 1;
    sl_renderer_lab_enter("toy_visibility");
    if (!sl_renderer_lab_result(r, "toy_visibility", toy_visibility(&visibility))) visibility = 1;
    mat4 view, projection;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, (float)width / (float)height, projection);
    glUseProgram(s->program.id);
    glUniformMatrix4fv(sl_program_uniform(&s->program, "u_view"), 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(sl_program_uniform(&s->program, "u_projection"), 1, GL_FALSE, (const float *)projection);
    glUniform1f(sl_program_uniform(&s->program, "u_visibility"), visibility);
    glUniform3f(sl_program_uniform(&s->program, "u_tint"), 1, params->show_shadow_map ? 0 : 1,
                params->show_shadow_map ? 0 : 1);
    sl_renderer_draw_objects(r, scene, sl_program_uniform(&s->program, "u_model"), -1, -1);
    r->info.lab_in_use = 0;
}

static void _toy_destroy(sl_renderer *r) {
    _toy_state *s = r->technique_state[0];
    if (!s) return;
    if (s->built) sl_program_destroy(&s->program);
    free(s);
    r->technique_state[0] = NULL;
}

/* Its probe: one row, no input, the visibility out. Not in sl_probe.c's table (that is the course's),
 * so the technique describes the function itself. */
static sl_status _toy_visibility_row(const float *inputs, double *outputs) {
    float visibility = -1;
    sl_status status = toy_visibility(&visibility);
    outputs[0] = visibility;
    return status;
}

static const sl_probe_function _toy_visibility_function = {
    .name = "toy_visibility",
    .lab = 0,
    .file = "tests/toy_technique/toy_technique.c",
    .todo = "lab0.1",
    .outputs = "visibility",
    .output_count = 1,
    .stub_value = 1,
    .stub_param = -1,
};

static const sl_technique_probe _toy_probes[] = {
    {.function = "toy_visibility", .run_row = _toy_visibility_row, .described = &_toy_visibility_function},
    {0},
};

/* Its key: the viewer joins it to its common keys (--help, --list-keys, the key panel) and calls the
 * hooks below when it is pressed in lab 0. Letters are their ASCII codes (GLFW's key codes). */
enum { _TOY_KEY_DEBUG_VIEW = 1 };
static const sl_technique_key _toy_keys[] = {
    {{'T'}, "T", "toy view", "the toy's debug view (its visibility in red) on, off", _TOY_KEY_DEBUG_VIEW},
    {{0}, NULL, NULL, NULL, 0},
};

static void _toy_key_pressed(sl_view_context *c, const sl_technique_key *k, int code, bool raise) {
    if (k->id == _TOY_KEY_DEBUG_VIEW) c->params->show_shadow_map = !c->params->show_shadow_map;
}

static void _toy_key_state(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n) {
    snprintf(out, n, "%s", c->params->show_shadow_map ? "on" : "off");
}

const sl_technique toy_technique = {
    .name = "toy: constant visibility",
    .lab = 0,
    .takes_frame = _toy_takes_frame,
    .draw_frame = _toy_draw_frame,
    .destroy = _toy_destroy,
    .probes = _toy_probes,
    .keys = _toy_keys,
    .key_pressed = _toy_key_pressed,
    .key_state = _toy_key_state,
};
