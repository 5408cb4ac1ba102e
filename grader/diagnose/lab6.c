/* Lab 6's diagnoses: the cascade-index image, the flicker score along a
 * camera path, and what lab 6's function probes show together. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_scene.h"
#include "sl_verdict.h"

/* ---- the cascade-index image ---- */

void sl_diagnose_cascade_index(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "cascade_index");
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no cascade-index image was captured");
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        sl_diag_say(out, "the image is %dx%d, the reference %dx%d", s->width, s->height, t->width, t->height);
        out->settled = true;
        return;
    }
    if (sl_diag_image_passes(k, &st, "cascade index", out)) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    out->message[0] = '\0';
    /* Pixel by pixel, on surfaces (the reference's index >= 0): how the student's index differs. */
    long covered = 0, differ = 0, above = 0, below = 0, by_one = 0, nan_pixels = 0;
    for (long i = 0; i < (long)t->width * t->height; i++) {
        float want = t->data[i], got = s->data[i];
        if (want < -0.5f) continue;
        covered++;
        if (isnan(got)) {
            nan_pixels++;
            continue;
        }
        long d = lroundf(got) - lroundf(want);
        if (d == 0) continue;
        differ++;
        above += d > 0;
        below += d < 0;
        by_one += d == 1 || d == -1;
    }
    double fraction = covered ? (double)differ / (double)covered : 0;
    if (covered && differ > 0.9 * covered && by_one > 0.95 * differ && (above > 0.95 * differ || below > 0.95 * differ)) {
        sl_diag_say(out, "the cascade index is off by one on %.0f%% of the surfaces (layer %s where the reference uses i)",
                    100 * fraction, above > below ? "i + 1" : "i - 1");
        sl_diag_cause(out, "cascade_index() must return the FIRST cascade whose far split is beyond the depth: 0..count-1 "
                           "(an off-by-one layer; TODO lab6.4)");
    } else if (differ && above > 0.95 * differ) {
        sl_diag_say(out, "%.1f%% of the surfaces use a farther cascade than the reference's, towards the sides of the view",
                    100 * fraction);
        sl_diag_cause(out, "cascades chosen by the distance to the camera (length of the view position), not by view "
                           "depth (-view_position.z): the splits are planes across the view direction (TODO lab6.4)");
    } else if (differ && below > 0.95 * differ) {
        sl_diag_say(out, "%.1f%% of the surfaces use a nearer cascade than the reference's", 100 * fraction);
        sl_diag_cause(out, "the cascades end farther out than the reference's: are the split distances right (lambda, "
                           "TODO lab6.1), and does cascade_index() compare with each cascade's FAR split (TODO lab6.4)?");
    } else {
        sl_diag_say(out, "the cascade index differs from the reference on %.1f%% of the surfaces (allowed %.1f%% of "
                         "pixels)", 100 * fraction, 100 * k->fail_fraction);
        sl_diag_cause(out, "check the split distances (TODO lab6.1) and cascade_index() (TODO lab6.4)");
    }
    if (nan_pixels) sl_diag_append(out, "; %ld pixels are NaN", nan_pixels);
}

/* ---- the flicker score along a camera path ---- */

typedef struct _sl_flicker {
    double score;    /* of receiver pixels, changing between consecutive frames, averaged over the frame pairs */
    double shadowed; /* of receiver pixels, in shadow, averaged over the frames */
} _sl_flicker;

static _sl_flicker _sl_measure_flicker(const sl_image *stack, const sl_image *mask, int frames) {
    _sl_flicker f = {0, 0};
    long pixels = (long)mask->width * mask->height, receivers = 0, changes = 0, dark = 0;
    for (long i = 0; i < pixels; i++) {
        if (mask->data[i] < 0.5f) continue;
        receivers++;
        for (int frame = 0; frame < frames; frame++) {
            float v = stack->data[frame * pixels + i];
            dark += !(v >= 0.5f);
            if (frame > 0) {
                float before = stack->data[(frame - 1) * pixels + i];
                changes += (v >= 0.5f) != (before >= 0.5f) || isnan(v) != isnan(before);
            }
        }
    }
    if (receivers && frames > 1) f.score = (double)changes / ((double)receivers * (frames - 1));
    if (receivers && frames > 0) f.shadowed = (double)dark / ((double)receivers * frames);
    return f;
}

/* Only the camera's aim changes along the path: it turns. */
static bool _sl_path_turns(const sl_case *c) {
    for (int f = 1; f < c->frame_count; f++)
        if (glm_vec3_distance((float *)c->frame_cameras[f].position, (float *)c->frame_cameras[0].position) > 1e-6f)
            return false;
    return true;
}

void sl_diagnose_flicker(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "flicker"), *mask = sl_result_capture(r, "lit_mask");
    if (!cap || !mask) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no frames of the camera path were captured");
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image, *m = &mask->image;
    if (s->width != t->width || s->height != t->height || m->width != c->width || m->height != c->height) {
        sl_diag_say(out, "the frames are %dx%d, the reference's %dx%d", s->width, s->height, t->width, t->height);
        out->settled = true;
        return;
    }
    _sl_flicker got = _sl_measure_flicker(s, m, c->frame_count), want = _sl_measure_flicker(t, m, c->frame_count);
    bool shadows_ok = want.shadowed < 0.005 || got.shadowed >= 0.5 * want.shadowed;
    if (got.score <= k->threshold && shadows_ok) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    if (!shadows_ok) {
        sl_diag_say(out, "along the camera path only %.1f%% of the receivers are in shadow, the reference %.1f%%: a "
                         "still picture without its shadows does not count as stable",
                    100 * got.shadowed, 100 * want.shadowed);
        sl_diag_cause(out, "fix the cascades' visibility first (the other checks of lab 6 say how)");
        return;
    }
    sl_diag_say(out, "shadows shimmer as the camera moves: snap the projection to whole texels (%.3f%% of the "
                     "world-fixed receiver pixels change from one frame to the next, allowed %.3f%%; the reference: "
                     "%.3f%%)",
                100 * got.score, 100 * k->threshold, 100 * want.score);
    if (_sl_path_turns(c))
        sl_diag_cause(out, "here the camera only turns: keep each cascade's size fixed as it turns (a bounding sphere, "
                           "TODO lab6.2) and move its origin by whole texels (TODO lab6.3)");
    else
        sl_diag_cause(out, "the camera moves by less than a texel per frame: move the projection's origin by whole "
                           "texels of the map (TODO lab6.3)");
}

/* ---- what lab 6's probes show together ---- */

static double _sl_out(const double *values, const sl_verdict_rows *v, int row, int i) {
    return values[row * v->f->output_count + i];
}

static bool _sl_close(double a, double b) { return fabs(a - b) <= 1e-3 * fmax(1.0, fabs(b)); }

static void _sl_splits(double near, double far, int count, double lambda, double *out) {
    for (int i = 0; i <= count; i++) {
        double t = (double)i / count;
        out[i] = lambda * near * pow(far / near, t) + (1 - lambda) * (near + (far - near) * t);
    }
}

static int _sl_verdict_splits(const sl_verdict_rows *v, char *text, size_t n) {
    int rows = v->k->rows, uniform = 0, logarithmic = 0, swapped = 0, ends = 0, failing = 0, first = -1;
    for (int r = 0; r < rows; r++) {
        if (!((v->failing >> r) & 1u)) continue;
        const float *in = v->k->inputs[r];
        int count = (int)in[2];
        if (count < 1 || count > SL_MAX_CASCADES) continue;
        double u[SL_MAX_CASCADES + 1], l[SL_MAX_CASCADES + 1], w[SL_MAX_CASCADES + 1];
        _sl_splits(in[0], in[1], count, 0, u);
        _sl_splits(in[0], in[1], count, 1, l);
        _sl_splits(in[0], in[1], count, 1 - in[3], w);
        bool is_u = true, is_l = true, is_w = true;
        for (int i = 0; i <= count; i++) {
            double got = _sl_out(v->student, v, r, i);
            is_u &= _sl_close(got, u[i]);
            is_l &= _sl_close(got, l[i]);
            is_w &= _sl_close(got, w[i]);
        }
        failing++;
        if (first < 0) first = r;
        uniform += is_u;
        logarithmic += is_l;
        swapped += is_w && !is_u && !is_l;
        ends += !_sl_close(_sl_out(v->student, v, r, 0), in[0]) || !_sl_close(_sl_out(v->student, v, r, count), in[1]);
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
    return -1;
}

/* The solution's sphere of a slice, for comparisons (the probe's camera, GL conventions). */
static void _sl_sphere(const float *in, double split_near, double split_far, double out[4]) {
    sl_camera cam = {.fov_deg = in[6], .near = in[8], .far = in[9]};
    glm_vec3_copy((float *)in, cam.position);
    glm_vec3_copy((float *)in + 3, cam.target);
    mat4 view, proj, vp, inv;
    sl_camera_view(&cam, view);
    sl_camera_projection(&cam, in[7], proj);
    glm_mat4_mul(proj, view, vp);
    glm_mat4_inv(vp, inv);
    double corners[8][3], centre[3] = {0, 0, 0};
    for (int i = 0; i < 4; i++) {
        vec4 a = {(i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, -1, 1}, b = {a[0], a[1], 1, 1}, wa, wb;
        glm_mat4_mulv(inv, a, wa);
        glm_mat4_mulv(inv, b, wb);
        double ta = (split_near - cam.near) / (cam.far - cam.near), tb = (split_far - cam.near) / (cam.far - cam.near);
        for (int k = 0; k < 3; k++) {
            double cn = wa[k] / wa[3], cf = wb[k] / wb[3];
            corners[i][k] = cn + (cf - cn) * ta;
            corners[4 + i][k] = cn + (cf - cn) * tb;
        }
    }
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++) centre[k] += corners[i][k] / 8;
    double radius = 0;
    for (int i = 0; i < 8; i++) {
        double d = sqrt(pow(corners[i][0] - centre[0], 2) + pow(corners[i][1] - centre[1], 2) +
                        pow(corners[i][2] - centre[2], 2));
        radius = fmax(radius, d);
    }
    for (int k = 0; k < 3; k++) out[k] = centre[k];
    out[3] = radius;
}

static int _sl_verdict_sphere(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, whole = 0, too_small = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!((v->failing >> r) & 1u)) continue;
        const float *in = v->k->inputs[r];
        double all[4];
        _sl_sphere(in, in[8], in[9], all);
        bool is_whole = true;
        for (int i = 0; i < 4; i++) is_whole &= fabs(_sl_out(v->student, v, r, i) - all[i]) <= 1e-3 * fmax(1, fabs(all[i]));
        failing++;
        whole += is_whole;
        too_small += _sl_out(v->student, v, r, 3) < _sl_out(v->expected, v, r, 3) * 0.999;
        if (first < 0) first = r;
    }
    if (!failing) return -1;
    if (whole == failing) {
        snprintf(text, n, "the sphere is fitted to the whole frustum, not to the slice between split_near and split_far "
                          "(move each corner along its edge to t = (split - near) / (far - near))");
        return first;
    }
    if (too_small == failing) {
        snprintf(text, n, "the sphere is too small to hold the slice's 8 corners: its radius is the distance from the "
                          "centre to the FARTHEST corner");
        return first;
    }
    return -1;
}

static int _sl_verdict_cascade_matrices(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!((v->failing >> r) & 1u)) continue;
        const float *in = v->k->inputs[r];
        double half = in[8] / 2;
        /* where the world's origin lands in the map, in texels: whole numbers when snapped */
        double x = _sl_out(v->student, v, r, 12) * half, y = _sl_out(v->student, v, r, 13) * half;
        double fx = fabs(x - round(x)), fy = fabs(y - round(y));
        if (fx > 0.01 || fy > 0.01) {
            snprintf(text, n, "shadows shimmer as the camera moves: snap the projection to whole texels — the world's "
                              "origin lands at texel (%.2f, %.2f) of the %g-texel map, between texels",
                     x + half, y + half, (double)in[8]);
            return r;
        }
        bool xy_ok = true, z_ok = true;
        for (int col = 0; col < 4; col++) {
            for (int row = 0; row < 4; row++) {
                double got = _sl_out(v->student, v, r, col * 4 + row), want = _sl_out(v->expected, v, r, col * 4 + row);
                bool close = fabs(got - want) <= 1e-3 * fmax(1, fabs(want));
                if (row == 2) z_ok &= close;
                else xy_ok &= close;
            }
        }
        if (xy_ok && !z_ok) {
            snprintf(text, n, "the depth range is wrong: the light's camera steps back radius + caster_margin from the "
                              "centre and the ortho box spans 0 .. 2 radius + caster_margin, so casters outside the "
                              "slice, towards the light, still cast");
            return r;
        }
        if (!xy_ok) {
            snprintf(text, n, "the box across the light is wrong: glm_ortho(-r, r, -r, r, ...) around the sphere's "
                              "centre, the camera looking along the light's direction with lab 2's up vector");
            return r;
        }
    }
    return -1;
}

static int _sl_verdict_cascade_index(const sl_verdict_rows *v, char *text, size_t n) {
    int failing = 0, plus = 0, minus = 0, distance = 0, first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        if (!((v->failing >> r) & 1u)) continue;
        const float *in = v->k->inputs[r];
        double got = _sl_out(v->student, v, r, 0), want = _sl_out(v->expected, v, r, 0);
        /* the index chosen by the distance to the camera */
        double d = sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2]);
        int count = (int)in[7], by_distance = count - 1;
        for (int i = 0; i < count - 1; i++)
            if (d < in[3 + i]) {
                by_distance = i;
                break;
            }
        failing++;
        plus += got == want + 1;
        minus += got == want - 1;
        distance += got == by_distance;
        if (first < 0) first = r;
    }
    if (!failing) return -1;
    if (distance == failing) {
        snprintf(text, n, "cascades chosen by the distance to the camera, length(view_position), not by view depth "
                          "-view_position.z: the splits are planes across the view direction");
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
    if (strcmp(name, "lab6_cascade_matrices") == 0) return _sl_verdict_cascade_matrices(v, text, n);
    if (strcmp(name, "cascade_index") == 0) return _sl_verdict_cascade_index(v, text, n);
    return -1;
}

/* ---- what lab 6's cases run (a first account from the renderer: sl_lab6_cascades.c) ---- */

bool sl_lab6_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    (void)k;
    /* lab 1's depth shaders and lab 2's shadow matrix, per cascade; lab 6's own functions */
    if (strcmp(fn, "depth.vert") == 0 || strcmp(fn, "lab2_shadow_matrix") == 0) return true;
    if (strcmp(fn, "cascade_blend") == 0) return c->params.cascades.blend_band > 0; /* the bonus: only where it is on */
    const sl_probe_function *f = sl_probe_find(fn);
    if (f) return f->lab == 6;
    return strcmp(fn, "cascade_compare") == 0;
}

void sl_lab6_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    const sl_cascade_params *p = &c->params.cascades;
    snprintf(out, n, "%d cascades, lambda %g%s", p->count, (double)p->lambda,
             p->blend_band > 0 ? ", blended across their borders" : ", no blend band");
}
