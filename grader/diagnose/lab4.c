/* Lab 4's diagnoses: filter kernels and PCSS penumbrae. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_diag_words.h"
#include "sl_gl.h"
#include "verdict_rows.h"

#include <cglm/cglm.h>

static int _sl_compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The filter lab 4's case c looks up with: its filter mode's (none: lab 2's manual comparison). */
static void _sl_lab4_lookup_function(const sl_case *c, const char **function, const char **todo) {
    static const char *const filters[SL_FILTER_MODE_COUNT][2] = {
        {"shadow_compare_manual() (lab 2)", "lab2.5"}, {"pcf_hardware()", "lab4.2"}, {"pcf_grid()", "lab4.3"},
        {"pcf_poisson()", "lab4.4"}, {"pcss()", "lab4.5"},
    };
    *function = filters[c->params.filter.mode][0];
    *todo = filters[c->params.filter.mode][1];
}

bool sl_diagnose_lab4_visibility(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                                 sl_check_result *out) {
    long n = (long)t->width * t->height, soft_ref = 0, soft_stu = 0, lit = 0, lit_exact = 0, penumbra = 0;
    long histogram[256] = {0}, core = 0, core_kept = 0, binary = 0, ratios = 0;
    double pen_s = 0, pen_t = 0;
    double *ratio = malloc(sizeof(double) * (size_t)n);
    for (long i = 0; i < n; i++) {
        if (mask && mask->data[i] < 0.5f) continue;
        float vs = s->data[i], vt = t->data[i];
        soft_ref += vt > 0.1f && vt < 0.9f;
        soft_stu += vs > 0.1f && vs < 0.9f;
        if (vt >= 0.99f) {
            lit++;
            lit_exact += vs >= 0.99f;
            histogram[(int)(glm_clamp(vs, 0, 1) * 255.0f + 0.5f)]++;
        }
        if (vt <= 0.01f) {
            core++;
            core_kept += vs <= 0.01f;
        }
        if (vt > 0.1f && vt < 0.9f) {
            penumbra++;
            pen_s += vs;
            pen_t += vt;
            binary += vs <= 0.01f || vs >= 0.99f;
            if (ratio && vs < 0.98f && vs > 0.02f) ratio[ratios++] = vs / vt;
        }
    }
    /* weights summing to k > 1 scale every soft value by k (until 1): the ratio is k across the penumbra */
    double ratio_low = 1, ratio_mid = 1, ratio_high = 1;
    if (ratio && ratios >= 20) {
        qsort(ratio, (size_t)ratios, sizeof(double), _sl_compare_doubles);
        ratio_low = ratio[ratios / 4];
        ratio_mid = ratio[ratios / 2];
        ratio_high = ratio[3 * ratios / 4];
    }
    free(ratio);
    long mode_count = 0;
    int mode = 255;
    for (int i = 0; i < 256; i++)
        if (histogram[i] > mode_count) {
            mode_count = histogram[i];
            mode = i;
        }
    const char *fn, *todo;
    _sl_lab4_lookup_function(c, &fn, &todo);
    sl_acne acne = sl_measure_acne(s, t, mask);
    double soft_ref_pc = 100.0 * (double)soft_ref / (double)n, soft_stu_pc = 100.0 * (double)soft_stu / (double)n;
    bool cores_intact = core_kept >= core * 9 / 10; /* too few weights keep 0 at 0; a wide kernel does not */
    if (acne.mean < 0.93 && lit_exact < lit / 5 && mode_count > lit * 7 / 10 && cores_intact) {
        /* weights summing to less than 1 scale every lit pixel to one value */
        sl_diag_say(out, "lit surfaces are too dark (visibility %.2f where the reference is fully lit)", mode / 255.0);
        sl_diag_cause_in(out, fn, "the kernel's weights sum to less than 1 — divide by the number of samples in %s", fn);
    } else if (acne.fraction > 0.05 && sl_acne_is_pattern(&acne)) {
        out->symptoms |= 1u << SL_SYMPTOM_ACNE;
        sl_diag_say(out, "shadow acne on %.0f%% of lit surfaces: they shadow themselves in a fine pattern, softened by "
                         "the filter (mean visibility %.2f where the reference is fully lit)", 100 * acne.fraction,
                    acne.mean);
        sl_diag_cause_in(out, fn, "is the bias subtracted in every comparison of %s, p.z - bias (TODO %s)?", fn, todo);
    } else if (acne.mean < 0.93) {
        /* smoothly darkened: samples far away compare the receiver with the surface's own distant depths */
        sl_diag_say(out, "lit surfaces are %s darkened, smoothly (mean visibility %.2f where the reference is fully "
                         "lit)", sl_diag_darkening_word(acne.mean), acne.mean);
        sl_diag_cause_in(out, fn, "the kernel reaches too far and compares with distant depths — are the sample offsets "
                           "scaled by the texel size, 1.0 / textureSize(map, 0)?");
    } else if (c->params.filter.mode == SL_FILTER_HARDWARE && soft_ref > n / 500 && soft_stu < soft_ref / 4) {
        out->symptoms |= 1u << SL_SYMPTOM_HARD_EDGES;
        sl_diag_say(out, "hard edges where the 2x2 hardware filter blends (%.1f%% of pixels in penumbra, reference "
                         "%.1f%%)", soft_stu_pc, soft_ref_pc);
        sl_diag_cause_in(out, "lab4_configure_shadow_texture", "the depth texture needs GL_LINEAR filtering with compare mode on "
                           "(lab4_configure_shadow_texture, TODO lab4.1)");
    } else if (!cores_intact && core > n / 200) {
        sl_diag_say(out, "shadows too faint: %.0f%% of the reference's fully shadowed pixels are partly lit here",
                    100.0 * (double)(core - core_kept) / (double)core);
        sl_diag_cause_in(out, fn, "samples land outside the shadow, or off the map — are the offsets scaled by the texel "
                           "size, 1.0 / textureSize(map, 0), in %s?", fn);
    } else if (penumbra > n / 1000 && ratio_mid > 1.3 && ratio_low > 1.15 && ratio_high < 2.5 * ratio_low) {
        sl_diag_say(out, "penumbrae too bright (mean %.2f, reference %.2f; about %.1f times the reference's value)",
                    pen_s / (double)penumbra, pen_t / (double)penumbra, ratio_mid);
        sl_diag_cause_in(out, fn, "the kernel's weights sum to more than 1 — divide by the number of samples in %s", fn);
    } else if (c->params.filter.mode == SL_FILTER_PCSS && soft_ref > n / 200 && soft_stu < soft_ref / 2) {
        sl_diag_say(out, "penumbrae too narrow for this light (%.1f%% of pixels in penumbra, reference %.1f%%)",
                    soft_stu_pc, soft_ref_pc);
        sl_diag_cause_in(out, "pcss", "does pcss() filter with the width from the blocker search, w = (d_receiver - d_blocker) * "
                           "w_light / d_blocker (TODO lab4.5)?");
    } else if (soft_ref > n / 200 && soft_stu < soft_ref / 4 && binary > penumbra * 9 / 10) {
        out->symptoms |= 1u << SL_SYMPTOM_HARD_EDGES;
        sl_diag_say(out, "hard edges where soft ones are expected (%.1f%% of pixels in penumbra, reference %.1f%%)",
                    soft_stu_pc, soft_ref_pc);
        sl_diag_cause_in(out, fn, "one comparison per pixel, or depths averaged before the comparison (Reeves 1987)? Compare "
                           "every sample in %s, then average the 0/1 results", fn);
    } else if (soft_ref > n / 200 && soft_stu < soft_ref * 2 / 3) {
        sl_diag_say(out, "penumbrae too narrow (%.1f%% of pixels in penumbra, reference %.1f%%)", soft_stu_pc, soft_ref_pc);
        sl_diag_cause_in(out, fn, "does the kernel's width follow its radius, in texels times 1.0 / textureSize(map, 0), in %s?",
                      fn);
    } else if (soft_stu > 3 * soft_ref && soft_stu > n / 50) {
        sl_diag_say(out, "the kernel is far too wide (%.1f%% of pixels in penumbra, reference %.1f%%)", soft_stu_pc,
                    soft_ref_pc);
        sl_diag_cause_in(out, fn, "are the sample offsets scaled by the texel size, 1.0 / textureSize(map, 0)?");
    } else {
        return false;
    }
    return true;
}

/* Width in pixels of the soft part (0.1 < v < 0.9) along a probe line. */
static float _sl_penumbra_width(const sl_image *img, const sl_probe *p) {
    float dx = p->to[0] - p->from[0], dy = p->to[1] - p->from[1];
    float length = sqrtf(dx * dx + dy * dy);
    int steps = (int)ceilf(length * 4);
    int soft = 0;
    for (int i = 0; i <= steps; i++) {
        float f = steps ? (float)i / (float)steps : 0;
        int x = (int)lroundf(p->from[0] + f * dx), y = (int)lroundf(p->from[1] + f * dy);
        if (x < 0 || y < 0 || x >= img->width || y >= img->height) continue;
        float v = sl_image_pixel(img, x, y)[0];
        soft += v > 0.1f && v < 0.9f;
    }
    return steps ? (float)soft * length / (float)steps : 0;
}

void sl_diagnose_penumbra(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "visibility");
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no visibility image was captured");
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    if (s->width != t->width || s->height != t->height) {
        sl_diag_say(out, "the image is %dx%d, the reference %dx%d", s->width, s->height, t->width, t->height);
        out->settled = true;
        return;
    }
    float ws[SL_CHECK_MAX_PROBES], wt[SL_CHECK_MAX_PROBES];
    bool ok = true;
    char widths[512] = "";
    for (int i = 0; i < k->probe_count; i++) {
        ws[i] = _sl_penumbra_width(s, &k->probes[i]);
        wt[i] = _sl_penumbra_width(t, &k->probes[i]);
        ok &= fabsf(ws[i] - wt[i]) <= fmaxf(2.0f, (float)k->threshold * wt[i]);
        snprintf(widths + strlen(widths), sizeof widths - strlen(widths), "%s%s %.0f px (reference %.0f)",
                 i ? ", " : "", k->probes[i].name, ws[i], wt[i]);
    }
    /* widths are measured on the student's own picture: it must also be lit where the reference is */
    const sl_image *m = ref->lit_mask.data ? &ref->lit_mask : NULL;
    bool light_ok = !sl_visibility_lit_lost(s, t, m).failed;
    if (ok && light_ok) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    if (ok && sl_diag_lit_lost(s, t, m, "penumbra", out)) return;
    int last = k->probe_count - 1;
    float most = 0, least = 1e9f;
    for (int i = 0; i < k->probe_count; i++) {
        most = fmaxf(most, ws[i] / fmaxf(wt[i], 1));
        least = fminf(least, ws[i]);
    }
    const char *fn, *todo;
    _sl_lab4_lookup_function(c, &fn, &todo);
    if (last > 0 && wt[0] < wt[last] && ws[0] > ws[last] + 1) {
        sl_diag_say(out, "penumbrae inverted: wide at the contact, narrow far from it (%s)", widths);
        sl_diag_cause_in(out, "pcss", "penumbra formula inverted — w = (d_receiver - d_blocker) * w_light / d_blocker (TODO %s)",
                      todo);
        return;
    }
    sl_diag_say(out, "penumbra widths differ from the reference: %s", widths);
    if (least <= 1 && wt[last] >= 3) {
        out->symptoms |= 1u << SL_SYMPTOM_HARD_EDGES;
        sl_diag_cause_in(out, fn, "hard edges where soft ones are expected: %s filters depths instead of comparison results, "
                           "or finds no blockers?", fn);
    } else if (most > 2.5f) {
        sl_diag_cause_in(out, fn, "penumbrae far too wide: are the offsets scaled by the texel size, and the penumbra projected "
                           "onto the map (* near / d_receiver)?");
    } else if (last > 0 && wt[last] > 1.5f * wt[0] && ws[last] <= 1.2f * ws[0]) {
        sl_diag_cause_in(out, "pcss", "no contact hardening: the penumbra does not widen away from the contact — does the filter "
                           "radius come from the blocker search (TODO %s)?", todo);
    }
}

/* ---- what lab 4's cases run ---- */

static const char *const _sl_filters[SL_FILTER_MODE_COUNT] = {"shadow_compare_manual", "pcf_hardware", "pcf_grid",
                                                              "pcf_poisson", "pcss"};

bool sl_lab4_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    if (k->kind == SL_CHECK_MATRICES) return sl_lab2_case_runs(c, k, fn);
    if (sl_depth_pass_runs(c, k, fn)) return true;
    if (!sl_camera_check(k)) return false;
    if (sl_biased_lookup_runs(c, fn)) return true;
    if (strcmp(fn, "lab4_configure_shadow_texture") == 0) return true;
    sl_filter_mode mode = c->params.filter.mode;
    return (unsigned)mode < SL_FILTER_MODE_COUNT && strcmp(fn, _sl_filters[mode]) == 0;
}

/* A filter's probe row at another radius than the case's says nothing about
 * the case, when some row has the case's radius. */
bool sl_lab4_meets_row(const sl_case *c, const sl_check *probe, int row) {
    const sl_probe_function *f = sl_probe_at(probe->function);
    const char *param = NULL;
    double want = 0;
    if (strcmp(f->name, "pcf_grid") == 0 && c->params.filter.mode == SL_FILTER_GRID) {
        param = "radius";
        want = c->params.filter.grid_radius;
    } else if (strcmp(f->name, "pcf_poisson") == 0 && c->params.filter.mode == SL_FILTER_POISSON) {
        param = "radius_texels";
        want = c->params.filter.poisson_radius;
    }
    if (!param) return true;
    bool any = false;
    for (int r = 0; r < probe->rows; r++) any |= fabs(*sl_probe_row_param(f, probe->inputs[r], param) - want) < 1e-6;
    return !any || fabs(*sl_probe_row_param(f, probe->inputs[row], param) - want) < 1e-6;
}

void sl_lab4_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    const sl_filter_settings *f = &c->params.filter;
    switch (f->mode) {
    case SL_FILTER_NONE: snprintf(out, n, "no filter: lab 2's shadow_compare_manual()"); break;
    case SL_FILTER_HARDWARE: snprintf(out, n, "pcf_hardware() on a GL_LINEAR map"); break;
    case SL_FILTER_GRID: snprintf(out, n, "pcf_grid() with radius %d", f->grid_radius); break;
    case SL_FILTER_POISSON: snprintf(out, n, "pcf_poisson() with radius %g texels", (double)f->poisson_radius); break;
    case SL_FILTER_PCSS: snprintf(out, n, "pcss() with light size %g", (double)c->scene.light.size); break;
    default: break;
    }
    if (c->params.bias.mode != SL_BIAS_CONSTANT) {
        char bias[200];
        sl_lab3_case_path(c, r, bias, sizeof bias);
        size_t used = strlen(out);
        snprintf(out + used, n - used, ", on lab 3's %.*s", (int)strcspn(bias, ","), bias);
    }
}

/* ---- lab 4 in the diagnosis table (diagnose/table.c) ---- */
/* Any filter of lab 4's reads past the map's edge. */
static bool _sl_lab4_filters_past_edge(const sl_case *c) { return c->params.filter.mode != SL_FILTER_NONE; }

/* lab4_configure_shadow_texture: the probe's texture holds GL_NEAREST_MIPMAP_NEAREST and GL_NEAREST before the
 * call (sl_probe_calls.c), a pair no mode asks for. Found unchanged on every row that differs, the calls did
 * not reach depth_texture: set on another texture, or none. */
static int _sl_verdict_configure(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, unchanged = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        failing++;
        unchanged += _sl_got(v, r, 0) == GL_NEAREST_MIPMAP_NEAREST && _sl_got(v, r, 1) == GL_NEAREST;
        if (first < 0) first = r;
    }
    if (!failing || unchanged < failing) return -1;
    snprintf(text, n, "none of its settings reached depth_texture: its filters are as they were before the call, on "
                      "every row that differs — glTexParameteri(GL_TEXTURE_2D, ...) changes the texture bound to "
                      "GL_TEXTURE_2D on the active unit: bind depth_texture there and set its parameters on that target "
                      "(glActiveTexture selects a unit, not a texture)");
    return first;
}

/* A row of lab4_configure_shadow_texture's probe is in one filter mode: the case's. */
static int _sl_filter_mode_of(const sl_case *c) { return (int)c->params.filter.mode; }

const sl_lab_diagnoses sl_lab4_diagnoses = {
    .lab = 4,
    .filtered_lookup = true,
    .filters_past_edge = _sl_lab4_filters_past_edge,
    .checks = {{SL_CHECK_PENUMBRA, sl_diagnose_penumbra}},
    .visibility = sl_diagnose_lab4_visibility,
    .case_runs = sl_lab4_case_runs,
    .case_path = sl_lab4_case_path,
    .meets_row = sl_lab4_meets_row,
    .lookup_function = _sl_lab4_lookup_function,
    .functions = {{"lab4_configure_shadow_texture", _sl_verdict_configure, .case_mode = _sl_filter_mode_of}},
};
