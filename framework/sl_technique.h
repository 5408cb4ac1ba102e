/* sl_technique: each lab's technique as one descriptor, and the table of them.
 *
 * The renderer draws every frame by walking the table: a technique that
 * draws a frame of its own (lab 6's cascades, lab 7's cube map) is asked
 * whether it takes this one; otherwise the renderer's shadow-map pipeline
 * (labs 1-4) draws it, with the passes a technique adds before its camera
 * pass (lab 5's moments) and the texture that camera pass then reads. Hot
 * reload, program counts and clean-up ask every technique in turn. So the
 * renderer names no lab module: a technique is added by writing its module
 * and listing its descriptor in sl_technique.c, or, for a build's own
 * technique, in slot 0 through the build (sl_labs_program's TECHNIQUE).
 * How, step by step, with the test technique that keeps it true:
 * docs/adding-a-technique.md.
 *
 * Every hook may be NULL (the technique has no such step). Which labs a
 * technique builds on is framework/lab_dependencies.cmake's, read through
 * sl_lab_builds_on and sl_lab_shows (sl_params.h). */
#ifndef SL_TECHNIQUE_H
#define SL_TECHNIQUE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_params.h"
#include "sl_scene.h"
#include "shadowlab.h"

struct sl_renderer;
struct sl_program_stats;
struct sl_frame_info;
struct sl_overlay;
struct sl_probe_function;

/* One C function of a technique the probe pass calls (sl_probe_pass.h): one row of its probe table's
 * inputs in (sl_probe.h says their layout), its outputs out; what it returns is the function's status. */
typedef struct sl_technique_probe {
    const char *function; /* as the probe table names it: "lab2_light_view"; NULL ends a list */
    sl_status (*run_row)(const float *inputs, double *outputs);
    /* A technique whose function is not in sl_probe.c's table (one a build adds, slot 0) describes it
     * here; NULL: sl_probe_find(function). */
    const struct sl_probe_function *described;
} sl_technique_probe;

typedef struct sl_technique {
    const char *name; /* what the lab teaches, as the status line says it ("VSM", "cascades") */
    int lab;          /* its lab, 1..SL_LAB_COUNT; 0: the technique a build adds (slot 0) */

    /* A frame of its own: whether it draws this one (it may note in the frame
     * info why it does not, e.g. no point light), and then the whole frame:
     * its depth passes, its camera pass and, with params.show_shadow_map, its
     * debug view, into framebuffer `target`. */
    bool (*takes_frame)(struct sl_renderer *r, const sl_scene *scene, const sl_render_params *params);
    void (*draw_frame)(struct sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                       int width, int height);

    /* Within the renderer's shadow-map frame, when params.lab is this lab:
     * passes drawn before the camera pass (true when what they make is ready),
     * and the texture the camera pass then reads on unit 2 (0: none). */
    bool (*depth_passes)(struct sl_renderer *r, const sl_scene *scene, const sl_render_params *params);
    GLuint (*camera_texture)(const struct sl_renderer *r);
    /* The debug view (params.show_shadow_map) when this lab's code drew the shadow-map frame. */
    void (*debug_view)(struct sl_renderer *r, int width, int height);

    /* The viewer's labels for what its frame shows, drawn when the overlay or --labels is on: lab 6's
     * cascade legend and layer numbers, lab 7's face names on the cross. */
    void (*overlay_labels)(struct sl_overlay *ov, const struct sl_frame_info *info, const sl_render_params *params,
                           int width, int height);

    /* Rebuilds its programs whose files changed (hot reload); false with err set if one failed. */
    bool (*reload_changed)(struct sl_renderer *r, bool *reloaded, char *err, size_t err_size);
    /* Adds its program builds (and their time) and the programs it holds to out. */
    void (*program_stats)(const struct sl_renderer *r, struct sl_program_stats *out);
    /* Frees what its frames made (the renderer's technique_state[lab]). */
    void (*destroy)(struct sl_renderer *r);

    /* ---- Probes: the C functions of this lab the probe pass calls on probe inputs ----
     * A list ended by an entry whose function is NULL; NULL: none. The GLSL functions need no entry: the
     * probe pass draws them in a full-screen pass from their sl_probe.c entry alone. */
    const sl_technique_probe *probes;
} sl_technique;

/* The technique of lab `lab` (1..SL_LAB_COUNT), or the one a build adds in slot 0 (its lab is 0: a
 * program built with sl_labs_program's TECHNIQUE, docs/adding-a-technique.md); NULL otherwise. Whoever
 * walks the table walks 0..SL_LAB_COUNT. */
const sl_technique *sl_technique_of(int lab);
/* The probe of `function` among the technique of lab `lab`'s, NULL if it has none of that name. */
const sl_technique_probe *sl_technique_probe_of(int lab, const char *function);

#endif
