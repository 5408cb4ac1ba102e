/* Lab 2's diagnoses: the light's matrices. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "sl_compare.h"
#include "sl_diag_words.h"
#include "verdict_rows.h"

static double _sl_matrix_error(const double *a, const double *b) {
    double worst = 0, scale = 1;
    for (int i = 0; i < 16; i++) scale = fmax(scale, fabs(b[i]));
    for (int i = 0; i < 16; i++) {
        double d = fabs(a[i] - b[i]);
        if (isnan(a[i])) d = INFINITY;
        worst = fmax(worst, d);
    }
    return worst / scale;
}

static void _sl_mul(const double *a, const double *b, double *out) { /* column-major out = a * b */
    for (int col = 0; col < 4; col++)
        for (int row = 0; row < 4; row++) {
            double sum = 0;
            for (int k = 0; k < 4; k++) sum += a[k * 4 + row] * b[col * 4 + k];
            out[col * 4 + row] = sum;
        }
}

/* Inverse of a column-major 4x4 (Gauss-Jordan, partial pivoting); false when singular. */
static bool _sl_invert(const double *m, double *out) {
    double a[4][8];
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 8; col++) a[row][col] = col < 4 ? m[col * 4 + row] : (col - 4 == row);
    for (int col = 0; col < 4; col++) {
        int pivot = col;
        for (int row = col + 1; row < 4; row++)
            if (fabs(a[row][col]) > fabs(a[pivot][col])) pivot = row;
        if (fabs(a[pivot][col]) < 1e-12) return false;
        for (int k = 0; k < 8; k++) {
            double t = a[col][k];
            a[col][k] = a[pivot][k];
            a[pivot][k] = t;
        }
        double d = a[col][col];
        for (int k = 0; k < 8; k++) a[col][k] /= d;
        for (int row = 0; row < 4; row++) {
            if (row == col) continue;
            double f = a[row][col];
            for (int k = 0; k < 8; k++) a[row][k] -= f * a[col][k];
        }
    }
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 4; col++) out[col * 4 + row] = a[row][col + 4];
    return true;
}

/* The bias matrix a shadow matrix holds, W' = S * (Lp Lv)^-1, read row by row: each of x, y, z mapped to
 * "a coordinate + b w", w to "c w". Said only when W' has that form (any other matrix is an order or a
 * product, which the callers tell apart), and only of the rows that differ from W's 0.5 c + 0.5 w. */
static bool _sl_describe_bias_matrix(const double *sm, const double *pv, char *text, size_t n) {
    double inv[16], w[16];
    if (!_sl_invert(pv, inv)) return false;
    _sl_mul(sm, inv, w);
    const double tolerance = 1e-3;
    /* W transposed (column-major w[col * 4 + row]): 0.5 on the diagonal, w' = 0.5 x + 0.5 y + 0.5 z + w */
    bool transposed = true;
    for (int col = 0; col < 4 && transposed; col++)
        for (int row = 0; row < 4; row++) {
            double want = row == col ? (row == 3 ? 1 : 0.5) : row == 3 ? 0.5 : 0;
            transposed &= fabs(w[col * 4 + row] - want) <= tolerance;
        }
    if (transposed) {
        snprintf(text, n, "the bias matrix W is transposed: its translation (0.5, 0.5, 0.5) ends up in the bottom row "
                          "(w' = 0.5 x + 0.5 y + 0.5 z + w), not the last column — cglm's mat4 is column-major, so an "
                          "initialiser lists columns: {{0.5,0,0,0}, {0,0.5,0,0}, {0,0,0.5,0}, {0.5,0.5,0.5,1}}");
        return true;
    }
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 3; col++)
            if (col != row && fabs(w[col * 4 + row]) > tolerance) return false; /* a coordinate from another */
    if (fabs(w[3 * 4 + 3]) < tolerance) {
        /* W whole but for its corner: w' = 0, every coordinate at infinity */
        bool rest = true;
        for (int row = 0; row < 3 && rest; row++)
            rest = fabs(w[row * 4 + row] - 0.5) <= tolerance && fabs(w[3 * 4 + row] - 0.5) <= tolerance;
        if (!rest) return false;
        snprintf(text, n, "the shadow matrix's bias matrix ends its last column in 0, not 1: w' = 0, so every shadow "
                          "coordinate has w = 0 and every point counts as outside the light's frustum (lit) — W's last "
                          "column is (0.5, 0.5, 0.5, 1): the translation, and the w that carries it");
        return true;
    }
    static const char axis[] = "xyzw";
    char rows[400] = "";
    size_t used = 0;
    int differ = 0;
    for (int row = 0; row < 4; row++) {
        double a = w[row * 4 + row], b = w[3 * 4 + row];
        bool wrong = row < 3 ? fabs(a - 0.5) > tolerance || fabs(b - 0.5) > tolerance : fabs(b - 1) > tolerance;
        if (!wrong) continue;
        if (row < 3)
            used += (size_t)snprintf(rows + used, sizeof rows - used, "%s%c' = %.3g %c + %.3g w", differ ? ", " : "",
                                     axis[row], fabs(a) < tolerance ? 0.0 : a, axis[row], fabs(b) < tolerance ? 0.0 : b);
        else
            used += (size_t)snprintf(rows + used, sizeof rows - used, "%sw' = %.3g w", differ ? ", " : "", b);
        differ++;
        if (used >= sizeof rows) return false;
    }
    if (differ == 0) return false;
    bool identity = differ == 4 - (fabs(w[15] - 1) <= tolerance);
    for (int row = 0; row < 3 && identity; row++)
        identity = fabs(w[row * 4 + row] - 1) <= tolerance && fabs(w[12 + row]) <= tolerance && fabs(w[15] - 1) <= tolerance;
    if (identity) {
        snprintf(text, n, "the shadow matrix is Lp * Lv without the bias matrix W: coordinates stay in [-1,1] instead of [0,1]");
        return true;
    }
    if (differ == 1 && rows[0] != 'w')
        snprintf(text, n, "the shadow matrix's bias matrix is not W: %s, where W gives %c' = 0.5 %c + 0.5 w (mapping [-1, 1] to "
                          "[0, 1])", rows, rows[0], rows[0]);
    else
        snprintf(text, n, "the shadow matrix's bias matrix is not W: %s, where W gives 0.5 c + 0.5 w for each of x, y and z, and "
                          "w' = w (mapping [-1, 1] to [0, 1])", rows);
    return true;
}

void sl_diagnose_matrices(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "matrices");
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "lab 2's matrices were not used");
        return;
    }
    const double *sv = cap->numbers, *sp = cap->numbers + 16, *sm = cap->numbers + 32;
    const double *rv = ref->numbers, *rp = ref->numbers + 16, *rm = ref->numbers + 32;
    double ev = _sl_matrix_error(sv, rv), ep = _sl_matrix_error(sp, rp), em = _sl_matrix_error(sm, rm);
    if (ev <= k->epsilon && ep <= k->epsilon && em <= k->epsilon) {
        out->passed = true;
        return;
    }
    static const double bias[16] = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0.5, 0.5, 0.5, 1};
    double pv[16], vp[16], wvp[16], tmp[16];
    _sl_mul(sp, sv, pv);
    _sl_mul(sv, sp, vp);
    _sl_mul(bias, vp, wvp);
    if (ev > k->epsilon) {
        sl_diag_say(out, "the light's view matrix differs from the reference (largest error %.3g): check eye, target and "
                     "up against README.md's recipe (TODO lab2.1)", ev);
    } else if (ep > k->epsilon) {
        /* Does the student's camera see the whole scene? */
        int outside = 0;
        const sl_aabb *b = &c->scene.bounds;
        for (int i = 0; i < 8 && c->scene.light.type == SL_LIGHT_DIRECTIONAL; i++) {
            double p[4] = {i & 1 ? b->max[0] : b->min[0], i & 2 ? b->max[1] : b->min[1], i & 4 ? b->max[2] : b->min[2], 1};
            double q[4] = {0};
            for (int row = 0; row < 4; row++)
                for (int col = 0; col < 4; col++) q[row] += pv[col * 4 + row] * p[col];
            for (int a = 0; a < 3; a++) outside += fabs(q[a] / q[3]) > 1.0001;
        }
        char slip[200];
        if (outside)
            sl_diag_say(out, "the orthographic fit is too small: scene corners fall outside the light's frustum, so shadows "
                         "are cut off at its edge (TODO lab2.2)");
        else if (c->scene.light.type == SL_LIGHT_SPOT &&
                 sl_diag_angle_slip(sp[5], sl_diag_perspective_fov_deg(rp[5]), "2 * spot_angle_deg", slip, sizeof slip))
            sl_diag_say(out, "the light's projection differs from the reference (largest error %.3g): %s (TODO lab2.2)", ep,
                        slip);
        else
            sl_diag_say(out, "the light's projection differs from the reference (largest error %.3g): %s (TODO lab2.2)", ep,
                    c->scene.light.type == SL_LIGHT_SPOT
                        ? "a spot light's field of view is twice the cone's half-angle, in radians, aspect 1"
                        : "fit left/right/bottom/top/near/far to the scene box's corners in light view space, padded");
    } else if (_sl_matrix_error(sm, pv) <= k->epsilon) {
        sl_diag_say(out, "the shadow matrix is Lp * Lv without the bias matrix W: coordinates stay in [-1,1] instead of "
                     "[0,1] (TODO lab2.3)");
    } else if (_sl_matrix_error(sm, wvp) <= k->epsilon) {
        sl_diag_say(out, "the shadow matrix multiplies Lv * Lp: the order is reversed, it must be W * Lp * Lv (TODO lab2.3)");
    } else {
        static const double transposed[16] = {0.5, 0, 0, 0.5, 0, 0.5, 0, 0.5, 0, 0, 0.5, 0.5, 0, 0, 0, 1};
        double twvp[16];
        char tmp_text[600];
        _sl_mul(transposed, pv, twvp);
        _sl_mul(pv, bias, tmp);
        if (_sl_matrix_error(sm, tmp) <= k->epsilon)
            sl_diag_say(out, "the shadow matrix is Lp * Lv * W: W must come first (leftmost), W * Lp * Lv (TODO lab2.3)");
        else if (_sl_matrix_error(sm, twvp) <= k->epsilon)
            sl_diag_say(out, "the bias matrix W is transposed: its translation (0.5, 0.5, 0.5) ends up in the bottom row. "
                         "cglm's initialiser lists columns, so the translation is the last of the four {...} (TODO lab2.3)");
        else if (_sl_describe_bias_matrix(sm, pv, tmp_text, sizeof tmp_text))
            sl_diag_say(out, "%s (TODO lab2.3)", tmp_text);
        else
            sl_diag_say(out, "the shadow matrix differs from W * Lp * Lv (largest error %.3g) (TODO lab2.3)", em);
    }
}

/* The lookup lab 2's cases draw with: its compare mode's comparison. */
void sl_lab2_lookup_function(const sl_case *c, const char **function, const char **todo) {
    bool hardware = c->params.compare == SL_COMPARE_HARDWARE;
    *function = hardware ? "shadow_compare_hardware()" : "shadow_compare_manual()";
    *todo = hardware ? "lab2.6" : "lab2.5";
}

bool sl_diagnose_lab2_visibility(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                                 sl_check_result *out) {
    if (!mask) return false;
    const char *fn, *todo;
    sl_lab2_lookup_function(c, &fn, &todo);
    sl_acne acne = sl_measure_acne(s, t, mask);
    if (acne.fraction <= 0.02) return false;
    if (sl_acne_is_pattern(&acne)) {
        out->symptoms |= 1u << SL_SYMPTOM_ACNE;
        sl_diag_say(out, "shadow acne on %.0f%% of lit surfaces: they shadow themselves in stripes", 100 * acne.fraction);
        sl_diag_cause_in(out, fn, "the bias is missing or added — a surface compared with its own stored depth needs "
                           "p.z - bias > closest to be shadowed, in %s (TODO %s)", fn, todo);
        return true;
    }
    if (c->scene.light.type == SL_LIGHT_SPOT) {
        /* a solid region: the floor past the spot light's far plane */
        out->symptoms |= 1u << SL_SYMPTOM_EXTRA_SHADOW;
        sl_diag_say(out, "%.0f%% of lit surfaces are shadowed in solid regions, not in the stripes of acne", 100 * acne.fraction);
        sl_diag_cause_in(out, fn, "points beyond the light's far plane (depth > 1) are outside the frustum, so lit: test "
                           "p.z as well as x and y in %s (TODO %s)", fn, todo);
        return true;
    }
    return false;
}

/* ---- verdicts on its probes' rows (verdict.c asks by the probe's name) ---- */

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

/* What a fitted box that is not the contract's is, from its six values (left, right, bottom, top, near, far)
 * against the contract's (be, padded by `pad` at near and far): a box that takes in the light view's origin
 * too (running bounds started at 0, not at the first corner), or sides that each hold another side's value
 * (the x extent copied into y, near and far exchanged). */
static bool _sl_box_reading(const double *bs, const double *be, double pad, double tol, char *text, size_t n) {
    static const char *const side[6] = {"left", "right", "bottom", "top", "near", "far"};
    /* the corners' box and the origin's point: near = -(max z) and far = -(min z) take in z = 0 too */
    double near0 = be[4] + pad, far0 = be[5] - pad, with[6] = {fmin(be[0], 0), fmax(be[1], 0), fmin(be[2], 0),
                                                               fmax(be[3], 0), fmin(near0, 0), fmax(far0, 0)};
    double pad0 = (with[5] - with[4]) * 0.01;
    with[4] -= pad0, with[5] += pad0;
    bool origin = true, differs = false;
    for (int i = 0; i < 6; i++) {
        origin &= fabs(bs[i] - with[i]) < tol;
        differs |= fabs(bs[i] - be[i]) >= tol;
    }
    if (origin && differs) {
        snprintf(text, n, "the box takes in the light view's origin (0, 0, 0) as well as the scene's corners: its %s "
                          "reach 0 — the running min and max start at 0, which no corner goes past on that side; "
                          "start them at the first corner, or at +FLT_MAX and -FLT_MAX",
                 fabs(bs[4] - be[4]) >= tol || fabs(bs[5] - be[5]) >= tol ? "near and far" : "sides");
        return true;
    }
    bool sides = true;
    for (int i = 0; i < 4; i++) sides &= fabs(bs[i] - be[i]) < tol;
    if (sides && fabs(bs[4] - (be[4] + 2 * pad)) < tol && fabs(bs[5] - (be[5] - 2 * pad)) < tol) {
        snprintf(text, n, "near and far are padded inwards: near = -(max z) + pad and far = -(min z) - pad cut 1%% off "
                          "the scene at both ends; the padding widens the range, near = -(max z) - pad, far = -(min z) "
                          "+ pad");
        return true;
    }
    char said[300] = "";
    size_t used = 0;
    int wrong = 0;
    for (int i = 0; i < 6; i++) {
        if (fabs(bs[i] - be[i]) < tol) continue;
        int j = 0;
        while (j < 6 && (j == i || fabs(bs[i] - be[j]) >= tol)) j++;
        if (j == 6) return false; /* a value of its own: no other side's */
        used += (size_t)snprintf(said + used, sizeof said - used, "%s%s is the contract's %s (%.4g)",
                                 wrong ? ", its " : "", side[i], side[j], be[j]);
        if (used >= sizeof said) return false;
        wrong++;
    }
    if (wrong == 0) return false;
    snprintf(text, n, "its %s: each holds the value another side of the box should have — left/right from the corners' "
                      "x, bottom/top from their y, near/far from -(max z) and -(min z)", said);
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
            if (_sl_box_reading(bs, be, pad, tol, text, n)) return r;
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
        if (e[5] > 0 && isfinite(s[5]) && s[5] != 0 && fabs(e[11] + 1) < 1e-6) {
            double fov_e = 2 * atan(1 / e[5]), fov_s = 2 * atan(1 / s[5]);
            if (fabs(fov_s * 2 - fov_e) < 1e-3) {
                snprintf(text, n, "the field of view is the cone's half-angle: fovy is twice spot_angle_deg");
                return r;
            }
            /* a slip of units: m11 may be negative (60 radians is past 180 degrees once folded), so it is not
             * required to be positive here */
            if (sl_diag_angle_slip(s[5], sl_diag_perspective_fov_deg(e[5]), "2 * spot_angle_deg", text, n)) return r;
        }
    }
    return -1;
}

/* A view whose eye is the contract's but which looks elsewhere: towards which point of its inputs. A spot light
 * looks from its position along its direction (target = position + direction), so a target that is one of
 * these points on its own (the direction read as a point, the origin, the scene's centre) is the slip. */
/* A sun's view that looks the right way from the wrong place: the eye moved across the light by what
 * another point of the box's inputs puts in place of its centre ((max - min) / 2, min, max, max + min, the
 * origin). Along the light the eye may move too (its distance depends on the box): only the part across the
 * light's direction is compared. */
static int _sl_sun_aims_elsewhere(const sl_verdict_rows *v, char *text, size_t n) {
    static const char *const named[] = {
        "(max - min) / 2, half the box's size", "bounds_min", "bounds_max", "min + max, twice the centre",
        "the world's origin"};
    unsigned fitting = 0x1f; /* the points every failing row so far fits: a row may fit two (a light straight
                              * down cannot tell points apart that differ only in height) */
    int first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        const float *type = _sl_param(v->f, in, "light_type"), *dir = _sl_param(v->f, in, "direction");
        const float *lo = _sl_param(v->f, in, "bounds_min"), *hi = _sl_param(v->f, in, "bounds_max");
        if (!type || !dir || !lo || !hi || (int)*type != 0) return -1;
        double s[16], e[16];
        for (int o = 0; o < 16; o++) s[o] = _sl_got(v, r, o), e[o] = _sl_want(v, r, o);
        sl_camera_reading cs = sl_camera_read(s), ce = sl_camera_read(e);
        if (cs.kind != SL_CAMERA_VIEW || ce.kind != SL_CAMERA_VIEW) return -1;
        double same = 0, moved[3], centre[3];
        for (int i = 0; i < 3; i++) same += cs.forward[i] * ce.forward[i], moved[i] = cs.eye[i] - ce.eye[i];
        if (same < 1 - 1e-6) return -1;
        for (int i = 0; i < 3; i++) centre[i] = (lo[i] + hi[i]) / 2;
        double points[5][3];
        for (int i = 0; i < 3; i++) {
            points[0][i] = (hi[i] - lo[i]) / 2, points[1][i] = lo[i], points[2][i] = hi[i];
            points[3][i] = lo[i] + hi[i], points[4][i] = 0;
        }
        unsigned fits = 0;
        for (int c = 0; c < 5; c++) {
            /* the eye's move against the aimed point's move, across the light's direction */
            double d[3], along = 0, off = 0, size = 0;
            for (int i = 0; i < 3; i++) d[i] = moved[i] - (points[c][i] - centre[i]), along += d[i] * ce.forward[i];
            for (int i = 0; i < 3; i++) {
                double across = d[i] - along * ce.forward[i], shift = points[c][i] - centre[i];
                off += across * across, size += shift * shift;
            }
            if (size > 1e-6 && sqrt(off) <= 1e-3 * fmax(1, sqrt(size))) fits |= 1u << c;
        }
        fitting &= fits;
        if (!fitting) return -1;
        if (first < 0) first = r;
    }
    if (first < 0 || (fitting & (fitting - 1))) return -1; /* none, or more than one point fits every row */
    int explained = 0;
    while (!(fitting & (1u << explained))) explained++;
    snprintf(text, n, "it looks the right way from the wrong place: the eye is where aiming at %s puts it, not at the "
                      "box's centre, (bounds_min + bounds_max) / 2 — the sun's eye is centre - direction * distance",
             named[explained]);
    return first;
}

/* A sun's eye that is the offset from the box's centre alone (-direction * distance, the centre never added):
 * on every failing row the eye lies at the contract's eye minus the centre, a centre that is not the origin. */
static int _sl_sun_eye_without_centre(const sl_verdict_rows *v, char *text, size_t n) {
    int first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        const float *in = v->k->inputs[r];
        const float *type = _sl_param(v->f, in, "light_type"), *lo = _sl_param(v->f, in, "bounds_min");
        const float *hi = _sl_param(v->f, in, "bounds_max");
        if (!type || !lo || !hi || (int)*type != 0) return -1;
        double s[16], e[16], size = 0;
        for (int o = 0; o < 16; o++) s[o] = _sl_got(v, r, o), e[o] = _sl_want(v, r, o);
        sl_camera_reading cs = sl_camera_read(s), ce = sl_camera_read(e);
        if (cs.kind != SL_CAMERA_VIEW || ce.kind != SL_CAMERA_VIEW) return -1;
        for (int i = 0; i < 3; i++) {
            double centre = (lo[i] + hi[i]) / 2;
            size += centre * centre;
            if (fabs(cs.eye[i] - (ce.eye[i] - centre)) > 1e-3 * fmax(1, fabs(ce.eye[i]))) return -1;
        }
        if (size < 1e-6) return -1;
        if (first < 0) first = r;
    }
    if (first < 0) return -1;
    snprintf(text, n, "its eye is the contract's eye minus the box's centre on every row that differs: the offset "
                      "-direction * distance without the centre added — the sun's eye is centre - direction * "
                      "distance, centre = (bounds_min + bounds_max) / 2 (right only for a box centred on the origin)");
    return first;
}

static int _sl_verdict_light_view(const sl_verdict_rows *v, char *text, size_t n) {
    int sun = _sl_sun_aims_elsewhere(v, text, n);
    if (sun >= 0) return sun;
    if ((sun = _sl_sun_eye_without_centre(v, text, n)) >= 0) return sun;
    static const char *const named[] = {
        "towards direction read as a point: the target is position + direction, a point along the light's "
        "direction",
        "towards the world's origin, not along the light's direction",
        "towards the scene box's centre, not along the light's direction (a spot light looks where it points)"};
    int explained = -1, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double s[16], e[16];
        for (int o = 0; o < 16; o++) s[o] = _sl_got(v, r, o), e[o] = _sl_want(v, r, o);
        sl_camera_reading cs = sl_camera_read(s), ce = sl_camera_read(e);
        if (cs.kind != SL_CAMERA_VIEW || ce.kind != SL_CAMERA_VIEW) return -1;
        for (int i = 0; i < 3; i++)
            if (fabs(cs.eye[i] - ce.eye[i]) > 1e-3 * fmax(1, fabs(ce.eye[i]))) return -1; /* the eye: said otherwise */
        double same = 0;
        for (int i = 0; i < 3; i++) same += cs.forward[i] * ce.forward[i];
        if (same > 1 - 1e-6) return -1; /* it looks the right way: its up is what differs */
        const float *in = v->k->inputs[r];
        const float *dir = _sl_param(v->f, in, "direction"), *lo = _sl_param(v->f, in, "bounds_min");
        const float *hi = _sl_param(v->f, in, "bounds_max");
        if (!dir || !lo || !hi) return -1;
        double points[3][3] = {{dir[0], dir[1], dir[2]}, {0, 0, 0},
                               {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}};
        int fits = -1;
        for (int c = 0; c < 3 && fits < 0; c++) {
            double to[3], length = 0, along = 0;
            for (int i = 0; i < 3; i++) to[i] = points[c][i] - cs.eye[i], length += to[i] * to[i];
            if (length < 1e-12) continue;
            for (int i = 0; i < 3; i++) along += to[i] / sqrt(length) * cs.forward[i];
            if (along > 1 - 1e-6) fits = c;
        }
        if (fits < 0 || (explained >= 0 && fits != explained)) return -1;
        explained = fits;
        if (first < 0) first = r;
    }
    if (first < 0) return -1;
    snprintf(text, n, "its eye is right, but it looks %s", named[explained]);
    return first;
}

/* The probe's rows: Lp Lv is W^-1 times the contract's answer, so the student's W is theirs times that. */
/* The shadow matrix's three factors for a row of lab2_shadow_matrix's probe, as the contract defines them:
 * W (the bias matrix), Lp = ortho(left, right, bottom, top, near, far), Lv = lookAt(eye, target, up). */
static void _sl_shadow_factors(const float *in, double factors[3][16]) {
    static const double w[16] = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0.5, 0.5, 0.5, 1};
    memcpy(factors[0], w, sizeof w);
    double l = in[0], r = in[1], b = in[2], t = in[3], zn = in[4], zf = in[5];
    double *p = factors[1];
    memset(p, 0, 16 * sizeof *p);
    p[0] = 2 / (r - l), p[5] = 2 / (t - b), p[10] = -2 / (zf - zn);
    p[12] = -(r + l) / (r - l), p[13] = -(t + b) / (t - b), p[14] = -(zf + zn) / (zf - zn), p[15] = 1;
    double f[3], sd[3], u[3], up[3] = {in[12], in[13], in[14]}, length = 0;
    for (int i = 0; i < 3; i++) f[i] = in[9 + i] - in[6 + i], length += f[i] * f[i];
    for (int i = 0; i < 3; i++) f[i] /= sqrt(length) + 1e-30;
    sd[0] = f[1] * up[2] - f[2] * up[1], sd[1] = f[2] * up[0] - f[0] * up[2], sd[2] = f[0] * up[1] - f[1] * up[0];
    length = sqrt(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]) + 1e-30;
    for (int i = 0; i < 3; i++) sd[i] /= length;
    u[0] = sd[1] * f[2] - sd[2] * f[1], u[1] = sd[2] * f[0] - sd[0] * f[2], u[2] = sd[0] * f[1] - sd[1] * f[0];
    double *m = factors[2];
    memset(m, 0, 16 * sizeof *m);
    for (int i = 0; i < 3; i++) m[i * 4 + 0] = sd[i], m[i * 4 + 1] = u[i], m[i * 4 + 2] = -f[i];
    m[12] = -(sd[0] * in[6] + sd[1] * in[7] + sd[2] * in[8]);
    m[13] = -(u[0] * in[6] + u[1] * in[7] + u[2] * in[8]);
    m[14] = f[0] * in[6] + f[1] * in[7] + f[2] * in[8];
    m[15] = 1;
}

/* The shadow matrix as another product of the contract's factors (one left out, or their order changed), or
 * one of them transposed: the same product on every failing row, said as what it is. */
static bool _sl_shadow_product(const sl_verdict_rows *v, char *text, size_t n, int *first_row) {
    static const char *const names[3] = {"W", "Lp", "Lv"};
    static const int orders[][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0},
                                    {0, 1, -1}, {0, 2, -1}, {1, 2, -1}, {1, 0, -1}, {2, 0, -1}, {2, 1, -1},
                                    {1, -1, -1}, {2, -1, -1}};
    for (size_t o = 0; o < sizeof orders / sizeof orders[0]; o++)
        for (int transposed = 0; transposed < 2; transposed++) {
            if (o == 0 && !transposed) continue; /* the contract itself */
            if (o == 8 && !transposed) continue; /* Lp * Lv: the bias-matrix reading below says it, rows written out */
            bool all = true, any = false;
            int first = -1;
            for (int r = 0; r < v->k->rows && all; r++) {
                if (!_sl_failed(v, r)) continue;
                double factors[3][16], product[16], next[16];
                _sl_shadow_factors(v->k->inputs[r], factors);
                memcpy(product, factors[orders[o][0]], sizeof product);
                for (int j = 1; j < 3 && orders[o][j] >= 0; j++) {
                    _sl_mul(product, factors[orders[o][j]], next);
                    memcpy(product, next, sizeof product);
                }
                for (int i = 0; i < 16 && all; i++) {
                    double got = _sl_got(v, r, transposed ? (i % 4) * 4 + i / 4 : i);
                    all &= fabs(got - product[i]) <= 1e-3 * (1 + fabs(product[i]));
                }
                any = true;
                if (first < 0) first = r;
            }
            if (!all || !any) continue;
            char said[40] = "";
            size_t used = 0;
            for (int j = 0; j < 3 && orders[o][j] >= 0; j++)
                used += (size_t)snprintf(said + used, sizeof said - used, "%s%s", j ? " * " : "", names[orders[o][j]]);
            int count = orders[o][2] >= 0 ? 3 : orders[o][1] >= 0 ? 2 : 1;
            const char *missing = count == 3 ? "" : count == 1 ? " (two factors left out)"
                                  : orders[o][0] != 0 && orders[o][1] != 0 ? " (the bias matrix W left out)"
                                  : orders[o][0] != 1 && orders[o][1] != 1 ? " (the light's projection Lp left out)"
                                                                          : " (the light's view Lv left out)";
            snprintf(text, n, "it is %s%s%s%s, where the contract says W * Lp * Lv: the bias matrix, then the light's "
                              "projection, then its view (the first to act on a point is the rightmost)",
                     transposed ? "(" : "", said, transposed ? ") transposed" : "", missing);
            *first_row = first;
            return true;
        }
    return false;
}

static int _sl_verdict_shadow_matrix(const sl_verdict_rows *v, char *text, size_t n) {
    static const double w_inverse[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, -1, -1, -1, 1};
    int product_row = -1;
    if (_sl_shadow_product(v, text, n, &product_row)) return product_row;
    char first_text[600] = "";
    int first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double s[16], e[16], pv[16];
        for (int o = 0; o < 16; o++) {
            s[o] = _sl_got(v, r, o);
            e[o] = _sl_want(v, r, o);
        }
        _sl_mul(w_inverse, e, pv);
        char said[600];
        if (!_sl_describe_bias_matrix(s, pv, said, sizeof said)) return -1;
        if (first < 0) {
            first = r;
            snprintf(first_text, sizeof first_text, "%s", said);
        } else if (strcmp(said, first_text) != 0) {
            return -1; /* one W on every row, or none to tell */
        }
    }
    if (first >= 0) snprintf(text, n, "%s", first_text);
    return first;
}

/* ---- what lab 2's cases run ---- */

static bool _sl_is_matrix_function(const char *fn) {
    return strcmp(fn, "lab2_light_view") == 0 || strcmp(fn, "lab2_light_projection") == 0 ||
           strcmp(fn, "lab2_shadow_matrix") == 0;
}

bool sl_camera_check(const sl_check *k) {
    return k->kind == SL_CHECK_VISIBILITY || k->kind == SL_CHECK_IMAGE || k->kind == SL_CHECK_PENUMBRA;
}

bool sl_lab2_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    if (k->kind == SL_CHECK_MATRICES) return _sl_is_matrix_function(fn);
    if (sl_depth_pass_runs(c, k, fn)) return true;
    if (!sl_camera_check(k)) return false;
    if (strcmp(fn, "shadow_coord") == 0) return true;
    return strcmp(fn, c->params.compare == SL_COMPARE_HARDWARE ? "shadow_compare_hardware" : "shadow_compare_manual") == 0;
}

void sl_lab2_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    snprintf(out, n, "%s with %s map",
             c->params.compare == SL_COMPARE_HARDWARE ? "shadow_compare_hardware() on a sampler2DShadow"
                                                      : "shadow_compare_manual() on a sampler2D",
             c->scene.light.type == SL_LIGHT_SPOT ? "a spot light's (perspective: w is not 1)" : "a sun's (orthographic)");
}

/* ---- lab 2 in the diagnosis table (diagnose/table.c) ---- */
const sl_lab_diagnoses sl_lab2_diagnoses = {
    .lab = 2,
    .functions = {{"lab2_light_view", _sl_verdict_light_view},
                  {"lab2_light_projection", _sl_verdict_light_projection},
                  {"lab2_shadow_matrix", _sl_verdict_shadow_matrix}},
    .lookup_function = sl_lab2_lookup_function,
    .checks = {{SL_CHECK_MATRICES, sl_diagnose_matrices}},
    .visibility = sl_diagnose_lab2_visibility,
    .case_runs = sl_lab2_case_runs,
    .case_path = sl_lab2_case_path,
};
