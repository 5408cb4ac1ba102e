/* Lab 3's diagnoses: acne and Peter Panning on the surfaces that face the light. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_params.h"
#include "verdict_rows.h"

/* Chamfer distance (in pixels) from every pixel to the nearest pixel where `seed` is set. */
/* The lookup lab 3's case c draws with: its own in midpoint mode, lab 2's otherwise. */
static void _sl_lab3_lookup_function(const sl_case *c, const char **function, const char **todo) {
    if (c->params.bias.mode == SL_BIAS_MIDPOINT) {
        *function = "midpoint_compare()";
        *todo = "lab3.5";
    } else {
        sl_lab2_lookup_function(c, function, todo);
    }
}

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
        _sl_lab3_lookup_function(c, &fn, &todo);
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
    _sl_lab3_lookup_function(c, &lookup, &lookup_todo);
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

/* ---- verdicts on its probes' rows (verdict.c asks by the probe's name) ---- */

static int _sl_verdict_slope(const sl_verdict_rows *v, char *text, size_t n) {
    const sl_probe_function *f = v->f;
    int rows = v->k->rows;
    double lo = INFINITY, hi = -INFINITY, want_lo = INFINITY, want_hi = -INFINITY;
    for (int r = 0; r < rows; r++) {
        lo = fmin(lo, _sl_got(v, r, 0));
        hi = fmax(hi, _sl_got(v, r, 0));
        want_lo = fmin(want_lo, _sl_want(v, r, 0));
        want_hi = fmax(want_hi, _sl_want(v, r, 0));
    }
    if (rows >= 3 && hi - lo <= 1e-7 && want_hi - want_lo > 1e-5) {
        snprintf(text, n, "it returns %.4g for every angle and every setting: a hand-tuned constant, not the slope-scaled "
                          "bias min(constant + slope * tan(theta), max_bias)", lo);
        return 0;
    }
    /* "the clamp is missing" only when every failing row is one where the reference is clamped and
     * this gives the unclamped constant + slope * tan(theta) there; a clamp to another value, or rows
     * wrong where no clamp acts, get the measured values instead */
    int clamped_wrong = -1, unclamped_rows = 0, failing_rows = 0;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double max_bias = *_sl_param(f, in, "max_bias"), cos_t = fmax(*_sl_param(f, in, "n_dot_l"), 1e-4);
        double open = *_sl_param(f, in, "constant_bias") + *_sl_param(f, in, "slope") * sqrt(1 - cos_t * cos_t) / cos_t;
        failing_rows++;
        if (!_sl_near(_sl_want(v, r, 0), max_bias, 1e-7)) continue;
        if (clamped_wrong < 0) clamped_wrong = r;
        unclamped_rows += _sl_near(_sl_got(v, r, 0), open, 0.002 * open + 1e-6);
    }
    int clamped_rows = 0;
    for (int r = 0; r < rows; r++)
        clamped_rows += _sl_failed(v, r) && _sl_near(_sl_want(v, r, 0), *_sl_param(f, v->k->inputs[r], "max_bias"), 1e-7);
    /* the clamp on the slope term alone, constant + min(slope * tan, max_bias): above max_bias by exactly
     * the constant on every failing row */
    int term_clamped = 0;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double max_bias = *_sl_param(f, in, "max_bias"), c = *_sl_param(f, in, "constant_bias");
        double cos_t = fmax(*_sl_param(f, in, "n_dot_l"), 1e-4);
        double slope_term = *_sl_param(f, in, "slope") * sqrt(1 - cos_t * cos_t) / cos_t;
        double fit = c + fmin(slope_term, max_bias);
        term_clamped += c > 0 && _sl_near(_sl_got(v, r, 0), fit, 0.002 * fit + 1e-7);
    }
    if (clamped_wrong >= 0 && term_clamped == failing_rows) {
        const float *in = v->k->inputs[clamped_wrong];
        snprintf(text, n, "the clamp acts on the slope term alone: where the reference is clamped to max_bias %.4g "
                          "(n_dot_l = %g), it gives %.4g, max_bias plus the constant — clamp the sum, "
                          "min(constant + slope * tan(theta), max_bias)",
                 (double)*_sl_param(f, in, "max_bias"), (double)*_sl_param(f, in, "n_dot_l"), _sl_got(v, clamped_wrong, 0));
        return clamped_wrong;
    }
    /* only the clamped rows fail, not all as without a clamp: the clamp is there, at another value */
    if (clamped_wrong >= 0 && clamped_rows == failing_rows && unclamped_rows < failing_rows) {
        const float *in = v->k->inputs[clamped_wrong];
        snprintf(text, n, "where the reference is clamped to max_bias %.4g (n_dot_l = %g), it gives %.4g — the bias is "
                          "min(constant + slope * tan(theta), max_bias), with the max_bias given",
                 (double)*_sl_param(f, in, "max_bias"), (double)*_sl_param(f, in, "n_dot_l"), _sl_got(v, clamped_wrong, 0));
        return clamped_wrong;
    }
    /* the clamp's label needs every failing row clamped there and unclamped here */
    bool no_clamp = clamped_wrong >= 0 && clamped_rows == failing_rows && unclamped_rows == failing_rows;
    for (int r = 0; r < rows; r++) {
        double max_bias = *_sl_param(f, v->k->inputs[r], "max_bias");
        if (no_clamp && _sl_failed(v, r) && _sl_near(_sl_want(v, r, 0), max_bias, 1e-7) && _sl_got(v, r, 0) > max_bias + 1e-7) {
            snprintf(text, n, "not clamped: the clamp to max_bias is missing — at n_dot_l = %g it gives %.4g, above "
                              "max_bias %.4g; return min(constant + slope * tan(theta), max_bias)",
                     (double)*_sl_param(f, v->k->inputs[r], "n_dot_l"), _sl_got(v, r, 0), max_bias);
            return r;
        }
    }
    /* a cap below the contract's on every failing row: one constant of its own, or one multiple of max_bias */
    int capped = 0, same_value = 0, same_share = 0, first_capped = -1;
    bool max_bias_varies = false;
    for (int r = 0; r < rows && failing_rows >= 2; r++) {
        if (!_sl_failed(v, r)) continue;
        double max_bias = *_sl_param(f, v->k->inputs[r], "max_bias"), s = _sl_got(v, r, 0);
        if (!(s < _sl_want(v, r, 0)) || max_bias <= 0) break;
        if (first_capped < 0) first_capped = r;
        double first_s = _sl_got(v, first_capped, 0);
        double first_max = *_sl_param(f, v->k->inputs[first_capped], "max_bias");
        capped++;
        same_value += _sl_near(s, first_s, 1e-3 * first_s + 1e-9);
        same_share += _sl_near(s / max_bias, first_s / first_max, 1e-3 * first_s / first_max);
        max_bias_varies |= !_sl_near(max_bias, first_max, 1e-9);
    }
    if (capped == failing_rows && capped >= 2 && (same_value == capped || same_share == capped)) {
        const float *in = v->k->inputs[first_capped];
        double s = _sl_got(v, first_capped, 0), max_bias = *_sl_param(f, in, "max_bias");
        if (same_share == capped && (max_bias_varies || same_value != capped))
            snprintf(text, n, "it caps the bias at %.3g times max_bias on every row that differs (%.4g where max_bias "
                              "is %.4g): the cap is max_bias itself — min(constant + slope * tan(theta), max_bias)",
                     s / max_bias, s, max_bias);
        else
            snprintf(text, n, "it caps the bias at %.4g on every row that differs (%.3g times max_bias %.4g)%s — "
                              "min(constant + slope * tan(theta), max_bias), with the max_bias given",
                     s, s / max_bias, max_bias, max_bias_varies ? ": a cap of its own where max_bias belongs" : "");
        return first_capped;
    }
    /* Where the clamp does not act: which function of the angle does the slope term follow? */
    int rows_seen = 0, as_sin = 0, as_angle = 0, as_theta = 0, as_one_minus = 0, as_max_one_minus = 0, as_converted = 0, first = -1;
    double ratio_lo = INFINITY, ratio_hi = -INFINITY, term_lo = INFINITY, term_hi = -INFINITY;
    for (int r = 0; r < rows; r++) {
        const float *in = v->k->inputs[r];
        double cos_t = *_sl_param(f, in, "n_dot_l"), c = *_sl_param(f, in, "constant_bias");
        double slope = *_sl_param(f, in, "slope"), max_bias = *_sl_param(f, in, "max_bias");
        double e = _sl_want(v, r, 0), s = _sl_got(v, r, 0);
        /* rows where either clamp acts say nothing about the slope term */
        if (!_sl_failed(v, r) || slope <= 0 || cos_t <= 0.01 || cos_t >= 1 || e >= max_bias - 1e-7 ||
            s >= max_bias - 1e-7)
            continue;
        if (first < 0) first = r;
        double sin_t = sqrt(1 - cos_t * cos_t), term = (s - c) / slope;
        rows_seen++;
        as_sin += _sl_near(term, sin_t, 0.02 * sin_t + 1e-4);
        as_angle += _sl_near(term, tan(cos_t), 0.02 * tan(cos_t) + 1e-4);
        as_theta += _sl_near(term, acos(cos_t), 0.02);
        /* acos's angle, in radians already, converted again as if it were in degrees */
        double converted = tan(acos(cos_t) * 3.14159265358979323846 / 180.0);
        as_converted += _sl_near(term, converted, 0.03 * converted + 1e-5);
        /* 1 - N.L: LearnOpenGL's bias, max(0.05 * (1 - N.L), 0.005), or that term added to the constant */
        double one_minus = slope * (1 - cos_t);
        as_one_minus += _sl_near(s, c + one_minus, 0.02 * (c + one_minus) + 1e-7);
        as_max_one_minus += _sl_near(s, fmax(one_minus, c), 0.02 * fmax(one_minus, c) + 1e-7);
        ratio_lo = fmin(ratio_lo, s / e);
        ratio_hi = fmax(ratio_hi, s / e);
        term_lo = fmin(term_lo, term / ((e - c) / slope));
        term_hi = fmax(term_hi, term / ((e - c) / slope));
    }
    if (rows_seen == 0) return -1;
    if (as_max_one_minus == rows_seen || as_one_minus == rows_seen) {
        snprintf(text, n, "the slope term follows 1 - N.L, not tan(theta)%s: 1 - N.L stays below 1 where tan(theta) "
                          "grows without bound, so grazing surfaces get too little bias — min(constant + slope * "
                          "tan(theta), max_bias), tan(theta) = sqrt(1 - cos^2) / cos",
                 as_max_one_minus == rows_seen ? ", and the larger of it and the constant where their sum belongs "
                                                 "(LearnOpenGL's max(0.05 * (1 - N.L), 0.005))" : "");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK);
        return first;
    }
    if (as_sin == rows_seen) {
        snprintf(text, n, "sin(theta) where tan(theta) belongs: the slope term follows sqrt(1 - cos^2), not "
                          "sqrt(1 - cos^2) / cos — divide by cos(theta) = N.L");
        return first;
    }
    if (as_theta == rows_seen) {
        snprintf(text, n, "the slope term is the angle theta = acos(N.L) itself, not tan(theta): theta stops at pi/2 "
                          "where tan(theta) grows without bound, so grazing surfaces get too little bias — "
                          "tan(theta) = sqrt(1 - cos^2) / cos");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK);
        return first;
    }
    if (as_angle == rows_seen) {
        snprintf(text, n, "N.L used as an angle: n_dot_l is cos(theta) already; tan(theta) = sqrt(1 - cos^2) / cos");
        return first;
    }
    if (as_converted == rows_seen && rows_seen >= 2) {
        snprintf(text, n, "the angle is converted as if it were in degrees: the slope term is tan(radians(acos(N.L))), "
                          "about 57 times too small, where acos already gives radians — tan(acos(N.L)), or "
                          "sqrt(1 - cos^2) / cos");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK);
        return first;
    }
    if (fabs(term_hi) <= 0.003 && fabs(term_lo) <= 0.003) {
        snprintf(text, n, "the slope term is missing: the constant alone, too small where the surface turns away "
                          "from the light — min(constant + slope * tan(theta), max_bias)");
        return first;
    }
    /* a factor from one row is any ratio at all */
    if (rows_seen >= 2 && term_hi - term_lo <= 0.03 * fabs(term_hi)) {
        snprintf(text, n, "the slope term is %.3g times slope * tan(theta): a factor inside the clamp? The bias is "
                          "min(constant + slope * tan(theta), max_bias)", term_lo);
        return first;
    }
    if (rows_seen >= 2 && ratio_hi - ratio_lo <= 0.03 * fabs(ratio_hi)) {
        snprintf(text, n, "%.3g times the expected bias wherever the clamp does not act: a factor inside the clamp? The "
                          "bias is min(constant + slope * tan(theta), max_bias)", ratio_lo);
        return first;
    }
    return -1;
}

static int _sl_verdict_normal_offset(const sl_verdict_rows *v, char *text, size_t n) {
    const sl_probe_function *f = v->f;
    int against = 0, facing = -1, seen = 0, first = -1;
    double ratio_lo = INFINITY, ratio_hi = -INFINITY;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        const float *p = _sl_param(f, in, "world_position"), *normal = _sl_param(f, in, "normal");
        double along_s = 0, along_e = 0, length_s = 0, length_e = 0;
        for (int i = 0; i < 3; i++) {
            double ds = _sl_got(v, r, i) - p[i], de = _sl_want(v, r, i) - p[i];
            along_s += ds * normal[i];
            along_e += de * normal[i];
            length_s += ds * ds;
            length_e += de * de;
        }
        if (first < 0) first = r;
        if (length_e < 1e-12) {
            if (facing < 0) facing = r;
            continue;
        }
        seen++;
        against += along_s < 0 && along_e > 0;
        double ratio = sqrt(length_s / length_e);
        ratio_lo = fmin(ratio_lo, ratio);
        ratio_hi = fmax(ratio_hi, ratio);
    }
    if (seen > 0 && against == seen) {
        snprintf(text, n, "the point moves against the normal, into the surface: move it along +normal, off the surface");
        return first;
    }
    if (facing >= 0) {
        snprintf(text, n, "a surface facing the light (N.L = 1) must not move: the offset is scaled by (1 - N.L)");
        return facing;
    }
    if (seen > 1 && ratio_hi - ratio_lo <= 0.03 * ratio_hi) {
        snprintf(text, n, "the offset is %.3g times texels * texel_world_size * (1 - N.L): a factor missing or extra",
                 ratio_lo);
        return first;
    }
    return -1;
}

/* Outputs: polygon offset on, factor, units, culling on, cull face. */
static int _sl_verdict_depth_pass_state(const sl_verdict_rows *v, char *text, size_t n) {
    /* nothing switched on in any mode, where the contract switches polygon offset on in one and culling in
     * another (and the call returned): what a mode enables does not survive the call */
    int enables = 0, first = -1, any_on = 0;
    for (int r = 0; r < v->k->rows; r++) {
        double s0 = _sl_got(v, r, 0), s3 = _sl_got(v, r, 3);
        if (isnan(s0) || isnan(s3)) return -1;
        any_on += s0 != 0 || s3 != 0;
        if (_sl_want(v, r, 0) != 0 || _sl_want(v, r, 3) != 0) {
            enables |= (_sl_want(v, r, 0) != 0 ? 1 : 0) | (_sl_want(v, r, 3) != 0 ? 2 : 0);
            if (first < 0) first = r;
        }
    }
    if (enables == 3 && !any_on) {
        snprintf(text, n, "in every mode it leaves polygon offset and culling off: nothing a mode switches on outlives "
                          "the call — a reset (glDisable) after the mode's own glEnable undoes it, or the mode's "
                          "branch is never taken; reset both switches first, then set the mode's");
        return first;
    }
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        int mode = (int)v->k->inputs[r][0], previous = v->f->param_count > 3 ? (int)v->k->inputs[r][3] : -1;
        char name[96];
        if (previous >= 0 && previous != mode)
            snprintf(name, sizeof name, "%s (right after %s)", sl_bias_mode_name((sl_bias_mode)mode),
                     sl_bias_mode_name((sl_bias_mode)previous));
        else
            snprintf(name, sizeof name, "%s", sl_bias_mode_name((sl_bias_mode)mode));
        double e[5], s[5];
        for (int o = 0; o < 5; o++) {
            e[o] = _sl_want(v, r, o);
            s[o] = _sl_got(v, r, o);
        }
        if (isnan(s[0])) continue;
        if (s[0] && e[0] && s[1] == e[2] && s[2] == e[1] && e[1] != e[2]) {
            snprintf(text, n, "factor and units swapped: glPolygonOffset(factor, units) takes the slope factor first");
            return r;
        }
        if (s[3] && !e[3]) {
            snprintf(text, n, "culling is left on in %s mode: switch GL_CULL_FACE off in every mode but front-culling — "
                              "a plane with no thickness has only a front face, and culled it casts no shadow%s", name,
                     previous >= 0 ? "; each mode sets every switch, whatever the mode before left on" : "");
            return r;
        }
        if (s[0] && !e[0]) {
            snprintf(text, n, "polygon offset is left on in %s mode: switch GL_POLYGON_OFFSET_FILL off in every mode "
                              "but polygon-offset%s", name,
                     previous >= 0 ? "; each mode sets every switch, whatever the mode before left on" : "");
            return r;
        }
        if (!s[0] && e[0]) {
            snprintf(text, n, "no polygon offset in polygon-offset mode: glPolygonOffset acts only while "
                              "GL_POLYGON_OFFSET_FILL is enabled");
            return r;
        }
        if (!s[3] && e[3]) {
            snprintf(text, n, "no culling in front-culling mode: glEnable(GL_CULL_FACE) with glCullFace(GL_FRONT)");
            return r;
        }
        if (e[3] && s[4] != e[4]) {
            snprintf(text, n, "the wrong faces are culled in front-culling mode: glCullFace(GL_FRONT), so the map keeps "
                              "the far side of each object");
            return r;
        }
    }
    return -1;
}

/* lab3_second_depth_state: front faces culled, back faces culled, faces chosen with culling off, depth test on,
 * depth func, depth writes on. */
static int _sl_verdict_second_depth_state(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double s[6];
        for (int o = 0; o < 6; o++) s[o] = _sl_got(v, r, o);
        if (isnan(s[0])) continue;
        bool after_back = v->k->inputs[r][0] == 1;
        int func = (int)s[4];
        if (func == 0x0204 || func == 0x0206) { /* GL_GREATER, GL_GEQUAL */
            snprintf(text, n, "the depth test keeps the farther fragment (glDepthFunc(%s)): lab1_begin_depth_pass has "
                              "cleared the map to 1.0, which no depth exceeds, so nothing is stored (and from a 0 "
                              "clear it would keep the farthest surface of all, not each object's far side); keep "
                              "GL_LESS and cull the faces that face the light, glCullFace(GL_FRONT)",
                     func == 0x0204 ? "GL_GREATER" : "GL_GEQUAL");
            return r;
        }
        if (s[0] && s[1]) {
            snprintf(text, n, "both front and back faces are culled (GL_FRONT_AND_BACK): no triangle is drawn and the "
                              "second map stays at its clear value; cull GL_FRONT only");
            return r;
        }
        if (s[1] && !s[0]) {
            snprintf(text, n, "the back faces are culled%s: the second map keeps the surface facing the light, the "
                              "first map's surface, so the midpoint is the first depth; cull GL_FRONT",
                     after_back ? " (after a pass that culled back faces, the function leaves that choice as it "
                                  "was: set glCullFace(GL_FRONT) every time)" : "");
            return r;
        }
        if (!s[0] && !s[1]) {
            if (s[2] == 1)
                snprintf(text, n, "glCullFace(GL_FRONT) chooses the faces, but GL_CULL_FACE is never enabled, so "
                                  "no face is culled and the second map keeps the first surface; glEnable(GL_CULL_FACE)");
            else
                snprintf(text, n, "no face is culled: the second map keeps the surface facing the light, as the "
                                  "first does; glEnable(GL_CULL_FACE) with glCullFace(GL_FRONT)");
            return r;
        }
        if (!s[3]) {
            snprintf(text, n, "the depth test is switched off: without it GL writes no depth at all, so the second map "
                              "keeps its clear value; leave the depth test on (lab 1's pass turned it on)");
            return r;
        }
        if (!s[5]) {
            snprintf(text, n, "depth writes are off (glDepthMask(GL_FALSE)): the second map keeps its clear value; "
                              "leave the mask on");
            return r;
        }
        if (func != 0x0201) { /* GL_LESS (GL_LEQUAL is read as GL_LESS) */
            snprintf(text, n, "the depth test is changed (glDepthFunc 0x%04X): of the back faces along a ray the map "
                              "must keep the nearest, GL_LESS as lab 1 set it", func);
            return r;
        }
    }
    return -1;
}

/* ---- what a failing row predicts a picture shows ---- */

#define _SL_DARK (1u << SL_SYMPTOM_TOO_DARK)
#define _SL_LIGHT (1u << SL_SYMPTOM_TOO_LIGHT)
#define _SL_GROSS (1u << SL_SYMPTOM_GROSS)

/* lab3_depth_pass_state: polygon offset on, factor, units, culling on, cull face. */
static uint32_t _sl_state_row_predicts(const sl_verdict_rows *v, int row) {
    double e[5], s[5];
    for (int o = 0; o < 5; o++) {
        e[o] = _sl_want(v, row, o);
        s[o] = _sl_got(v, row, o);
        if (isnan(s[o])) return SL_SYMPTOMS_ANY;
    }
    uint32_t p = 0;
    if (s[0] && !e[0]) p |= _SL_LIGHT;                          /* an offset pushes depths away: detached shadows */
    if (!s[0] && e[0]) p |= _SL_DARK | _SL_GROSS;               /* acne where the offset belonged */
    if (s[0] && e[0] && (s[1] != e[1] || s[2] != e[2])) p |= _SL_DARK | _SL_LIGHT;
    if (s[3] && !e[3]) p |= _SL_LIGHT | _SL_GROSS;              /* culled faces cast no shadow (a plane loses its own) */
    if (!s[3] && e[3]) p |= _SL_DARK | _SL_GROSS;               /* the lit side stays in the map: acne */
    if (s[3] && e[3] && s[4] != e[4]) p |= _SL_DARK | _SL_GROSS; /* the near faces kept: acne */
    return p ? p : SL_SYMPTOMS_ANY;
}

/* normal_offset_position: a point moved less along the normal than it should shadows itself. */
static uint32_t _sl_offset_row_predicts(const sl_verdict_rows *v, int row) {
    const float *in = v->k->inputs[row];
    const float *p = _sl_param(v->f, in, "world_position"), *normal = _sl_param(v->f, in, "normal");
    if (!p || !normal) return SL_SYMPTOMS_ANY;
    double along_s = 0, along_e = 0;
    for (int i = 0; i < 3; i++) {
        double got = _sl_got(v, row, i);
        if (isnan(got)) return SL_SYMPTOMS_ANY;
        along_s += (got - p[i]) * normal[i];
        along_e += (_sl_want(v, row, i) - p[i]) * normal[i];
    }
    if (along_s < 0) return _SL_DARK | _SL_GROSS; /* into the surface */
    return along_s < along_e ? _SL_DARK : _SL_LIGHT | (along_s > 4 * along_e + 1e-6 ? _SL_GROSS : 0);
}

/* lab3_second_depth_state: a map with the first surface in it gives the first depth as the midpoint (acne);
 * one with nothing in it gives a midpoint halfway to 1.0 (shadows that lose their contact). */
static uint32_t _sl_second_state_row_predicts(const sl_verdict_rows *v, int row) {
    double front = _sl_got(v, row, 0), back = _sl_got(v, row, 1);
    if (isnan(front)) return SL_SYMPTOMS_ANY;
    if (!front && !back) return _SL_DARK | _SL_GROSS;
    return SL_SYMPTOMS_ANY;
}

/* ---- lab 3 in the diagnosis table (diagnose/table.c) ---- */
/* A row of lab3_depth_pass_state's probe is in one bias mode: the case's. */
static int _sl_bias_mode_of(const sl_case *c) { return (int)c->params.bias.mode; }

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
    .functions = {{"lab3_depth_pass_state", _sl_verdict_depth_pass_state, _sl_state_row_predicts, _sl_bias_mode_of},
                  {"slope_scaled_bias", _sl_verdict_slope},
                  {"normal_offset_position", _sl_verdict_normal_offset, _sl_offset_row_predicts},
                  {"lab3_second_depth_state", _sl_verdict_second_depth_state, _sl_second_state_row_predicts}},
    .lookup_function = _sl_lab3_lookup_function,
    .same_path = _sl_lab3_same_path,
    .visibility = _sl_lab3_visibility_on_mask,
    .case_runs = sl_lab3_case_runs,
    .case_path = sl_lab3_case_path,
};
