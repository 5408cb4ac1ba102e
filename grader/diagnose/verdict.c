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
#include "verdict_filter.h"
#include "verdict_rows.h"

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
