#define _POSIX_C_SOURCE 200809L
#include "sl_viewer_overlay.h"

#include <stdio.h>
#include <string.h>

#include "sl_viewer_keys.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

void _sl_viewer_update_title(_sl_viewer *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    if (!w) return;
    const sl_frame_info *info = sl_renderer_info(v->show_second ? &v->second : &v->renderer);
    char title[512], settings[512];
    const sl_render_params *p = &v->params;
    const sl_technique *t = sl_technique_of(p->lab);
    sl_view_context c = _sl_viewer_context(v, info);
    settings[0] = '\0';
    if (t && t->settings_text) t->settings_text(&c, settings, sizeof settings);
    if (v->status[0]) snprintf(settings, sizeof settings, "%s", v->status); /* the asked lab's settings do not draw */
    int n = snprintf(title, sizeof title, "shadowlab — lab %d — %s — %s%s%s%s", p->lab, v->scene.name, settings,
                     p->output == SL_OUTPUT_VISIBILITY ? " — visibility" : "", v->show_second ? " — " : "",
                     v->show_second ? v->second_kind : "");
    if (info->not_implemented_count > 0 && n > 0 && (size_t)n < sizeof title)
        snprintf(title + n, sizeof title - (size_t)n, " — not implemented: %s%s", info->not_implemented[0],
                 info->not_implemented_count > 1 ? ", ..." : "");
    glfwSetWindowTitle(w, title);
}

/* Pass times read off the GL's timer queries, smoothed so they can be read
 * (and not smoothed with --frames, where each frame stands alone). */
void _sl_viewer_update_timing(_sl_viewer *v, sl_renderer *r, double frame_seconds, bool smooth) {
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
    sl_view_context c = _sl_viewer_context(v, info);
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
void _sl_viewer_status(_sl_viewer *v, const sl_frame_info *info, char *out, size_t n) {
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
void _sl_viewer_add_frustum(sl_overlay *ov, const sl_frame_info *info) {
    if (info->cube_frame) return; /* a point light has no one frustum: its marker shows where it is */
    mat4 vp, inv;
    glm_mat4_mul((vec4 *)info->light_projection, (vec4 *)info->light_view, vp);
    glm_mat4_inv(vp, inv);
    sl_overlay_box(ov, inv, _sl_frustum_rgb);
}

/* The labels of what is drawn (with the overlay or --labels): the cascade
 * colours' legend, the cube faces' names in the cross, the light's marker;
 * the frozen cascades' slices and light boxes as lines the overlay's width. */
void _sl_viewer_labels(_sl_viewer *v, const sl_frame_info *info, int width, int height, bool labels) {
    sl_overlay *ov = v->overlay;
    const sl_render_params *p = &v->params;
    const sl_technique *t = sl_technique_of(p->lab);
    if (labels && t && t->overlay_labels) t->overlay_labels(ov, info, p, width, height);
    if (v->frozen && t && t->frozen_lines) {
        sl_view_context c = _sl_viewer_context(v, info);
        t->frozen_lines(ov, &c, width, height);
    }
    const sl_light *l = &v->scene.light;
    if ((labels || v->show_frustum) && l->type != SL_LIGHT_DIRECTIONAL)
        sl_overlay_marker(ov, l->position, _sl_frustum_rgb, l->type == SL_LIGHT_POINT ? "point light" : "spot light");
}

/* What the overlay says: the lab and what really draws with its parameters
 * (top left), the pass times (top right), the keys (bottom left, in a window). */
/* The status line, for a hall: the lab and its technique, the setting the last key changed (or, before
 * any, the settings of what draws, as the window's title gives them; what draws instead when the lab is
 * off), and the frame time (the passes' when frames are not timed by the clock). */
static void _sl_viewer_status_line(_sl_viewer *v, const sl_frame_info *info) {
    const sl_render_params *p = &v->params;
    const sl_technique *t = sl_technique_of(p->lab);
    char setting[256] = "";
    if (!_sl_viewer_last_change(v, info, setting, sizeof setting)) {
        char status[512];
        _sl_viewer_status(v, info, status, sizeof status);
        const char *drawing = strstr(status, "; drawing ");
        if (drawing) snprintf(setting, sizeof setting, "off, %s (I: why)", drawing + 2);
        else if (t && t->settings_text) {
            sl_view_context c = _sl_viewer_context(v, info);
            t->settings_text(&c, setting, sizeof setting);
        }
    }
    double ms = v->frame_ms;
    for (int i = 0; ms <= 0 && i < v->pass_count; i++) ms += v->pass_ms[i];
    char time[32] = "";
    if (ms > 0) snprintf(time, sizeof time, "   %.1f ms", ms);
    sl_overlay_status_line(v->overlay, "lab %d  %s%s%s%s", p->lab, sl_lab_title(p->lab), setting[0] ? "   " : "",
                           setting, time);
}

void _sl_viewer_overlay_fill(_sl_viewer *v, const sl_renderer *r, int width, int height, bool windowed) {
    sl_overlay *ov = v->overlay;
    const sl_render_params *p = &v->params;
    const sl_light *l = &v->scene.light;
    const sl_frame_info *info = sl_renderer_info(r);
    int drawn = info->lab_in_use;
    if (!v->show_panels) {
        _sl_viewer_status_line(v, info);
        return;
    }
    char title[96];
    snprintf(title, sizeof title, "lab %d: %s", p->lab, sl_lab_title(p->lab));
    sl_overlay_panel(ov, SL_OVERLAY_TOP_LEFT, title);
    sl_overlay_line(ov, NULL, "scene: %s  %dx%d", v->scene.name, width, height);
    if (v->second_functions)
        sl_overlay_line(ov, v->show_second ? _sl_green : _sl_blue, "code: %s (U: %s)",
                        v->show_second ? v->second_kind : sl_build_labs_kind,
                        v->show_second ? sl_build_labs_kind : v->second_kind);
    else
        sl_overlay_line(ov, NULL, "code: %s", sl_build_labs_kind);
    char status[512];
    _sl_viewer_status(v, info, status, sizeof status);
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
    sl_view_context c = _sl_viewer_context(v, info);
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
    if (windowed) _sl_viewer_key_panel(v, info);
}

