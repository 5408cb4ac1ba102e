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
 * The probe pass and the benchmark walk it too, and the viewer reads the
 * rest from it (the struct's last block): its keys, which the viewer joins
 * to its common ones, and what the title and the overlay say of it; so
 * neither names a lab. How, step by step, with the test technique that
 * keeps it true: docs/adding-a-technique.md.
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

/* ---- The viewer's side of a technique: what its keys, texts and lines are given -------------
 * A technique never sees the viewer's own state: a key or a text gets this context, with what a
 * key may change (the render parameters, the scene's light), what it may read (the frame last
 * drawn, the viewer's frozen frustum and camera path) and where it asks the viewer for more. */
typedef enum sl_view_request {
    SL_VIEW_REQUEST_NONE = 0,
    SL_VIEW_REQUEST_FREEZE,      /* freeze the camera's frustum and look at it from above, or go back */
    SL_VIEW_REQUEST_CAMERA_PATH, /* the next camera path: slide, turn, none */
} sl_view_request;

typedef struct sl_view_context {
    sl_render_params *params;          /* what a key changes */
    sl_scene *scene;                   /* its light (a key may move it) and its name */
    const struct sl_frame_info *info;  /* the frame last drawn; NULL before the first */
    bool frozen;                       /* the viewer's frustum is frozen, seen from above */
    const char *camera_path;           /* the camera's path ("slide", "turn"); NULL: it stays */
    sl_view_request request;           /* set by a key: what the viewer does next */
} sl_view_context;

/* One of a technique's keys: tried before the viewer's common keys when its lab is in use. */
#define SL_TECHNIQUE_KEY_CODES 7
typedef struct sl_technique_key {
    int codes[SL_TECHNIQUE_KEY_CODES]; /* GLFW key codes (letters, digits and [ ] - = , . are their ASCII
                                          codes); 0 ends; of a pair, the second raises */
    const char *names;                 /* the keys as written: "R T", "PgUp PgDn"; NULL ends a list */
    const char *label;                 /* a word or two, for the overlay's key panel */
    const char *help;                  /* a line, for --help, --list-keys and the browser's page */
    int id;                            /* the technique's own number for the key, given to its hooks */
} sl_technique_key;

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
    /* ---- The viewer (sl_viewer_keys.c, sl_viewer_overlay.c): keys and what the overlay and title say ---- */
    const sl_technique_key *keys; /* its own keys, ended by one without names; NULL: none */
    /* Key `k` pressed (`code` of its codes; `raise`: the second of a pair). */
    void (*key_pressed)(sl_view_context *c, const sl_technique_key *k, int code, bool raise);
    /* The setting key `k` changes, as it is now, for the key panel ("" when it has none to show). */
    void (*key_state)(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n);
    /* The viewer's common keys (as written: "C", "[ ]") its key panel lists after its own. */
    const char *panel_keys[6];
    /* Its settings, for the window's title ("VSM: blur 2, bleeding 0.30, ..."). */
    void (*settings_text)(const sl_view_context *c, char *out, size_t n);
    /* What its code draws with these settings, when an asked lab's does not ("lab 2's hard shadows");
     * NULL: "lab N's <name>". */
    void (*drawing_text)(const sl_view_context *c, char *out, size_t n);
    /* Why it is off when a setting turned it off ("switched off with P"); NULL: "switched off". */
    const char *switched_off_text;
    /* The overlay's line on its maps when asked for ("shadow maps: 4 layers of ..."); false: the
     * viewer says the single shadow map's. */
    bool (*maps_text)(const sl_view_context *c, char *out, size_t n);
    /* The overlay's lines on its settings when its code draws the frame. */
    void (*overlay_lines)(struct sl_overlay *ov, const sl_view_context *c);
    /* Its bias is its own: when an earlier lab draws in its stead, the overlay does not say theirs. */
    bool own_bias;
    /* With the viewer's frustum frozen and this lab asked: the overlay's line saying so, and the
     * frozen frustum's lines (lab 6's slices and light boxes); drawn whenever it is frozen. */
    const char *frozen_text;
    void (*frozen_lines)(struct sl_overlay *ov, const sl_view_context *c, int width, int height);
    /* The viewer's frustum frozen on camera `walking` (`on`: what the technique fits is pinned to it and
     * shown, and `view` becomes the camera that looks at it) or thawed (the viewer puts its camera back).
     * Asked of every technique, whichever lab is in use (--freeze comes before the lab is known). */
    void (*freeze)(sl_render_params *p, const sl_camera *walking, bool on, sl_camera *view);
    /* The camera the technique fits its maps to, from now on `camera` (--path-fits-cascades moves it alone,
     * so the picture stays and what changes is what the shadows do); NULL: it fits to none. */
    sl_camera *(*fit_camera)(sl_render_params *p, const sl_camera *camera);
    /* The lights (bit 1 << sl_light_type) of scenes the viewer opens in this lab when none is asked. */
    unsigned default_for_lights;

    /* ---- The benchmark (sl_bench.c): what only the technique can tell of a frame ---- */
    /* Why its last frame (`info`) did not draw the way `params` asked, in a few words into out (lab 7:
     * six passes where one layered pass was asked, the build's lab7_begin_cube_pass has none); out left
     * empty when it did. The benchmark says it after the row, with the stubs and errors it sees itself. */
    void (*frame_shortfall)(const struct sl_frame_info *info, const sl_render_params *params, char *out, size_t n);
} sl_technique;

/* The technique of lab `lab` (1..SL_LAB_COUNT), or the one a build adds in slot 0 (its lab is 0: a
 * program built with sl_labs_program's TECHNIQUE, docs/adding-a-technique.md); NULL otherwise. Whoever
 * walks the table walks 0..SL_LAB_COUNT. */
const sl_technique *sl_technique_of(int lab);
/* The probe of `function` among the technique of lab `lab`'s, NULL if it has none of that name. */
const sl_technique_probe *sl_technique_probe_of(int lab, const char *function);

#endif
