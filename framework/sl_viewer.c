#define _POSIX_C_SOURCE 200809L
#include "sl_viewer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "sl_bench.h"
#include "sl_case_view.h"
#include "sl_context.h"
#include "sl_log.h"
#include "sl_overlay.h"
#include "sl_platform.h"
#include "sl_renderer.h"
#include "sl_serve.h"
#include "sl_technique.h"
#include <cjson/cJSON.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

typedef struct _sl_viewer {
    sl_context *ctx;
    sl_renderer renderer;
    sl_scene scene;
    sl_render_params params;
    bool dragging;
    double last_x, last_y;
    bool dirty_title;
    /* lab 6: the frozen camera's frustum seen from above; the camera to return to */
    bool frozen;
    sl_camera walking_camera;
    double last_frame_time;
    /* Lecture aids: the overlay, the light's frustum, light animation, screenshots on a key. */
    sl_overlay *overlay;
    bool show_overlay, show_frustum, animate_light, screenshot_requested;
    const char *caption; /* --caption: a line at the bottom, overlay or not (figures) */
    const char *frame_dir; /* --frame-dir: every frame saved there (animations for slides) */
    sl_animation *animation; /* --screenshot FILE.gif: every frame into one animated GIF */
    /* --camera-path: the camera moves back and forth by itself (lab 6's shimmer demo). What
     * it added last frame is taken away first, so flying and orbiting still work. */
    int camera_path;       /* _SL_PATH_NONE, _SL_PATH_SLIDE, _SL_PATH_TURN */
    vec3 path_shift;       /* slide: added to the camera's position and target */
    float path_yaw;        /* turn: radians the target is turned about the camera's position */
    bool path_fit_only;    /* --path-fits-cascades: the path moves only the camera lab 6 fits to */
    /* --mark-changes: the first frame, and where a later one differed from it */
    bool mark_changes;
    sl_image first_frame;
    unsigned char *changed;
    const char *keys;      /* --keys: keys pressed before the first frame */
    char status[512];      /* what is drawing instead of the asked lab, as last said ("" when it draws) */
    bool lecture;          /* --lecture: large text, a high-contrast overlay, thick lines, the labels */
    bool labels;           /* --labels: the cascade legend, cube-face labels, the light's marker */
    int text_scale;        /* --text-scale: the overlay's font size; 0: from the frame's size */
    int screenshot_count;
    double pass_ms[SL_MAX_PASSES], frame_ms; /* smoothed, for reading */
    const char *pass_names[SL_MAX_PASSES];
    int pass_count;
    /* Student vs solutions (U key): the second renderer draws with the second lab code. */
    sl_renderer second;
    bool second_ready, show_second;
    sl_serve *serve; /* --serve: frames to a browser, its keys and mouse back */
    unsigned long keys_acted; /* key presses a binding took (--serve's page counts them) */
} _sl_viewer;

enum { _SL_PATH_NONE = 0, _SL_PATH_SLIDE, _SL_PATH_TURN };
static const char *const _sl_path_names[] = {"none", "slide", "turn"};
/* One period of the path: a GIF of --frames K frames loops without a jump. */
#define _SL_PATH_SECONDS 6.0
#define _SL_PATH_SLIDE_METRES 0.25f /* half the sideways travel */
#define _SL_PATH_TURN_DEGREES 3.0f  /* half the turn */


/* What a technique's key or text is given of the viewer (sl_technique.h): `info`, the frame last drawn. */
static sl_view_context _sl_view_context(_sl_viewer *v, const sl_frame_info *info) {
    return (sl_view_context){.params = &v->params, .scene = &v->scene, .info = info, .frozen = v->frozen,
                             .camera_path = v->camera_path ? _sl_path_names[v->camera_path] : NULL};
}

/* The second lab code (sl_viewer_set_second_labs), NULL in builds without one. */
static const sl_lab_functions *_sl_second_functions;
static const char *_sl_second_dir, *_sl_second_kind;

void sl_viewer_set_second_labs(const sl_lab_functions *functions, const char *labs_dir, const char *kind) {
    _sl_second_functions = functions;
    _sl_second_dir = labs_dir;
    _sl_second_kind = kind;
}

/* The offscreen backends of this build, for messages: "osmesa, egl or window". */
static const char *_sl_backend_choices(void) { return sl_backend_choices(); }

static void _sl_print_keys(FILE *f);

static void _sl_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab [options]\n"
            "  --lab N             labs in use: 1 depth map, 2 shadows, 3 bias, 4 filtering, 5 VSM,\n"
            "                      6 cascades, 7 cube maps (a point light); default 7 for a point light, else 4\n"
            "  --scene NAME|FILE   a built-in scene (boxes_on_floor, spot_on_floor, curved_grazing,\n"
            "                      pole_on_floor, thin_caster, long_ground, cascade_field, closed_room,\n"
            "                      stacked_occluders) or a scene\n"
            "                      .json; default boxes_on_floor\n"
            "  --size WxH          window size; default 960x640\n"
            "  --map-size N        shadow map size in texels; default 1024 (lab 7: each cube face, 512)\n"
            "  --compare MODE      manual (sampler2D) or hardware (sampler2DShadow)\n"
            "  --bias X            constant depth bias; default 0.005\n"
            "  --bias-mode MODE    lab 3: none, constant, slope, polygon-offset, front-culling,\n"
            "                      normal-offset, midpoint (the extension); default slope\n"
            "  --filter MODE       lab 4: none, hardware, grid, poisson, pcss; default grid\n"
            "  --kernel R          lab 4: grid radius in texels (1 = 3x3); default 1\n"
            "  --poisson-radius R  lab 4: Poisson disk radius in texels; default 2.5\n"
            "  --light-size S      lab 4: the light's size in world units (PCSS)\n"
            "  --blur R            lab 5: blur radius of the moments in texels; default 2\n"
            "  --bleeding A        lab 5: light-bleeding reduction amount 0..0.99; default 0.3\n"
            "  --min-variance V    lab 5: minimum variance; default 2e-5\n"
            "  --moments-size N    lab 5: the moments maps' size; default 512, 0: --map-size's\n"
            "  --pcf               lab 5: lab 4's filter instead of VSM (key P)\n"
            "  --cascades N        lab 6: cascades, 1..4; default 4\n"
            "  --lambda X          lab 6: the split scheme's weight, 0 uniform .. 1 logarithmic; default 0.8\n"
            "  --show-cascades     lab 6: tint each pixel by the cascade it uses\n"
            "  --blend-band X      lab 6 (bonus): blend the last fraction X of each cascade with the next\n"
            "  --freeze            lab 6: freeze the camera's frustum and look at it, its slices and\n"
            "                      their light boxes from above\n"
            "  --no-snap           lab 6: undo texel snapping (each light box recentred on its sphere): the\n"
            "                      shimmer that snapping removes (key T)\n"
            "  --camera-path PATH  the camera moves back and forth by itself: slide (%.2f m each way) or\n"
            "                      turn (%.0f degrees each way); one period is %.0f s, or --frames K frames\n"
            "  --path-fits-cascades lab 6: the path moves only the camera the cascades are fitted to; the\n"
            "                      picture stays, so what changes is what the shadows do\n"
            "  --mark-changes      with --frames K and --screenshot FILE.png: the first frame, with every\n"
            "                      pixel a later frame changed painted red (shimmer, on paper)\n"
            "  --visibility        show the visibility term alone (what the grader compares)\n"
            "  --show-map          show the shadow map in a corner (lab 7: the six cube faces as a cross)\n"
            "  --soft              lab 7: the soft lookup (20 directions)\n"
            "  --soft-radius R     lab 7: its disk at the far plane, world units; default 0.35\n"
            "  --cube-bias B       lab 7: the lookup's bias, in distance / far; default 0.004 (0.01 soft)\n"
            "  --cube-pass MODE    lab 7: auto, six or layered (auto: layered where the lab does it)\n"
            "  --frames K          render K frames, then exit (for scripts)\n"
            "  --screenshot FILE   save the last frame as PNG (with --frames); FILE.gif: every frame, as\n"
            "                      an animated GIF (10 frames a second, looping)\n"
            "  --headless          render offscreen, with the default headless backend (%s in\n"
            "                      this build)\n"
            "  --backend NAME      offscreen backend: %s (implies --headless; window: a\n"
            "                      hidden window, where there is a display but no headless GL)\n"
            "  --labs-dir DIR      lab sources to load shaders from; default this build's\n"
            "  --overlay           draw the on-screen text (lab, parameters, pass times); the default in a\n"
            "                      window without --frames\n"
            "  --no-overlay        no on-screen text; the default with --frames (screenshots, figures)\n"
            "  --caption TEXT      a line of text at the bottom of the picture, with or without the\n"
            "                      overlay (labels for slide figures)\n"
            "  --text-scale N      the overlay's and caption's font pixel size (1-8); default from the\n"
            "                      frame's size: 1, 2 from 800x480 up, 3 from 1600x1000 up\n"
            "  --frame-dir DIR     save every frame as DIR/001.png, 002.png ... (with --frames: an animation)\n"
            "  --serve PORT        render offscreen and show the viewer in a browser at\n"
            "                      http://127.0.0.1:PORT/ (keys, drags and the wheel work there)\n"
            "  --serve-address A   the address --serve listens on; default 127.0.0.1 (this machine\n"
            "                      only; 0.0.0.0: every network this machine is on)\n"
            "  --keys KEYS         press these keys before the first frame, e.g. --keys 'OG' (overlay,\n"
            "                      frustum) or --keys 'BB]' (letters, digits, [ ] - = , .; not Esc)\n"
            "  --frustum           draw the light's frustum in the scene\n"
            "  --animate           turn the light around the scene (with --frames: a fixed step per frame)\n"
            "  --solutions         start with the solutions' code (builds that have solutions/: key U)\n"
            "  --lecture           for a lecture hall: large text, a high-contrast overlay, thick lines, and\n"
            "                      the labels of --labels\n"
            "  --labels            label what is drawn, with or without the overlay: a legend for the\n"
            "                      cascade colours (lab 6), the cube faces in the cross (lab 7), a marker at\n"
            "                      a spot or point light\n"
            "  --list-keys         print every key as LAB<tab>KEYS<tab>WHAT (LAB: all, 5-7, or case) and exit\n"
            "  --case NAME         render what the grader renders for case NAME (grader/cases/NAME.json),\n"
            "                      beside the reference and their difference (red: a shadow missing,\n"
            "                      blue: one too many), each labelled, with the check's criterion; depth\n"
            "                      and distance images stretched to their own range (printed)\n"
            "  --check NAME        with --case: the check to show first (as the case file names it)\n",
            (double)_SL_PATH_SLIDE_METRES, (double)_SL_PATH_TURN_DEGREES, _SL_PATH_SECONDS, sl_backend_name(sl_backend_default_headless()), _sl_backend_choices());
    _sl_print_keys(f);
    sl_bench_usage(f);
}

static void _sl_update_title(_sl_viewer *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    if (!w) return;
    const sl_frame_info *info = sl_renderer_info(v->show_second ? &v->second : &v->renderer);
    char title[512], settings[512];
    const sl_render_params *p = &v->params;
    const sl_technique *t = sl_technique_of(p->lab);
    sl_view_context c = _sl_view_context(v, info);
    settings[0] = '\0';
    if (t && t->settings_text) t->settings_text(&c, settings, sizeof settings);
    if (v->status[0]) snprintf(settings, sizeof settings, "%s", v->status); /* the asked lab's settings do not draw */
    int n = snprintf(title, sizeof title, "shadowlab — lab %d — %s — %s%s%s%s", p->lab, v->scene.name, settings,
                     p->output == SL_OUTPUT_VISIBILITY ? " — visibility" : "", v->show_second ? " — " : "",
                     v->show_second ? _sl_second_kind : "");
    if (info->not_implemented_count > 0 && n > 0 && (size_t)n < sizeof title)
        snprintf(title + n, sizeof title - (size_t)n, " — not implemented: %s%s", info->not_implemented[0],
                 info->not_implemented_count > 1 ? ", ..." : "");
    glfwSetWindowTitle(w, title);
}

static void _sl_move_light(sl_light *light, float yaw, float pitch) {
    vec3 d;
    glm_vec3_copy(light->direction, d);
    float y = atan2f(d[0], d[2]) + yaw;
    float p = asinf(glm_clamp(d[1], -1, 1)) + pitch;
    p = glm_clamp(p, glm_rad(-89), glm_rad(-5));
    light->direction[0] = cosf(p) * sinf(y);
    light->direction[1] = sinf(p);
    light->direction[2] = cosf(p) * cosf(y);
}

/* Lab 6: freezes the cascades on the current camera and looks at its frustum
 * from above (the slices and their light boxes are drawn as lines), or goes back. */
static void _sl_freeze(_sl_viewer *v, bool on) {
    if (on == v->frozen) return;
    v->frozen = on;
    sl_cascade_params *c = &v->params.cascades;
    if (!on) {
        v->scene.camera = v->walking_camera;
        c->use_camera = c->show_frustum = false;
        return;
    }
    v->walking_camera = v->scene.camera;
    c->camera = v->scene.camera;
    c->use_camera = c->show_frustum = true;
    /* above the middle of the range the cascades cover, a little behind, looking down */
    const sl_camera *w = &v->walking_camera;
    float reach = c->max_distance > w->near && c->max_distance < w->far ? c->max_distance : w->far;
    float d = fminf(reach, 400.0f) * 0.5f;
    vec3 forward;
    glm_vec3_sub((float *)w->target, (float *)w->position, forward);
    forward[1] = 0;
    if (glm_vec3_norm(forward) < 1e-4f) forward[2] = -1;
    glm_vec3_normalize(forward);
    sl_camera *top = &v->scene.camera;
    glm_vec3_copy((float *)w->position, top->target);
    glm_vec3_muladds(forward, d * 0.8f, top->target);
    glm_vec3_copy(top->target, top->position);
    top->position[1] += d * 2.2f;
    glm_vec3_muladds(forward, -d * 0.35f, top->position);
    top->near = 0.5f;
    top->far = d * 6;
}

/* A key held down: in the window, or on the --serve page. */
static bool _sl_held(_sl_viewer *v, GLFWwindow *w, int key) {
    return w ? glfwGetKey(w, key) == GLFW_PRESS : sl_serve_key_down(v->serve, key);
}

/* Lab 6's long scenes: W A S D fly along the view and across it, Q E down and up; Shift is five times faster. */
static void _sl_fly(_sl_viewer *v, GLFWwindow *w, double now) {
    double dt = v->last_frame_time > 0 ? now - v->last_frame_time : 0;
    v->last_frame_time = now;
    if (dt <= 0 || dt > 0.5) return;
    float speed = (float)dt * 8.0f *
                  (_sl_held(v, w, GLFW_KEY_LEFT_SHIFT) || _sl_held(v, w, GLFW_KEY_RIGHT_SHIFT)
                       ? 5.0f : 1.0f);
    sl_camera *cam = &v->scene.camera;
    vec3 forward, right, move = {0, 0, 0};
    glm_vec3_sub(cam->target, cam->position, forward);
    glm_vec3_normalize(forward);
    glm_vec3_cross(forward, (vec3){0, 1, 0}, right);
    glm_vec3_normalize(right);
    if (_sl_held(v, w, GLFW_KEY_W)) glm_vec3_muladds(forward, speed, move);
    if (_sl_held(v, w, GLFW_KEY_S)) glm_vec3_muladds(forward, -speed, move);
    if (_sl_held(v, w, GLFW_KEY_D)) glm_vec3_muladds(right, speed, move);
    if (_sl_held(v, w, GLFW_KEY_A)) glm_vec3_muladds(right, -speed, move);
    if (_sl_held(v, w, GLFW_KEY_E)) move[1] += speed;
    if (_sl_held(v, w, GLFW_KEY_Q)) move[1] -= speed;
    glm_vec3_add(cam->position, move, cam->position);
    glm_vec3_add(cam->target, move, cam->target);
}

/* ---- Keys ---------------------------------------------------------------
 * Every key the viewer handles is one binding of one table, the union of the
 * viewer's common keys and each technique's own (sl_technique.keys): what it
 * does (--help, --list-keys, the --serve page), its short label and the
 * setting it changes now (the overlay's key panel). A lab's own keys are
 * tried before the common ones, so a letter can mean one thing in lab 5 and
 * another in lab 6. */
typedef enum _sl_action {
    _SL_KEY_LAB, _SL_KEY_VISIBILITY, _SL_KEY_MAP, _SL_KEY_COMPARE, _SL_KEY_BIAS, _SL_KEY_BIAS_MODE, _SL_KEY_FILTER,
    _SL_KEY_KERNEL, _SL_KEY_LIGHT, _SL_KEY_OVERLAY, _SL_KEY_FRUSTUM, _SL_KEY_ANIMATE, _SL_KEY_SCREENSHOT,
    _SL_KEY_CODE, _SL_KEY_QUIT,
} _sl_action;

/* The keys of every lab. A technique's key panel lists the ones it names (sl_technique.panel_keys) with its
 * own; the others are the panel's line of general keys. */
static const sl_technique_key _sl_common_keys[] = {
    {{GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4, GLFW_KEY_5, GLFW_KEY_6, GLFW_KEY_7}, "1-7", "lab",
     "the lab in use", _SL_KEY_LAB},
    {{GLFW_KEY_V}, "V", "view", "the visibility term (what the grader compares) or the shaded picture",
     _SL_KEY_VISIBILITY},
    {{GLFW_KEY_M}, "M", "map", "the shadow map in a corner (5: the moments, 6: the layers, 7: the faces)",
     _SL_KEY_MAP},
    {{GLFW_KEY_C}, "C", "compare", "compare by hand (sampler2D) or in hardware (sampler2DShadow)", _SL_KEY_COMPARE},
    {{GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET}, "[ ]", "bias", "the constant depth bias halve, double",
     _SL_KEY_BIAS},
    {{GLFW_KEY_B}, "B", "bias mode", "bias mode: none, constant, slope, polygon offset, culling, normal offset, "
     "midpoint", _SL_KEY_BIAS_MODE},
    {{GLFW_KEY_F}, "F", "filter", "filter: none, hardware 2x2, grid, Poisson, PCSS (lab 5: with VSM off)",
     _SL_KEY_FILTER},
    {{GLFW_KEY_MINUS, GLFW_KEY_EQUAL}, "- =", "kernel", "the filter's kernel radius, Poisson radius or PCSS light "
     "size down, up", _SL_KEY_KERNEL},
    {{GLFW_KEY_LEFT, GLFW_KEY_RIGHT, GLFW_KEY_UP, GLFW_KEY_DOWN}, "arrows", "light",
     "move the light (a point light: along x and z)", _SL_KEY_LIGHT},
    {{GLFW_KEY_O}, "O", "overlay", "the overlay (this text) on, off", _SL_KEY_OVERLAY},
    {{GLFW_KEY_G}, "G", "frustum", "the light's frustum and a marker at the light", _SL_KEY_FRUSTUM},
    {{GLFW_KEY_H}, "H", "turn light", "the light turns about the scene", _SL_KEY_ANIMATE},
    {{GLFW_KEY_X}, "X", "screenshot", "screenshot of the window, overlay included (shadowlab-NNN.png)",
     _SL_KEY_SCREENSHOT},
    {{GLFW_KEY_U}, "U", "code", "student or solutions code (builds that carry both)", _SL_KEY_CODE},
    {{GLFW_KEY_ESCAPE}, "Esc", "quit", "quit", _SL_KEY_QUIT},
    {{0}, NULL, NULL, NULL, 0},
};

/* One binding of the union: a technique's own key (lab N) or a common one (lab 0, no technique). */
typedef struct _sl_key_binding {
    int lab;
    const sl_technique *technique;
    const sl_technique_key *key;
} _sl_key_binding;

#define _SL_MAX_BINDINGS 128
static _sl_key_binding _sl_bindings[_SL_MAX_BINDINGS];
static int _sl_binding_count = -1;

/* The union, made once: each technique's keys, lab by lab, then the common keys. */
static int _sl_key_table(const _sl_key_binding **table) {
    if (_sl_binding_count < 0) {
        int n = 0;
        for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
            const sl_technique *t = sl_technique_of(lab);
            for (const sl_technique_key *k = t ? t->keys : NULL; k && k->names && n < _SL_MAX_BINDINGS; k++)
                _sl_bindings[n++] = (_sl_key_binding){lab, t, k};
        }
        for (const sl_technique_key *k = _sl_common_keys; k->names && n < _SL_MAX_BINDINGS; k++)
            _sl_bindings[n++] = (_sl_key_binding){0, NULL, k};
        _sl_binding_count = n;
    }
    *table = _sl_bindings;
    return _sl_binding_count;
}

/* Whether the common key written `names` is one technique `t`'s panel lists (NULL: any technique's). */
static bool _sl_panel_lists(const sl_technique *t, const char *names) {
    for (int lab = t ? t->lab : 1; lab <= (t ? t->lab : SL_LAB_COUNT); lab++) {
        const sl_technique *u = sl_technique_of(lab);
        for (int i = 0; u && i < (int)(sizeof u->panel_keys / sizeof u->panel_keys[0]) && u->panel_keys[i]; i++)
            if (strcmp(u->panel_keys[i], names) == 0) return true;
    }
    return false;
}

/* A common key of action `action`. */
static bool _sl_is_common(const _sl_key_binding *b, _sl_action action) {
    return !b->technique && b->key->id == (int)action;
}

/* The binding of `key` in lab `lab`: the lab's own first, then the common ones. */
static const _sl_key_binding *_sl_binding(int lab, int key) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < count; i++) {
            const _sl_key_binding *b = &table[i];
            if (b->lab != (pass == 0 ? lab : 0)) continue;
            for (int k = 0; k < SL_TECHNIQUE_KEY_CODES && b->key->codes[k]; k++)
                if (b->key->codes[k] == key) return b;
        }
    return NULL;
}

static const char *_sl_on(bool on) { return on ? "on" : "off"; }

/* What `key` of binding `b` does. */
static void _sl_act(_sl_viewer *v, GLFWwindow *w, const _sl_key_binding *b, int key) {
    sl_render_params *p = &v->params;
    bool up = key == b->key->codes[1]; /* of a pair, the second key raises */
    if (b->technique) {
        sl_view_context c = _sl_view_context(v, sl_renderer_info(v->show_second ? &v->second : &v->renderer));
        if (b->technique->key_pressed) b->technique->key_pressed(&c, b->key, key, up);
        if (c.request == SL_VIEW_REQUEST_FREEZE) _sl_freeze(v, !v->frozen);
        else if (c.request == SL_VIEW_REQUEST_CAMERA_PATH) v->camera_path = (v->camera_path + 1) % 3;
        return;
    }
    switch ((_sl_action)b->key->id) {
    case _SL_KEY_LAB: p->lab = key - GLFW_KEY_0; break;
    case _SL_KEY_VISIBILITY: p->output = p->output == SL_OUTPUT_SHADED ? SL_OUTPUT_VISIBILITY : SL_OUTPUT_SHADED; break;
    case _SL_KEY_MAP: p->show_shadow_map = !p->show_shadow_map; break;
    case _SL_KEY_COMPARE: p->compare = p->compare == SL_COMPARE_MANUAL ? SL_COMPARE_HARDWARE : SL_COMPARE_MANUAL; break;
    case _SL_KEY_BIAS: {
        float *bias = &p->bias.constant;
        *bias = up ? (*bias > 0 ? *bias * 2 : 0.0005f) : *bias * 0.5f;
        break;
    }
    case _SL_KEY_BIAS_MODE: p->bias.mode = (sl_bias_mode)((p->bias.mode + 1) % SL_BIAS_MODE_COUNT); break;
    case _SL_KEY_FILTER: p->filter.mode = (sl_filter_mode)((p->filter.mode + 1) % SL_FILTER_MODE_COUNT); break;
    case _SL_KEY_KERNEL: {
        int step = up ? 1 : -1;
        sl_filter_settings *f = &p->filter;
        if (f->mode == SL_FILTER_GRID) f->grid_radius = f->grid_radius + step < 0 ? 0 : f->grid_radius + step;
        else if (f->mode == SL_FILTER_POISSON) f->poisson_radius = glm_clamp(f->poisson_radius * (up ? 1.25f : 0.8f), 0.5f, 64);
        else if (f->mode == SL_FILTER_PCSS) v->scene.light.size = glm_clamp(v->scene.light.size * (up ? 1.25f : 0.8f), 0.01f, 10);
        break;
    }
    case _SL_KEY_LIGHT:
        if (v->scene.light.type == SL_LIGHT_POINT) {
            /* a point light moves in the room (x, z); PgUp/PgDn move it up and down */
            v->scene.light.position[0] += key == GLFW_KEY_LEFT ? -0.2f : key == GLFW_KEY_RIGHT ? 0.2f : 0;
            v->scene.light.position[2] += key == GLFW_KEY_UP ? -0.2f : key == GLFW_KEY_DOWN ? 0.2f : 0;
        } else {
            _sl_move_light(&v->scene.light, key == GLFW_KEY_LEFT ? -0.05f : key == GLFW_KEY_RIGHT ? 0.05f : 0,
                           key == GLFW_KEY_UP ? 0.05f : key == GLFW_KEY_DOWN ? -0.05f : 0);
        }
        break;
    case _SL_KEY_OVERLAY: v->show_overlay = !v->show_overlay; break;
    case _SL_KEY_FRUSTUM: v->show_frustum = !v->show_frustum; break;
    case _SL_KEY_ANIMATE: v->animate_light = !v->animate_light; break;
    case _SL_KEY_SCREENSHOT: v->screenshot_requested = true; break;
    case _SL_KEY_CODE:
        if (!_sl_second_functions) printf("shadowlab: this build has no second lab code to switch to (U)\n");
        else v->show_second = !v->show_second;
        break;
    case _SL_KEY_QUIT:
        if (w) glfwSetWindowShouldClose(w, GLFW_TRUE);
        break;
    }
}

/* The setting binding `b` changes, as it is now ("" when it has none to show). */
static void _sl_key_state(_sl_viewer *v, const sl_frame_info *info, const _sl_key_binding *b, char *out, size_t n) {
    const sl_render_params *p = &v->params;
    out[0] = '\0';
    if (b->technique) {
        sl_view_context c = _sl_view_context(v, info);
        if (b->technique->key_state) b->technique->key_state(&c, b->key, out, n);
        return;
    }
    switch ((_sl_action)b->key->id) {
    case _SL_KEY_VISIBILITY: snprintf(out, n, "%s", p->output == SL_OUTPUT_VISIBILITY ? "visibility" : "shaded"); break;
    case _SL_KEY_MAP: snprintf(out, n, "%s", _sl_on(p->show_shadow_map)); break;
    case _SL_KEY_COMPARE: snprintf(out, n, "%s", p->compare == SL_COMPARE_HARDWARE ? "hardware" : "manual"); break;
    case _SL_KEY_BIAS: snprintf(out, n, "%.5f", p->bias.constant); break;
    case _SL_KEY_BIAS_MODE: snprintf(out, n, "%s", sl_bias_mode_name(p->bias.mode)); break;
    case _SL_KEY_FILTER: snprintf(out, n, "%s", sl_filter_mode_name(p->filter.mode)); break;
    case _SL_KEY_KERNEL:
        if (p->filter.mode == SL_FILTER_GRID)
            snprintf(out, n, "%dx%d", 2 * p->filter.grid_radius + 1, 2 * p->filter.grid_radius + 1);
        else if (p->filter.mode == SL_FILTER_POISSON) snprintf(out, n, "radius %.1f", p->filter.poisson_radius);
        else if (p->filter.mode == SL_FILTER_PCSS) snprintf(out, n, "light %.2f", v->scene.light.size);
        else snprintf(out, n, "-");
        break;
    case _SL_KEY_FRUSTUM: snprintf(out, n, "%s", _sl_on(v->show_frustum)); break;
    case _SL_KEY_ANIMATE: snprintf(out, n, "%s", _sl_on(v->animate_light)); break;
    case _SL_KEY_CODE: snprintf(out, n, "%s", v->show_second ? _sl_second_kind : sl_build_labs_kind); break;
    default: break;
    }
}

/* The viewer --keys presses keys for, with no window (w NULL) or before the first frame. */
static _sl_viewer *_sl_keys_viewer;

static void _sl_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    if (action == GLFW_RELEASE) return;
    _sl_viewer *v = w ? glfwGetWindowUserPointer(w) : _sl_keys_viewer;
    const _sl_key_binding *b = _sl_binding(v->params.lab, key);
    if (!b) return;
    _sl_act(v, w, b, key);
    v->keys_acted++;
    v->dirty_title = true;
}

/* --help's keys, from the table: every lab's, then each lab's own, then --case's. */
static void _sl_print_keys(FILE *f) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    fprintf(f, "keys (a lab's own keys come first: a letter can mean one thing in lab 5, another in lab 6):\n");
    for (int lab = 0; lab <= SL_LAB_COUNT; lab++) {
        bool any = false;
        for (int i = 0; i < count; i++) {
            const _sl_key_binding *b = &table[i];
            if (b->lab != lab) continue;
            if (!any) {
                if (lab == 0) fprintf(f, "  every lab:\n");
                else fprintf(f, "  lab %d (%s):\n", lab, sl_lab_title(lab));
                any = true;
            }
            fprintf(f, "    %-12s %s\n", b->key->names, b->key->help);
        }
    }
    fprintf(f, "  mouse: drag orbits the camera, the wheel zooms; shaders reload when their files change\n"
               "  with --case:\n");
    for (const sl_case_view_key *k = sl_case_view_keys(); k->names; k++) fprintf(f, "    %-12s %s\n", k->names, k->help);
}

/* --list-keys: the same, one key binding a line, for scripts (the slides' key test). */
static void _sl_list_keys(FILE *f) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    for (int i = 0; i < count; i++) {
        const _sl_key_binding *b = &table[i];
        if (b->lab == 0) fprintf(f, "all\t%s\t%s\n", b->key->names, b->key->help);
        else fprintf(f, "%d\t%s\t%s\n", b->lab, b->key->names, b->key->help);
    }
    for (const sl_case_view_key *k = sl_case_view_keys(); k->names; k++) fprintf(f, "case\t%s\t%s\n", k->names, k->help);
}

/* --serve's key table for the page (framework/serve/index.html): every
 * binding but Esc (a page is closed in the browser) with its keys' browser
 * codes and GLFW codes, and the keys only held (Shift, for lab 6's flying).
 * The page takes these keys and no others, so it has exactly the window's. */
static char *_sl_keys_json(void) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    cJSON *root = cJSON_CreateObject(), *keys = cJSON_AddArrayToObject(root, "keys");
    char code[16];
    for (int i = 0; i < count; i++) {
        const _sl_key_binding *b = &table[i];
        if (_sl_is_common(b, _SL_KEY_QUIT)) continue;
        cJSON *k = cJSON_CreateObject();
        cJSON_AddNumberToObject(k, "lab", b->lab);
        cJSON_AddStringToObject(k, "names", b->key->names);
        cJSON_AddStringToObject(k, "label", b->key->label);
        cJSON_AddStringToObject(k, "help", b->key->help);
        cJSON *codes = cJSON_AddArrayToObject(k, "codes");
        for (int j = 0; j < SL_TECHNIQUE_KEY_CODES && b->key->codes[j]; j++) {
            cJSON *c = cJSON_CreateObject();
            cJSON_AddStringToObject(c, "code", sl_serve_key_code(b->key->codes[j], code));
            cJSON_AddNumberToObject(c, "key", b->key->codes[j]);
            cJSON_AddItemToArray(codes, c);
        }
        cJSON_AddItemToArray(keys, k);
    }
    cJSON *held = cJSON_AddArrayToObject(root, "held");
    const int held_keys[] = {GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT};
    for (int j = 0; j < 2; j++) {
        cJSON *c = cJSON_CreateObject();
        cJSON_AddStringToObject(c, "code", sl_serve_key_code(held_keys[j], code));
        cJSON_AddNumberToObject(c, "key", held_keys[j]);
        cJSON_AddItemToArray(held, c);
    }
    char *json = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return json;
}

static void _sl_mouse_button(GLFWwindow *w, int button, int action, int mods) {
    (void)mods;
    _sl_viewer *v = w ? glfwGetWindowUserPointer(w) : _sl_keys_viewer;
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
        v->dragging = action == GLFW_PRESS;
        if (w) glfwGetCursorPos(w, &v->last_x, &v->last_y); /* the page sets them itself */
    }
}

static void _sl_cursor(GLFWwindow *w, double x, double y) {
    _sl_viewer *v = w ? glfwGetWindowUserPointer(w) : _sl_keys_viewer;
    if (!v->dragging) return;
    sl_camera_orbit(&v->scene.camera, (float)(v->last_x - x) * 0.01f, (float)(y - v->last_y) * 0.01f, 1);
    v->last_x = x;
    v->last_y = y;
}

static void _sl_scroll(GLFWwindow *w, double dx, double dy) {
    (void)dx;
    _sl_viewer *v = w ? glfwGetWindowUserPointer(w) : _sl_keys_viewer;
    sl_camera_orbit(&v->scene.camera, 0, 0, powf(0.9f, (float)dy));
}

/* The --serve page's keys, button, pointer and wheel, into the handlers a
 * window's events reach (no window: they find the viewer as --keys does). */
static void _sl_serve_events(_sl_viewer *v) {
    sl_serve_event events[64];
    int n = sl_serve_poll(v->serve, events, 64);
    for (int i = 0; i < n; i++) {
        const sl_serve_event *e = &events[i];
        switch (e->kind) {
        case SL_SERVE_KEY_DOWN:
            /* Esc would close a window; a page is closed in the browser, the server with Ctrl-C */
            if (e->key != GLFW_KEY_ESCAPE) _sl_key(NULL, e->key, 0, GLFW_PRESS, 0);
            break;
        case SL_SERVE_KEY_UP: break; /* held keys are polled (sl_serve_key_down) */
        case SL_SERVE_BUTTON_DOWN:
        case SL_SERVE_BUTTON_UP:
            v->last_x = e->x;
            v->last_y = e->y;
            _sl_mouse_button(NULL, GLFW_MOUSE_BUTTON_LEFT, e->kind == SL_SERVE_BUTTON_DOWN ? GLFW_PRESS : GLFW_RELEASE, 0);
            break;
        case SL_SERVE_MOVE: _sl_cursor(NULL, e->x, e->y); break;
        case SL_SERVE_WHEEL: _sl_scroll(NULL, 0, e->y); break;
        }
    }
}

/* Turns the light about the vertical axis: a sun's direction; a spot or point
 * light's position about the point it aims at on the ground, so it keeps
 * lighting the same place. */
static void _sl_animate_light(sl_light *l, float angle) {
    vec3 target;
    if (l->type != SL_LIGHT_DIRECTIONAL) {
        float t = l->direction[1] < -0.05f ? -l->position[1] / l->direction[1] : 1.0f;
        glm_vec3_copy(l->position, target);
        glm_vec3_muladds(l->direction, t, target);
        vec3 offset;
        glm_vec3_sub(l->position, target, offset);
        glm_vec3_rotate(offset, angle, (vec3){0, 1, 0});
        glm_vec3_add(target, offset, l->position);
    }
    glm_vec3_rotate(l->direction, angle, (vec3){0, 1, 0});
}

/* Pass times read off the GL's timer queries, smoothed so they can be read
 * (and not smoothed with --frames, where each frame stands alone). */
static void _sl_update_timing(_sl_viewer *v, sl_renderer *r, double frame_seconds, bool smooth) {
    sl_frame_timing t;
    if (!sl_renderer_frame_timing(r, &t)) return;
    bool same = t.pass_count == v->pass_count;
    for (int i = 0; same && i < t.pass_count; i++) same = strcmp(t.passes[i].name, v->pass_names[i]) == 0;
    double k = smooth && same ? 0.1 : 1.0;
    for (int i = 0; i < t.pass_count; i++) {
        v->pass_names[i] = t.passes[i].name;
        v->pass_ms[i] = same ? v->pass_ms[i] + k * (t.passes[i].ms - v->pass_ms[i]) : t.passes[i].ms;
    }
    v->pass_count = t.pass_count;
    if (frame_seconds > 0) v->frame_ms = v->frame_ms > 0 ? v->frame_ms + 0.1 * (frame_seconds * 1e3 - v->frame_ms)
                                                         : frame_seconds * 1e3;
}

/* ---- What is drawing ------------------------------------------------------ */

/* Each lab's technique, as the status line names it ("lab 5 VSM is off"): the table's name. */
static const char *_sl_technique_name(int lab) {
    const sl_technique *t = sl_technique_of(lab);
    return t ? t->name : "?";
}

/* What lab `lab`'s code draws with these settings: "lab 2's hard shadows". */
static void _sl_drawing(_sl_viewer *v, const sl_frame_info *info, int lab, char *out, size_t n) {
    const sl_technique *t = sl_technique_of(lab);
    sl_view_context c = _sl_view_context(v, info);
    if (!t) snprintf(out, n, "no shadows");
    else if (t->drawing_text) t->drawing_text(&c, out, n);
    else snprintf(out, n, "lab %d's %s", lab, t->name);
}

/* One reason the renderer noted: "lab 3's depth_pass_state is not implemented". */
static void _sl_stop_text(const _sl_viewer *v, const sl_frame_stop *s, char *out, size_t n) {
    char prefix[16];
    snprintf(prefix, sizeof prefix, "lab%d_", s->lab);
    const char *fn = s->function ? s->function : "?";
    if (strncmp(fn, prefix, strlen(prefix)) == 0) fn += strlen(prefix);
    switch (s->reason) {
    case SL_STOP_NOT_IMPLEMENTED: snprintf(out, n, "lab %d's %s is not implemented", s->lab, fn); break;
    case SL_STOP_FAILED: snprintf(out, n, "lab %d's %s failed", s->lab, fn); break;
    case SL_STOP_SHADERS: snprintf(out, n, "lab %d's shaders do not compile", s->lab); break;
    case SL_STOP_SWITCHED_OFF: {
        const sl_technique *t = sl_technique_of(s->lab);
        snprintf(out, n, "%s", t && t->switched_off_text ? t->switched_off_text : "switched off");
        break;
    }
    case SL_STOP_NO_POINT_LIGHT: snprintf(out, n, "%s has no point light (closed_room has one)", v->scene.name); break;
    }
}

/* Why the asked lab's technique is not what draws, from what the renderer noted this frame, and what
 * draws instead: "lab 5 VSM is off: lab 3's depth_pass_state is not implemented; drawing lab 2's hard
 * shadows". Empty when it draws. */
static void _sl_status(_sl_viewer *v, const sl_frame_info *info, char *out, size_t n) {
    out[0] = '\0';
    if (info->stop_count == 0) return;
    int lab = info->lab_asked;
    size_t used = (size_t)snprintf(out, n, "lab %d %s is off: ", lab,
                                   _sl_technique_name(lab));
    for (int i = 0; i < info->stop_count && used < n; i++) {
        char why[160];
        _sl_stop_text(v, &info->stops[i], why, sizeof why);
        used += (size_t)snprintf(out + used, n - used, "%s%s", i == 0 ? "" : ", and ", why);
    }
    char drawing[96];
    _sl_drawing(v, info, info->lab_in_use, drawing, sizeof drawing);
    if (used < n) snprintf(out + used, n - used, "; drawing %s", drawing);
}

/* Text in lines of at most `width` characters, broken after "; " or ", " or at spaces. */
static void _sl_wrapped(sl_overlay *ov, const float *rgb, const char *text, int width) {
    const char *rest = text;
    while (*rest) {
        int len = (int)strlen(rest);
        if (len <= width) {
            sl_overlay_line(ov, rgb, "%s", rest);
            return;
        }
        int cut = -1;
        for (int i = width; i > width / 3 && cut < 0; i--)
            if (rest[i] == ' ' && (rest[i - 1] == ';' || rest[i - 1] == ',')) cut = i;
        for (int i = width; i > 0 && cut < 0; i--)
            if (rest[i] == ' ') cut = i;
        if (cut < 0) cut = width;
        sl_overlay_line(ov, rgb, "%.*s", cut, rest);
        rest += cut;
        while (*rest == ' ') rest++;
    }
}

/* ---- The overlay -------------------------------------------------------- */

static const float _sl_red[3] = {1.0f, 0.45f, 0.4f}, _sl_green[3] = {0.55f, 0.95f, 0.55f},
                   _sl_blue[3] = {0.55f, 0.75f, 1.0f}, _sl_frustum_rgb[3] = {1.0f, 0.85f, 0.2f},
                   _sl_orange[3] = {1.0f, 0.7f, 0.3f};

/* The light's frustum: the clip-space cube taken back to the world by the
 * inverse of the matrices the frame used (lab 2's, or the framework's for lab 1). */
static void _sl_add_frustum(sl_overlay *ov, const sl_frame_info *info) {
    if (info->cube_frame) return; /* a point light has no one frustum: its marker shows where it is */
    mat4 vp, inv;
    glm_mat4_mul((vec4 *)info->light_projection, (vec4 *)info->light_view, vp);
    glm_mat4_inv(vp, inv);
    sl_overlay_box(ov, inv, _sl_frustum_rgb);
}

/* The key panel (bottom left): the lab's own keys and the common keys that
 * matter in it, one a line with what they set now; then the general keys. */
static void _sl_key_panel(_sl_viewer *v, const sl_frame_info *info) {
    sl_overlay *ov = v->overlay;
    int lab = v->params.lab;
    const sl_technique *t = sl_technique_of(lab);
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    char title[32];
    snprintf(title, sizeof title, "keys, lab %d", lab);
    sl_overlay_panel(ov, SL_OVERLAY_BOTTOM_LEFT, title);
    int pad = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < count; i++) {
            const _sl_key_binding *b = &table[i];
            bool listed = b->lab == lab || (b->lab == 0 && t && _sl_panel_lists(t, b->key->names));
            /* a common key the lab's own keys take over is not this lab's */
            if (!listed || _sl_binding(lab, b->key->codes[0]) != b) continue;
            if (pass == 0) { /* names aligned, but a long one ("W A S D Q E") does not push the others */
                int len = (int)strlen(b->key->names);
                if (len > pad && len <= 5) pad = len;
                continue;
            }
            char state[64];
            _sl_key_state(v, info, b, state, sizeof state);
            sl_overlay_line(ov, NULL, "%-*s %s%s%s", pad, b->key->names, b->key->label, state[0] ? ": " : "", state);
        }
    /* the general keys, as many to a line as fit in 60 characters (40 in a lecture's larger text, so the
     * panel leaves room beside it for the right-hand ones) */
    size_t width = v->lecture ? 40 : 60;
    char line[128] = "";
    for (int i = 0; i < count; i++) {
        const _sl_key_binding *b = &table[i];
        if (b->lab != 0 || _sl_panel_lists(NULL, b->key->names) || _sl_binding(lab, b->key->codes[0]) != b) continue;
        if (_sl_is_common(b, _SL_KEY_CODE) && !_sl_second_functions) continue;
        if (_sl_is_common(b, _SL_KEY_QUIT) && v->serve) continue; /* a page is closed in the browser */
        char state[64], item[128];
        _sl_key_state(v, info, b, state, sizeof state);
        snprintf(item, sizeof item, "%s %s%s%s", b->key->names, b->key->label, state[0] ? ": " : "", state);
        if (line[0] && strlen(line) + 2 + strlen(item) > width) {
            sl_overlay_line(ov, _sl_blue, "%s", line);
            line[0] = '\0';
        }
        snprintf(line + strlen(line), sizeof line - strlen(line), "%s%s", line[0] ? "  " : "", item);
    }
    if (line[0]) sl_overlay_line(ov, _sl_blue, "%s", line);
}

/* The labels of what is drawn (with the overlay or --labels): the cascade
 * colours' legend, the cube faces' names in the cross, the light's marker;
 * the frozen cascades' slices and light boxes as lines the overlay's width. */
static void _sl_labels(_sl_viewer *v, const sl_frame_info *info, int width, int height, bool labels) {
    sl_overlay *ov = v->overlay;
    const sl_render_params *p = &v->params;
    const sl_technique *t = sl_technique_of(p->lab);
    if (labels && t && t->overlay_labels) t->overlay_labels(ov, info, p, width, height);
    if (v->frozen && t && t->frozen_lines) {
        sl_view_context c = _sl_view_context(v, info);
        t->frozen_lines(ov, &c, width, height);
    }
    const sl_light *l = &v->scene.light;
    if ((labels || v->show_frustum) && l->type != SL_LIGHT_DIRECTIONAL)
        sl_overlay_marker(ov, l->position, _sl_frustum_rgb, l->type == SL_LIGHT_POINT ? "point light" : "spot light");
}

/* What the overlay says: the lab and what really draws with its parameters
 * (top left), the pass times (top right), the keys (bottom left, in a window). */
static void _sl_overlay_fill(_sl_viewer *v, const sl_renderer *r, int width, int height, bool windowed) {
    sl_overlay *ov = v->overlay;
    const sl_render_params *p = &v->params;
    const sl_light *l = &v->scene.light;
    const sl_frame_info *info = sl_renderer_info(r);
    int drawn = info->lab_in_use;
    char title[96];
    snprintf(title, sizeof title, "lab %d: %s", p->lab, sl_lab_title(p->lab));
    sl_overlay_panel(ov, SL_OVERLAY_TOP_LEFT, title);
    sl_overlay_line(ov, NULL, "scene: %s  %dx%d", v->scene.name, width, height);
    if (_sl_second_functions)
        sl_overlay_line(ov, v->show_second ? _sl_green : _sl_blue, "code: %s (U: %s)",
                        v->show_second ? _sl_second_kind : sl_build_labs_kind,
                        v->show_second ? sl_build_labs_kind : _sl_second_kind);
    else
        sl_overlay_line(ov, NULL, "code: %s", sl_build_labs_kind);
    char status[512];
    _sl_status(v, info, status, sizeof status);
    char *drawing = strstr(status, "; drawing ");
    if (drawing) { /* the reason, then what draws, each on lines of their own */
        *drawing = '\0';
        _sl_wrapped(ov, _sl_orange, status, 72);
        _sl_wrapped(ov, _sl_orange, drawing + 2, 72);
    }
    static const char *const light_types[] = {"directional", "spot", "point"};
    sl_overlay_line(ov, NULL, "light: %s, size %.2f%s", light_types[l->type % 3], l->size,
                    v->animate_light ? ", turning" : "");
    /* the settings of what draws (a lab that is off is said above): the asked lab's maps, then the
     * settings of the lab whose code drew */
    const sl_technique *asked = sl_technique_of(p->lab), *drawing_technique = sl_technique_of(drawn);
    sl_view_context c = _sl_view_context(v, info);
    char maps[128];
    if (!asked || !asked->maps_text || !asked->maps_text(&c, maps, sizeof maps))
        snprintf(maps, sizeof maps, "shadow map: %dx%d", p->shadow_map_size, p->shadow_map_size);
    sl_overlay_line(ov, NULL, "%s", maps);
    if (drawing_technique && drawing_technique->overlay_lines) drawing_technique->overlay_lines(ov, &c);
    if (v->frozen && asked && asked->frozen_text) sl_overlay_line(ov, _sl_blue, "%s", asked->frozen_text);
    if (p->output == SL_OUTPUT_VISIBILITY) sl_overlay_line(ov, NULL, "view: visibility term");
    for (int i = 0; i < info->not_implemented_count; i++)
        sl_overlay_line(ov, _sl_red, "not implemented: %s()", info->not_implemented[i]);
    if (info->shader_error) sl_overlay_line(ov, _sl_red, "lab %d's shaders do not compile", info->shader_error_lab);

    if (v->pass_count > 0 || v->frame_ms > 0) {
        const char *gpu = sl_context_renderer_name();
        bool software = strstr(gpu, "llvmpipe") || strstr(gpu, "softpipe");
        sl_overlay_panel(ov, SL_OVERLAY_TOP_RIGHT, software ? "pass times (ms): CPU" : "pass times (ms): GPU");
        double total = 0;
        for (int i = 0; i < v->pass_count; i++) {
            sl_overlay_line(ov, NULL, "%-12s %7.2f", v->pass_names[i], v->pass_ms[i]);
            total += v->pass_ms[i];
        }
        sl_overlay_line(ov, NULL, "%-12s %7.2f", "all passes", total);
        if (v->frame_ms > 0) sl_overlay_line(ov, NULL, "%-12s %7.2f", "frame", v->frame_ms);
        /* On Mesa's software rasteriser a GL timestamp is taken when its
         * threads reach it: the times are CPU time, not a GPU's. */
        if (software) sl_overlay_line(ov, _sl_blue, "llvmpipe: rasteriser CPU time");
    }
    if (windowed) _sl_key_panel(v, info);
}

static void _sl_camera_turn(sl_camera *cam, float yaw) {
    vec3 look;
    glm_vec3_sub(cam->target, cam->position, look);
    glm_vec3_rotate(look, yaw, (vec3){0, 1, 0});
    glm_vec3_add(cam->position, look, cam->target);
}

/* Moves `cam` to where the path is at `phase` (0..1, one period); what it added goes to shift and yaw. */
static void _sl_path_step(int path, double phase, sl_camera *cam, vec3 shift, float *yaw) {
    glm_vec3_zero(shift);
    *yaw = 0;
    float s = (float)sin(2 * GLM_PI * phase);
    if (path == _SL_PATH_SLIDE) {
        vec3 forward, right;
        glm_vec3_sub(cam->target, cam->position, forward);
        glm_vec3_cross(forward, (vec3){0, 1, 0}, right);
        if (glm_vec3_norm(right) < 1e-6f) glm_vec3_copy((vec3){1, 0, 0}, right);
        glm_vec3_normalize(right);
        glm_vec3_scale(right, s * _SL_PATH_SLIDE_METRES, shift);
        glm_vec3_add(cam->position, shift, cam->position);
        glm_vec3_add(cam->target, shift, cam->target);
    } else if (path == _SL_PATH_TURN) {
        *yaw = glm_rad(_SL_PATH_TURN_DEGREES) * s;
        _sl_camera_turn(cam, *yaw);
    }
}

/* The camera path of this frame. With path_fit_only (lab 6) the picture's
 * camera stays and only the camera the cascades are fitted to moves, so what
 * changes in the picture is what the shadows do (as the grader's flicker check
 * sees it); otherwise the camera itself moves: last frame's step is taken back
 * first, so flying and orbiting still work. */
static void _sl_camera_path(_sl_viewer *v, double phase) {
    sl_cascade_params *c = &v->params.cascades;
    if (v->path_fit_only && !v->frozen) {
        vec3 shift;
        float yaw;
        c->camera = v->scene.camera;
        c->use_camera = true;
        _sl_path_step(v->camera_path, phase, &c->camera, shift, &yaw);
        return;
    }
    sl_camera *cam = &v->scene.camera;
    glm_vec3_sub(cam->position, v->path_shift, cam->position);
    glm_vec3_sub(cam->target, v->path_shift, cam->target);
    _sl_camera_turn(cam, -v->path_yaw);
    _sl_path_step(v->camera_path, phase, cam, v->path_shift, &v->path_yaw);
}

static void _sl_camera_view_projection(const sl_scene *scene, int width, int height, mat4 out) {
    mat4 view, proj;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, height > 0 ? (float)width / (float)height : 1, proj);
    glm_mat4_mul(proj, view, out);
}

/* --screenshot FILE.gif: every frame goes into the animation. */
static bool _sl_is_gif(const char *path) {
    size_t n = path ? strlen(path) : 0;
    return n > 4 && strcasecmp(path + n - 4, ".gif") == 0;
}

static bool _sl_add_frame(_sl_viewer *v, GLuint target, int width, int height, const char *path) {
    char err[1024] = "";
    sl_image shot = {0};
    glFinish();
    if (!v->animation) v->animation = sl_animation_open(path, 10, err, sizeof err);
    bool ok = v->animation && sl_capture_framebuffer(target, width, height, 3, &shot) &&
              sl_animation_add(v->animation, &shot, err, sizeof err);
    if (!ok) fprintf(stderr, "shadowlab: cannot save the animation: %s\n", err[0] ? err : "cannot read the frame");
    sl_image_free(&shot);
    return ok;
}

/* --mark-changes: remembers the first frame, then marks every pixel a later frame
 * differs on (more than 0.1 summed over R, G, B: a shadow edge that moved, not
 * noise). False if a frame cannot be read or has another size. */
static bool _sl_mark_changes(_sl_viewer *v, GLuint target, int width, int height) {
    sl_image frame;
    glFinish();
    if (!sl_capture_framebuffer(target, width, height, 3, &frame)) return false;
    if (!v->first_frame.data) {
        v->first_frame = frame;
        v->changed = calloc((size_t)width * (size_t)height, 1);
        return v->changed != NULL;
    }
    bool same_size = frame.width == v->first_frame.width && frame.height == v->first_frame.height;
    for (size_t i = 0; same_size && i < (size_t)width * (size_t)height; i++) {
        float d = 0;
        for (int c = 0; c < 3; c++) d += fabsf(frame.data[i * 3 + c] - v->first_frame.data[i * 3 + c]);
        if (d > 0.1f) v->changed[i] = 1;
    }
    sl_image_free(&frame);
    return same_size;
}

/* Puts an image (top-down RGB floats, the frame's size) into framebuffer `target`. */
static void _sl_show_image(const sl_image *img, GLuint target) {
    sl_image flipped = sl_image_alloc(img->width, img->height, 3);
    if (!flipped.data) return;
    memcpy(flipped.data, img->data, sizeof(float) * 3 * (size_t)img->width * (size_t)img->height);
    sl_image_flip_rows(&flipped);
    GLuint texture, fbo;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, img->width, img->height, 0, GL_RGB, GL_FLOAT, flipped.data);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, img->width, img->height, 0, 0, img->width, img->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, 0);
    sl_image_free(&flipped);
}

/* The first frame with the pixels that changed painted red, into `path`; with
 * the overlay, the last frame's overlay drawn over it (the marks are the
 * scene's, never the overlay's changing text). */
static bool _sl_save_changes(_sl_viewer *v, const char *path, int frames, bool overlay, mat4 camera, GLuint target) {
    char err[1024] = "";
    sl_image *img = &v->first_frame;
    size_t count = 0, n = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < n; i++)
        if (v->changed[i]) {
            img->data[i * 3] = 1, img->data[i * 3 + 1] = 0.05f, img->data[i * 3 + 2] = 0.05f;
            count++;
        }
    if (overlay && v->overlay) {
        _sl_show_image(img, target);
        sl_overlay_draw(v->overlay, camera, target, img->width, img->height);
        sl_image shot;
        glFinish();
        if (sl_capture_framebuffer(target, img->width, img->height, 3, &shot)) {
            sl_image_free(img);
            *img = shot;
        }
    }
    bool ok = sl_image_write(path, img, err, sizeof err);
    if (ok) printf("shadowlab: saved %s: %zu pixels (%.3f%%) changed over %d frames, in red\n", path, count,
                   n ? 100.0 * (double)count / (double)n : 0.0, frames);
    else fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
    return ok;
}

static bool _sl_save(GLuint target, int width, int height, const char *path) {
    sl_image shot;
    char err[1024] = "";
    glFinish();
    bool ok = sl_capture_framebuffer(target, width, height, 3, &shot) && sl_image_write(path, &shot, err, sizeof err);
    if (ok) printf("shadowlab: saved %s (%dx%d)\n", path, width, height);
    else fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
    sl_image_free(&shot);
    return ok;
}

/* The S key: shadowlab-001.png, -002 ... in the current folder, never overwriting. */
static void _sl_screenshot_key(_sl_viewer *v, GLuint target, int width, int height) {
    char path[64];
    for (int tries = 0; tries < 1000; tries++) {
        snprintf(path, sizeof path, "shadowlab-%03d.png", ++v->screenshot_count);
        FILE *f = fopen(path, "r");
        if (!f) break;
        fclose(f);
    }
    _sl_save(target, width, height, path);
}

int sl_viewer_main(int argc, char **argv) {
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--bench") == 0) return sl_bench_main(argc, argv);
    _sl_viewer v = {0};
    sl_render_params_defaults(&v.params);
    const char *scene_name = "boxes_on_floor", *screenshot = NULL, *labs_dir = NULL, *case_name = NULL,
               *check_name = NULL;
    int frames = 0, width = 960, height = 640;
    bool headless = false;
    sl_backend backend = sl_backend_default_headless();
    float light_size = -1;
    bool freeze = false; /* lab 6 */
    int overlay_option = -1; /* --overlay 1, --no-overlay 0, default -1 */
    int serve_port = 0;
    const char *serve_address = NULL;
    bool lab_given = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        bool takes_value = strcmp(a, "--lab") == 0 || strcmp(a, "--scene") == 0 || strcmp(a, "--size") == 0 ||
                           strcmp(a, "--map-size") == 0 || strcmp(a, "--compare") == 0 ||
                           strcmp(a, "--bias") == 0 || strcmp(a, "--frames") == 0 ||
                           strcmp(a, "--screenshot") == 0 || strcmp(a, "--labs-dir") == 0 ||
                           strcmp(a, "--bias-mode") == 0 || strcmp(a, "--filter") == 0 ||
                           strcmp(a, "--kernel") == 0 || strcmp(a, "--light-size") == 0 ||
                           strcmp(a, "--poisson-radius") == 0 || strcmp(a, "--case") == 0 ||
                           strcmp(a, "--camera-path") == 0 || strcmp(a, "--check") == 0 ||
                           strcmp(a, "--backend") == 0 || strcmp(a, "--blur") == 0 ||
                           strcmp(a, "--bleeding") == 0 || strcmp(a, "--min-variance") == 0 ||
                           strcmp(a, "--moments-size") == 0 ||
                           strcmp(a, "--cascades") == 0 || strcmp(a, "--lambda") == 0 || strcmp(a, "--blend-band") == 0 ||
                           strcmp(a, "--caption") == 0 || strcmp(a, "--frame-dir") == 0 || strcmp(a, "--keys") == 0 ||
                           strcmp(a, "--text-scale") == 0 || strcmp(a, "--serve") == 0 || strcmp(a, "--serve-address") == 0 ||
                           strcmp(a, "--cube-pass") == 0 || strcmp(a, "--soft-radius") == 0 || strcmp(a, "--cube-bias") == 0;
        if (takes_value && !next) {
            fprintf(stderr, "shadowlab: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            _sl_usage(stdout);
            return 0;
        } else if (strcmp(a, "--list-keys") == 0) {
            _sl_list_keys(stdout);
            return 0;
        } else if (strcmp(a, "--lecture") == 0) {
            v.lecture = v.labels = true;
        } else if (strcmp(a, "--labels") == 0) {
            v.labels = true;
        } else if (strcmp(a, "--lab") == 0) {
            v.params.lab = atoi(next);
            lab_given = true;
            if (v.params.lab < 1 || v.params.lab > SL_RENDERER_MAX_LAB || !sl_lab_folder(v.params.lab)) {
                fprintf(stderr, "shadowlab: --lab must be one of this build's labs (1..%d; a lab number whose "
                                "folder is missing is not in this build yet)\n", SL_RENDERER_MAX_LAB);
                return 2;
            }
        } else if (strcmp(a, "--scene") == 0) {
            scene_name = next;
        } else if (strcmp(a, "--size") == 0) {
            if (sscanf(next, "%dx%d", &width, &height) != 2 || width < 16 || height < 16) {
                fprintf(stderr, "shadowlab: --size expects WxH, e.g. 800x600\n");
                return 2;
            }
        } else if (strcmp(a, "--map-size") == 0) {
            v.params.shadow_map_size = atoi(next);
            if (v.params.shadow_map_size < 16 || v.params.shadow_map_size > 8192) {
                fprintf(stderr, "shadowlab: --map-size must be 16..8192\n");
                return 2;
            }
            v.params.cube.map_size = v.params.shadow_map_size < 2048 ? v.params.shadow_map_size : 2048;
        } else if (strcmp(a, "--compare") == 0) {
            if (strcmp(next, "manual") == 0) v.params.compare = SL_COMPARE_MANUAL;
            else if (strcmp(next, "hardware") == 0) v.params.compare = SL_COMPARE_HARDWARE;
            else {
                fprintf(stderr, "shadowlab: --compare is manual or hardware\n");
                return 2;
            }
        } else if (strcmp(a, "--bias") == 0) {
            v.params.bias.constant = (float)atof(next);
        } else if (strcmp(a, "--bias-mode") == 0) {
            if (!sl_bias_mode_parse(next, &v.params.bias.mode)) {
                fprintf(stderr, "shadowlab: --bias-mode is none, constant, slope, polygon-offset, front-culling, "
                                "normal-offset or midpoint\n");
                return 2;
            }
        } else if (strcmp(a, "--filter") == 0) {
            if (!sl_filter_mode_parse(next, &v.params.filter.mode)) {
                fprintf(stderr, "shadowlab: --filter is none, hardware, grid, poisson or pcss\n");
                return 2;
            }
        } else if (strcmp(a, "--kernel") == 0) {
            v.params.filter.grid_radius = atoi(next);
            if (v.params.filter.grid_radius < 0 || v.params.filter.grid_radius > 16) {
                fprintf(stderr, "shadowlab: --kernel is a radius 0..16\n");
                return 2;
            }
        } else if (strcmp(a, "--poisson-radius") == 0) {
            v.params.filter.poisson_radius = (float)atof(next);
            if (v.params.filter.poisson_radius <= 0 || v.params.filter.poisson_radius > 64) {
                fprintf(stderr, "shadowlab: --poisson-radius is 0..64 texels\n");
                return 2;
            }
        } else if (strcmp(a, "--blur") == 0) { /* lab 5 */
            v.params.vsm.blur_radius = atoi(next);
            if (v.params.vsm.blur_radius < 0 || v.params.vsm.blur_radius > 32) {
                fprintf(stderr, "shadowlab: --blur is a radius 0..32 texels\n");
                return 2;
            }
        } else if (strcmp(a, "--bleeding") == 0) {
            v.params.vsm.bleeding = (float)atof(next);
            if (v.params.vsm.bleeding < 0 || v.params.vsm.bleeding > 0.99f) {
                fprintf(stderr, "shadowlab: --bleeding is an amount 0..0.99\n");
                return 2;
            }
        } else if (strcmp(a, "--min-variance") == 0) {
            v.params.vsm.min_variance = (float)atof(next);
        } else if (strcmp(a, "--moments-size") == 0) {
            v.params.vsm.map_size = atoi(next);
            if (v.params.vsm.map_size != 0 && (v.params.vsm.map_size < 16 || v.params.vsm.map_size > 8192)) {
                fprintf(stderr, "shadowlab: --moments-size must be 16..8192, or 0 for the shadow map's size\n");
                return 2;
            }
        } else if (strcmp(a, "--pcf") == 0) {
            v.params.vsm_off = true;
        } else if (strcmp(a, "--light-size") == 0) {
            light_size = (float)atof(next);
        } else if (strcmp(a, "--frames") == 0) {
            frames = atoi(next);
        } else if (strcmp(a, "--screenshot") == 0) {
            screenshot = next;
        } else if (strcmp(a, "--labs-dir") == 0) {
            labs_dir = next;
        } else if (strcmp(a, "--case") == 0) {
            case_name = next;
        } else if (strcmp(a, "--check") == 0) {
            check_name = next;
        } else if (strcmp(a, "--cascades") == 0) { /* lab 6 */
            v.params.cascades.count = atoi(next);
            if (v.params.cascades.count < 1 || v.params.cascades.count > SL_MAX_CASCADES) {
                fprintf(stderr, "shadowlab: --cascades is 1..%d\n", SL_MAX_CASCADES);
                return 2;
            }
        } else if (strcmp(a, "--lambda") == 0) {
            v.params.cascades.lambda = (float)atof(next);
            if (v.params.cascades.lambda < 0 || v.params.cascades.lambda > 1) {
                fprintf(stderr, "shadowlab: --lambda is 0..1\n");
                return 2;
            }
        } else if (strcmp(a, "--blend-band") == 0) {
            v.params.cascades.blend_band = (float)atof(next);
            if (v.params.cascades.blend_band < 0 || v.params.cascades.blend_band > 1) {
                fprintf(stderr, "shadowlab: --blend-band is 0..1\n");
                return 2;
            }
        } else if (strcmp(a, "--show-cascades") == 0) {
            v.params.cascades.show_cascades = true;
        } else if (strcmp(a, "--freeze") == 0) {
            freeze = true;
        } else if (strcmp(a, "--mark-changes") == 0) {
            v.mark_changes = true;
        } else if (strcmp(a, "--path-fits-cascades") == 0) {
            v.path_fit_only = true;
        } else if (strcmp(a, "--no-snap") == 0) {
            v.params.cascades.unsnapped = true;
        } else if (strcmp(a, "--camera-path") == 0) {
            v.camera_path = _SL_PATH_NONE;
            for (int k = 1; k < 3; k++)
                if (strcmp(next, _sl_path_names[k]) == 0) v.camera_path = k;
            if (v.camera_path == _SL_PATH_NONE) {
                fprintf(stderr, "shadowlab: --camera-path is slide or turn\n");
                return 2;
            }
        } else if (strcmp(a, "--visibility") == 0) {
            v.params.output = SL_OUTPUT_VISIBILITY;
        } else if (strcmp(a, "--overlay") == 0 || strcmp(a, "--no-overlay") == 0) {
            overlay_option = strcmp(a, "--overlay") == 0;
        } else if (strcmp(a, "--text-scale") == 0) {
            v.text_scale = atoi(next);
            if (v.text_scale < 1 || v.text_scale > 8) {
                fprintf(stderr, "shadowlab: --text-scale is 1..8\n");
                return 2;
            }
        } else if (strcmp(a, "--keys") == 0) {
            for (const char *k = next; *k; k++)
                if (!strchr("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789[]-=,.", *k)) {
                    fprintf(stderr, "shadowlab: --keys takes letters, digits and [ ] - = , ., not '%c'\n", *k);
                    return 2;
                }
            v.keys = next;
        } else if (strcmp(a, "--frame-dir") == 0) {
            v.frame_dir = next;
        } else if (strcmp(a, "--caption") == 0) {
            v.caption = next;
        } else if (strcmp(a, "--frustum") == 0) {
            v.show_frustum = true;
        } else if (strcmp(a, "--animate") == 0) {
            v.animate_light = true;
        } else if (strcmp(a, "--solutions") == 0) {
            if (!_sl_second_functions) {
                fprintf(stderr, "shadowlab: --solutions: this build has no solutions beside its labs (a student "
                                "handout, or a build of the solutions themselves)\n");
                return 2;
            }
            v.show_second = true;
        } else if (strcmp(a, "--soft") == 0) {
            v.params.cube.soft = true;
            if (v.params.cube.bias == SL_CUBE_HARD_BIAS) v.params.cube.bias = SL_CUBE_SOFT_BIAS;
        } else if (strcmp(a, "--soft-radius") == 0) {
            v.params.cube.soft_radius = (float)atof(next);
            if (!(v.params.cube.soft_radius >= 0 && v.params.cube.soft_radius <= 100)) {
                fprintf(stderr, "shadowlab: --soft-radius is 0..100 world units\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-bias") == 0) {
            v.params.cube.bias = (float)atof(next);
            if (!(v.params.cube.bias >= 0 && v.params.cube.bias <= 1)) {
                fprintf(stderr, "shadowlab: --cube-bias is 0..1 (distance / far)\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-pass") == 0) {
            if (!sl_cube_pass_parse(next, &v.params.cube.pass)) {
                fprintf(stderr, "shadowlab: --cube-pass is auto, six or layered\n");
                return 2;
            }
        } else if (strcmp(a, "--show-map") == 0) {
            v.params.show_shadow_map = true;
        } else if (strcmp(a, "--serve") == 0) {
            char *end = NULL;
            serve_port = (int)strtol(next, &end, 10);
            if (!end || *end || serve_port < 1 || serve_port > 65535) {
                fprintf(stderr, "shadowlab: --serve takes a port, 1..65535\n");
                return 2;
            }
        } else if (strcmp(a, "--serve-address") == 0) {
            serve_address = next;
        } else if (strcmp(a, "--headless") == 0) {
            headless = true;
        } else if (strcmp(a, "--backend") == 0) {
            if (!sl_backend_parse(next, &backend) || !sl_backend_available(backend)) {
                fprintf(stderr, "shadowlab: --backend is %s in this build\n", _sl_backend_choices());
                return 2;
            }
            headless = true;
        } else {
            fprintf(stderr, "shadowlab: unknown option %s\n", a);
            _sl_usage(stderr);
            return 2;
        }
        if (takes_value) i++;
    }
    if ((screenshot || case_name) && headless && frames <= 0) frames = 1;
    if (screenshot && frames <= 0) frames = 3;
    if (serve_port && (frames > 0 || screenshot)) {
        fprintf(stderr, "shadowlab: --serve runs until stopped (Ctrl-C): not with --frames or --screenshot\n");
        return 2;
    }
    if (serve_port && !sl_serve_available()) {
        char why[512];
        sl_serve_start(&(sl_serve_desc){.port = serve_port}, why, sizeof why);
        fprintf(stderr, "shadowlab: %s\n", why);
        return 2;
    }
    if (serve_port) headless = true; /* offscreen; the page shows it */
    if (headless && frames <= 0 && !serve_port) {
        fprintf(stderr, "shadowlab: --headless needs --frames K (and usually --screenshot FILE)\n");
        return 2;
    }
    bool gif = _sl_is_gif(screenshot);
    if (v.mark_changes && (gif || !screenshot || frames < 2)) {
        fprintf(stderr, "shadowlab: --mark-changes needs --frames K (2 or more) and --screenshot FILE.png\n");
        return 2;
    }
    if (gif && case_name) {
        fprintf(stderr, "shadowlab: --case saves one picture: --screenshot FILE.png\n");
        return 2;
    }

    if (case_name) {
        sl_case_view_desc cv = {.case_name = case_name, .labs_dir = labs_dir, .headless = headless,
                                .backend = backend, .frames = frames, .screenshot = screenshot,
                                .check_name = check_name, .serve_port = serve_port, .serve_address = serve_address};
        return sl_case_view_main(&cv);
    }
    char err[16384];
    if (!sl_scene_load(&v.scene, scene_name, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    if (light_size > 0) v.scene.light.size = light_size;
    if (freeze) _sl_freeze(&v, true);
    if (!lab_given) {
        /* the lab whose technique the scene's light is for (sl_technique.default_for_lights: a point light's cube
         * maps, a sun's or a spot's filtering); if it is not in this build, a sun's, or the highest below it */
        v.params.lab = 0;
        for (int pass = 0; pass < 2 && !v.params.lab; pass++)
            for (int lab = SL_LAB_COUNT; lab >= 1 && !v.params.lab; lab--) {
                const sl_technique *t = sl_technique_of(lab);
                unsigned light = 1u << (pass == 0 ? v.scene.light.type : SL_LIGHT_DIRECTIONAL);
                if (t && (t->default_for_lights & light) && (pass == 1 || sl_lab_folder(lab))) v.params.lab = lab;
            }
        if (!v.params.lab) v.params.lab = 1;
        while (v.params.lab > 1 && !sl_lab_folder(v.params.lab)) v.params.lab--;
    }
    sl_context_desc cd = {
        .backend = headless ? backend : SL_BACKEND_GLFW,
        .width = width,
        .height = height,
        .title = "shadowlab",
        .resizable = true,
    };
    v.ctx = sl_context_create(&cd, err, sizeof err);
    if (!v.ctx) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    sl_renderer_desc rd = {.labs_dir = labs_dir};
    if (!sl_renderer_init(&v.renderer, &rd, err, sizeof err) ||
        !sl_renderer_set_scene(&v.renderer, &v.scene, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        sl_context_destroy(v.ctx);
        return 1;
    }
    printf("shadowlab: %s through %s, %s labs from %s\n", sl_context_renderer_name(), sl_backend_name(sl_context_backend(v.ctx)),
           sl_build_labs_kind, v.renderer.labs_dir);
    /* The overlay is on in an interactive window and off in unattended runs,
     * so screenshots and slide figures show the scene alone unless asked. */
    v.show_overlay = overlay_option >= 0 ? overlay_option == 1 : ((!headless || serve_port) && frames <= 0);
    v.overlay = sl_overlay_create(sl_framework_dir(), err, sizeof err);
    if (!v.overlay) fprintf(stderr, "shadowlab: no overlay: %s\n", err);
    else {
        sl_overlay_set_scale(v.overlay, v.text_scale);
        sl_overlay_set_lecture(v.overlay, v.lecture);
    }
    /* GLFW's key codes for letters, digits and [ ] - = are their ASCII codes (upper case). */
    _sl_keys_viewer = &v;
    for (const char *k = v.keys; k && *k; k++)
        _sl_key(NULL, *k >= 'a' && *k <= 'z' ? *k - 'a' + 'A' : *k, 0, GLFW_PRESS, 0);
    /* 0 would do too (the EGL backend binds its own for it); the name says what is meant. */
    GLuint target = sl_context_default_framebuffer(v.ctx);

    if (serve_port) {
        char *keys = _sl_keys_json();
        sl_serve_desc sd = {.port = serve_port, .address = serve_address, .hello = keys};
        v.serve = sl_serve_start(&sd, err, sizeof err);
        cJSON_free(keys);
        if (!v.serve) {
            fprintf(stderr, "shadowlab: %s\n", err);
            sl_overlay_destroy(v.overlay);
            sl_renderer_destroy(&v.renderer);
            sl_context_destroy(v.ctx);
            return 1;
        }
        printf("shadowlab: serving the viewer at %s (open it in a browser; Ctrl-C stops)\n", sl_serve_url(v.serve));
        fflush(stdout);
    }
    GLFWwindow *window = sl_context_window(v.ctx);
    bool live = window || v.serve; /* someone watches: a window or a page */
    if (window) {
        glfwSetWindowUserPointer(window, &v);
        glfwSetKeyCallback(window, _sl_key);
        glfwSetMouseButtonCallback(window, _sl_mouse_button);
        glfwSetCursorPosCallback(window, _sl_cursor);
        glfwSetScrollCallback(window, _sl_scroll);
    }
    int rendered = 0;
    double last_reload_check = 0, last_frame_time = 0;
    char reported_missing[512] = "-";
    const char *reported_shader_error = NULL;
    int status = 0;
    v.dirty_title = true;
    while (!sl_context_should_close(v.ctx)) {
        double now = window ? glfwGetTime() : v.serve ? sl_platform_seconds() : 0;
        if (v.serve) _sl_serve_events(&v);
        if (live && now - last_reload_check > 0.25) {
            last_reload_check = now;
            bool reloaded = false;
            if (!sl_renderer_reload_changed(v.show_second && v.second_ready ? &v.second : &v.renderer, &reloaded, err,
                                            sizeof err))
                fprintf(stderr, "shadowlab: shader reload failed, keeping the previous version:\n%s\n", err);
            else if (reloaded)
                printf("shadowlab: shaders reloaded\n");
        }
        if (live) _sl_fly(&v, window, now);
        int fw, fh;
        sl_context_framebuffer_size(v.ctx, &fw, &fh);
        if (v.show_second && !v.second_ready) {
            /* The second code draws with its own renderer: its own shaders, its own maps. */
            sl_renderer_desc sd = {.labs_dir = _sl_second_dir};
            if (!sl_renderer_init(&v.second, &sd, err, sizeof err) ||
                !sl_renderer_set_scene(&v.second, &v.scene, err, sizeof err)) {
                fprintf(stderr, "shadowlab: cannot draw with the %s: %s\n", _sl_second_kind, err);
                v.show_second = false;
            } else {
                for (int lab = 1; lab <= SL_LAB_COUNT; lab++) v.second.fns[lab] = _sl_second_functions;
                v.second_ready = true;
            }
        }
        sl_renderer *active = v.show_second ? &v.second : &v.renderer;
        static bool last_second;
        if (last_second != v.show_second) {
            printf("shadowlab: drawing with the %s code\n", v.show_second ? _sl_second_kind : sl_build_labs_kind);
            last_second = v.show_second;
            v.dirty_title = true;
        }
        /* Per-pass GL timer queries only while the overlay shows them. */
        bool timing = v.overlay && v.show_overlay;
        if (active->timing != timing) sl_renderer_set_timing(active, timing);
        if (v.animate_light) {
            double dt = live ? now - last_frame_time : 1.0 / 30.0;
            _sl_animate_light(&v.scene.light, (float)(0.4 * (dt > 0.2 ? 0.2 : dt)));
        }
        double frame_seconds = live && last_frame_time > 0 ? now - last_frame_time : 0;
        last_frame_time = now;
        if (v.camera_path) _sl_camera_path(&v, frames > 0 ? (double)rendered / frames : now / _SL_PATH_SECONDS);
        sl_renderer_draw(active, &v.scene, &v.params, target, fw, fh);
        const sl_frame_info *info = sl_renderer_info(active);
        /* --mark-changes compares the frames as drawn, before the overlay: its text (the pass times) changes
         * from frame to frame, the scene it is about may not */
        if (v.mark_changes && frames > 0 && !_sl_mark_changes(&v, target, fw, fh)) {
            fprintf(stderr, "shadowlab: --mark-changes: cannot read frame %d (or its size changed)\n", rendered + 1);
            status = 1;
            break;
        }
        bool labels = v.show_overlay || v.labels;
        const sl_technique *asked = sl_technique_of(v.params.lab);
        bool overlay_drawn = v.overlay && (labels || v.show_frustum || v.caption ||
                                           (v.frozen && asked && asked->frozen_lines));
        mat4 camera;
        _sl_camera_view_projection(&v.scene, fw, fh, camera);
        if (overlay_drawn) {
            if (timing) _sl_update_timing(&v, active, frame_seconds, live);
            sl_overlay_clear(v.overlay);
            if (v.show_overlay) _sl_overlay_fill(&v, active, fw, fh, live);
            if (v.show_frustum) _sl_add_frustum(v.overlay, info);
            _sl_labels(&v, info, fw, fh, labels);
            if (v.caption) {
                sl_overlay_panel(v.overlay, SL_OVERLAY_BOTTOM_LEFT, NULL);
                sl_overlay_line(v.overlay, (const float[3]){1, 1, 1}, "%s", v.caption);
            }
            sl_overlay_draw(v.overlay, camera, target, fw, fh);
        }
        if (v.screenshot_requested) {
            v.screenshot_requested = false;
            _sl_screenshot_key(&v, target, fw, fh);
        }
        if (info->shader_error != reported_shader_error) {
            reported_shader_error = info->shader_error;
            if (info->shader_error)
                fprintf(stderr, "shadowlab: lab %d's shaders do not compile, so it is switched off until you fix "
                                "them (they reload when saved):\n%s\n", info->shader_error_lab, info->shader_error);
        }
        /* Say what is really drawing whenever that changes (a stub in the way, a setting, the scene). */
        char drawing_status[512];
        _sl_status(&v, info, drawing_status, sizeof drawing_status);
        if (strcmp(drawing_status, v.status) != 0) {
            snprintf(v.status, sizeof v.status, "%s", drawing_status);
            if (drawing_status[0]) printf("shadowlab: %s\n", drawing_status);
            v.dirty_title = true;
        }
        /* Say which stubs are in the way whenever that list changes (another lab, a mode). */
        char missing[512] = "";
        for (int i = 0; i < info->not_implemented_count; i++)
            snprintf(missing + strlen(missing), sizeof missing - strlen(missing), "%s ", info->not_implemented[i]);
        if (strcmp(missing, reported_missing) != 0) {
            snprintf(reported_missing, sizeof reported_missing, "%s", missing);
            for (int i = 0; i < info->not_implemented_count; i++)
                printf("shadowlab: not implemented yet: %s() (rendering without it)\n", info->not_implemented[i]);
            v.dirty_title = true;
        }
        if (v.dirty_title) {
            _sl_update_title(&v);
            v.dirty_title = false;
        }
        rendered++;
        if (gif && frames > 0 && !_sl_add_frame(&v, target, fw, fh, screenshot)) {
            status = 1;
            break;
        }
        if (v.frame_dir) {
            char path[SL_PATH_MAX + 16];
            snprintf(path, sizeof path, "%s/%03d.png", v.frame_dir, rendered);
            if (!_sl_save(target, fw, fh, path)) {
                status = 1;
                break;
            }
        }
        if (frames > 0 && rendered >= frames) {
            if (screenshot && !gif && v.mark_changes) {
                if (!_sl_save_changes(&v, screenshot, rendered, overlay_drawn, camera, target)) status = 1;
            } else if (screenshot && !gif && !_sl_save(target, fw, fh, screenshot)) {
                status = 1;
            }
            /* The last frame's overlay in words, for logs and tests. */
            if (v.overlay && overlay_drawn && (v.show_overlay || v.labels)) {
                char text[8192];
                sl_overlay_text(v.overlay, text, sizeof text);
                printf("shadowlab: overlay:\n%s", text);
            }
            break;
        }
        if (v.serve) {
            /* the overlay's words: its panels, labels and markers, whichever are drawn */
            static char text[16384];
            text[0] = '\0';
            if (overlay_drawn) sl_overlay_text(v.overlay, text, sizeof text);
            sl_serve_frame_desc fd = {.text = text, .lab = v.params.lab, .keys_acted = v.keys_acted};
            if (!sl_serve_frame(v.serve, target, fw, fh, &fd, err, sizeof err))
                fprintf(stderr, "shadowlab: --serve: %s\n", err);
            sl_serve_idle(v.serve);
        }
        sl_context_end_frame(v.ctx);
    }
    if (v.animation) {
        char aerr[1024] = "";
        if (sl_animation_close(v.animation, aerr, sizeof aerr))
            printf("shadowlab: saved %s (%d frames)\n", screenshot, rendered);
        else {
            fprintf(stderr, "shadowlab: cannot save the animation: %s\n", aerr);
            status = 1;
        }
    }
    sl_serve_stop(v.serve);
    sl_image_free(&v.first_frame);
    free(v.changed);
    sl_overlay_destroy(v.overlay);
    if (v.second_ready) sl_renderer_destroy(&v.second);
    sl_renderer_destroy(&v.renderer);
    sl_context_destroy(v.ctx);
    return status;
}
