/* Verdicts on a failed function probe: what the pattern of its rows says is
 * wrong, in a few words, before the row that shows it is quoted. Each
 * verdict reads only the rows' inputs and the two sets of outputs, never a
 * guess at the student's code: a filter's weight sum is what it gives on an
 * empty map, its width how far its results depart from a single comparison
 * across the synthetic step edge, and so on. */
#define _POSIX_C_SOURCE 200809L
#include "sl_verdict.h"
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_params.h"

/* The inputs of one parameter of a row, or NULL if the function has none of that name. */
static const float *_sl_param(const sl_probe_function *f, const float *row, const char *name) {
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        if (strcmp(f->params[i].name, name) == 0) return row + offset;
        offset += sl_probe_type_size(f->params[i].type);
    }
    return NULL;
}

static bool _sl_failed(const sl_verdict_rows *v, int row) { return (v->failing >> row) & 1u; }
static double _sl_got(const sl_verdict_rows *v, int row, int o) { return v->student[row * v->f->output_count + o]; }
static double _sl_want(const sl_verdict_rows *v, int row, int o) { return v->expected[row * v->f->output_count + o]; }
static bool _sl_near(double a, double b, double tolerance) { return fabs(a - b) <= tolerance; }

/* ---- filters: a map, a shadow coordinate, a bias; 1 lit, 0 shadowed ---- */

typedef enum _sl_row_kind {
    _SL_ROW_OUTSIDE,     /* behind the light, or off the map or past its far plane: lit */
    _SL_ROW_HOMOGENEOUS, /* inside, w not 1: the divide matters */
    _SL_ROW_EMPTY_MAP,   /* nothing in front anywhere: 1, whatever the kernel */
    _SL_ROW_OWN_SURFACE, /* on the stored surface itself: lit thanks to the bias alone */
    _SL_ROW_OCCLUDED,    /* an occluder over every sample: 0 */
    _SL_ROW_EDGE,        /* the step map: an occluder's edge */
    _SL_ROW_OTHER
} _sl_row_kind;

typedef struct _sl_filter_row {
    _sl_row_kind kind;
    double p[3];   /* the divided coordinate */
    double bias;
    double centre; /* one comparison at p.xy, as an unfiltered lookup gives it */
} _sl_filter_row;

static _sl_filter_row _sl_filter_row_of(const sl_probe_function *f, const float *in) {
    _sl_filter_row r = {.kind = _SL_ROW_OTHER};
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias");
    r.bias = bias ? *bias : 0;
    if (!map || !coord) return r;
    double w = coord[3];
    for (int i = 0; i < 3; i++) r.p[i] = w != 0 ? coord[i] / w : 0;
    bool outside = w <= 0;
    for (int i = 0; i < 3; i++) outside |= r.p[i] < 0 || r.p[i] > 1;
    int texel = (int)floor(r.p[0] * SL_PROBE_MAP_SIZE);
    texel = texel < 0 ? 0 : texel >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : texel;
    double stored = sl_probe_map_depth((sl_probe_map)(int)*map, texel, 0);
    r.centre = r.p[2] - r.bias > stored ? 0.0 : 1.0;
    /* the occluder's own surface: behind its stored depth by less than the bias */
    double occluder = sl_probe_map_depth(SL_PROBE_MAP_OCCLUDED, 0, 0);
    bool own_surface = stored == occluder && r.p[2] > occluder && r.p[2] - r.bias <= occluder;
    if (outside) r.kind = _SL_ROW_OUTSIDE;
    else if (w != 1) r.kind = _SL_ROW_HOMOGENEOUS;
    else if ((int)*map == SL_PROBE_MAP_LIT) r.kind = _SL_ROW_EMPTY_MAP;
    else if (own_surface) r.kind = _SL_ROW_OWN_SURFACE;
    else if ((int)*map == SL_PROBE_MAP_OCCLUDED) r.kind = _SL_ROW_OCCLUDED;
    else if ((int)*map == SL_PROBE_MAP_STEP) r.kind = _SL_ROW_EDGE;
    return r;
}

/* The first failing row of a kind (-1: none). */
static int _sl_first_failing(const sl_verdict_rows *v, _sl_row_kind kind) {
    for (int row = 0; row < v->k->rows; row++)
        if (_sl_failed(v, row) && _sl_filter_row_of(v->f, v->k->inputs[row]).kind == kind) return row;
    return -1;
}

/* A failing row with w not 1 whose result differs from its twin's, the same
 * point given with w = 1 (the divide is wrong), or with no twin, the only
 * kind of row that fails; -1 otherwise (a twin failing alike is another mistake). */
static int _sl_homogeneous_differs(const sl_verdict_rows *v) {
    const sl_probe_function *f = v->f;
    int coord = 0, floats = sl_probe_input_count(f), others = 0, lone = -1;
    for (int i = 0; i < f->param_count && strcmp(f->params[i].name, "shadow_coord") != 0; i++)
        coord += sl_probe_type_size(f->params[i].type);
    for (int a = 0; a < v->k->rows; a++) {
        if (!_sl_failed(v, a)) continue;
        _sl_filter_row fa = _sl_filter_row_of(f, v->k->inputs[a]);
        if (fa.kind != _SL_ROW_HOMOGENEOUS) {
            others++;
            continue;
        }
        bool twin = false;
        for (int b = 0; b < v->k->rows && !twin; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            bool same = ib[coord + 3] == 1.0f;
            for (int i = 0; same && i < floats; i++)
                same = i >= coord && i < coord + 3 ? fabs(ia[i] / ia[coord + 3] - ib[i]) < 1e-6
                       : i == coord + 3   ? true
                                          : ia[i] == ib[i];
            if (!same) continue;
            twin = true;
            if (!_sl_near(_sl_got(v, a, 0), _sl_got(v, b, 0), 1e-3)) return a;
        }
        if (!twin && lone < 0) lone = a;
    }
    return others == 0 ? lone : -1;
}

/* Rows that differ only in a parameter called *radius*, giving the same result where the reference's differ. */
static int _sl_radius_ignored(const sl_verdict_rows *v, char *text, size_t n) {
    const sl_probe_function *f = v->f;
    int radius = -1, offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        if (strstr(f->params[i].name, "radius")) radius = offset;
        offset += sl_probe_type_size(f->params[i].type);
    }
    if (radius < 0) return -1;
    int floats = sl_probe_input_count(f);
    for (int a = 0; a < v->k->rows; a++) {
        if (!_sl_failed(v, a)) continue;
        for (int b = 0; b < v->k->rows; b++) {
            if (b == a) continue;
            bool same = true;
            for (int i = 0; i < floats; i++) same &= i == radius || v->k->inputs[a][i] == v->k->inputs[b][i];
            if (!same || v->k->inputs[a][radius] == v->k->inputs[b][radius]) continue;
            if (_sl_near(_sl_got(v, a, 0), _sl_got(v, b, 0), 1e-4) && !_sl_near(_sl_want(v, a, 0), _sl_want(v, b, 0), 0.02)) {
                snprintf(text, n, "the radius is ignored: radius %g and radius %g give the same %.4g at the same point "
                                  "(expected %.4g and %.4g) — the kernel's extent must come from the radius",
                         (double)v->k->inputs[a][radius], (double)v->k->inputs[b][radius], _sl_got(v, a, 0),
                         _sl_want(v, a, 0), _sl_want(v, b, 0));
                return a;
            }
        }
    }
    return -1;
}

/* PCSS's blocker search, told apart from the filter that follows it:
 * - over a floor (the "step_floor" map) the receiver's own surface, stored a
 *   little nearer than p.z but within the bias, must not count as a blocker:
 *   if it does, d_blocker comes out near d_receiver and the penumbra shrinks
 *   (lighter there), while on the "step" map, with nothing behind the
 *   occluder, every row still agrees;
 * - on the lit side of an edge (a single comparison says lit) a wide light
 *   still sees the occluder: a search region too small (a fixed width, not
 *   light_size_uv * (d_receiver - near) / d_receiver) finds no blocker there
 *   and returns 1.0, while inside the occluder, where the point itself is a
 *   blocker, the penumbra, and so every result, is right (a penumbra wrong
 *   there too is the filter's width: raw depths, a fixed radius). */
static int _sl_verdict_pcss_search(const sl_verdict_rows *v, char *text, size_t n) {
    int floor_lighter = -1, floor_rows = 0, other_failing = 0, lit_side_lost = -1, lit_side_fail = 0, shadow_partial_fail = 0;
    for (int r = 0; r < v->k->rows; r++) {
        const float *in = v->k->inputs[r];
        const float *map = _sl_param(v->f, in, "shadow_map");
        _sl_filter_row fr = _sl_filter_row_of(v->f, in);
        double e = _sl_want(v, r, 0), s = _sl_got(v, r, 0);
        bool failed = _sl_failed(v, r), floor = map && (int)*map == SL_PROBE_MAP_STEP_FLOOR;
        if (floor) floor_rows++;
        if (floor && failed && s > e && floor_lighter < 0) floor_lighter = r;
        if (!floor && failed) other_failing++;
        bool soft = e > 0.02 && e < 0.98, edge = fr.kind == _SL_ROW_EDGE;
        if (edge && soft && fr.centre == 1.0 && failed) {
            lit_side_fail++;
            if (s >= 0.999 && lit_side_lost < 0) lit_side_lost = r;
        }
        if (edge && fr.centre == 0.0 && failed) shadow_partial_fail++; /* inside the occluder, the point is a blocker */
    }
    if (floor_rows && floor_lighter >= 0 && other_failing == 0) {
        snprintf(text, n, "the blocker search counts the receiver's own surface as a blocker: over a floor it finds "
                          "the floor itself, a little nearer than p.z, so d_blocker comes out near d_receiver and the "
                          "penumbra shrinks — a blocker is a stored depth nearer than p.z - bias: the bias belongs in "
                          "the blocker search too");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_NARROW_PENUMBRA | 1u << SL_SYMPTOM_GROSS);
        return floor_lighter;
    }
    if (lit_side_lost >= 0 && lit_side_fail > 0 && shadow_partial_fail == 0) {
        snprintf(text, n, "the blocker search looks too close: beside an occluder, where a wide light still sees it, it "
                          "finds no blocker and returns 1.0, while inside the occluder the penumbra is right — search "
                          "light_size_uv * (d_receiver - near) / d_receiver around p (the receiver's view of the light), "
                          "not a fixed width");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_NARROW_PENUMBRA | 1u << SL_SYMPTOM_GROSS);
        return lit_side_lost;
    }
    return -1;
}

/* A (2r+1)^2 grid whose samples are `spacing` texels apart, on a synthetic map (nearest texels, the
 * border's depth 1.0 off the map): what pcf_grid gives for a row with that spacing. */
static double _sl_grid_with_spacing(const sl_probe_function *f, const float *in, double spacing) {
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias"), *radius = _sl_param(f, in, "radius");
    if (!map || !coord || !bias || !radius || coord[3] <= 0) return NAN;
    double x = coord[0] / coord[3], y = coord[1] / coord[3], z = coord[2] / coord[3] - *bias;
    int r = (int)*radius, lit = 0, all = 0;
    for (int j = -r; j <= r; j++)
        for (int i = -r; i <= r; i++) {
            double u = x + i * spacing / SL_PROBE_MAP_SIZE, w = y + j * spacing / SL_PROBE_MAP_SIZE;
            double stored = u < 0 || u >= 1 || w < 0 || w >= 1
                                ? 1.0
                                : sl_probe_map_depth((sl_probe_map)(int)*map, (int)floor(u * SL_PROBE_MAP_SIZE),
                                                     (int)floor(w * SL_PROBE_MAP_SIZE));
            lit += !(z > stored);
            all++;
        }
    return (double)lit / all;
}

/* The grid's samples another distance apart than one texel (a scale of 1.5, as some published
 * kernels take, or a fixed step in uv): the spacings, in texels of the 64-texel map, at which a grid
 * gives every failing row what the student's gives. One map size cannot tell a scale from a uv
 * step, so the message names both. */
static int _sl_grid_spacing(const sl_verdict_rows *v, char *text, size_t n) {
    if (strcmp(v->f->name, "pcf_grid") != 0) return -1;
    double lo = INFINITY, hi = -INFINITY;
    int first = -1;
    for (int step = 25; step <= 400; step++) {
        double spacing = step / 100.0;
        if (step == 100) continue;
        bool all = true;
        int failing = 0;
        for (int r = 0; r < v->k->rows && all; r++) {
            if (!_sl_failed(v, r)) continue;
            failing++;
            double tolerance = v->k->row_tolerance[r] > 0 ? v->k->row_tolerance[r] : v->k->tolerance;
            double model = _sl_grid_with_spacing(v->f, v->k->inputs[r], spacing);
            all = !isnan(model) && _sl_near(_sl_got(v, r, 0), model, tolerance + 1e-4);
            if (all && first < 0) first = r;
        }
        if (all && failing > 0) {
            lo = fmin(lo, spacing);
            hi = fmax(hi, spacing);
        }
    }
    if (first < 0 || !(lo <= hi) || (lo < 1 && hi > 1)) return -1;
    bool wide = lo > 1;
    char spacing[64];
    if (hi - lo < 0.05) snprintf(spacing, sizeof spacing, "%.2g", lo);
    else snprintf(spacing, sizeof spacing, "%.2g to %.2g", lo, hi);
    snprintf(text, n, "the kernel is too %s: its samples are %s texels apart on this 64-texel map, not one — offset "
                      "(x, y) times the texel, 1.0 / textureSize(map, 0), and nothing else: no scale (some published "
                      "kernels spread a 3x3 grid 1.5 texels apart) and no fixed step in uv",
             wide ? "wide" : "narrow", spacing);
    sl_verdict_predicts(v, (wide ? 1u << SL_SYMPTOM_WIDE_PENUMBRA : 1u << SL_SYMPTOM_NARROW_PENUMBRA) |
                               1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_GROSS |
                               SL_PREDICTS_EVERY_SETTING);
    return first;
}

static int _sl_verdict_filter(const sl_verdict_rows *v, char *text, size_t n) {
    const sl_probe_function *f = v->f;
    bool kernel = strcmp(f->name, "pcf_grid") == 0 || strcmp(f->name, "pcf_poisson") == 0;
    bool pcss = strcmp(f->name, "pcss") == 0;
    int row;
    /* lit and shadowed exchanged on most rows: the comparison itself, whatever else */
    int swapped = 0, compared = 0;
    for (int r = 0; r < v->k->rows; r++) {
        _sl_filter_row fr = _sl_filter_row_of(f, v->k->inputs[r]);
        if (fr.kind == _SL_ROW_OUTSIDE || fr.kind == _SL_ROW_OTHER) continue;
        double e = _sl_want(v, r, 0), s = _sl_got(v, r, 0);
        if (e > 0.02 && e < 0.98) continue;
        compared++;
        swapped += _sl_near(s, 1 - e, 0.02);
    }
    if (compared >= 3 && swapped * 3 >= compared * 2) {
        snprintf(text, n, "the comparison is inverted: lit where the point is shadowed and the other way round — 0.0 "
                          "when p.z - bias is farther than the stored depth");
        return -1; /* the first row that differs shows it */
    }
    /* the coordinate first: every other row depends on it */
    if ((row = _sl_first_failing(v, _SL_ROW_OUTSIDE)) >= 0) {
        snprintf(text, n, "a point outside the light's frustum must be lit: return 1.0 when w <= 0, or when x, y or z "
                          "is outside [0, 1] after the divide");
        return row;
    }
    if ((row = _sl_homogeneous_differs(v)) >= 0) {
        snprintf(text, n, "no divide by w: the shadow coordinate is homogeneous — divide xyz by w before the lookup");
        return row;
    }
    if (pcss && (row = _sl_first_failing(v, _SL_ROW_EMPTY_MAP)) >= 0) {
        snprintf(text, n, "no blocker found must mean fully lit: with nothing in the map in front of the point, the "
                          "blocker search finds none, and pcss() returns 1.0");
        return row;
    }
    if (kernel && (row = _sl_first_failing(v, _SL_ROW_EMPTY_MAP)) >= 0) {
        double sum = _sl_got(v, row, 0);
        snprintf(text, n, "the weights sum to %.4g, not 1 (nothing in front gives %.4g): the kernel is not normalised "
                          "— divide the sum of the results by the number of samples", sum, sum);
        return row;
    }
    if ((row = _sl_first_failing(v, _SL_ROW_OWN_SURFACE)) >= 0 && _sl_got(v, row, 0) < _sl_want(v, row, 0)) {
        snprintf(text, n, "the bias is not subtracted: a point on the stored surface itself compares as shadowed, which "
                          "is shadow acne — compare p.z - bias with the stored depth");
        return row;
    }
    if ((row = _sl_first_failing(v, _SL_ROW_OCCLUDED)) >= 0 && _sl_got(v, row, 0) > _sl_want(v, row, 0)) {
        if (pcss)
            snprintf(text, n, "the blocker search finds no blockers where an occluder covers the whole map: stored "
                              "depths nearer than p.z - bias are the blockers");
        else
            snprintf(text, n, "samples land off the map: with an occluder over the whole map it still gives %.3g lit — "
                              "the kernel is far too wide; scale the offsets by the texel size, 1.0 / textureSize(map, 0)",
                     _sl_got(v, row, 0));
        return row;
    }
    if (pcss && (row = _sl_verdict_pcss_search(v, text, n)) >= 0) return row;
    if (!kernel) return -1; /* PCSS and single lookups: their rows say the rest */
    /* Across the edge: hard 0/1 results where soft ones are expected, then the width */
    int soft = 0, hard = 0, as_centre = 0, narrow = 0, wide = 0, first_soft = -1, first_width = -1;
    for (int r = 0; r < v->k->rows; r++) {
        _sl_filter_row fr = _sl_filter_row_of(f, v->k->inputs[r]);
        if (fr.kind != _SL_ROW_EDGE || !_sl_failed(v, r)) continue;
        double e = _sl_want(v, r, 0), s = _sl_got(v, r, 0);
        if (e > 0.02 && e < 0.98) {
            soft++;
            if (first_soft < 0) first_soft = r;
            if (s <= 0.001 || s >= 0.999) {
                hard++;
                as_centre += _sl_near(s, fr.centre, 0.001);
            }
        }
        double tolerance = v->k->row_tolerance[r] > 0 ? v->k->row_tolerance[r] : v->k->tolerance;
        double here = fabs(s - fr.centre), there = fabs(e - fr.centre);
        if (here < there - tolerance) narrow++;
        if (here > there + tolerance) wide++;
        if (first_width < 0 && (here < there - tolerance || here > there + tolerance)) first_width = r;
    }
    if (soft > 0 && hard == soft) {
        if (as_centre == hard)
            snprintf(text, n, "one comparison per point: results are 0 or 1 where the kernel should blend, exactly as "
                              "a single lookup gives them — the kernel has no width; compare at every sample and "
                              "average the results");
        else
            snprintf(text, n, "depths averaged, then compared once: results are 0 or 1 where the kernel should blend, "
                              "and not where one comparison puts them — filtering depths instead of comparison results "
                              "(Reeves 1987); compare at every sample, then average the 0/1 results");
        return first_soft;
    }
    /* fractional, but the same whatever the radius */
    if ((row = _sl_radius_ignored(v, text, n)) >= 0) return row;
    if ((row = _sl_grid_spacing(v, text, n)) >= 0) return row;
    if (narrow > wide && first_width >= 0) {
        snprintf(text, n, "the kernel is too narrow: across an occluder's edge its results stay closer to a single "
                          "comparison's 0 or 1 than they should — are the offsets radius texels wide, each texel "
                          "1.0 / textureSize(map, 0)?");
        return first_width;
    }
    if (wide > narrow && first_width >= 0) {
        snprintf(text, n, "the kernel is too wide: results blend farther from an occluder's edge than they should — "
                          "are the offsets scaled by the texel size, 1.0 / textureSize(map, 0), and by the radius only once?");
        return first_width;
    }
    return -1;
}

/* ---- lab 3 ---- */

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
    /* where the reference is clamped, above max_bias here: no clamp */
    for (int r = 0; r < rows; r++) {
        double max_bias = *_sl_param(f, v->k->inputs[r], "max_bias");
        if (_sl_failed(v, r) && _sl_near(_sl_want(v, r, 0), max_bias, 1e-7) && _sl_got(v, r, 0) > max_bias + 1e-7) {
            snprintf(text, n, "not clamped: the clamp to max_bias is missing — at n_dot_l = %g it gives %.4g, above "
                              "max_bias %.4g; return min(constant + slope * tan(theta), max_bias)",
                     (double)*_sl_param(f, v->k->inputs[r], "n_dot_l"), _sl_got(v, r, 0), max_bias);
            return r;
        }
    }
    /* Where the clamp does not act: which function of the angle does the slope term follow? */
    int rows_seen = 0, as_sin = 0, as_angle = 0, as_one_minus = 0, as_max_one_minus = 0, first = -1;
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
        as_angle += _sl_near(term, tan(cos_t), 0.02 * tan(cos_t) + 1e-4) || _sl_near(term, acos(cos_t), 0.02);
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
    if (as_angle == rows_seen) {
        snprintf(text, n, "N.L used as an angle: n_dot_l is cos(theta) already; tan(theta) = sqrt(1 - cos^2) / cos");
        return first;
    }
    if (fabs(term_hi) <= 0.02 && fabs(term_lo) <= 0.02) {
        snprintf(text, n, "the slope term is missing: the constant alone, too small where the surface turns away "
                          "from the light — min(constant + slope * tan(theta), max_bias)");
        return first;
    }
    if (term_hi - term_lo <= 0.03 * fabs(term_hi)) {
        snprintf(text, n, "the slope term is %.3g times slope * tan(theta): a factor inside the clamp? The bias is "
                          "min(constant + slope * tan(theta), max_bias)", term_lo);
        return first;
    }
    if (ratio_hi - ratio_lo <= 0.03 * fabs(ratio_hi)) {
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

/* ---- lab 2 ---- */

/* glm_ortho's box and glm_perspective's field of view, read back from a
 * column-major matrix (outputs m00, m10, ...: index col * 4 + row). */
static bool _sl_ortho_box(const double *m, double box[6]) {
    if (fabs(m[15] - 1) > 1e-6 || fabs(m[11]) > 1e-6 || m[0] == 0 || m[5] == 0 || m[10] == 0) return false;
    double w = 2 / m[0], h = 2 / m[5], d = -2 / m[10];
    double cx = -m[12] * w / 2, cy = -m[13] * h / 2, cz = -m[14] * d / 2;
    box[0] = cx - w / 2, box[1] = cx + w / 2, box[2] = cy - h / 2, box[3] = cy + h / 2;
    box[4] = cz - d / 2, box[5] = cz + d / 2; /* near, far */
    return true;
}

static int _sl_verdict_light_projection(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double s[16], e[16], bs[6], be[6];
        for (int o = 0; o < 16; o++) {
            s[o] = _sl_got(v, r, o);
            e[o] = _sl_want(v, r, o);
        }
        if (_sl_ortho_box(e, be)) {
            if (!_sl_ortho_box(s, bs)) {
                snprintf(text, n, "a sun needs an orthographic projection (glm_ortho): parallel rays");
                return r;
            }
            double depth = be[5] - be[4], pad = depth / 1.02 * 0.01, tol = 1e-3 * fmax(1, depth);
            bool sides = fabs(bs[0] - be[0]) < tol && fabs(bs[1] - be[1]) < tol && fabs(bs[2] - be[2]) < tol &&
                         fabs(bs[3] - be[3]) < tol;
            if (sides && fabs(bs[4] - (be[4] + pad)) < tol && fabs(bs[5] - (be[5] - pad)) < tol) {
                snprintf(text, n, "near and far hug the scene's box with no padding: pad each by 1%% of the box's "
                                  "depth range (near = -max z - pad, far = -min z + pad), or rounding clips the "
                                  "farthest corner");
                sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_TOO_DARK);
                return r;
            }
            if (!sides) {
                snprintf(text, n, "the box's sides are not the scene's corners' extent in light view space: left/right "
                                  "and bottom/top are the min and max x and y of all 8 corners, transformed by the "
                                  "light's view as points (w = 1)");
                return r;
            }
            snprintf(text, n, "near and far are not -(max z) and -(min z) of the corners in light view space (the "
                              "camera looks down -z), padded by 1%% of the range");
            return r;
        }
        /* a spot light: glm_perspective(fovy, 1, near, far), fovy = 2 * spot_angle_deg in radians */
        if (e[5] > 0 && s[5] > 0 && fabs(e[11] + 1) < 1e-6) {
            double fov_e = 2 * atan(1 / e[5]), fov_s = 2 * atan(1 / s[5]);
            if (fabs(fov_s * 2 - fov_e) < 1e-3) {
                snprintf(text, n, "the field of view is the cone's half-angle: fovy is twice spot_angle_deg");
                return r;
            }
            const double degrees_per_radian = 57.29577951308232;
            if (fabs(s[5] - 1 / tan(fov_e * degrees_per_radian / 2)) < 1e-3) {
                snprintf(text, n, "the angle is in degrees where glm_perspective takes radians: glm_rad(2 * spot_angle_deg)");
                return r;
            }
        }
    }
    return -1;
}

/* ---- lab 1 ---- */

/* Outputs: min filter, mag filter, wrap S, wrap T, the border's depth (-1 without a border). */
static int _sl_verdict_create_shadow_map(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 0))) continue;
        double wrap_s = _sl_got(v, r, 2), wrap_t = _sl_got(v, r, 3), border = _sl_got(v, r, 4);
        bool wrap_wrong = wrap_s != _sl_want(v, r, 2) || wrap_t != _sl_want(v, r, 3);
        if (wrap_wrong) {
            double wrong = wrap_s != _sl_want(v, r, 2) ? wrap_s : wrap_t;
            snprintf(text, n, "lookups past the map's edge do not read \"nothing there\": the wrap mode is %s, not "
                              "GL_CLAMP_TO_BORDER on S and T — %s, so a filter's samples past the edge find shadow where "
                              "there is none (lab 4's kernels); use GL_CLAMP_TO_BORDER with GL_TEXTURE_BORDER_COLOR "
                              "(1, 1, 1, 1), the far plane, lit",
                     sl_diag_enum_name((unsigned)wrong),
                     wrong == GL_REPEAT || wrong == GL_MIRRORED_REPEAT ? "depths from the opposite edge wrap in"
                                                                       : "the edge texels are stretched outwards");
            sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK);
            return r;
        }
        if (fabs(border - _sl_want(v, r, 4)) > 1e-6) {
            snprintf(text, n, "the border's depth is %g, not 1.0: a lookup past the map's edge must read the far plane, "
                              "lit — GL_TEXTURE_BORDER_COLOR (1, 1, 1, 1) (a depth texture reads its first component)",
                     border);
            sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK);
            return r;
        }
        double min = _sl_got(v, r, 0), mag = _sl_got(v, r, 1);
        if (min != _sl_want(v, r, 0) || mag != _sl_want(v, r, 1)) {
            bool mipmap = min != GL_NEAREST && min != GL_LINEAR;
            snprintf(text, n, "the map is filtered with %s (min) and %s (mag), not GL_NEAREST: %s",
                     sl_diag_enum_name((unsigned)min), sl_diag_enum_name((unsigned)mag),
                     mipmap ? "a mipmap min filter makes a map without mipmaps incomplete, and every read 0"
                            : "a depth map is read exactly; GL_LINEAR blends the depths of different surfaces");
            return r;
        }
    }
    return -1;
}

/* Outputs: the map's framebuffer bound, viewport width and height, depth
 * test, depth function, depth writes, the depth after the call (cleared: 1). */
static int _sl_verdict_begin_depth_pass(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 0))) continue;
        double size = v->k->inputs[r][0];
        if (_sl_got(v, r, 0) != 1) {
            snprintf(text, n, "the map's framebuffer is not bound: glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer) "
                              "first, or the depth pass draws into another one");
        } else if (_sl_got(v, r, 1) != size || _sl_got(v, r, 2) != size) {
            snprintf(text, n, "the viewport is %gx%g, not the map's %gx%g: glViewport(0, 0, map->size, map->size)",
                     _sl_got(v, r, 1), _sl_got(v, r, 2), size, size);
        } else if (!_sl_got(v, r, 3)) {
            snprintf(text, n, "the depth test is off: with GL_DEPTH_TEST disabled no depth is written at all — "
                              "glEnable(GL_DEPTH_TEST)");
        } else if (_sl_got(v, r, 4) != _sl_want(v, r, 4)) {
            snprintf(text, n, "the depth function is not GL_LESS (nor GL_LEQUAL): each texel must keep the nearest "
                              "depth — glDepthFunc(GL_LESS)");
        } else if (!_sl_got(v, r, 5)) {
            snprintf(text, n, "depth writes are off: glDepthMask(GL_TRUE), before the clear too (glClear respects it)");
        } else if (_sl_got(v, r, 6) != 1) {
            snprintf(text, n, "the depths are not cleared to 1.0 at the start of the pass: glClear(GL_DEPTH_BUFFER_BIT) "
                              "after binding the map's framebuffer, every pass");
        } else {
            continue;
        }
        return r;
    }
    return -1;
}

int sl_probe_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    text[0] = '\0';
    const char *name = v->f->name;
    if (v->f->glsl && _sl_param(v->f, v->k->inputs[0], "shadow_map") && _sl_param(v->f, v->k->inputs[0], "shadow_coord"))
        return _sl_verdict_filter(v, text, n);
    if (strcmp(name, "lab1_create_shadow_map") == 0) return _sl_verdict_create_shadow_map(v, text, n);
    if (strcmp(name, "lab2_light_projection") == 0) return _sl_verdict_light_projection(v, text, n);
    if (strcmp(name, "lab1_begin_depth_pass") == 0) return _sl_verdict_begin_depth_pass(v, text, n);
    if (strcmp(name, "slope_scaled_bias") == 0) return _sl_verdict_slope(v, text, n);
    if (strcmp(name, "normal_offset_position") == 0) return _sl_verdict_normal_offset(v, text, n);
    if (strcmp(name, "lab3_depth_pass_state") == 0) return _sl_verdict_depth_pass_state(v, text, n);
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(v->f->lab);
    return lab && lab->rows_verdict ? lab->rows_verdict(v, text, n) : -1;
}

/* ---- what a failing row predicts a picture shows ---- */

#define _SL_DARK (1u << SL_SYMPTOM_TOO_DARK)
#define _SL_LIGHT (1u << SL_SYMPTOM_TOO_LIGHT)
#define _SL_GROSS (1u << SL_SYMPTOM_GROSS)
#define _SL_NARROW (1u << SL_SYMPTOM_NARROW_PENUMBRA)
#define _SL_WIDE (1u << SL_SYMPTOM_WIDE_PENUMBRA)

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

uint32_t sl_probe_row_predicts(const sl_verdict_rows *v, int row) {
    const sl_probe_function *f = v->f;
    if (strcmp(f->name, "lab3_depth_pass_state") == 0) return _sl_state_row_predicts(v, row);
    if (strcmp(f->name, "normal_offset_position") == 0) return _sl_offset_row_predicts(v, row);
    if (f->output_count != 1) return SL_SYMPTOMS_ANY;
    /* a visibility (a lighter one), or a bias (a larger one lightens) */
    bool visibility = strcmp(f->outputs, "visibility") == 0 || strcmp(f->outputs, "p_max") == 0;
    bool bias = strcmp(f->outputs, "bias") == 0;
    if (!visibility && !bias) return SL_SYMPTOMS_ANY;
    double s = _sl_got(v, row, 0), e = _sl_want(v, row, 0);
    if (isnan(s) || isinf(s)) return SL_SYMPTOMS_ANY;
    uint32_t p = s < e ? _SL_DARK : _SL_LIGHT;
    if (bias) {
        if (s <= 0.25 * e || s >= 4 * e + 1e-6) p |= _SL_GROSS;
        return p;
    }
    if (fabs(s - e) >= 0.5) p |= _SL_GROSS;
    /* across an edge: nearer a single comparison's 0 or 1 than the solution is narrower; a width
     * off by much there grows with the kernel (a wide light, a large radius): gross in a picture */
    if (e > 0.02 && e < 0.98 && _sl_param(f, v->k->inputs[row], "shadow_map")) {
        _sl_filter_row fr = _sl_filter_row_of(f, v->k->inputs[row]);
        p |= fabs(s - fr.centre) < fabs(e - fr.centre) ? _SL_NARROW : _SL_WIDE;
        if (fabs(s - e) >= 0.15) p |= _SL_GROSS;
    }
    return p;
}
