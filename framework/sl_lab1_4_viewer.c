#include "sl_lab1_4_viewer.h"

#include <stdio.h>
#include <string.h>

#include "sl_overlay.h"
#include "sl_probe_calls.h"
#include "sl_renderer.h"

/* Labs 1 and 2: how the depth is compared, and the constant bias. */
static void _sl_compare_text(const sl_view_context *c, char *out, size_t n) {
    const sl_render_params *p = c->params;
    snprintf(out, n, "%s compare, bias %.4f", p->compare == SL_COMPARE_HARDWARE ? "hardware" : "manual",
             p->bias.constant);
}

void sl_lab1_settings_text(const sl_view_context *c, char *out, size_t n) { _sl_compare_text(c, out, n); }

void sl_lab1_drawing_text(const sl_view_context *c, char *out, size_t n) {
    (void)c;
    snprintf(out, n, "no shadows (only lab 1's depth map)");
}

/* ---- Lab 2: the shadow lookup ---- */
static void _sl_lab2_drawing_text(const sl_view_context *c, char *out, size_t n) {
    (void)c;
    snprintf(out, n, "lab 2's hard shadows");
}

/* The bias and compare lines of the frame lab `drawn` (2..4) drew, unless the asked lab's bias is its own. */
static void _sl_bias_lines(sl_overlay *ov, const sl_view_context *c, int drawn) {
    const sl_render_params *p = c->params;
    const sl_technique *asked = sl_technique_of(p->lab);
    if (c->info->cube_frame || (asked && asked->own_bias)) return;
    const sl_bias_settings *b = &p->bias;
    if (drawn == 2 || b->mode == SL_BIAS_CONSTANT)
        sl_overlay_line(ov, NULL, "bias: constant %.5f", b->constant);
    else if (b->mode == SL_BIAS_SLOPE_SCALED)
        sl_overlay_line(ov, NULL, "bias: slope %.4f + %.4f tan, max %.3f", b->constant, b->slope, b->max_bias);
    else if (b->mode == SL_BIAS_POLYGON_OFFSET)
        sl_overlay_line(ov, NULL, "bias: polygon offset (%.1f, %.1f)", b->polygon_offset_factor,
                        b->polygon_offset_units);
    else if (b->mode == SL_BIAS_NORMAL_OFFSET)
        sl_overlay_line(ov, NULL, "bias: normal offset %.2f texels + %.5f", b->normal_offset, b->constant);
    else
        sl_overlay_line(ov, NULL, "bias: %s", sl_bias_mode_name(b->mode));
    if (drawn <= 3) sl_overlay_line(ov, NULL, "compare: %s", p->compare == SL_COMPARE_HARDWARE ? "hardware" : "manual");
}

static void _sl_lab2_overlay_lines(sl_overlay *ov, const sl_view_context *c) { _sl_bias_lines(ov, c, 2); }

const sl_technique sl_lab2_technique = {
    .name = "shadow lookup",
    .lab = 2,
    .panel_keys = {"C", "[ ]"},
    .settings_text = _sl_compare_text,
    .drawing_text = _sl_lab2_drawing_text,
    .overlay_lines = _sl_lab2_overlay_lines,
    .probes = sl_lab2_probes,
};

/* ---- Lab 3: bias ---- */
static void _sl_lab3_settings_text(const sl_view_context *c, char *out, size_t n) {
    snprintf(out, n, "bias: %s %.4f", sl_bias_mode_name(c->params->bias.mode), c->params->bias.constant);
}

static void _sl_lab3_drawing_text(const sl_view_context *c, char *out, size_t n) {
    snprintf(out, n, "lab 3's hard shadows, %s bias", sl_bias_mode_name(c->params->bias.mode));
}

static void _sl_lab3_overlay_lines(sl_overlay *ov, const sl_view_context *c) { _sl_bias_lines(ov, c, 3); }

const sl_technique sl_lab3_technique = {
    .name = "bias",
    .lab = 3,
    .panel_keys = {"C", "[ ]", "B"},
    .settings_text = _sl_lab3_settings_text,
    .drawing_text = _sl_lab3_drawing_text,
    .overlay_lines = _sl_lab3_overlay_lines,
    .probes = sl_lab3_probes,
};

/* ---- Lab 4: filtering ---- */
static void _sl_lab4_settings_text(const sl_view_context *c, char *out, size_t n) {
    const sl_render_params *p = c->params;
    const sl_filter_settings *f = &p->filter;
    snprintf(out, n, "bias: %s %.4f, filter: %s", sl_bias_mode_name(p->bias.mode), p->bias.constant,
             sl_filter_mode_name(f->mode));
    size_t used = strlen(out);
    if (f->mode == SL_FILTER_GRID)
        snprintf(out + used, n - used, " %dx%d", 2 * f->grid_radius + 1, 2 * f->grid_radius + 1);
    if (f->mode == SL_FILTER_POISSON) snprintf(out + used, n - used, " r=%.1f", f->poisson_radius);
    if (f->mode == SL_FILTER_PCSS) snprintf(out + used, n - used, " light %.2f", c->scene->light.size);
}

static void _sl_lab4_drawing_text(const sl_view_context *c, char *out, size_t n) {
    const sl_filter_settings *f = &c->params->filter;
    if (f->mode == SL_FILTER_GRID)
        snprintf(out, n, "lab 4's PCF grid %dx%d", 2 * f->grid_radius + 1, 2 * f->grid_radius + 1);
    else if (f->mode == SL_FILTER_NONE) snprintf(out, n, "lab 4's unfiltered shadows");
    else snprintf(out, n, "lab 4's %s filter", sl_filter_mode_name(f->mode));
}

static void _sl_lab4_overlay_lines(sl_overlay *ov, const sl_view_context *c) {
    _sl_bias_lines(ov, c, 4);
    const sl_filter_settings *f = &c->params->filter;
    if (f->mode == SL_FILTER_GRID)
        sl_overlay_line(ov, NULL, "filter: PCF grid %dx%d (kernel radius %d)", 2 * f->grid_radius + 1,
                        2 * f->grid_radius + 1, f->grid_radius);
    else if (f->mode == SL_FILTER_POISSON)
        sl_overlay_line(ov, NULL, "filter: Poisson disk, radius %.1f texels", f->poisson_radius);
    else if (f->mode == SL_FILTER_PCSS)
        sl_overlay_line(ov, NULL, "filter: PCSS, light size %.2f", c->scene->light.size);
    else
        sl_overlay_line(ov, NULL, "filter: %s", sl_filter_mode_name(f->mode));
}

const sl_technique sl_lab4_technique = {
    .name = "filtering",
    .lab = 4,
    .panel_keys = {"[ ]", "B", "F", "- ="},
    .settings_text = _sl_lab4_settings_text,
    .drawing_text = _sl_lab4_drawing_text,
    .overlay_lines = _sl_lab4_overlay_lines,
    .default_for_lights = 1u << SL_LIGHT_DIRECTIONAL | 1u << SL_LIGHT_SPOT,
    .probes = sl_lab4_probes,
};
