/* Lab 5's probes read together (lab5.c holds its pictures' diagnoses): the
 * blur's rows, light bleeding's and the Chebyshev bound's, into one verdict. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_gl.h"
#include "sl_probe.h"
#include "sl_verdict.h"
#include "verdict_rows.h"

/* ---- what lab 5's probes show together ---- */

/* The texel of a moments map at a row's uv: what the stub (no blur) returns. */
static double _sl_centre_texel(const float *in) {
    int x = (int)floor(in[1] * SL_PROBE_MAP_SIZE), y = (int)floor(in[2] * SL_PROBE_MAP_SIZE);
    return sl_probe_moments_depth((sl_probe_map)(int)in[0], x, y);
}

/* The first moment of a Gaussian blur of a row's map along (dx, dy) with sigma, edge texels repeated. */
static double _sl_blur_model(const float *in, int dx, int dy, double sigma) {
    int radius = (int)in[5];
    int x = (int)floor(in[1] * SL_PROBE_MAP_SIZE), y = (int)floor(in[2] * SL_PROBE_MAP_SIZE);
    double sum = 0, weights = 0;
    for (int i = -radius; i <= radius; i++) {
        int tx = x + i * dx, ty = y + i * dy;
        tx = tx < 0 ? 0 : tx >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : tx;
        ty = ty < 0 ? 0 : ty >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : ty;
        double w = exp(-(double)(i * i) / (2 * sigma * sigma));
        sum += w * sl_probe_moments_depth((sl_probe_map)(int)in[0], tx, ty);
        weights += w;
    }
    return sum / weights;
}

/* The sigmas (0.1 to 20 texels) with which the contract's Gaussian gives a row's first moment within 1e-4:
 * false where none does. Scanned, then refined, not solved: the far side's share need not be monotonic in
 * sigma for every tap position, and a row far from the edge fits a whole range. */
static bool _sl_implied_sigma(const float *in, double got, double *lo, double *hi) {
    int dx = (int)in[3], dy = (int)in[4];
    double best = -1, best_error = INFINITY, step = pow(200.0, 1 / 400.0);
    *lo = INFINITY, *hi = -INFINITY;
    for (int k = 0; k <= 400; k++) {
        double sigma = 0.1 * pow(step, k), error = fabs(_sl_blur_model(in, dx, dy, sigma) - got);
        if (error < best_error) best_error = error, best = sigma;
        if (error < 1e-4) *lo = fmin(*lo, sigma), *hi = fmax(*hi, sigma);
    }
    /* refined between the scan's neighbours of the best: the error is smooth there */
    double a = best / step, b = best * step;
    for (int k = 0; k < 60; k++) {
        double p = a + (b - a) / 3, q = b - (b - a) / 3;
        if (fabs(_sl_blur_model(in, dx, dy, p) - got) < fabs(_sl_blur_model(in, dx, dy, q) - got)) b = q;
        else a = p;
    }
    double refined = 0.5 * (a + b);
    if (fabs(_sl_blur_model(in, dx, dy, refined) - got) < 1e-4) *lo = fmin(*lo, refined), *hi = fmax(*hi, refined);
    return *lo <= *hi;
}

/* Every failing row a Gaussian blur of the map with a sigma of its own, one sigma per radius: the kernel's
 * width is said by radius, beside the contract's; and where each is 1 / the contract's, the sigma is
 * multiplied where it should divide. Rows that fit a wide range of sigmas (far from the edge) only have to
 * agree; at least two that pin sigma down say it. */
static bool _sl_blur_sigma_by_radius(const sl_verdict_rows *v, char *text, size_t n, int *row) {
    double lo[16], hi[16];
    for (int i = 0; i < 16; i++) lo[i] = 0, hi[i] = INFINITY;
    int pinned = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        int radius = (int)in[5];
        double a, b;
        if (radius < 1 || radius >= 16 || !_sl_implied_sigma(in, _sl_got(v, r, 0), &a, &b)) return false;
        lo[radius] = fmax(lo[radius], a * 0.98);
        hi[radius] = fmin(hi[radius], b * 1.02);
        if (lo[radius] > hi[radius]) return false;
        if (b <= a * 1.1) {
            pinned++;
            if (first < 0) first = r;
        }
    }
    if (pinned < 2) return false;
    char said[400] = "";
    size_t used = 0;
    int listed = 0, inverse = 0, root = 0, narrow = 0;
    double ratio_lo = INFINITY, ratio_hi = 0;
    for (int radius = 1; radius < 16; radius++) {
        if (!(hi[radius] <= lo[radius] * 1.25)) continue; /* pinned down for this radius */
        double sigma = sqrt(lo[radius] * hi[radius]), contract = fmax(radius * 0.5, 0.5);
        inverse += fabs(sigma - 1 / contract) <= 0.05 / contract;
        root += fabs(sigma - sqrt(contract)) <= 0.04 * sqrt(contract);
        ratio_lo = fmin(ratio_lo, sigma / contract);
        ratio_hi = fmax(ratio_hi, sigma / contract);
        narrow++;
        if (listed < 4 && used < sizeof said) {
            used += (size_t)snprintf(said + used, sizeof said - used, "%sradius %d like sigma %.2g (the contract's %.2g)",
                                     listed ? ", " : "", radius, sigma, contract);
            listed++;
        }
    }
    if (!listed) return false;
    char why[300];
    if (inverse == narrow && narrow >= 2)
        snprintf(why, sizeof why, "each sigma is 1 / the contract's, as exp(-i * i / 2.0 * sigma * sigma) gives it: "
                                  "the sigma^2 belongs in the divisor, exp(-i^2 / (2.0 * sigma * sigma))");
    else if (root == narrow && narrow >= 2)
        snprintf(why, sizeof why, "each sigma is the square root of the contract's, as exp(-i * i / (2.0 * sigma)) "
                                  "gives it: the divisor is 2 sigma^2, exp(-i^2 / (2.0 * sigma * sigma))");
    else if (narrow >= 2 && ratio_hi <= ratio_lo * 1.05 && fabs(ratio_lo - 1) > 0.05) {
        double ratio = sqrt(ratio_lo * ratio_hi);
        snprintf(why, sizeof why, "each sigma is %.2g times the contract's%s: sigma = max(float(radius) * 0.5, 0.5)",
                 ratio, fabs(ratio - 2) < 0.05          ? " (sigma = radius)"
                        : fabs(ratio - sqrt(0.5)) < 0.03 ? " (the weights exp(-i^2 / sigma^2): the 2 left out of the "
                                                           "divisor 2 sigma^2)"
                                                         : "");
    }
    else
        snprintf(why, sizeof why, "the weights are exp(-i^2 / (2 sigma^2)) with sigma = max(float(radius) * 0.5, 0.5)");
    snprintf(text, n, "the kernel is a Gaussian of another width: %s — %s", said, why);
    *row = first;
    return true;
}

/* blur_moments(moments, uv, direction, radius): inputs map, uv.x, uv.y, direction.x, direction.y, radius. */
static int _sl_verdict_blur(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, failing = 0, first = -1, as_stub = 0;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        failing++;
        if (first < 0) first = r;
        as_stub += fabs(_sl_got(v, r, 0) - _sl_centre_texel(v->k->inputs[r])) < 1e-5;
    }
    if (!failing) return -1;
    if (as_stub == failing) {
        /* "not implemented" only of the stub as handed out: written code that blurs nothing is told so */
        snprintf(text, n, "%s the texel at uv unblurred, as the stub does — the weighted sum of 2 * radius + 1 texels "
                          "along direction",
                 sl_diag_still_the_stub(v->f->file, v->f->name) == 0 ? "it is written, but returns"
                                                                      : "not implemented: it returns");
        return first;
    }
    /* NaN at radius 0 alone, every other row right: sigma = radius * 0.5 is 0 there, and exp(-0 / 0) is NaN */
    int nan_at_zero = 0;
    for (int r = 0; r < rows; r++)
        nan_at_zero += _sl_failed(v, r) && (int)v->k->inputs[r][5] == 0 && isnan(_sl_got(v, r, 0));
    if (nan_at_zero > 0 && nan_at_zero == failing) {
        snprintf(text, n, "at radius 0 it gives NaN: sigma = radius * 0.5 is 0 there, and the centre's weight exp(-0.0 "
                          "/ 0.0) is NaN — sigma = max(float(radius) * 0.5, 0.5), so radius 0 is the texel itself");
        return first;
    }
    /* a flat map stays flat whatever the kernel: what it gives there is the sum of the weights */
    for (int r = 0; r < rows; r++) {
        const float *in = v->k->inputs[r];
        if (!_sl_failed(v, r) || (int)in[0] != SL_PROBE_MAP_MOMENTS_FLAT) continue;
        /* the flat map holds (0.5, 0.25): a weight sum scales both moments alike */
        double m1 = _sl_got(v, r, 0), m2 = _sl_got(v, r, 1), sum = m1 / 0.5;
        if (fabs(m2 / 0.25 - sum) <= 1e-3 * fabs(sum) + 1e-6) {
            snprintf(text, n, "the weights sum to %.3g, not 1 (a flat map at depth 0.5 comes out at %.4g): divide the "
                              "weighted sum by the sum of the weights", sum, m1);
        } else if (fabs(m2 - m1) <= 1e-5) {
            snprintf(text, n, "its second moment comes out as its first: a flat map of moments (0.5, 0.25) gives "
                              "(%.4g, %.4g) — one value blurred into both components (a float, .r, where the two "
                              "moments belong: the weighted sum of the texels' .rg)", m1, m2);
        } else {
            snprintf(text, n, "a flat map of moments (0.5, 0.25) does not stay flat: it gives (%.4g, %.4g) — each "
                              "moment is blurred on its own, the weighted sum of the texels' .rg over weights that "
                              "sum to 1", m1, m2);
        }
        return r;
    }
    /* only the rows of one direction fail: the other direction is followed, this one not */
    int fail_x = 0, fail_y = 0, first_y = -1, first_x = -1;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        if (in[3] == 0 && in[4] != 0) {
            fail_y++;
            if (first_y < 0) first_y = r;
        } else if (in[4] == 0 && in[3] != 0) {
            fail_x++;
            if (first_x < 0) first_x = r;
        }
    }
    /* "along x whatever direction is" only when every failing row gives what the same blur along the
     * other axis gives; a step too long (a uv unit, not a texel) shows other values */
    bool as_other_axis = true;
    for (int r = 0; r < rows; r++)
        if (_sl_failed(v, r)) {
            const float *in = v->k->inputs[r];
            double swapped = _sl_blur_model(in, (int)in[4], (int)in[3], fmax(in[5] * 0.5, 0.5));
            as_other_axis &= fabs(_sl_got(v, r, 0) - swapped) < 1e-4;
        }
    if (as_other_axis && (fail_y == failing) != (fail_x == failing) && (fail_x == failing || fail_y == failing)) {
        bool y_wrong = fail_y == failing;
        snprintf(text, n, "it blurs along %s whatever direction is: every row with direction %s differs, every row "
                          "with direction %s is right — step along `direction`, one texel at a time",
                 y_wrong ? "x" : "y", y_wrong ? "(0, 1)" : "(1, 0)", y_wrong ? "(1, 0)" : "(0, 1)");
        return y_wrong ? first_y : first_x;
    }
    /* every failing row gives the moments of the map's corner texel, wherever uv is (one of them where its
     * own texel holds another): the lookup does not follow uv */
    int at_corner = 0, elsewhere = 0;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double corner = sl_probe_moments_depth((sl_probe_map)(int)in[0], 0, 0);
        at_corner += fabs(_sl_got(v, r, 0) - corner) < 1e-5 && fabs(_sl_got(v, r, 1) - corner * corner) < 1e-5;
        elsewhere += fabs(_sl_centre_texel(in) - corner) > 1e-3;
    }
    if (at_corner == failing && elsewhere > 0) {
        snprintf(text, n, "it reads the map's corner, texel (0, 0), wherever uv is: every failing row gives the moments "
                          "stored there — uv made an integer before it is scaled to texels? ivec2(uv * size), not "
                          "ivec2(uv) * size (or sample at uv, not at a constant)");
        return first;
    }
    /* rows that differ in the radius alone, the same answer where the solution's differ: on every such pair */
    bool radius_free = true;
    for (int a = 0; a < rows; a++)
        for (int b = 0; b < rows; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            bool twin = b != a && ia[5] != ib[5];
            for (int i = 0; twin && i < 5; i++) twin = ia[i] == ib[i];
            if (twin && fabs(_sl_got(v, a, 0) - _sl_got(v, b, 0)) >= 1e-5) radius_free = false;
        }
    for (int a = 0; radius_free && a < rows; a++) {
        if (!_sl_failed(v, a)) continue;
        for (int b = 0; b < rows; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            bool twin = b != a && ia[5] != ib[5];
            for (int i = 0; twin && i < 5; i++) twin = ia[i] == ib[i];
            if (!twin) continue;
            if (fabs(_sl_got(v, a, 0) - _sl_got(v, b, 0)) < 1e-5 && fabs(_sl_want(v, a, 0) - _sl_want(v, b, 0)) > 1e-3) {
                snprintf(text, n, "the radius is ignored: radius %d and radius %d give the same — a fixed kernel? "
                                  "2 * radius + 1 taps with weights exp(-i^2 / (2 sigma^2)), sigma = max(float(radius) * 0.5, 0.5)",
                         (int)ia[5], (int)ib[5]);
                return a;
            }
        }
    }
    /* sigma = max(float(radius) * 0.5, 0.5) typed in GLSL: radius / 2 is an integer division, so an odd radius
     * gets sigma 1 where 1.5 is meant (radius 3), 2 where 2.5 is meant (radius 5) */
    int integer_sigma = 0, first_integer = -1;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        int radius = (int)in[5], dx = (int)in[3], dy = (int)in[4];
        int x = (int)floor(in[1] * SL_PROBE_MAP_SIZE), y = (int)floor(in[2] * SL_PROBE_MAP_SIZE);
        double sigma = fmax((double)(radius / 2), 0.5), sum = 0, weights = 0;
        for (int i = -radius; i <= radius; i++) {
            int tx = x + i * dx, ty = y + i * dy;
            tx = tx < 0 ? 0 : tx >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : tx;
            ty = ty < 0 ? 0 : ty >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : ty;
            double w = exp(-(double)(i * i) / (2 * sigma * sigma));
            sum += w * sl_probe_moments_depth((sl_probe_map)(int)in[0], tx, ty);
            weights += w;
        }
        if (radius % 2 == 1 && radius > 1 && fabs(_sl_got(v, r, 0) - sum / weights) < 1e-4) {
            integer_sigma++;
            if (first_integer < 0) first_integer = r;
        }
    }
    if (integer_sigma > 0 && integer_sigma == failing) {
        snprintf(text, n, "the kernel is too narrow at odd radii: radius %d blurs with sigma %d, as radius / 2 gives it "
                          "in integer arithmetic — in GLSL write sigma = max(float(radius) * 0.5, 0.5)",
                 (int)v->k->inputs[first_integer][5], (int)v->k->inputs[first_integer][5] / 2);
        return first_integer;
    }
    /* every failing row one whose taps reach past the map's edge, every other row right: the edge texel is not
     * repeated there (a texel clamped to size, or not at all: texelFetch outside the texture reads 0 here) */
    int past_edge = 0, first_edge = -1;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        int radius = (int)in[5], x = (int)floor(in[1] * SL_PROBE_MAP_SIZE), y = (int)floor(in[2] * SL_PROBE_MAP_SIZE);
        int along = in[3] != 0 ? x : y;
        if (radius > 0 && (along - radius < 0 || along + radius > SL_PROBE_MAP_SIZE - 1)) {
            past_edge++;
            if (first_edge < 0) first_edge = r;
        }
    }
    if (past_edge > 0 && past_edge == failing) {
        snprintf(text, n, "taps past the map's edge do not read the edge texel: near the border it answers %.4g where the "
                          "map's own value, repeated, gives %.4g — clamp the texel to [0, size - 1] (texelFetch outside "
                          "the texture is undefined; here it reads 0)",
                 _sl_got(v, first_edge, 0), _sl_want(v, first_edge, 0));
        return first_edge;
    }
    /* a Gaussian of another width: the sigma each failing row's answer implies, by radius */
    if (_sl_blur_sigma_by_radius(v, text, n, &first)) return first;
    /* across the edges: too little or too much of the other side */
    int narrow = 0, wide = 0, first_width = -1;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double centre = _sl_centre_texel(v->k->inputs[r]);
        double here = fabs(_sl_got(v, r, 0) - centre), there = fabs(_sl_want(v, r, 0) - centre);
        narrow += here < there;
        wide += here > there;
        if (first_width < 0) first_width = r;
    }
    if (narrow == failing || wide == failing) {
        snprintf(text, n, "the kernel is too %s: across an edge it takes %s of the other side than a Gaussian with "
                          "sigma = max(float(radius) * 0.5, 0.5) does — are the taps one texel apart (1.0 / textureSize), and "
                          "the weights exp(-i^2 / (2 sigma^2))?",
                 narrow == failing ? "narrow" : "wide", narrow == failing ? "less" : "more");
        return first_width;
    }
    /* two rows that are mirror images about an edge (the same map, direction and radius, the texels either side):
     * any kernel with the same weight at -i and +i gives first moments that add to 0.25 + 0.75 = 1 */
    for (int a = 0; a < rows; a++)
        for (int b = a + 1; b < rows; b++) {
            const float *ia = v->k->inputs[a], *ib = v->k->inputs[b];
            if (!_sl_failed(v, a) && !_sl_failed(v, b)) continue;
            if (ia[0] != ib[0] || ia[3] != ib[3] || ia[4] != ib[4] || ia[5] != ib[5] || ia[5] < 1) continue;
            int across = ia[3] != 0 ? 1 : 2; /* the uv component along the blur */
            if (fabs(ia[across] + ib[across] - 1) > 1e-6 || ia[3 - across] != ib[3 - across]) continue;
            double want = _sl_want(v, a, 0) + _sl_want(v, b, 0), got = _sl_got(v, a, 0) + _sl_got(v, b, 0);
            if (fabs(want - 1) > 1e-4 || fabs(got - want) <= 1e-3) continue;
            snprintf(text, n, "the kernel is not symmetric: the texels either side of the edge, mirror images, blurred "
                              "along %s with radius %d, give first moments %.4g and %.4g, which add to %.4g, where any "
                              "kernel with the same weight at -i and +i gives two that add to 1 (0.25 + 0.75) — taps "
                              "from -radius to radius, both ends, weights exp(-i^2 / (2 sigma^2)) that depend on i * i",
                     across == 1 ? "x" : "y", (int)ia[5], _sl_got(v, a, 0), _sl_got(v, b, 0), got);
            return _sl_failed(v, a) ? a : b;
        }
    return -1;
}

/* reduce_light_bleeding(p_max, amount) */
static int _sl_verdict_bleeding(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, failing = 0, first = -1, swapped = 0;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double p = in[0], amount = in[1];
        failing++;
        if (first < 0) first = r;
        double lo = p, hi = 1, x = amount; /* linstep(p_max, 1, amount) */
        double inverted = hi - lo > 1e-9 ? fmin(fmax((x - lo) / (hi - lo), 0), 1) : (x >= lo ? 1 : 0);
        swapped += fabs(_sl_got(v, r, 0) - inverted) < 1e-3;
    }
    if (!failing) return -1;
    if (swapped == failing) {
        snprintf(text, n, "linstep's arguments swapped: linstep(amount, 1.0, p_max) cuts p_max below amount off, "
                          "linstep(p_max, 1.0, amount) does something else");
        return first;
    }
    /* one amount that explains every row: a constant of its own */
    for (int k = 1; k < 100; k++) {
        double amount = k / 100.0;
        bool all = true;
        for (int r = 0; r < rows && all; r++) {
            double p = v->k->inputs[r][0];
            double want = fmin(fmax((p - amount) / (1 - amount), 0), 1);
            all = fabs(_sl_got(v, r, 0) - want) < 1e-3;
        }
        if (all) {
            snprintf(text, n, "the amount is not the one given: every row is linstep(%.2f, 1.0, p_max), whatever "
                              "amount is — use the parameter (the viewer's K and L change it)", amount);
            return first;
        }
    }
    return -1;
}

/* chebyshev_upper_bound(moments, t, min_variance): the variance each failing row was computed with, read
 * back from p_max = v / (v + d^2); one constant for all of them, not the row's minimum, is a minimum of its own. */
static int _sl_verdict_chebyshev(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, failing = 0, first = -1, implied_rows = 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int r = 0; r < rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        double mu = in[0], m2 = in[1], t = in[2], min_variance = in[3], p = _sl_got(v, r, 0), d = t - mu;
        failing++;
        if (first < 0) first = r;
        if (t <= mu || p <= 0 || p >= 1) continue;
        double implied = p * d * d / (1 - p);
        /* the row's own variance is below the minimum that was used: a minimum decided it */
        if (m2 - mu * mu < implied * 0.9 && fabs(implied - min_variance) > 0.05 * min_variance) {
            implied_rows++;
            lo = fmin(lo, implied);
            hi = fmax(hi, implied);
        }
    }
    if (!failing) return -1;
    if (implied_rows == failing && hi - lo <= 0.05 * hi) {
        snprintf(text, n, "the minimum variance is not the one given: every failing row used about %.2g whatever "
                          "min_variance is — variance = max(M2 - M1^2, min_variance), with the parameter (the viewer's "
                          "N and J change it)", 0.5 * (lo + hi));
        return first;
    }
    return -1;
}

int sl_verdict_lab5(const sl_verdict_rows *v, char *text, size_t n) {
    if (strcmp(v->f->name, "chebyshev_upper_bound") == 0) return _sl_verdict_chebyshev(v, text, n);
    if (strcmp(v->f->name, "blur_moments") == 0) return _sl_verdict_blur(v, text, n);
    if (strcmp(v->f->name, "reduce_light_bleeding") == 0) return _sl_verdict_bleeding(v, text, n);
    return -1;
}
