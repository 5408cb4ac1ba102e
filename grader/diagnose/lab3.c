/* Lab 3's diagnoses: acne and Peter Panning on the surfaces that face the light. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"

/* Chamfer distance (in pixels) from every pixel to the nearest pixel where `seed` is set. */
static float *_sl_distance_to(const bool *seed, int w, int h) {
    float *d = malloc(sizeof(float) * (size_t)w * (size_t)h);
    if (!d) return NULL;
    for (int i = 0; i < w * h; i++) d[i] = seed[i] ? 0.0f : 1e9f;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float *v = &d[y * w + x];
            if (x > 0) *v = fminf(*v, d[y * w + x - 1] + 1);
            if (y > 0) *v = fminf(*v, d[(y - 1) * w + x] + 1);
            if (x > 0 && y > 0) *v = fminf(*v, d[(y - 1) * w + x - 1] + 1.4142f);
            if (x + 1 < w && y > 0) *v = fminf(*v, d[(y - 1) * w + x + 1] + 1.4142f);
        }
    for (int y = h - 1; y >= 0; y--)
        for (int x = w - 1; x >= 0; x--) {
            float *v = &d[y * w + x];
            if (x + 1 < w) *v = fminf(*v, d[y * w + x + 1] + 1);
            if (y + 1 < h) *v = fminf(*v, d[(y + 1) * w + x] + 1);
            if (x + 1 < w && y + 1 < h) *v = fminf(*v, d[(y + 1) * w + x + 1] + 1.4142f);
            if (x > 0 && y + 1 < h) *v = fminf(*v, d[(y + 1) * w + x - 1] + 1.4142f);
        }
    return d;
}

static int _sl_compare_floats(const void *a, const void *b) {
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Lab 3's artifacts, measured on surfaces that face the light (the mask):
 * acne = lit in the reference but shadowed here, as a fraction of those lit
 * surfaces; detachment = the reference's shadow missing here, and how far
 * (90th percentile) those pixels are from shadow both images agree on. */
typedef struct _sl_artifacts {
    double acne, missing;
    float gap_px;
} _sl_artifacts;

static _sl_artifacts _sl_measure_artifacts(const sl_image *s, const sl_image *t, const sl_image *mask) {
    _sl_artifacts a = {0};
    int w = t->width, h = t->height, n = w * h;
    long lit = 0, acne = 0, shadow = 0, missing = 0;
    bool *agreed = calloc((size_t)n, 1);
    float *gaps = malloc(sizeof(float) * (size_t)n);
    if (!agreed || !gaps) goto done;
    for (int i = 0; i < n; i++) {
        bool surface = mask->data[i] > 0.5f, ref_lit = t->data[i] >= 0.5f, lit_here = s->data[i] >= 0.5f;
        agreed[i] = !ref_lit && !lit_here;
        if (!surface) continue;
        lit += ref_lit;
        acne += ref_lit && !lit_here;
        shadow += !ref_lit;
        missing += !ref_lit && lit_here;
    }
    a.acne = lit ? (double)acne / (double)lit : 0;
    a.missing = shadow ? (double)missing / (double)shadow : 0;
    float *dist = _sl_distance_to(agreed, w, h);
    int count = 0;
    for (int i = 0; dist && i < n; i++)
        if (mask->data[i] > 0.5f && t->data[i] < 0.5f && s->data[i] >= 0.5f) gaps[count++] = fminf(dist[i], 200);
    if (count) {
        qsort(gaps, (size_t)count, sizeof(float), _sl_compare_floats);
        a.gap_px = gaps[(int)(0.9 * (count - 1))];
    }
    free(dist);
done:
    free(agreed);
    free(gaps);
    return a;
}

bool sl_diagnose_lab3_visibility(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                             sl_check_result *out) {
    _sl_artifacts a = _sl_measure_artifacts(s, t, mask);
    sl_bias_mode mode = c->params.bias.mode;
    sl_acne pattern = sl_measure_acne(s, t, mask);
    if (a.acne > 0.5 && !sl_acne_is_pattern(&pattern)) {
        /* not acne's stripes: lit surfaces shadowed as a whole */
        out->symptoms |= 1u << SL_SYMPTOM_EXTRA_SHADOW;
        sl_diag_say(out, "%.0f%% of lit surfaces are shadowed, in solid regions rather than acne's stripes", 100 * a.acne);
        const char *fn, *todo;
        sl_diag_lookup_function(c, &fn, &todo);
        sl_diag_cause_in(out, fn, "is lab 2's comparison inverted, or the bias added instead of subtracted?");
        return true;
    }
    /* the function each mode's tip is about */
    static const char *const owners[SL_BIAS_MODE_COUNT] = {
        [SL_BIAS_SLOPE_SCALED] = "slope_scaled_bias", [SL_BIAS_POLYGON_OFFSET] = "lab3_depth_pass_state",
        [SL_BIAS_FRONT_FACE_CULLING] = "lab3_depth_pass_state", [SL_BIAS_NORMAL_OFFSET] = "normal_offset_position",
        [SL_BIAS_MIDPOINT] = "lab3_second_depth_state",
    };
    const char *lookup, *lookup_todo;
    sl_diag_lookup_function(c, &lookup, &lookup_todo);
    const char *owner = owners[mode] ? owners[mode] : lookup;
    if (a.acne > 0.01 && a.acne >= a.missing) {
        static const char *const tips[SL_BIAS_MODE_COUNT] = {
            [SL_BIAS_CONSTANT] = "is the constant bias subtracted in the comparison?",
            [SL_BIAS_SLOPE_SCALED] = "slope_scaled_bias() gives too little (still returns 0? TODO lab3.2)",
            [SL_BIAS_POLYGON_OFFSET] = "is GL_POLYGON_OFFSET_FILL enabled with glPolygonOffset(factor, units) in lab3_depth_pass_state (TODO lab3.1)?",
            [SL_BIAS_FRONT_FACE_CULLING] = "are front faces culled in the depth pass (glEnable(GL_CULL_FACE), glCullFace(GL_FRONT), TODO lab3.1)?",
            [SL_BIAS_NORMAL_OFFSET] = "normal_offset_position() moves the point too little (still returns it unchanged? TODO lab3.3)",
            [SL_BIAS_MIDPOINT] = "the second map must hold each object's far side: cull the front faces in "
                                 "lab3_second_depth_state (TODO lab3.4), and compare with the midpoint of the two depths",
        };
        out->symptoms |= 1u << SL_SYMPTOM_ACNE;
        sl_diag_say(out, "shadow acne on %.0f%% of lit surfaces", 100 * a.acne);
        sl_diag_cause_in(out, owner, "bias too small or missing — %s", tips[mode] ? tips[mode] : "compare with a bias");
        return true;
    }
    if (a.missing > 0.02 && a.gap_px >= 1.5f) {
        static const char *const tips[SL_BIAS_MODE_COUNT] = {
            [SL_BIAS_SLOPE_SCALED] = "is the slope term clamped to max_bias?",
            [SL_BIAS_POLYGON_OFFSET] = "are factor and units passed in the right order?",
            [SL_BIAS_NORMAL_OFFSET] = "the offset is texels * texel size * (1 - N.L), along the normal",
            [SL_BIAS_FRONT_FACE_CULLING] = "with culling on, the lookup needs no extra bias",
        };
        out->symptoms |= 1u << SL_SYMPTOM_DETACHED;
        sl_diag_say(out, "shadows detached from their casters by about %.0f px (Peter Panning; %.0f%% of the reference's "
                         "shadow missing)", a.gap_px, 100 * a.missing);
        if (tips[mode] && mode != SL_BIAS_FRONT_FACE_CULLING)
            sl_diag_cause_in(out, owner, "bias too large — %s", tips[mode]);
        else
            sl_diag_cause(out, "bias too large%s%s", tips[mode] ? " — " : "", tips[mode] ? tips[mode] : "");
        return true;
    }
    return false;
}

/* ---- what lab 3's cases run ---- */

/* The camera pass's biased lookup of labs 3 and 4 (framework/shaders/shadow_inputs.glsl): lab 3's
 * function for the mode, and the shadow coordinate, which normal offset computes anew. */
bool sl_biased_lookup_runs(const sl_case *c, const char *fn) {
    sl_bias_mode mode = c->params.bias.mode;
    if (strcmp(fn, "slope_scaled_bias") == 0) return mode == SL_BIAS_SLOPE_SCALED;
    if (strcmp(fn, "normal_offset_position") == 0) return mode == SL_BIAS_NORMAL_OFFSET;
    if (strcmp(fn, "shadow_coord") == 0) return mode != SL_BIAS_NORMAL_OFFSET;
    return false;
}

bool sl_lab3_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    if (k->kind == SL_CHECK_MATRICES) return sl_lab2_case_runs(c, k, fn);
    if (sl_depth_pass_runs(c, k, fn)) return true;
    if (!sl_camera_check(k)) return false;
    if (sl_biased_lookup_runs(c, fn)) return true;
    if (c->params.bias.mode == SL_BIAS_MIDPOINT) return strcmp(fn, "midpoint_compare") == 0;
    return strcmp(fn, c->params.compare == SL_COMPARE_HARDWARE ? "shadow_compare_hardware" : "shadow_compare_manual") == 0;
}

void sl_lab3_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    static const char *const modes[SL_BIAS_MODE_COUNT] = {
        [SL_BIAS_NONE] = "no bias", [SL_BIAS_CONSTANT] = "the constant bias",
        [SL_BIAS_SLOPE_SCALED] = "slope_scaled_bias()", [SL_BIAS_POLYGON_OFFSET] = "polygon offset in the depth pass",
        [SL_BIAS_FRONT_FACE_CULLING] = "front faces culled in the depth pass",
        [SL_BIAS_NORMAL_OFFSET] = "normal_offset_position()", [SL_BIAS_MIDPOINT] = "the midpoint of two maps (the extension)",
    };
    sl_bias_mode mode = c->params.bias.mode;
    if (mode == SL_BIAS_MIDPOINT)
        snprintf(out, n, "%s, compared by midpoint_compare()", modes[mode]);
    else
        snprintf(out, n, "%s, compared by lab 2's %s()", modes[mode] ? modes[mode] : "?",
                 c->params.compare == SL_COMPARE_HARDWARE ? "shadow_compare_hardware" : "shadow_compare_manual");
}

/* ---- lab 3 in the diagnosis table (diagnose/table.c) ---- */
/* Acne is measured on the surfaces facing the light: only with that mask. */
static bool _sl_lab3_visibility_on_mask(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                                        sl_check_result *out) {
    return mask && sl_diagnose_lab3_visibility(c, s, t, mask, out);
}
/* Each bias mode runs code of its own: a failed check in one mode is not behind another's. */
static bool _sl_lab3_same_path(const sl_case *failed, const sl_case *c) {
    return failed->params.bias.mode == c->params.bias.mode;
}

const sl_lab_diagnoses sl_lab3_diagnoses = {
    .lab = 3,
    .same_path = _sl_lab3_same_path,
    .visibility = _sl_lab3_visibility_on_mask,
    .case_runs = sl_lab3_case_runs,
    .case_path = sl_lab3_case_path,
};
