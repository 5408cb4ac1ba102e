#define _POSIX_C_SOURCE 200809L
#include "sl_viewer_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_case_view.h"
#include "sl_viewer_camera.h"
#include "sl_viewer_split.h"
#include <cjson/cJSON.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* ---- Keys ---------------------------------------------------------------
 * Every key the viewer handles is one binding of one table, the union of the
 * viewer's common keys and each technique's own (sl_technique.keys): what it
 * does (--help, --list-keys, the --serve page), its short label and the
 * setting it changes now (the overlay's key panel). A lab's own keys are
 * tried before the common ones, so a letter can mean one thing in lab 5 and
 * another in lab 6. */
typedef enum _sl_action {
    _SL_KEY_LAB, _SL_KEY_VISIBILITY, _SL_KEY_MAP, _SL_KEY_COMPARE, _SL_KEY_BIAS, _SL_KEY_BIAS_MODE, _SL_KEY_FILTER,
    _SL_KEY_KERNEL, _SL_KEY_LIGHT, _SL_KEY_OVERLAY, _SL_KEY_PANELS, _SL_KEY_FRUSTUM, _SL_KEY_ANIMATE, _SL_KEY_SCREENSHOT,
    _SL_KEY_CODE, _SL_KEY_SPLIT, _SL_KEY_FLY, _SL_KEY_QUIT,
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
    {{GLFW_KEY_I}, "I", "panels", "the overlay's panels (parameters, times, keys, legend) or its one status line",
     _SL_KEY_PANELS},
    {{GLFW_KEY_G}, "G", "frustum", "the light's frustum and a marker at the light", _SL_KEY_FRUSTUM},
    {{GLFW_KEY_H}, "H", "turn light", "the light turns about the scene", _SL_KEY_ANIMATE},
    {{GLFW_KEY_X}, "X", "screenshot", "screenshot of the window, overlay included (shadowlab-NNN.png)",
     _SL_KEY_SCREENSHOT},
    {{GLFW_KEY_U}, "U", "code", "student or solutions code (builds that carry both)", _SL_KEY_CODE},
    {{GLFW_KEY_Y}, "Y", "split", "with --split: its two halves, or the left half's setting alone", _SL_KEY_SPLIT},
    /* held, not pressed: the viewer polls them every frame (_sl_viewer_fly), but a letter a lab takes for
     * its own key (lab 7's S) is that key there */
    {{GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E}, "W A S D Q E", "fly",
     "fly: forward, left, back, right, down, up (Shift: faster)", _SL_KEY_FLY},
    {{GLFW_KEY_ESCAPE}, "Esc", "quit", "quit", _SL_KEY_QUIT},
    {{0}, NULL, NULL, NULL, 0},
};

/* One binding of the union: a technique's own key (its lab, 0 for a build's slot-0 technique) or a common
 * one (no technique). */
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
        for (int lab = 0; lab <= SL_LAB_COUNT; lab++) {
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
            if (pass == 0 ? !b->technique || b->lab != lab : b->technique != NULL) continue;
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
        sl_view_context c = _sl_viewer_context(v, sl_renderer_info(v->show_second ? &v->second : &v->renderer));
        if (b->technique->key_pressed) b->technique->key_pressed(&c, b->key, key, up);
        if (c.request == SL_VIEW_REQUEST_FREEZE) _sl_viewer_freeze(v, !v->frozen);
        else if (c.request == SL_VIEW_REQUEST_CAMERA_PATH) v->camera_path = (v->camera_path + 1) % 3;
        return;
    }
    /* the setting --split's halves differ in stays theirs */
    _sl_action action = (_sl_action)b->key->id;
    if ((action == _SL_KEY_LAB && _sl_viewer_split_holds(v, _SL_SPLIT_LAB)) ||
        (action == _SL_KEY_FILTER && _sl_viewer_split_holds(v, _SL_SPLIT_FILTER)) ||
        (action == _SL_KEY_CODE && v->second_functions && _sl_viewer_split_holds(v, _SL_SPLIT_CODE)))
        return;
    switch (action) {
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
            _sl_viewer_move_light(&v->scene.light, key == GLFW_KEY_LEFT ? -0.05f : key == GLFW_KEY_RIGHT ? 0.05f : 0,
                           key == GLFW_KEY_UP ? 0.05f : key == GLFW_KEY_DOWN ? -0.05f : 0);
        }
        break;
    case _SL_KEY_OVERLAY: v->show_overlay = !v->show_overlay; break;
    case _SL_KEY_PANELS:
        v->show_panels = !v->show_panels;
        if (v->show_panels) v->show_overlay = true; /* asking for the panels shows them */
        break;
    case _SL_KEY_FRUSTUM: v->show_frustum = !v->show_frustum; break;
    case _SL_KEY_ANIMATE: v->animate_light = !v->animate_light; break;
    case _SL_KEY_SCREENSHOT: v->screenshot_requested = true; break;
    case _SL_KEY_CODE:
        if (!v->second_functions) printf("shadowlab: this build has no second lab code to switch to (U)\n");
        else v->show_second = !v->show_second;
        break;
    case _SL_KEY_SPLIT:
        if (!v->split.given) printf("shadowlab: Y shows --split's two halves: this run has no --split\n");
        else _sl_viewer_split_show(v, !v->split.on);
        break;
    case _SL_KEY_FLY: break; /* held keys, polled every frame (_sl_viewer_fly) */
    case _SL_KEY_QUIT:
        if (w) glfwSetWindowShouldClose(w, GLFW_TRUE);
        break;
    }
}

/* A key held down: in the window, or on the --serve page. */
static bool _sl_held(_sl_viewer *v, GLFWwindow *w, int key) {
    return w ? glfwGetKey(w, key) == GLFW_PRESS : sl_serve_key_down(v->serve, key);
}

/* A fly key held down, where the lab in use leaves it to fly. */
static bool _sl_flying(_sl_viewer *v, GLFWwindow *w, int key) {
    const _sl_key_binding *b = _sl_binding(v->params.lab, key);
    return b && _sl_is_common(b, _SL_KEY_FLY) && _sl_held(v, w, key);
}

/* W A S D fly along the view and across it, Q E down and up (lab 6's long scenes above all); Shift is five
 * times faster. */
void _sl_viewer_fly(_sl_viewer *v, GLFWwindow *w, double now) {
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
    if (_sl_flying(v, w, GLFW_KEY_W)) glm_vec3_muladds(forward, speed, move);
    if (_sl_flying(v, w, GLFW_KEY_S)) glm_vec3_muladds(forward, -speed, move);
    if (_sl_flying(v, w, GLFW_KEY_D)) glm_vec3_muladds(right, speed, move);
    if (_sl_flying(v, w, GLFW_KEY_A)) glm_vec3_muladds(right, -speed, move);
    if (_sl_flying(v, w, GLFW_KEY_E)) move[1] += speed;
    if (_sl_flying(v, w, GLFW_KEY_Q)) move[1] -= speed;
    glm_vec3_add(cam->position, move, cam->position);
    glm_vec3_add(cam->target, move, cam->target);
}

/* The names of binding `b`'s keys in lab `lab`: its own, or where the lab takes some of a common binding's
 * letters for keys of its own (lab 7's S of W A S D Q E), the letters it leaves. */
static const char *_sl_names_in(int lab, const _sl_key_binding *b, char *out, size_t n) {
    bool taken = false, letters = true;
    for (int k = 0; k < SL_TECHNIQUE_KEY_CODES && b->key->codes[k]; k++) {
        taken |= _sl_binding(lab, b->key->codes[k]) != b;
        letters &= b->key->codes[k] >= GLFW_KEY_A && b->key->codes[k] <= GLFW_KEY_Z;
    }
    if (!taken || !letters) return b->key->names;
    out[0] = '\0';
    for (int k = 0; k < SL_TECHNIQUE_KEY_CODES && b->key->codes[k]; k++)
        if (_sl_binding(lab, b->key->codes[k]) == b && strlen(out) + 3 < n)
            snprintf(out + strlen(out), n - strlen(out), "%s%c", out[0] ? " " : "", (char)b->key->codes[k]);
    return out;
}

/* The setting binding `b` changes, as it is now ("" when it has none to show). */
static void _sl_key_state(_sl_viewer *v, const sl_frame_info *info, const _sl_key_binding *b, char *out, size_t n) {
    const sl_render_params *p = &v->params;
    out[0] = '\0';
    if (b->technique) {
        sl_view_context c = _sl_viewer_context(v, info);
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
    case _SL_KEY_PANELS: snprintf(out, n, "%s", _sl_on(v->show_panels)); break;
    case _SL_KEY_ANIMATE: snprintf(out, n, "%s", _sl_on(v->animate_light)); break;
    case _SL_KEY_CODE: snprintf(out, n, "%s", v->show_second ? v->second_kind : sl_build_labs_kind); break;
    case _SL_KEY_SPLIT: snprintf(out, n, "%s", v->split.given ? _sl_on(v->split.on) : ""); break;
    default: break;
    }
}

/* The viewer --keys presses keys for, with no window (w NULL) or before the first frame. */
static _sl_viewer *_sl_keys_viewer;

void _sl_viewer_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    if (action == GLFW_RELEASE) return;
    _sl_viewer *v = w ? glfwGetWindowUserPointer(w) : _sl_keys_viewer;
    const _sl_key_binding *b = _sl_binding(v->params.lab, key);
    if (!b) return;
    _sl_act(v, w, b, key);
    /* the status line names the setting this key changed (keys that change none leave it as it was) */
    char state[64];
    _sl_key_state(v, sl_renderer_info(v->show_second ? &v->second : &v->renderer), b, state, sizeof state);
    if (state[0] && !_sl_is_common(b, _SL_KEY_LAB) && !_sl_is_common(b, _SL_KEY_OVERLAY) &&
        !_sl_is_common(b, _SL_KEY_PANELS)) {
        v->changed_lab = v->params.lab;
        v->changed_key = key;
    }
    v->keys_acted++;
    v->dirty_title = true;
}

bool _sl_viewer_last_change(_sl_viewer *v, const sl_frame_info *info, char *out, size_t n) {
    out[0] = '\0';
    /* a key of another lab than the one now shown said nothing about this one */
    if (!v->changed_key || v->changed_lab != v->params.lab) return false;
    const _sl_key_binding *b = _sl_binding(v->params.lab, v->changed_key);
    if (!b) return false;
    char state[64];
    _sl_key_state(v, info, b, state, sizeof state);
    if (!state[0]) return false;
    snprintf(out, n, "%s: %s", b->key->label, state);
    return true;
}

/* --help's keys, from the table: every lab's, then each lab's own, then --case's. */
void _sl_viewer_print_keys(FILE *f) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    fprintf(f, "keys (a lab's own keys come first: a letter can mean one thing in lab 5, another in lab 6):\n");
    for (int lab = -1; lab <= SL_LAB_COUNT; lab++) { /* -1: the common keys */
        bool any = false;
        for (int i = 0; i < count; i++) {
            const _sl_key_binding *b = &table[i];
            if (lab < 0 ? b->technique != NULL : !b->technique || b->lab != lab) continue;
            if (!any) {
                if (lab < 0) fprintf(f, "  every lab:\n");
                else if (lab == 0) fprintf(f, "  lab 0 (%s, this build's own):\n", b->technique->name);
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
void _sl_viewer_list_keys(FILE *f) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    for (int i = 0; i < count; i++) {
        const _sl_key_binding *b = &table[i];
        if (!b->technique) fprintf(f, "all\t%s\t%s\n", b->key->names, b->key->help);
        else fprintf(f, "%d\t%s\t%s\n", b->lab, b->key->names, b->key->help);
    }
    for (const sl_case_view_key *k = sl_case_view_keys(); k->names; k++) fprintf(f, "case\t%s\t%s\n", k->names, k->help);
}

/* --serve's key table for the page (framework/serve/index.html): every
 * binding but Esc (a page is closed in the browser) with its keys' browser
 * codes and GLFW codes, and the keys only held (Shift, for lab 6's flying).
 * The page takes these keys and no others, so it has exactly the window's. */
char *_sl_viewer_keys_json(int lab) {
    const _sl_key_binding *table;
    int count = _sl_key_table(&table);
    cJSON *root = cJSON_CreateObject();
    /* the lab the viewer starts in: the page lists its keys before the first frame names the lab */
    cJSON_AddNumberToObject(root, "lab", lab);
    cJSON *keys = cJSON_AddArrayToObject(root, "keys");
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

static const float _sl_blue[3] = {0.55f, 0.75f, 1.0f};

/* The key panel (bottom left): the lab's own keys and the common keys that
 * matter in it, one a line with what they set now; then the general keys. */
void _sl_viewer_key_panel(_sl_viewer *v, const sl_frame_info *info) {
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
            bool listed = (b->technique && b->lab == lab) || (!b->technique && t && _sl_panel_lists(t, b->key->names));
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
        if (b->technique || _sl_panel_lists(NULL, b->key->names) || _sl_binding(lab, b->key->codes[0]) != b) continue;
        if (_sl_is_common(b, _SL_KEY_CODE) && !v->second_functions) continue;
        if (_sl_is_common(b, _SL_KEY_SPLIT) && !v->split.given) continue;
        if (_sl_is_common(b, _SL_KEY_QUIT) && v->serve) continue; /* a page is closed in the browser */
        char state[64], item[128], names[32];
        _sl_key_state(v, info, b, state, sizeof state);
        snprintf(item, sizeof item, "%s %s%s%s", _sl_names_in(lab, b, names, sizeof names), b->key->label,
                 state[0] ? ": " : "", state);
        if (line[0] && strlen(line) + 2 + strlen(item) > width) {
            sl_overlay_line(ov, _sl_blue, "%s", line);
            line[0] = '\0';
        }
        snprintf(line + strlen(line), sizeof line - strlen(line), "%s%s", line[0] ? "  " : "", item);
    }
    if (line[0]) sl_overlay_line(ov, _sl_blue, "%s", line);
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
void _sl_viewer_serve_events(_sl_viewer *v) {
    sl_serve_event events[64];
    int n = sl_serve_poll(v->serve, events, 64);
    for (int i = 0; i < n; i++) {
        const sl_serve_event *e = &events[i];
        switch (e->kind) {
        case SL_SERVE_KEY_DOWN:
            /* Esc would close a window; a page is closed in the browser, the server with Ctrl-C */
            if (e->key != GLFW_KEY_ESCAPE) _sl_viewer_key(NULL, e->key, 0, GLFW_PRESS, 0);
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

void _sl_viewer_keys_attach(_sl_viewer *v) { _sl_keys_viewer = v; }

void _sl_viewer_input_callbacks(GLFWwindow *window) {
    glfwSetKeyCallback(window, _sl_viewer_key);
    glfwSetMouseButtonCallback(window, _sl_mouse_button);
    glfwSetCursorPosCallback(window, _sl_cursor);
    glfwSetScrollCallback(window, _sl_scroll);
}
