#define _POSIX_C_SOURCE 200809L
#include "verdict_filter.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_params.h"
#include "sl_filter_model.h"
#include "verdict_rows.h"

/* ---- filters: a map, a shadow coordinate, a bias; 1 lit, 0 shadowed ---- */

_sl_filter_row _sl_filter_row_of(const sl_probe_function *f, const float *in) {
    _sl_filter_row r = {.kind = _SL_ROW_OTHER};
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias");
    r.bias = bias ? *bias : 0;
    if (!map || !coord) return r;
    double w = coord[3];
    for (int i = 0; i < 3; i++) r.p[i] = w != 0 ? coord[i] / w : 0;
    bool outside = w <= 0;
    for (int i = 0; i < 3; i++) outside |= r.p[i] < 0 || r.p[i] > 1;
    int tx = (int)floor(r.p[0] * SL_PROBE_MAP_SIZE), ty = (int)floor(r.p[1] * SL_PROBE_MAP_SIZE);
    tx = tx < 0 ? 0 : tx >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : tx;
    ty = ty < 0 ? 0 : ty >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : ty;
    double stored = sl_probe_map_depth((sl_probe_map)(int)*map, tx, ty);
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
    int coord = _sl_param_offset(f, "shadow_coord"), floats = sl_probe_input_count(f), others = 0, lone = -1;
    if (coord < 0) return -1;
    /* a generic row has w != 1 and every other term drawn too: its failure alone says nothing of the divide */
    int written = v->k->rows - v->k->generic_rows;
    for (int a = 0; a < written; a++) {
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
    bool blend_shared = false;
    /* "ignored" only when every pair of rows that differ in the radius alone agrees: a kernel whose
     * results change with the radius (an asymmetric loop, a pattern of its own) may agree on one pair */
    for (int a = 0; a < v->k->rows; a++)
        for (int b = 0; b < v->k->rows; b++) {
            bool same = b != a;
            for (int i = 0; same && i < floats; i++) same = i == radius || v->k->inputs[a][i] == v->k->inputs[b][i];
            if (same && !_sl_near(_sl_got(v, a, 0), _sl_got(v, b, 0), 1e-4)) return -1;
            /* a shared 0 or 1 is a kernel that does not reach the edge at either radius (too small, or
             * halved), not one without an extent: a blend the radius does not change is */
            blend_shared |= same && _sl_got(v, a, 0) > 0.02 && _sl_got(v, a, 0) < 0.98;
        }
    if (!blend_shared) return -1;
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

/* Exactly 1.0 where the contract gives 0: a point behind an occluder (one comparison at p says shadowed)
 * with every search sample blocked comes out lit, and only the no-blocker branch returns exactly 1.0 from
 * there — a filter of any width over an all-blocked region gives 0. So the blocker search found none. */
static int _sl_pcss_misses_umbra(const sl_verdict_rows *v, char *text, size_t n) {
    int row = -1;
    for (int r = 0; r < v->k->rows && row < 0; r++) {
        _sl_filter_row fr = _sl_filter_row_of(v->f, v->k->inputs[r]);
        if (_sl_failed(v, r) && fr.kind == _SL_ROW_EDGE && fr.centre == 0.0 && _sl_want(v, r, 0) <= 0.02 &&
            _sl_got(v, r, 0) >= 0.999)
            row = r;
    }
    if (row < 0) return -1;
    snprintf(text, n, "the blocker search finds no blockers behind an occluder: a point whose whole search region is "
                      "occluded (the contract gives 0) comes out exactly 1.0, which only \"no blocker found\" returns "
                      "— a blocker is a stored depth d with d < p.z - bias, both raw depths from the map (only the "
                      "blockers' average is made a distance, with pcf_linear_depth)");
    sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_MISSING_SHADOW | 1u << SL_SYMPTOM_NO_SHADOWS |
                               1u << SL_SYMPTOM_GROSS);
    return row;
}

/* Shadowed on every row of the empty map (every stored depth 1.0, the far plane) while an occluder's rows
 * are right: each comparison found a stored depth nearer than p.z - bias where the map holds 1.0. Said of a
 * sampler2D's reads only (a sampler2DShadow compares in the texture unit, by its own state). */
static int _sl_empty_map_shadowed(const sl_verdict_rows *v, char *text, size_t n) {
    const char *name = v->f->name;
    /* PCSS's empty map is its no-blocker branch, told apart below */
    if (strcmp(name, "shadow_compare_hardware") == 0 || strcmp(name, "pcf_hardware") == 0 || strcmp(name, "pcss") == 0)
        return -1;
    int empty = 0, dark = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        _sl_filter_row fr = _sl_filter_row_of(v->f, v->k->inputs[r]);
        /* an occluder's rows right and the outside's lit: it can answer both ways, so not a constant 0 */
        if ((fr.kind == _SL_ROW_OCCLUDED || fr.kind == _SL_ROW_OUTSIDE) && _sl_failed(v, r)) return -1;
        if (fr.kind != _SL_ROW_EMPTY_MAP) continue;
        empty++;
        if (_sl_got(v, r, 0) <= 0.001 && _sl_want(v, r, 0) >= 0.999) {
            dark++;
            if (first < 0) first = r;
        }
    }
    if (empty < 1 || dark != empty) return -1;
    _sl_filter_row fr = _sl_filter_row_of(v->f, v->k->inputs[first]);
    snprintf(text, n, "shadowed with nothing in the map: every stored depth is 1.0 (the far plane), yet at p.z - bias "
                      "= %.3g it finds a nearer one — the depth it compares with is not the map's: a depth texture read "
                      "through a sampler2D holds it in .r, texture(shadow_map, p.xy).r (.g and .b read 0)",
             fr.p[2] - fr.bias);
    sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_GROSS);
    return first;
}

/* PCSS across an edge, every failing row on one side of the contract's answer: a penumbra too wide blends
 * farther from the edge (results farther from a single comparison's 0 or 1), one too narrow stays closer.
 * Rows with other mistakes mixed in (some wider, some narrower) say nothing of the width. */
static int _sl_pcss_width(const sl_verdict_rows *v, char *text, size_t n) {
    int narrow = 0, wide = 0, other = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        _sl_filter_row fr = _sl_filter_row_of(v->f, v->k->inputs[r]);
        double tolerance = v->k->row_tolerance[r] > 0 ? v->k->row_tolerance[r] : v->k->tolerance;
        double here = fabs(_sl_got(v, r, 0) - fr.centre), there = fabs(_sl_want(v, r, 0) - fr.centre);
        /* an occluder's edge over a floor, or its corner, a tilted surface (the ramp), or any of them seen
         * through w != 1, is an edge too: its centre is the point's own texel's comparison */
        const float *map = _sl_param(v->f, v->k->inputs[r], "shadow_map");
        int m = map ? (int)*map : -1;
        bool edge = fr.kind == _SL_ROW_EDGE ||
                    (fr.kind == _SL_ROW_OTHER &&
                     (m == SL_PROBE_MAP_STEP_FLOOR || m == SL_PROBE_MAP_CORNER || m == SL_PROBE_MAP_RAMP)) ||
                    (fr.kind == _SL_ROW_HOMOGENEOUS &&
                     (m == SL_PROBE_MAP_STEP || m == SL_PROBE_MAP_STEP_FLOOR || m == SL_PROBE_MAP_CORNER));
        if (!edge) other++;
        else if (here > there + tolerance) wide++;
        else if (here < there - tolerance) narrow++;
        else other++;
        if (first < 0) first = r;
    }
    if (other > 0 || (wide > 0) == (narrow > 0)) return -1;
    snprintf(text, n, "the penumbra is too %s: on every row that differs, across an occluder's edge, it %s — the "
                      "width is (d_receiver - d_blocker) * light_size_uv / d_blocker, projected onto the map with "
                      "* near / d_receiver, every distance from pcf_linear_depth(d, near, far)",
             wide ? "wide" : "narrow",
             wide ? "blends farther from the edge than the contract's" : "stays closer to a single comparison's 0 or 1");
    sl_verdict_predicts(v, 1u << (wide ? SL_SYMPTOM_WIDE_PENUMBRA : SL_SYMPTOM_NARROW_PENUMBRA) | 1u << SL_SYMPTOM_GROSS);
    return first;
}

/* The frustum test turned round: every point inside the light's frustum that the contract shadows (even
 * partly) comes out exactly 1.0, as the test's early return gives, while a point outside comes out other than
 * lit (it was read). Both sides are needed: a filter that lights everything fails only the inside rows. */
static int _sl_frustum_test_inverted(const sl_verdict_rows *v, char *text, size_t n) {
    int inside = 0, lit_inside = 0, outside_read = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        _sl_filter_row fr = _sl_filter_row_of(v->f, v->k->inputs[r]);
        if (fr.kind == _SL_ROW_OUTSIDE) {
            if (_sl_failed(v, r) && _sl_got(v, r, 0) < 0.999) {
                outside_read++;
                if (first < 0) first = r;
            }
            continue;
        }
        if (_sl_want(v, r, 0) > 0.98) continue;
        inside++;
        lit_inside += _sl_got(v, r, 0) >= 0.999;
    }
    if (inside < 2 || lit_inside != inside || outside_read < 1) return -1;
    snprintf(text, n, "the frustum test is the wrong way round: every point inside the light's frustum that is shadowed "
                      "comes out exactly 1.0 without a lookup, while a point outside it is read from the map — return "
                      "1.0 when the point is outside (w <= 0, or x, y or z outside [0, 1] after the divide: "
                      "pcf_project / the test returns false), and look up otherwise");
    sl_verdict_predicts(v, 1u << SL_SYMPTOM_NO_SHADOWS | 1u << SL_SYMPTOM_MISSING_SHADOW | 1u << SL_SYMPTOM_TOO_LIGHT |
                               1u << SL_SYMPTOM_GROSS);
    return first;
}

int _sl_verdict_filter(const sl_verdict_rows *v, char *text, size_t n) {
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
    /* a slip in one of PCSS's terms that gives every row's answer names that term */
    if (pcss && (row = sl_pcss_slip_verdict(v, text, n)) >= 0) return row;
    if ((row = sl_poisson_slip_verdict(v, text, n)) >= 0) return row;
    /* the coordinate first: every other row depends on it */
    if ((row = _sl_frustum_test_inverted(v, text, n)) >= 0) return row;
    if ((row = _sl_first_failing(v, _SL_ROW_OUTSIDE)) >= 0) {
        snprintf(text, n, "a point outside the light's frustum must be lit: return 1.0 when w <= 0, or when x, y or z "
                          "is outside [0, 1] after the divide");
        return row;
    }
    if ((row = _sl_homogeneous_differs(v)) >= 0) {
        snprintf(text, n, "no divide by w: the shadow coordinate is homogeneous — divide xyz by w before the lookup");
        /* lookups at the wrong place: wherever w is not 1, shadows can go missing, appear or move */
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_NO_SHADOWS | 1u << SL_SYMPTOM_MISSING_SHADOW |
                                   1u << SL_SYMPTOM_EXTRA_SHADOW | 1u << SL_SYMPTOM_TOO_DARK |
                                   1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_GROSS);
        return row;
    }
    if ((row = _sl_empty_map_shadowed(v, text, n)) >= 0) return row;
    if (pcss && (row = _sl_first_failing(v, _SL_ROW_EMPTY_MAP)) >= 0) {
        snprintf(text, n, "no blocker found must mean fully lit: with nothing in the map in front of the point, the "
                          "blocker search finds none, and pcss() returns 1.0");
        return row;
    }
    /* a weight sum is what an empty map gives, when it gives something: 0 there is no kernel's weights
     * but comparisons that all fail, which the rows below quote */
    /* shadowed with nothing in the map: no label below has that as its evidence (a weight sum, a radius, a
     * width all read a working comparison); the row that shows it is quoted as measured */
    if (kernel && (row = _sl_first_failing(v, _SL_ROW_EMPTY_MAP)) >= 0 && _sl_got(v, row, 0) <= 0.05) return row;
    if (kernel && (row = _sl_first_failing(v, _SL_ROW_EMPTY_MAP)) >= 0) {
        double sum = _sl_got(v, row, 0), count = sum > 0 ? 1 / sum : 0;
        /* exactly one over a whole count: one sample's result divided by the count of them all */
        if (count >= 5 && fabs(count - round(count)) <= 0.005 * count) {
            snprintf(text, n, "only one sample counts: nothing in front gives %.4g = 1/%.0f, one lit sample divided by "
                              "the %.0f samples' count — the sum is overwritten in the loop (= where += belongs) "
                              "or reset inside it", sum, round(count), round(count));
            return row;
        }
        /* a sum off 1 is a divisor that is not the count of samples taken: none, the wrong count, or loops
         * that take fewer (or more) samples than the count divided by */
        snprintf(text, n, "the weights sum to %.4g, not 1 (nothing in front gives %.4g): the kernel is not normalised "
                          "— divide the sum of the results by the number of samples the loops take (every offset "
                          "from -radius to radius, both ends included)", sum, sum);
        return row;
    }
    /* the bias decides the own-surface rows alone: with an empty map failing too, something else shadows */
    if ((row = _sl_first_failing(v, _SL_ROW_OWN_SURFACE)) >= 0 && _sl_got(v, row, 0) < _sl_want(v, row, 0) &&
        _sl_first_failing(v, _SL_ROW_EMPTY_MAP) < 0) {
        snprintf(text, n, "the bias is not subtracted: a point on the stored surface itself compares as shadowed, which "
                          "is shadow acne — compare p.z - bias with the stored depth");
        return row;
    }
    if (pcss && (row = _sl_pcss_misses_umbra(v, text, n)) >= 0) return row;
    /* no blocker found is exactly 1.0: a penumbra too wide also lights an occluded point, partly */
    if ((row = _sl_first_failing(v, _SL_ROW_OCCLUDED)) >= 0 && _sl_got(v, row, 0) > _sl_want(v, row, 0) &&
        (!pcss || _sl_got(v, row, 0) >= 0.999)) {
        if (pcss)
            snprintf(text, n, "the blocker search finds no blockers where an occluder covers the whole map: stored "
                              "depths nearer than p.z - bias are the blockers");
        else
            snprintf(text, n, "samples land off the map: with an occluder over the whole map it still gives %.3g lit — "
                              "the kernel is far too wide, or not around p.xy: offsets scaled by the texel size, "
                              "1.0 / textureSize(map, 0), and added to p.xy (the point itself unmoved, unrotated)",
                     _sl_got(v, row, 0));
        return row;
    }
    if (pcss && (row = _sl_verdict_pcss_search(v, text, n)) >= 0) return row;
    if (pcss) return _sl_pcss_width(v, text, n);
    if (!kernel) return -1; /* single lookups: their rows say the rest */
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
    /* both readings compare correctly on an empty map: a kernel that shadows it too is neither */
    if (soft > 0 && hard == soft && _sl_first_failing(v, _SL_ROW_EMPTY_MAP) < 0) {
        if (as_centre == hard)
            /* samples closer together than a texel give a single lookup's answer on the probe's map too: the
             * rows show no blend, not that the code has no kernel */
            snprintf(text, n, "one comparison per point: results are 0 or 1 where the kernel should blend, exactly as "
                              "a single lookup gives them — on this 64-texel map every sample stays in the point's own "
                              "texel: offsets of (almost) 0 — each is radius texels wide, a texel 1.0 / "
                              "vec2(textureSize(map, 0)) (1 / textureSize(map, 0) divides integers: 0); compare at "
                              "every sample and average the results");
        else
            snprintf(text, n, "depths averaged, then compared once: results are 0 or 1 where the kernel should blend, "
                              "and not where one comparison puts them — filtering depths instead of comparison results "
                              "(Reeves 1987); compare at every sample, then average the 0/1 results");
        return first_soft;
    }
    /* fractional, but the same whatever the radius */
    if ((row = _sl_radius_ignored(v, text, n)) >= 0) return row;
    if ((row = sl_grid_spacing_verdict(v, text, n)) >= 0) return row;
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
