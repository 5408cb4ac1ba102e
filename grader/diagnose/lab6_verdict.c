/* Lab 6's probes read together (lab6.c holds its pictures' diagnoses): the
 * split distances, each slice's sphere, the cascade lookup and index, and
 * lab6_cascade_matrices judged by its contract. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_probe.h"
#include "sl_scene.h"
#include "sl_verdict.h"
#include "verdict_rows.h"

/* ---- what lab 6's probes show together ---- */

static bool _sl_close(double a, double b) { return fabs(a - b) <= 1e-3 * fmax(1.0, fabs(b)); }

/* The uniform scheme: near + (far - near) * i / count. */
static void _sl_uniform_splits(double near, double far, int count, double *out) {
    for (int i = 0; i <= count; i++) out[i] = near + (far - near) * ((double)i / count);
}

/* The logarithmic scheme for row `row`'s near, far and count, read back from
 * the solution's own splits (the expected outputs) rather than computed here:
 * the practical scheme is C = lambda * C_log + (1 - lambda) * C_uniform, so
 * any row with the same near, far and count and a lambda above 0 gives
 * C_log = (C - (1 - lambda) * C_uniform) / lambda (the largest lambda: the
 * least rounding). False when no row does (lambda 0 alone for these numbers). */
static bool _sl_log_splits(const sl_verdict_rows *v, int row, const double *uniform, double *out) {
    const float *in = v->k->inputs[row];
    int best = -1;
    for (int b = 0; b < v->k->rows; b++) {
        const float *ib = v->k->inputs[b];
        if (ib[0] != in[0] || ib[1] != in[1] || ib[2] != in[2] || !(ib[3] > 0.05f) || ib[3] > 1) continue;
        if (best < 0 || ib[3] > v->k->inputs[best][3]) best = b;
    }
    if (best < 0) return false;
    double lambda = v->k->inputs[best][3];
    for (int i = 0; i <= (int)in[2]; i++)
        out[i] = (_sl_want(v, best, i) - (1 - lambda) * uniform[i]) / lambda;
    return true;
}

static int _sl_verdict_splits(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, uniform = 0, logarithmic = 0, swapped = 0, ends = 0, failing = 0, first = -1;
    int known = 0; /* failing rows whose logarithmic splits are known */
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        int count = (int)in[2];
        if (count < 1 || count > SL_MAX_CASCADES) continue;
        double u[SL_MAX_CASCADES + 1], l[SL_MAX_CASCADES + 1], w[SL_MAX_CASCADES + 1];
        _sl_uniform_splits(in[0], in[1], count, u);
        bool have_log = _sl_log_splits(v, r, u, l);
        /* lambda swapped: (1 - lambda) * C_log + lambda * C_uniform */
        for (int i = 0; have_log && i <= count; i++) w[i] = (1 - in[3]) * l[i] + in[3] * u[i];
        bool is_u = true, is_l = have_log, is_w = have_log;
        for (int i = 0; i <= count; i++) {
            double got = _sl_got(v, r, i);
            is_u &= _sl_close(got, u[i]);
            if (have_log) {
                is_l &= _sl_close(got, l[i]);
                is_w &= _sl_close(got, w[i]);
            }
        }
        failing++;
        known += have_log;
        if (first < 0) first = r;
        uniform += is_u;
        logarithmic += is_l;
        swapped += is_w; /* at lambda 0 or 1 the swapped blend is the other pure scheme */
        ends += !_sl_close(_sl_got(v, r, 0), in[0]) || !_sl_close(_sl_got(v, r, count), in[1]);
    }
    /* a row whose logarithmic splits no row tells (lambda 0 alone) neither confirms nor rules out those verdicts */
    if (known < failing) {
        if (logarithmic < known || known == 0) logarithmic = -1;
        else logarithmic = failing;
        if (swapped < known || known == 0) swapped = -1;
        else swapped = failing;
    }
    if (!failing) return -1;
    if (uniform == failing || logarithmic == failing) {
        snprintf(text, n, "lambda is ignored: these are the %s splits (lambda = %d) whatever lambda is; the practical "
                          "scheme blends both, lambda * C_log + (1 - lambda) * C_uniform",
                 uniform == failing ? "uniform" : "logarithmic", uniform == failing ? 0 : 1);
        return first;
    }
    if (swapped == failing) {
        snprintf(text, n, "lambda weighs the wrong term: lambda * C_log + (1 - lambda) * C_uniform, not the other way "
                          "round");
        return first;
    }
    if (ends == failing) {
        snprintf(text, n, "the wrong near/far: splits[0] must be near and splits[count] far");
        return first;
    }
    /* rows that differ only in lambda, the same splits where the solution's differ: a scheme of its own */
    for (int a = 0; a < rows; a++) {
        if (!_sl_failed(v, a)) continue;
        for (int b = 0; b < rows; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            if (b == a || ia[0] != ib[0] || ia[1] != ib[1] || ia[2] != ib[2] || ia[3] == ib[3]) continue;
            bool same = true, differ = false;
            for (int i = 0; i <= (int)ia[2] && i <= SL_MAX_CASCADES; i++) {
                same &= _sl_close(_sl_got(v, a, i), _sl_got(v, b, i));
                differ |= !_sl_close(_sl_want(v, a, i), _sl_want(v, b, i));
            }
            if (same && differ) {
                snprintf(text, n, "lambda is ignored: lambda %g and lambda %g give the same splits — fixed splits of "
                                  "your own? The practical scheme is lambda * C_log + (1 - lambda) * C_uniform",
                         (double)ia[3], (double)ib[3]);
                return a;
            }
        }
    }
    return -1;
}

/* The solution's sphere of a slice, for comparisons (the probe's camera, GL conventions). */
/* The sphere around the slice whose corners lie at fractions ta and tb of each frustum edge (near corner 0,
 * far corner 1): the contract's, from the split distances (_sl_sphere), or a slip's fractions. */
/* The 8 corners of the slice whose corners lie at fractions ta and tb of each frustum edge (near corner 0,
 * far corner 1), in world space (the probe's camera, GL conventions). */
static void _sl_slice_corners_as(const float *in, double ta, double tb, bool divide, float near_z, double corners[8][3]) {
    sl_camera cam = {.fov_deg = in[6], .near = in[8], .far = in[9]};
    glm_vec3_copy((float *)in, cam.position);
    glm_vec3_copy((float *)in + 3, cam.target);
    mat4 view, proj, vp, inv;
    sl_camera_view(&cam, view);
    sl_camera_projection(&cam, in[7], proj);
    glm_mat4_mul(proj, view, vp);
    glm_mat4_inv(vp, inv);
    for (int i = 0; i < 4; i++) {
        vec4 a = {(i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, near_z, 1}, b = {a[0], a[1], 1, 1}, wa, wb;
        glm_mat4_mulv(inv, a, wa);
        glm_mat4_mulv(inv, b, wb);
        for (int k = 0; k < 3; k++) {
            double cn = divide ? wa[k] / wa[3] : wa[k], cf = divide ? wb[k] / wb[3] : wb[k];
            corners[i][k] = cn + (cf - cn) * ta;
            corners[4 + i][k] = cn + (cf - cn) * tb;
        }
    }
}

static void _sl_slice_corners(const float *in, double ta, double tb, double corners[8][3]) {
    _sl_slice_corners_as(in, ta, tb, true, -1, corners);
}

static double _sl_distance3(const double *a, const double *b) {
    return sqrt(pow(a[0] - b[0], 2) + pow(a[1] - b[1], 2) + pow(a[2] - b[2], 2));
}

/* The sphere around the slice at fractions ta and tb: the corners' mean, and the farthest corner's distance. */
static void _sl_sphere_at(const float *in, double ta, double tb, double out[4]) {
    double corners[8][3], centre[3] = {0, 0, 0};
    _sl_slice_corners(in, ta, tb, corners);
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++) centre[k] += corners[i][k] / 8;
    double radius = 0;
    for (int i = 0; i < 8; i++) radius = fmax(radius, _sl_distance3(corners[i], centre));
    for (int k = 0; k < 3; k++) out[k] = centre[k];
    out[3] = radius;
}

static void _sl_sphere(const float *in, double split_near, double split_far, double out[4]) {
    double near = in[8], far = in[9];
    _sl_sphere_at(in, (split_near - near) / (far - near), (split_far - near) / (far - near), out);
}

/* Fractions along the frustum's edges other than the contract's (split - near) / (far - near), each a slip
 * of one term: which one every failing row's sphere is. */
static int _sl_sphere_fraction_slip(const sl_verdict_rows *v) {
    int fits = -1;
    for (int slip = 0; slip < 3 && fits < 0; slip++) {
        bool all = true, any = false;
        for (int r = 0; r < v->k->rows && all; r++) {
            if (!_sl_failed(v, r)) continue;
            const float *in = v->k->inputs[r];
            double near = in[8], far = in[9], a = in[10], b = in[11], ta, tb, sphere[4];
            if (slip == 0) ta = a / far, tb = b / far;
            else if (slip == 1) ta = (a - near) / far, tb = (b - near) / far;
            else ta = a / (far - near), tb = b / (far - near);
            _sl_sphere_at(in, ta, tb, sphere);
            for (int i = 0; i < 4; i++) all &= fabs(_sl_got(v, r, i) - sphere[i]) <= 1e-3 * fmax(1, fabs(sphere[i]));
            any = true;
        }
        if (all && any) fits = slip;
    }
    return fits;
}

/* The sphere read by what the contract asks of it, where no slip explains it: centred on the view axis (the
 * slice is symmetric about it, so its corners' mean lies on it), at the corners' mean depth, holding all 8
 * corners. Says the first of these the row with the largest departure breaks, with its measures. */
static int _sl_sphere_by_contract(const sl_verdict_rows *v, char *text, size_t n) {
    int worst = -1;
    double worst_error = 0;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double error = 0;
        for (int i = 0; i < 4; i++) error += fabs(_sl_got(v, r, i) - _sl_want(v, r, i));
        if (worst < 0 || error > worst_error) worst = r, worst_error = error;
    }
    if (worst < 0) return -1;
    /* every failing row's sphere is the one around corners taken another way: left homogeneous (xyz of
     * inv(VP) * ndc, no / w), or with the near plane at NDC z = 0 (Direct3D's and Vulkan's depth range) */
    static const struct {
        bool divide;
        float near_z;
        const char *text;
    } ways[] = {
        {false, -1, "the corners are not divided by w: inv_view_projection * (x, y, -1 or 1, 1) is a homogeneous "
                    "point, and its xyz alone is not the corner (w is not 1 under a perspective projection) — "
                    "divide xyz by w, then move along each edge to split_near and split_far"},
        {true, 0, "the near corners are taken at NDC z = 0, Direct3D's and Vulkan's near plane: GL's clip space runs "
                  "from z = -1 at the near plane to 1 at the far one, so inv_view_projection * (x, y, 0, 1) is a point "
                  "part way into the frustum — take the near corners at z = -1"},
    };
    for (size_t w = 0; w < sizeof ways / sizeof ways[0]; w++) {
        int fits = 0, failing = 0;
        for (int r = 0; r < v->k->rows; r++) {
            if (!_sl_failed(v, r)) continue;
            const float *row = v->k->inputs[r];
            double raw[8][3], centre[3] = {0, 0, 0}, radius = 0, error = 0;
            _sl_slice_corners_as(row, (row[10] - row[8]) / (row[9] - row[8]), (row[11] - row[8]) / (row[9] - row[8]),
                                 ways[w].divide, ways[w].near_z, raw);
            for (int i = 0; i < 8; i++)
                for (int k = 0; k < 3; k++) centre[k] += raw[i][k] / 8;
            for (int i = 0; i < 8; i++) radius = fmax(radius, _sl_distance3(raw[i], centre));
            for (int k = 0; k < 3; k++) error = fmax(error, fabs(_sl_got(v, r, k) - centre[k]));
            error = fmax(error, fabs(_sl_got(v, r, 3) - radius) - (double)v->k->above[3]);
            failing++;
            fits += error <= 1e-3 * fmax(1, radius);
        }
        if (failing && fits == failing) {
            snprintf(text, n, "%s", ways[w].text);
            return worst;
        }
    }
    const float *in = v->k->inputs[worst];
    double near = in[8], far = in[9], split_near = in[10], split_far = in[11], corners[8][3];
    _sl_slice_corners(in, (split_near - near) / (far - near), (split_far - near) / (far - near), corners);
    double eye[3] = {in[0], in[1], in[2]}, forward[3] = {in[3] - in[0], in[4] - in[1], in[5] - in[2]};
    double length = sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
    if (length <= 0) return -1;
    double centre[3], relative[3], depth = 0, off_axis = 0, radius = _sl_got(v, worst, 3), outside = 0, slack;
    for (int k = 0; k < 3; k++) {
        forward[k] /= length;
        centre[k] = _sl_got(v, worst, k);
        relative[k] = centre[k] - eye[k];
        depth += relative[k] * forward[k];
    }
    for (int k = 0; k < 3; k++) off_axis += pow(relative[k] - depth * forward[k], 2);
    off_axis = sqrt(off_axis);
    for (int i = 0; i < 8; i++) outside = fmax(outside, _sl_distance3(corners[i], centre) - radius);
    slack = v->k->tolerance + v->k->relative * _sl_want(v, worst, 3);
    double want_depth = 0;
    for (int k = 0; k < 3; k++) want_depth += (_sl_want(v, worst, k) - eye[k]) * forward[k];
    if (off_axis > slack) {
        snprintf(text, n, "the centre is %.3g m off the camera's view axis, where the slice is symmetric about that "
                          "axis, so the mean of its 8 corners lies on it%s", off_axis,
                 outside > slack ? ", and the sphere leaves part of the slice out" : "");
        return worst;
    }
    if (outside > slack) {
        snprintf(text, n, "the sphere does not hold the slice: its centre lies at view depth %.3g m and it reaches "
                          "%.3g m, where the slice runs from view depth %g to %g m and a corner lies %.3g m outside "
                          "it — the slice's 8 corners are where its edges reach split_near and split_far, and the "
                          "sphere is centred at their mean (view depth %.3g m) and reaches the farthest one",
                 depth, radius, split_near, split_far, outside, want_depth);
        return worst;
    }
    snprintf(text, n, "the sphere holds the slice but is larger than it needs (radius %.4g where %.4g is enough): "
                      "its centre lies at view depth %.3g m, where the mean of the slice's 8 corners lies at %.3g m — "
                      "a larger sphere spreads the cascade's texels thinner",
             radius, _sl_want(v, worst, 3), depth, want_depth);
    return worst;
}

static int _sl_verdict_sphere(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, whole = 0, too_small = 0, rounded = 0, first = -1, most = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double all[4];
        _sl_sphere(in, in[8], in[9], all);
        bool is_whole = true;
        for (int i = 0; i < 4; i++) is_whole &= fabs(_sl_got(v, r, i) - all[i]) <= 1e-3 * fmax(1, fabs(all[i]));
        /* the slice's own centre, and a radius only larger: rounded up by more than "above" allows */
        bool centred = true;
        for (int i = 0; i < 3; i++)
            centred &= fabs(_sl_got(v, r, i) - _sl_want(v, r, i)) <= v->k->tolerance + v->k->relative * fabs(_sl_want(v, r, i));
        bool larger = _sl_got(v, r, 3) > _sl_want(v, r, 3);
        failing++;
        whole += is_whole;
        /* a radius too small says "to the farthest corner" only about the slice's own centre */
        too_small += centred && _sl_got(v, r, 3) < _sl_want(v, r, 3) * 0.999;
        rounded += centred && larger && !is_whole;
        if (centred && larger && (most < 0 || _sl_got(v, r, 3) - _sl_want(v, r, 3) > _sl_got(v, most, 3) - _sl_want(v, most, 3)))
            most = r;
        if (first < 0) first = r;
    }
    if (!failing) return -1;
    /* a radius that is the farthest corner's squared distance (a squared length, cglm's glm_vec3_distance2) */
    int squared = 0;
    double factor_lo = INFINITY, factor_hi = -INFINITY;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double own[4];
        _sl_sphere(in, in[10], in[11], own);
        squared += fabs(_sl_got(v, r, 3) - own[3] * own[3]) <= 1e-3 * own[3] * own[3] + (double)v->k->above[3];
        /* the centre as a multiple of the corners' mean (a sum divided by another count) */
        for (int i = 0; i < 3; i++)
            if (fabs(own[i]) > 0.1) {
                factor_lo = fmin(factor_lo, _sl_got(v, r, i) / own[i]);
                factor_hi = fmax(factor_hi, _sl_got(v, r, i) / own[i]);
            }
    }
    if (squared == failing) {
        snprintf(text, n, "the radius is the squared distance to the farthest corner (%.4g where that corner is %.4g m "
                          "away): a squared length, as cglm's glm_vec3_distance2 gives — take its square root, or "
                          "glm_vec3_distance", _sl_got(v, first, 3), sqrt(_sl_got(v, first, 3)));
        return first;
    }
    if (factor_lo <= factor_hi && fabs(factor_hi - factor_lo) <= 1e-3 * fabs(factor_hi) && fabs(factor_lo - 1) > 0.01) {
        double count = 8 / factor_lo;
        char divisor[80] = "";
        if (count >= 1 && fabs(count - round(count)) <= 1e-3 * count)
            snprintf(divisor, sizeof divisor, ": the sum of the 8 corners divided by %.0f, not by 8", round(count));
        snprintf(text, n, "the centre is %.4g times the corners' mean%s — the centre is the mean of the slice's 8 "
                          "corners", factor_lo, divisor);
        return first;
    }
    /* a radius larger on every row, by more than any rounding step: the distance to the corners measured
     * from another point; the world's origin and the eye are the ones code reaches for */
    if (rounded == failing && most >= 0 && _sl_got(v, most, 3) - _sl_want(v, most, 3) > 1 + 0.05 * _sl_want(v, most, 3)) {
        static const char *const from[] = {"the world's origin (the corners' own length, glm_vec3_norm(corner))",
                                           "the camera's eye"};
        for (int p = 0; p < 2; p++) {
            int fits = 0;
            for (int r = 0; r < v->k->rows; r++) {
                if (!_sl_failed(v, r)) continue;
                const float *in = v->k->inputs[r];
                double corners[8][3], point[3] = {p ? in[0] : 0, p ? in[1] : 0, p ? in[2] : 0}, farthest = 0;
                _sl_slice_corners(in, (in[10] - in[8]) / (in[9] - in[8]), (in[11] - in[8]) / (in[9] - in[8]), corners);
                for (int i = 0; i < 8; i++) farthest = fmax(farthest, _sl_distance3(corners[i], point));
                fits += fabs(_sl_got(v, r, 3) - farthest) <= 1e-3 * farthest + (double)v->k->above[3];
            }
            if (fits == failing) {
                snprintf(text, n, "the radius is the farthest corner's distance from %s, not from the sphere's centre: "
                                  "%.4g where the corners lie within %.4g of the centre — the radius is the largest "
                                  "distance from the corners' mean to a corner",
                         from[p], _sl_got(v, most, 3), _sl_want(v, most, 3));
                return most;
            }
        }
        snprintf(text, n, "the radius is %.3g m larger than the farthest corner's distance from the sphere's centre "
                          "(%.4g where %.4g holds every corner): the radius is the largest distance from the corners' "
                          "mean to a corner, measured from that centre",
                 _sl_got(v, most, 3) - _sl_want(v, most, 3), _sl_got(v, most, 3), _sl_want(v, most, 3));
        return most;
    }
    if (rounded == failing && v->k->above[3] > 0) {
        snprintf(text, n, "the radius is %.3g m larger than the farthest corner's distance, and the lab lets it be "
                          "rounded up by %g m at most: round up to a multiple of 1/%g m (ceil(r * %g) / %g) or not "
                          "at all — a coarser step only makes every texel of the cascade larger",
                 _sl_got(v, most, 3) - _sl_want(v, most, 3), (double)v->k->above[3], 1.0 / v->k->above[3],
                 1.0 / v->k->above[3], 1.0 / v->k->above[3]);
        return most;
    }
    if (whole == failing) {
        snprintf(text, n, "the sphere is fitted to the whole frustum, not to the slice between split_near and split_far "
                          "(move each corner along its edge to t = (split - near) / (far - near))");
        return first;
    }
    static const char *const fractions[] = {"split / far", "(split - near) / far", "split / (far - near)"};
    int slip = _sl_sphere_fraction_slip(v);
    if (slip >= 0) {
        snprintf(text, n, "the slice's corners lie at t = %s along each frustum edge: the view depth runs from near "
                          "(t = 0) to far (t = 1) along an edge, so t = (split - near) / (far - near)",
                 fractions[slip]);
        return first;
    }
    if (too_small == failing) {
        snprintf(text, n, "the sphere is too small to hold the slice's 8 corners: its radius is the distance from the "
                          "centre to the FARTHEST corner");
        return first;
    }
    return _sl_sphere_by_contract(v, text, n);
}

/* ---- lab6_cascade_matrices by its contract ----
 *
 * The light camera may be built many ways (lookAt or not, the eye anywhere on
 * the light's ray, any depth range that holds the casters, snapped with
 * round, floor or ceil, a box rounded up a little). What it must do, checked
 * on test points of each row's projection * view (README, "One light camera
 * per slice" and "Shadows that stand still"):
 *   - be orthographic, looking along the light's direction (depth grows with it);
 *   - a square box across the light, r to _SL_BOX_BAND r each way (r the sphere's radius);
 *   - the sphere's centre within one texel of the map's middle (snapping moves it by less);
 *   - depths from c - d (r + caster_margin) (casters towards the light) to c + d r inside [-1, 1];
 *   - rows that differ only in the sphere's centre (the same light, radius, margin and map size) have the
 *     same box, and the world lands on the same fraction of a texel in both: the texel grid is fixed in
 *     the world, so shadows do not shimmer. */
#define _SL_BOX_BAND 1.05

typedef struct _sl_light_box {
    const char *broken;   /* what breaks the contract, NULL when nothing does */
    char detail[400];
    double origin[2];     /* where the world's origin lands, in texels from the map's corner */
} _sl_light_box;

static double _sl_dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double _sl_norm3(const double *a) { return sqrt(_sl_dot3(a, a)); }

/* Row i (x, y, z or w) of a column-major matrix: its linear part, then its translation. */
static void _sl_matrix_row4(const double *m, int i, double out[4]) {
    for (int col = 0; col < 4; col++) out[col] = m[col * 4 + i];
}

static double _sl_apply(const double row[4], const double p[3]) { return _sl_dot3(row, p) + row[3]; }

static _sl_light_box _sl_judge_light_box(const float *in, const double *m) {
    _sl_light_box b = {.broken = NULL};
    double d[3] = {in[0], in[1], in[2]}, c[3] = {in[3], in[4], in[5]}, r = in[6], margin = in[7], size = in[8];
    double length = _sl_norm3(d), half = size / 2;
    for (int i = 0; i < 3 && length > 0; i++) d[i] /= length;
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i])) {
            b.broken = "the matrices are not finite (NaN or infinity)";
            return b;
        }
    double x[4], y[4], z[4], w[4];
    _sl_matrix_row4(m, 0, x);
    _sl_matrix_row4(m, 1, y);
    _sl_matrix_row4(m, 2, z);
    _sl_matrix_row4(m, 3, w);
    if (fabs(w[0]) + fabs(w[1]) + fabs(w[2]) > 1e-5 || fabs(w[3] - 1) > 1e-5) {
        b.broken = "the projection is not orthographic (w is not 1): a directional light's rays are parallel, "
                   "glm_ortho";
        return b;
    }
    double nx = _sl_norm3(x), ny = _sl_norm3(y), nz = _sl_norm3(z);
    if (nx < 1e-12 || ny < 1e-12 || nz < 1e-12) {
        b.broken = "the box is flat: a row of the projection * view is zero";
        return b;
    }
    /* the light's direction maps to depth only, growing away from the light */
    if (fabs(_sl_dot3(x, d)) > 1e-3 * nx || fabs(_sl_dot3(y, d)) > 1e-3 * ny || _sl_dot3(z, d) < 0.999 * nz) {
        double across = hypot(_sl_dot3(x, d) / nx, _sl_dot3(y, d) / ny);
        b.broken = "the light camera does not look along the light's direction";
        snprintf(b.detail, sizeof b.detail, "a step along the light moves %.3g across the map%s: the eye at "
                 "centre - dir * (r + caster_margin), looking at the centre", across,
                 _sl_dot3(z, d) < 0 ? ", and depth shrinks along it (the camera looks towards the light)" : "");
        return b;
    }
    double hx = 1 / nx, hy = 1 / ny;
    if (fabs(_sl_dot3(x, y)) > 1e-3 * nx * ny || fabs(hx - hy) > 1e-3 * r) {
        b.broken = "the box across the light is not square";
        snprintf(b.detail, sizeof b.detail, "%.4g by %.4g each way from its centre: glm_ortho(-r, r, -r, r, ...)", hx, hy);
        return b;
    }
    if (hx < 0.999 * r || hx > _SL_BOX_BAND * r) {
        b.broken = hx < r ? "the box across the light is smaller than the sphere" : "the box across the light is "
                                                                                    "larger than the sphere";
        snprintf(b.detail, sizeof b.detail, "%.4g each way from its centre where the sphere's radius is %.4g (allowed "
                 "r to %.2f r): glm_ortho(-r, r, -r, r, ...), so a texel is 2 r / map_size", hx, r, _SL_BOX_BAND);
        return b;
    }
    double cx = _sl_apply(x, c) * half, cy = _sl_apply(y, c) * half;
    if (fabs(cx) > 1.001 || fabs(cy) > 1.001) {
        b.broken = "the box is not centred on the sphere";
        /* either the camera aims elsewhere or the snap's correction is too large: the rows cannot tell which */
        snprintf(b.detail, sizeof b.detail, "the sphere's centre lands %.1f texels from the middle of the map, where a "
                 "camera looking at the centre puts it in the middle and a snap moves it by less than one texel: the "
                 "camera's target, or the snap's correction (a fraction of a texel, in NDC (round(x) - x) / "
                 "(map_size / 2))", hypot(cx, cy));
        return b;
    }
    double caster[3], far[3];
    for (int i = 0; i < 3; i++) {
        caster[i] = c[i] - d[i] * (r + margin);
        far[i] = c[i] + d[i] * r;
    }
    double z_caster = _sl_apply(z, caster), z_far = _sl_apply(z, far);
    if (z_caster < -1 - 1e-4) {
        b.broken = "casters up to caster_margin towards the light fall before the near plane";
        snprintf(b.detail, sizeof b.detail, "the point caster_margin = %g beyond the sphere, towards the light, is at "
                 "depth %.3g (NDC; at least -1): step the eye back by r + caster_margin, and let the box span 0 .. "
                 "2 r + caster_margin", margin, z_caster);
        return b;
    }
    if (z_far > 1 + 1e-4) {
        b.broken = "the far side of the sphere lies beyond the far plane";
        snprintf(b.detail, sizeof b.detail, "the sphere's far side is at depth %.3g (NDC; at most 1): the box spans 0 "
                 ".. 2 r + caster_margin from the eye", z_far);
        return b;
    }
    b.origin[0] = (x[3] + 1) * half;
    b.origin[1] = (y[3] + 1) * half;
    return b;
}

/* The fraction of a texel where a coordinate lands, in [0, 1). */
static double _sl_fraction(double texels) { return texels - floor(texels); }

/* How far apart two fractions of a texel are, around the circle (0.98 and 0.01 are 0.03 apart). */
static double _sl_fraction_gap(double a, double b) {
    double gap = fabs(_sl_fraction(a) - _sl_fraction(b));
    return fmin(gap, 1 - gap);
}

/* Rows with the same light, radius, margin and map size: the box may only move with the sphere's centre. */
static bool _sl_twins(const float *a, const float *b) {
    for (int i = 0; i < 9; i++)
        if (i < 3 || i >= 6)
            if (a[i] != b[i]) return false;
    return true;
}

/* The snap's offset added with the wrong sign: the origin's position in texels x0 (where a box centred on the
 * sphere puts it, the box's own axes) moved to x0 + (x0 - round(x0)) (or floor), a fraction doubled where it
 * should be cancelled, in both axes. */
static bool _sl_snap_sign_flipped(const float *in, const double *m) {
    double c[3] = {in[3], in[4], in[5]}, half = in[8] / 2;
    bool any_fraction = false;
    for (int axis = 0; axis < 2; axis++) {
        double row[4];
        _sl_matrix_row4(m, axis, row);
        double x0 = -_sl_dot3(row, c) * half, got = row[3] * half;
        bool rounded = fabs(got - (2 * x0 - round(x0))) <= 0.01, floored = fabs(got - (2 * x0 - floor(x0))) <= 0.01;
        if (!rounded && !floored) return false;
        any_fraction |= fabs(x0 - round(x0)) > 0.02;
    }
    return any_fraction;
}

/* The box's translation exactly the unsnapped one (the box centred on the sphere) in both axes, with the
 * world's origin off whole texels: the snap moves nothing. */
static bool _sl_snap_missing(const float *in, const double *m) {
    double c[3] = {in[3], in[4], in[5]}, half = in[8] / 2;
    bool any_fraction = false;
    for (int axis = 0; axis < 2; axis++) {
        double row[4];
        _sl_matrix_row4(m, axis, row);
        double x0 = -_sl_dot3(row, c) * half, got = row[3] * half;
        if (fabs(got - x0) > 0.01) return false;
        any_fraction |= fabs(x0 - round(x0)) > 0.02;
    }
    return any_fraction;
}

/* 0 (x) or 1 (y) when two boxes' world origins land on whole texels in that axis alone and slide in the
 * other: the snap is done in one axis only; -1 otherwise. */
static int _sl_snapped_in_one_axis(const _sl_light_box *a, const _sl_light_box *b, double gx, double gy) {
    for (int axis = 0; axis < 2; axis++) {
        bool whole = fabs(a->origin[axis] - round(a->origin[axis])) <= 0.02 &&
                     fabs(b->origin[axis] - round(b->origin[axis])) <= 0.02;
        if (whole && (axis == 0 ? gy : gx) > 0.02) return axis;
    }
    return -1;
}

/* The grid every box's world origin lands on, in texels, where the boxes snap to a finer grid than whole
 * texels: 0.5 or 0.25 (the offset rounded with map_size, or 2 map_size, texels per NDC unit, where NDC spans
 * 2); 0 where they share no such grid (or the whole one: a coarser grid, every second texel, holds still). */
static double _sl_snap_grid(const _sl_light_box *boxes, int rows) {
    static const double grids[] = {0.5, 0.25};
    bool whole = true;
    for (int r = 0; r < rows; r++)
        for (int axis = 0; axis < 2; axis++)
            whole &= fabs(boxes[r].origin[axis] - round(boxes[r].origin[axis])) <= 0.02;
    if (whole || rows < 2) return 0;
    for (size_t g = 0; g < sizeof grids / sizeof grids[0]; g++) {
        bool on = true;
        for (int r = 0; r < rows && on; r++)
            for (int axis = 0; axis < 2; axis++) {
                double at = boxes[r].origin[axis] / grids[g];
                on &= fabs(at - round(at)) <= 0.02;
            }
        if (on) return grids[g];
    }
    return 0;
}

static bool _sl_cascade_matrices_contract(const sl_check *k, const double *student, uint32_t *broken, char *text,
                                          size_t n, int *shown) {
    _sl_light_box boxes[SL_PROBE_MAX_ROWS];
    *broken = 0;
    *shown = -1;
    text[0] = '\0';
    for (int r = 0; r < k->rows; r++) {
        boxes[r] = _sl_judge_light_box(k->inputs[r], student + r * 16);
        if (!boxes[r].broken) continue;
        *broken |= 1u << r;
        if (*shown < 0) {
            *shown = r;
            snprintf(text, n, "%s%s%s", boxes[r].broken, boxes[r].detail[0] ? ": " : "", boxes[r].detail);
        }
    }
    if (*shown >= 0) return true;
    /* every box holds its sphere: now the pairs, for the texel grid */
    for (int a = 0; a < k->rows; a++)
        for (int b = a + 1; b < k->rows; b++) {
            if (!_sl_twins(k->inputs[a], k->inputs[b])) continue;
            const double *ma = student + a * 16, *mb = student + b * 16;
            bool same_box = true;
            for (int col = 0; col < 3; col++)
                for (int row = 0; row < 3; row++)
                    same_box &= fabs(ma[col * 4 + row] - mb[col * 4 + row]) <= 1e-5 * fmax(1, fabs(ma[col * 4 + row]));
            double gx = _sl_fraction_gap(boxes[a].origin[0], boxes[b].origin[0]);
            double gy = _sl_fraction_gap(boxes[a].origin[1], boxes[b].origin[1]);
            if (same_box && gx <= 0.02 && gy <= 0.02) continue;
            *broken |= (1u << a) | (1u << b);
            if (*shown >= 0) continue;
            *shown = b;
            if (!same_box)
                snprintf(text, n, "the box turns or changes size when only the sphere's centre moves: keep the "
                                  "light's up vector and the box's size fixed, so the texel grid stays put");
            else if (_sl_snap_missing(k->inputs[a], ma) && _sl_snap_missing(k->inputs[b], mb))
                snprintf(text, n, "shadows shimmer as the camera moves: the projection is not snapped at all — its "
                                  "translation is the box's centred on the sphere, so the world's origin lands at texel "
                                  "(%.2f, %.2f), then at (%.2f, %.2f); the snap must add (round(x) - x) / (map_size / 2) "
                                  "to the translation (in cglm's column-major matrices m[3][0] and m[3][1]; m[0][3] and "
                                  "m[1][3] are the last row, 0 in a projection)",
                         boxes[a].origin[0], boxes[a].origin[1], boxes[b].origin[0], boxes[b].origin[1]);
            else if (_sl_snap_sign_flipped(k->inputs[a], ma) && _sl_snap_sign_flipped(k->inputs[b], mb))
                snprintf(text, n, "shadows shimmer as the camera moves: the snap's offset has the wrong sign — it "
                                  "moves the world's origin as far again from a whole texel (x + (x - round(x))) where "
                                  "it must cancel that fraction, + (round(x) - x) in texels, rescaled to NDC by / "
                                  "(map_size / 2): the origin lands at texel (%.2f, %.2f), then at (%.2f, %.2f)",
                         boxes[a].origin[0], boxes[a].origin[1], boxes[b].origin[0], boxes[b].origin[1]);
            else if (_sl_snap_grid(boxes, k->rows) > 0) {
                double grid = _sl_snap_grid(boxes, k->rows);
                snprintf(text, n, "shadows shimmer as the camera moves: the snap rounds to %s texels, not whole ones — "
                                  "every box's world origin lands on a multiple of %g texel (at (%.2f, %.2f), then "
                                  "(%.2f, %.2f)): the offset is rounded in units of %s per NDC unit, where a texel is "
                                  "2 / map_size of NDC (NDC spans 2): round the origin's x and y times map_size / 2, "
                                  "then divide the offset by map_size / 2",
                         grid == 0.5 ? "half" : "quarter", grid, boxes[a].origin[0], boxes[a].origin[1],
                         boxes[b].origin[0], boxes[b].origin[1], grid == 0.5 ? "map_size" : "2 map_size");
            }
            else if (_sl_snapped_in_one_axis(&boxes[a], &boxes[b], gx, gy) >= 0) {
                /* one axis keeps the origin on whole texels: the snap is there, the other axis's is not its own */
                char good = _sl_snapped_in_one_axis(&boxes[a], &boxes[b], gx, gy) == 0 ? 'x' : 'y';
                char bad = good == 'x' ? 'y' : 'x';
                snprintf(text, n, "shadows shimmer as the camera moves: the projection is snapped to whole texels in "
                                  "%c but not in %c — when the sphere moves, the world's origin lands at texel (%.2f, "
                                  "%.2f), then at (%.2f, %.2f): whole texels in %c, %.2f of a texel apart in %c; the %c "
                                  "offset must round the origin's own %c in texels, as the %c offset does",
                         good, bad, boxes[a].origin[0], boxes[a].origin[1], boxes[b].origin[0], boxes[b].origin[1],
                         good, bad == 'x' ? gx : gy, bad, bad, bad, good);
            }
            else
                snprintf(text, n, "shadows shimmer as the camera moves: snap the projection to whole texels — when "
                                  "the sphere moves, the world slides over the texel grid (the world's origin lands at "
                                  "texel (%.2f, %.2f), then at (%.2f, %.2f): %.2f and %.2f of a texel apart, not a "
                                  "whole number of texels)",
                         boxes[a].origin[0], boxes[a].origin[1], boxes[b].origin[0], boxes[b].origin[1], gx, gy);
        }
    return true;
}

bool sl_lab6_probe_contract(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                            char *text, size_t n, int *shown) {
    (void)expected; /* the boxes' contract holds whatever the solution's numbers are */
    const sl_probe_function *f = sl_probe_at(k->function);
    if (!f || strcmp(f->name, "lab6_cascade_matrices") != 0) return false;
    return _sl_cascade_matrices_contract(k, student, broken, text, n, shown);
}

/* ---- cascade_compare ---- */

/* What one comparison in layer `layer` of the probe's texture array gives at a row's point, with the bias
 * `bias` (a negative layer: the row's own), divided by w or not; -1 where a layer does not exist. */
static double _sl_layer_compare_remapped(const float *in, int layer, double bias, bool divide, bool clamped,
                                         bool remapped) {
    double w = divide ? in[5] : 1.0;
    if (w == 0) return -1;
    double p[3] = {in[2] / w, in[3] / w, in[4] / w};
    for (int i = 0; i < 3 && remapped; i++) p[i] = p[i] * 0.5 + 0.5;
    if (p[2] > 1.0) return 1.0;
    for (int i = 0; i < 2 && clamped; i++) p[i] = fmin(fmax(p[i], 0), 1); /* 1.0 itself is the border's texel */
    if (p[0] < 0 || p[0] > 1 || p[1] < 0 || p[1] > 1) return 1.0; /* the border: depth 1.0 */
    if (layer < 0 || layer >= SL_PROBE_LAYERS) return -1;
    int tx = (int)floor(p[0] * SL_PROBE_MAP_SIZE), ty = (int)floor(p[1] * SL_PROBE_MAP_SIZE);
    if (tx >= SL_PROBE_MAP_SIZE || ty >= SL_PROBE_MAP_SIZE) return 1.0; /* s or t exactly 1: the border's texel */
    double stored = sl_probe_layer_depth(SL_PROBE_MAP_CASCADES, layer, tx, ty);
    return p[2] - bias > stored ? 0.0 : 1.0;
}

static double _sl_layer_compare_at(const float *in, int layer, double bias, bool divide, bool clamped) {
    return _sl_layer_compare_remapped(in, layer, bias, divide, clamped, false);
}

/* Every failing row outside the cascade's square (s or t outside [0, 1] after the divide), every row inside
 * it right: the lookup there does not reach the border. With clamped p.xy every row is explained. */
static int _sl_compare_outside_square(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, outside = 0, first = -1;
    bool clamped = true;
    for (int r = 0; r < v->k->rows; r++) {
        const float *in = v->k->inputs[r];
        double want = _sl_layer_compare_at(in, (int)in[1], in[6], true, true);
        clamped &= want >= 0 && fabs(_sl_got(v, r, 0) - want) <= 1e-3;
        if (!_sl_failed(v, r)) continue;
        failing++;
        double s = in[2] / in[5], t = in[3] / in[5];
        if (in[5] > 0 && (s < 0 || s > 1 || t < 0 || t > 1)) {
            outside++;
            if (first < 0) first = r;
        }
    }
    if (!failing || outside != failing) return -1;
    snprintf(text, n, "outside the cascade's square (s or t outside [0, 1]) it answers shadowed, where nothing was "
                      "recorded: the texture's border, depth 1.0, answers lit there%s",
             clamped ? " — every row reads as p.xy clamped to [0, 1], which reads the map's edge texel instead: look "
                       "up p.xy as it is"
                     : "");
    return first;
}

/* One way of reading the rows, to test on every row at once: the layer read (relative to the given one,
 * or 0 for "always layer 0"), the bias used (a constant, or < 0 for the given one), the divide by w. */
typedef struct _sl_compare_reading {
    int layer_shift;
    bool first_layer;
    double bias;
    bool divide;
    bool bias_added; /* the given bias added to p.z, not subtracted */
    bool normalised; /* the layer given as layer / layers, a 3D texture's coordinate: GL reads round(layer / 4) */
    bool remapped;   /* p moved to [0, 1] again, p * 0.5 + 0.5, after the divide */
} _sl_compare_reading;

static bool _sl_reading_explains(const sl_verdict_rows *v, _sl_compare_reading h) {
    for (int r = 0; r < v->k->rows; r++) {
        const float *in = v->k->inputs[r];
        int layer = h.first_layer ? 0
                  : h.normalised ? (int)floor((double)(int)in[1] / SL_PROBE_LAYERS + 0.5)
                                 : (int)in[1] + h.layer_shift;
        double bias = h.bias < 0 ? in[6] : h.bias;
        double want = _sl_layer_compare_remapped(in, layer, h.bias_added ? -bias : bias, h.divide, false, h.remapped);
        if (want < 0 || fabs(_sl_got(v, r, 0) - want) > 1e-3) return false;
    }
    return true;
}

static int _sl_verdict_cascade_compare(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, failing = 0, first = -1, inverted = 0, far_rows = 0, no_far = 0;
    for (int r = 0; r < rows; r++) {
        const float *in = v->k->inputs[r];
        double got = _sl_got(v, r, 0), want = _sl_want(v, r, 0);
        inverted += fabs(got - (1 - want)) < 1e-3;
        if (in[4] / in[5] > 1.0) {
            far_rows++;
            no_far += got < 0.5;
        }
        if (!_sl_failed(v, r)) continue;
        failing++;
        if (first < 0) first = r;
    }
    if (!failing) return -1;
    /* Each mistake is a whole reading of the rows: it must explain every row, failing or not. */
    if (_sl_reading_explains(v, (_sl_compare_reading){.normalised = true, .bias = -1, .divide = true})) {
        snprintf(text, n, "it reads layer round(layer / %d): the layer given as a fraction of the array, as a 3D "
                          "texture's coordinate would be — a sampler2DArray takes the layer's index itself, "
                          "texture(cascades, vec3(p.xy, float(layer)))", SL_PROBE_LAYERS);
        return first;
    }
    if (_sl_reading_explains(v, (_sl_compare_reading){.first_layer = true, .bias = -1, .divide = true})) {
        snprintf(text, n, "it reads layer 0 whatever `layer` is: texture(cascades, vec3(p.xy, float(layer)))");
        return first;
    }
    for (int shift = -1; shift <= 1; shift += 2)
        if (_sl_reading_explains(v, (_sl_compare_reading){.layer_shift = shift, .bias = -1, .divide = true})) {
            snprintf(text, n, "it reads the layer %s the one given: texture(cascades, vec3(p.xy, float(layer))), layer "
                              "as cascade_index() chose it", shift > 0 ? "after" : "before");
            return first;
        }
    if (_sl_reading_explains(v, (_sl_compare_reading){.bias = -1, .divide = true, .remapped = true})) {
        snprintf(text, n, "it moves p to [0, 1] again, p * 0.5 + 0.5 after the divide (as shaders whose matrix has no "
                          "bias matrix must): lab 2's shadow matrix already holds W, so p is in [0, 1] — read the "
                          "layer at p.xy and compare p.z - bias as they are");
        return first;
    }
    if (_sl_reading_explains(v, (_sl_compare_reading){.bias = -1, .divide = false})) {
        snprintf(text, n, "no divide by w: the shadow coordinate is homogeneous — divide xyz by w before the lookup");
        return first;
    }
    if (_sl_reading_explains(v, (_sl_compare_reading){.bias = -1, .divide = true, .bias_added = true})) {
        snprintf(text, n, "the bias is added, not subtracted: a point just in front of a stored surface, within the "
                          "bias, comes out shadowed (and acne spreads) — compare p.z - bias, moved towards the light, "
                          "with the stored depth");
        return first;
    }
    static const double constants[] = {0, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 3e-3, 5e-3, 0.01, 0.02, 0.05};
    for (size_t i = 0; i < sizeof constants / sizeof constants[0]; i++)
        if (_sl_reading_explains(v, (_sl_compare_reading){.bias = constants[i], .divide = true})) {
            if (constants[i] == 0)
                snprintf(text, n, "the bias is not the one given: the rows read as no bias at all (or one too small "
                                  "to show here), so points just behind a stored surface, within the bias, come out "
                                  "shadowed (shadow acne) — compare p.z - bias with the stored depth");
            else
                snprintf(text, n, "the bias is not the one given: every row reads as a constant bias of %g — compare "
                                  "p.z - bias (the framework's bias is one and a half texels of this cascade, "
                                  "different in every cascade)", constants[i]);
            return first;
        }
    int outside = _sl_compare_outside_square(v, text, n);
    if (outside >= 0) return outside;
    if (inverted == rows) {
        snprintf(text, n, "every answer is the opposite of the reference's: the comparison is inverted (shadowed where "
                          "p.z - bias is FARTHER than the stored depth)");
        return first;
    }
    if (far_rows && no_far == far_rows) {
        snprintf(text, n, "beyond the cascade's far plane (p.z > 1) it answers shadowed: nothing was recorded there, so "
                          "it is lit (return 1.0)");
        return first;
    }
    /* rows that differ only in the bias, the same answer where the solution's differ: the bias is not the one given */
    for (int a = 0; a < rows; a++) {
        if (!_sl_failed(v, a)) continue;
        for (int b = 0; b < rows; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            bool twin = b != a && ia[6] != ib[6];
            for (int i = 0; twin && i < 6; i++) twin = ia[i] == ib[i];
            if (!twin) continue;
            if (fabs(_sl_got(v, a, 0) - _sl_got(v, b, 0)) < 1e-3 &&
                fabs(_sl_want(v, a, 0) - _sl_want(v, b, 0)) > 0.5) {
                snprintf(text, n, "the bias is not the one given: the same point with bias %g and with bias %g gives "
                                  "the same answer — compare p.z - bias (the framework's bias is one and a half texels "
                                  "of this cascade, different in every cascade)", (double)ia[6], (double)ib[6]);
                return a;
            }
        }
    }
    return -1;
}

static int _sl_verdict_cascade_index(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, plus = 0, minus = 0, distance = 0, evenly = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double got = _sl_got(v, r, 0), want = _sl_want(v, r, 0);
        /* the index chosen by the distance to the camera */
        double d = sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2]);
        int count = (int)in[7], by_distance = count - 1;
        for (int i = 0; i < count - 1; i++)
            if (d < in[3 + i]) {
                by_distance = i;
                break;
            }
        /* the index as the depth's fraction of the last split, as if the splits were evenly spaced */
        double last = in[3 + (count >= 1 && count <= 4 ? count - 1 : 0)];
        double fraction = last > 0 ? floor(-in[2] / last * count) : -1;
        failing++;
        plus += got == want + 1;
        minus += got == want - 1;
        distance += got == by_distance;
        evenly += got == fmin(fmax(fraction, 0), count - 1) || got == fraction;
        if (first < 0) first = r;
    }
    if (!failing) return -1;
    if (distance == failing) {
        snprintf(text, n, "cascades chosen by the distance to the camera, length(view_position), not by view depth "
                          "-view_position.z: the splits are planes across the view direction");
        return first;
    }
    if (evenly == failing) {
        snprintf(text, n, "the index is the depth's fraction of the last split, int(depth / split_far[count - 1] * "
                          "count), as if the splits were evenly spaced: the practical splits crowd near the camera, "
                          "so return the first cascade whose far split lies beyond the depth (a loop over split_far)");
        return first;
    }
    if (plus == failing || minus == failing) {
        snprintf(text, n, "off by one layer: the index is %s the reference's (return the first cascade whose far split "
                          "is beyond the depth, 0..count-1)", plus == failing ? "one above" : "one below");
        return first;
    }
    return -1;
}

int sl_verdict_lab6(const sl_verdict_rows *v, char *text, size_t n) {
    const char *name = v->f->name;
    if (strcmp(name, "lab6_split_distances") == 0) return _sl_verdict_splits(v, text, n);
    if (strcmp(name, "lab6_slice_sphere") == 0) return _sl_verdict_sphere(v, text, n);
    if (strcmp(name, "cascade_index") == 0) return _sl_verdict_cascade_index(v, text, n);
    if (strcmp(name, "cascade_compare") == 0) return _sl_verdict_cascade_compare(v, text, n);
    return -1;
}
