#include "sl_lab6_viewer.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_overlay.h"
#include "sl_renderer.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

enum {
    _SL_LAB6_KEY_COLOURS, _SL_LAB6_KEY_COUNT, _SL_LAB6_KEY_LAMBDA, _SL_LAB6_KEY_BLEND_BAND, _SL_LAB6_KEY_FREEZE,
    _SL_LAB6_KEY_SNAPPING, _SL_LAB6_KEY_CAMERA_PATH,
};

const sl_technique_key sl_lab6_keys[] = {
    {{GLFW_KEY_K}, "K", "cascade colours", "tint each pixel by its cascade (a legend names them)", _SL_LAB6_KEY_COLOURS},
    {{GLFW_KEY_N}, "N", "cascades", "cascade count, 1 to 4", _SL_LAB6_KEY_COUNT},
    {{GLFW_KEY_COMMA, GLFW_KEY_PERIOD}, ", .", "lambda", "the split scheme's lambda down, up (0 uniform .. 1 "
     "logarithmic)", _SL_LAB6_KEY_LAMBDA},
    {{GLFW_KEY_J}, "J", "blend band", "blend band between cascades (bonus)", _SL_LAB6_KEY_BLEND_BAND},
    {{GLFW_KEY_Z}, "Z", "frozen frustum", "freeze the camera's frustum, seen from above with its slices and "
     "light boxes", _SL_LAB6_KEY_FREEZE},
    {{GLFW_KEY_T}, "T", "texel snapping", "texel snapping on, off (off: the shimmer it removes)", _SL_LAB6_KEY_SNAPPING},
    {{GLFW_KEY_P}, "P", "camera path", "the camera moves by itself: slide, turn, off", _SL_LAB6_KEY_CAMERA_PATH},
    {{0}, NULL, NULL, NULL, 0},
};

static const char *_sl_on(bool on) { return on ? "on" : "off"; }

void sl_lab6_key_pressed(sl_view_context *c, const sl_technique_key *k, int code, bool up) {
    (void)code;
    sl_cascade_params *cascades = &c->params->cascades;
    switch (k->id) {
    case _SL_LAB6_KEY_COLOURS: cascades->show_cascades = !cascades->show_cascades; break;
    case _SL_LAB6_KEY_COUNT: cascades->count = cascades->count % SL_MAX_CASCADES + 1; break;
    case _SL_LAB6_KEY_LAMBDA: cascades->lambda = glm_clamp(cascades->lambda + (up ? 0.1f : -0.1f), 0, 1); break;
    case _SL_LAB6_KEY_BLEND_BAND: cascades->blend_band = cascades->blend_band > 0 ? 0 : 0.2f; break;
    case _SL_LAB6_KEY_FREEZE: c->request = SL_VIEW_REQUEST_FREEZE; break;
    case _SL_LAB6_KEY_SNAPPING: cascades->unsnapped = !cascades->unsnapped; break;
    case _SL_LAB6_KEY_CAMERA_PATH: c->request = SL_VIEW_REQUEST_CAMERA_PATH; break;
    }
}

void sl_lab6_key_state(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n) {
    const sl_cascade_params *cascades = &c->params->cascades;
    switch (k->id) {
    case _SL_LAB6_KEY_COLOURS: snprintf(out, n, "%s", _sl_on(cascades->show_cascades)); break;
    case _SL_LAB6_KEY_COUNT: snprintf(out, n, "%d", cascades->count); break;
    case _SL_LAB6_KEY_LAMBDA: snprintf(out, n, "%.2f", cascades->lambda); break;
    case _SL_LAB6_KEY_BLEND_BAND: snprintf(out, n, "%s", _sl_on(cascades->blend_band > 0)); break;
    case _SL_LAB6_KEY_FREEZE: snprintf(out, n, "%s", _sl_on(c->frozen)); break;
    case _SL_LAB6_KEY_SNAPPING: snprintf(out, n, "%s", _sl_on(!cascades->unsnapped)); break;
    case _SL_LAB6_KEY_CAMERA_PATH: snprintf(out, n, "%s", c->camera_path ? c->camera_path : "off"); break;
    default: break;
    }
}

void sl_lab6_settings_text(const sl_view_context *c, char *out, size_t n) {
    const sl_cascade_params *cascades = &c->params->cascades;
    snprintf(out, n, "%d cascades, lambda %.2f%s%s%s", cascades->count, cascades->lambda,
             cascades->blend_band > 0 ? ", blend band" : "", cascades->show_cascades ? ", coloured" : "",
             c->frozen ? ", frustum frozen (Z)" : "");
}

bool sl_lab6_maps_text(const sl_view_context *c, char *out, size_t n) {
    const sl_render_params *p = c->params;
    snprintf(out, n, "shadow maps: %d layers of %dx%d", p->cascades.count, p->shadow_map_size, p->shadow_map_size);
    return true;
}

void sl_lab6_overlay_lines(sl_overlay *ov, const sl_view_context *c) {
    static const float red[3] = {1.0f, 0.45f, 0.4f};
    const sl_cascade_params *cascades = &c->params->cascades;
    const sl_frame_info *info = c->info;
    sl_overlay_line(ov, NULL, "cascades: %d, lambda %.2f%s", cascades->count, cascades->lambda,
                    cascades->blend_band > 0 ? ", blend band" : "");
    char splits[160] = "";
    for (int i = 0; i <= info->cascade_count && i <= SL_MAX_CASCADES; i++)
        snprintf(splits + strlen(splits), sizeof splits - strlen(splits), "%s%.1f", i ? " " : "",
                 info->cascade_splits[i]);
    sl_overlay_line(ov, NULL, "splits (view depth): %s", splits);
    sl_overlay_line(ov, cascades->unsnapped ? red : NULL, "texel snapping: %s (T)%s%s",
                    cascades->unsnapped ? "off" : "on", c->camera_path ? ", camera path: " : "",
                    c->camera_path ? c->camera_path : "");
}

/* Each slice is the frozen camera's frustum between two splits, with its light box dimmer. */
void sl_lab6_frozen_lines(sl_overlay *ov, const sl_view_context *c, int width, int height) {
    const sl_frame_info *info = c->info;
    const sl_render_params *p = c->params;
    if (!info->cascades_ready) return;
    for (int i = 0; i < info->cascade_count && i < SL_MAX_CASCADES; i++) {
        sl_camera slice = p->cascades.camera;
        slice.near = info->cascade_splits[i];
        slice.far = info->cascade_splits[i + 1];
        mat4 view, proj, vp, inv;
        sl_camera_view(&slice, view);
        sl_camera_projection(&slice, height > 0 ? (float)width / (float)height : 1, proj);
        glm_mat4_mul(proj, view, vp);
        glm_mat4_inv(vp, inv);
        sl_overlay_box_on_top(ov, inv, sl_cascade_colours[i]);
        glm_mat4_mul((vec4 *)info->cascade_projection[i], (vec4 *)info->cascade_view[i], vp);
        glm_mat4_inv(vp, inv);
        vec3 dim;
        glm_vec3_scale((float *)sl_cascade_colours[i], 0.55f, dim);
        sl_overlay_box_on_top(ov, inv, dim);
    }
}

/* Fits the cascades to the walking camera, frozen, and looks at its frustum from above: over the middle of
 * the range the cascades cover, a little behind, looking down. Thawed, they follow the camera again. */
void sl_lab6_freeze(sl_render_params *p, const sl_camera *walking, bool on, sl_camera *view) {
    sl_cascade_params *c = &p->cascades;
    if (!on) {
        c->use_camera = c->show_frustum = false;
        return;
    }
    c->camera = *walking;
    c->use_camera = c->show_frustum = true;
    const sl_camera *w = walking;
    float reach = c->max_distance > w->near && c->max_distance < w->far ? c->max_distance : w->far;
    float d = fminf(reach, 400.0f) * 0.5f;
    vec3 forward;
    glm_vec3_sub((float *)w->target, (float *)w->position, forward);
    forward[1] = 0;
    if (glm_vec3_norm(forward) < 1e-4f) forward[2] = -1;
    glm_vec3_normalize(forward);
    sl_camera *top = view;
    glm_vec3_copy((float *)w->position, top->target);
    glm_vec3_muladds(forward, d * 0.8f, top->target);
    glm_vec3_copy(top->target, top->position);
    top->position[1] += d * 2.2f;
    glm_vec3_muladds(forward, -d * 0.35f, top->position);
    top->near = 0.5f;
    top->far = d * 6;
}

sl_camera *sl_lab6_fit_camera(sl_render_params *p, const sl_camera *camera) {
    p->cascades.camera = *camera;
    p->cascades.use_camera = true;
    return &p->cascades.camera;
}
