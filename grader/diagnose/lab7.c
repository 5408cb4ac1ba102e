/* Lab 7's diagnoses: the cube map's faces, the face matrices, the lookup. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "sl_compare.h"
#include "sl_diag_words.h"
#include "sl_json.h"
#include "sl_probe.h"

/* The axis each face looks down (its name). Its up vector and image right (GL's table of cube map faces) are
 * lab 7's answer, so the grader does not hold them: it reads them from the solution's face views (the
 * lab7_face_view probe's expected outputs, from the references or computed at grading time). */
static const float _sl_axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
static const char *const _sl_face_names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

static const char *_sl_face(int face) { return face >= 0 && face < 6 ? _sl_face_names[face] : "?"; }

bool sl_lab7_drawn_layered(const sl_case_result *r) {
    const sl_capture *path = sl_result_capture(r, sl_capture_name(SL_CAPTURE_PATH));
    return path && path->number_count >= SL_PATH_NUMBERS && path->numbers[1] != 0;
}

/* The layered pass was drawn after lab7_begin_cube_pass answered SL_OK to SL_CUBE_ALL_FACES without attaching the
 * whole cube map (no layered attachment): the six faces' copies went to whatever was attached. */
static bool _sl_layered_unattached(const sl_case_result *r) {
    const sl_capture *path = sl_result_capture(r, sl_capture_name(SL_CAPTURE_PATH));
    return path && path->number_count >= SL_PATH_NUMBERS && path->numbers[1] == 2;
}

static const char *const _sl_unattached_text =
    "lab7_begin_cube_pass returned SL_OK to SL_CUBE_ALL_FACES without attaching the whole cube map (the depth "
    "attachment is not layered), so the framework drew one layered pass into whatever was attached";
static const char *const _sl_unattached_fix =
    "for SL_CUBE_ALL_FACES return SL_NOT_IMPLEMENTED (the framework then draws six passes), or attach the whole cube "
    "map with glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, map->depth_cube, 0) (TODO lab7.2)";

bool sl_lab7_case_calls(const sl_case *c, const sl_check *k, const char *name) {
    if (strncmp(name, "lab7_", 5) == 0) return true; /* every frame of lab 7 makes and fills the cube map */
    if (k->kind != SL_CHECK_VISIBILITY && k->kind != SL_CHECK_IMAGE) return false;
    return strcmp(name, c->params.cube.soft ? "point_shadow_soft" : "point_shadow") == 0;
}

/* ---- the faces ---- */

/* Fraction of the reference's texels (those in front of the far plane) that
 * `s` matches within `threshold` after mapping each texel of s to the
 * reference by `map` (face coordinates in [-1, 1], x right, y up); texels
 * mapped outside the face are left out. */
typedef void (*_sl_face_map)(double x, double y, double *rx, double *ry, double param);

static double _sl_match(const sl_image *s, const sl_image *t, _sl_face_map map, double param, double threshold) {
    int n = s->width;
    long counted = 0, matched = 0;
    for (int j = 0; j < n; j += 2)
        for (int i = 0; i < n; i += 2) {
            double x = 2.0 * (i + 0.5) / n - 1.0, y = 1.0 - 2.0 * (j + 0.5) / n, rx, ry;
            map(x, y, &rx, &ry, param);
            int ri = (int)floor((rx + 1.0) * 0.5 * n), rj = (int)floor((1.0 - ry) * 0.5 * n);
            if (ri < 0 || rj < 0 || ri >= n || rj >= n) continue;
            float sv = s->data[(long)j * n + i];
            /* the best of the reference's 3x3 neighbourhood: silhouettes may move by a texel */
            double best = INFINITY;
            for (int dj = -1; dj <= 1; dj++)
                for (int di = -1; di <= 1; di++) {
                    int a = ri + di, b = rj + dj;
                    if (a < 0 || b < 0 || a >= n || b >= n) continue;
                    double d = fabs((double)sv - (double)t->data[(long)b * n + a]);
                    if (d < best) best = d;
                }
            counted++;
            matched += best <= threshold;
        }
    return counted ? (double)matched / (double)counted : 0;
}

static void _sl_mirror_x(double x, double y, double *rx, double *ry, double p) { (void)p; *rx = -x; *ry = y; }
static void _sl_mirror_y(double x, double y, double *rx, double *ry, double p) { (void)p; *rx = x; *ry = -y; }
static void _sl_rotate_180(double x, double y, double *rx, double *ry, double p) { (void)p; *rx = -x; *ry = -y; }
static void _sl_rotate_90(double x, double y, double *rx, double *ry, double p) { (void)p; *rx = -y; *ry = x; }
static void _sl_rotate_270(double x, double y, double *rx, double *ry, double p) { (void)p; *rx = y; *ry = -x; }
/* a face rendered with field of view f sees direction (x tan(f/2), y tan(f/2), 1): the reference's (x, y) scaled */
static void _sl_scale(double x, double y, double *rx, double *ry, double scale) { *rx = x * scale; *ry = y * scale; }

/* The texel's distance along the face axis over its distance from the light. */
static double _sl_cos_axis(int n, int i, int j) {
    double x = 2.0 * (i + 0.5) / n - 1.0, y = 1.0 - 2.0 * (j + 0.5) / n;
    return 1.0 / sqrt(1.0 + x * x + y * y);
}

/* Do the student's values follow `predict` of the reference's (distance / far) on most texels? */
typedef double (*_sl_predict)(double r, double cos_axis, double near, double far);

static double _sl_ndc_depth(double r, double c, double near, double far) {
    double z = r * far * c; /* the distance along the face's axis */
    return z <= near ? 0.0 : far * (z - near) / ((far - near) * z);
}
static double _sl_not_divided(double r, double c, double near, double far) {
    (void)c;
    (void)near;
    return fmin(1.0, r * far);
}

static double _sl_follows(const sl_image *s, const sl_image *t, _sl_predict predict, double near, double far) {
    int n = s->width;
    long counted = 0, matched = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double r = t->data[(long)j * n + i];
            if (r >= 0.999) continue;
            counted++;
            matched += fabs((double)s->data[(long)j * n + i] - predict(r, _sl_cos_axis(n, i, j), near, far)) < 0.01;
        }
    return counted ? (double)matched / (double)counted : 0;
}

static void _sl_vector(const float *v, char *out, size_t n) { snprintf(out, n, "(%g,%g,%g)", v[0], v[1], v[2]); }

/* A face's image right and up in world space, from a correct view of it (column-major 4x4: rows 0 and 1 of
 * its linear part), as whole numbers; false when that view is not one of a cube face's. */
static bool _sl_face_frame(const double *view, float right[3], float up[3]) {
    for (int i = 0; i < 3; i++) {
        double r = view[i * 4 + 0], u = view[i * 4 + 1];
        if (!isfinite(r) || !isfinite(u) || fabs(r - lround(r)) > 1e-3 || fabs(u - lround(u)) > 1e-3) return false;
        right[i] = (float)lround(r);
        up[i] = (float)lround(u);
    }
    return true;
}

/* Face `face`'s up vector as the solution's lab7_face_view gives it, from the references beside `ref_path`
 * (REFERENCES/CASE/FILE): the lab7_probes case's face_view.probe.json. False where it is not there. */
static bool _sl_reference_face_up(const char *ref_path, int face, float up[3]) {
    char path[1200];
    snprintf(path, sizeof path, "%s", ref_path);
    for (int cut = 0; cut < 2; cut++) {
        char *slash = strrchr(path, '/');
        if (!slash) return false;
        *slash = '\0';
    }
    size_t used = strlen(path);
    snprintf(path + used, sizeof path - used, "/lab7_probes/face_view.probe.json");
    char err[600];
    cJSON *json = sl_json_load_file(path, "reference", err, sizeof err);
    if (!json) return false;
    bool found = false;
    const cJSON *rows = cJSON_GetObjectItemCaseSensitive(json, "rows"), *row;
    cJSON_ArrayForEach(row, rows) {
        const cJSON *in = cJSON_GetObjectItemCaseSensitive(row, "inputs"), *outs = cJSON_GetObjectItemCaseSensitive(row, "outputs");
        if (!cJSON_IsArray(in) || !cJSON_IsNumber(cJSON_GetArrayItem(in, 0)) || cJSON_GetArrayItem(in, 0)->valuedouble != face ||
            cJSON_GetArraySize(outs) != 16)
            continue;
        double view[16];
        bool numbers = true;
        for (int i = 0; i < 16; i++) {
            const cJSON *v = cJSON_GetArrayItem(outs, i);
            numbers &= cJSON_IsNumber(v);
            view[i] = numbers ? v->valuedouble : 0;
        }
        float right[3];
        if (numbers && _sl_face_frame(view, right, up)) {
            found = true;
            break;
        }
    }
    cJSON_Delete(json);
    return found;
}

/* ---- what a face stores, measured against the contract ----
 *
 * The contract: each texel holds length(surface point - light) / far. The reference gives that value, r,
 * for each texel the face sees; with the texel's direction from the light (the face's axis, right and up,
 * the up read from the solution's face views) it gives the surface point too, P = L + r far dir. What the
 * student's face holds, s, is then fitted against forms a stored distance takes when one step of the
 * contract is changed: s = a r + b (divided by another number, an offset, reversed), s = a r^2 (the
 * squared distance), s = a r cos (the distance along the face's axis, not the length), and
 * s = |P - Q| / far (measured from another point Q than the light). The form that holds on the most
 * texels, when it holds on nearly all, is what the message says. */

typedef struct _sl_stored_texel {
    double s, r, cos_axis;
    double point[3]; /* the surface point (valid when the face's frame is known) */
} _sl_stored_texel;

/* The share of texels on which `predict(texel)` is within the tolerance of the stored value. */
#define _SL_FIT_TOLERANCE 0.004
#define _SL_FIT_SHARE 0.95

typedef struct _sl_fit {
    double a, b, q[3];
    double share;
} _sl_fit;

static double _sl_fit_share(const _sl_stored_texel *t, long n, double (*predict)(const _sl_stored_texel *, const _sl_fit *),
                            const _sl_fit *f) {
    long ok = 0;
    for (long i = 0; i < n; i++) ok += fabs(t[i].s - predict(&t[i], f)) <= _SL_FIT_TOLERANCE;
    return n ? (double)ok / (double)n : 0;
}

static double _sl_predict_affine(const _sl_stored_texel *t, const _sl_fit *f) { return f->a * t->r + f->b; }
static double _sl_predict_squared(const _sl_stored_texel *t, const _sl_fit *f) { return f->a * t->r * t->r; }
static double _sl_predict_axis(const _sl_stored_texel *t, const _sl_fit *f) { return f->a * t->r * t->cos_axis; }
static double _sl_predict_point(const _sl_stored_texel *t, const _sl_fit *f) {
    double d[3] = {t->point[0] - f->q[0], t->point[1] - f->q[1], t->point[2] - f->q[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * f->b; /* b: 1 / far */
}

/* Least squares of s = a x (through the origin), x = g(texel). */
static double _sl_scale_fit(const _sl_stored_texel *t, long n, double (*g)(const _sl_stored_texel *)) {
    double sxy = 0, sxx = 0;
    for (long i = 0; i < n; i++) {
        double x = g(&t[i]);
        sxy += x * t[i].s;
        sxx += x * x;
    }
    return sxx > 0 ? sxy / sxx : 0;
}
static double _sl_x_squared(const _sl_stored_texel *t) { return t->r * t->r; }
static double _sl_x_axis(const _sl_stored_texel *t) { return t->r * t->cos_axis; }

/* Solves the 4x4 system m x = v by Gaussian elimination; false when it is singular. */
static bool _sl_solve4(double m[4][4], double v[4], double x[4]) {
    for (int col = 0; col < 4; col++) {
        int pivot = col;
        for (int row = col + 1; row < 4; row++)
            if (fabs(m[row][col]) > fabs(m[pivot][col])) pivot = row;
        if (fabs(m[pivot][col]) < 1e-12) return false;
        for (int j = 0; j < 4; j++) {
            double tmp = m[col][j];
            m[col][j] = m[pivot][j];
            m[pivot][j] = tmp;
        }
        double tmp = v[col];
        v[col] = v[pivot];
        v[pivot] = tmp;
        for (int row = col + 1; row < 4; row++) {
            double f = m[row][col] / m[col][col];
            for (int j = col; j < 4; j++) m[row][j] -= f * m[col][j];
            v[row] -= f * v[col];
        }
    }
    for (int row = 3; row >= 0; row--) {
        double sum = v[row];
        for (int j = row + 1; j < 4; j++) sum -= m[row][j] * x[j];
        x[row] = sum / m[row][row];
    }
    return true;
}

/* The point Q the stored distances (times far) are measured from: |P - Q|^2 = |P|^2 - 2 P.Q + |Q|^2 is
 * linear in Q and |Q|^2, so four unknowns by least squares. */
static bool _sl_point_fit(const _sl_stored_texel *t, long n, double far, double q[3]) {
    double m[4][4] = {{0}}, v[4] = {0}, x[4];
    for (long i = 0; i < n; i++) {
        const double *p = t[i].point;
        double row[4] = {-2 * p[0], -2 * p[1], -2 * p[2], 1};
        double rhs = t[i].s * t[i].s * far * far - (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int a = 0; a < 4; a++) {
            for (int b = 0; b < 4; b++) m[a][b] += row[a] * row[b];
            v[a] += row[a] * rhs;
        }
    }
    if (!_sl_solve4(m, v, x)) return false;
    for (int i = 0; i < 3; i++) q[i] = x[i];
    return true;
}

/* Says what face `face` stores, if one changed step of the contract explains it on nearly every texel. */
static bool _sl_stored_distance_fit(const sl_case *c, int face, const float *face_up, const sl_image *s,
                                    const sl_image *t, sl_check_result *out) {
    int n = s->width;
    double far = c->scene.light.far;
    const float *light = c->scene.light.position;
    if (n <= 0 || far <= 0 || s->height != n || t->width != n || t->height != n) return false;
    _sl_stored_texel *texels = malloc(sizeof *texels * (size_t)n * (size_t)n);
    if (!texels) return false;
    double right[3] = {0, 0, 0};
    const float *axis = _sl_axes[face];
    if (face_up) { /* a lookAt's right: forward x up */
        right[0] = axis[1] * face_up[2] - axis[2] * face_up[1];
        right[1] = axis[2] * face_up[0] - axis[0] * face_up[2];
        right[2] = axis[0] * face_up[1] - axis[1] * face_up[0];
    }
    long count = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double sv = s->data[(long)j * n + i], rv = t->data[(long)j * n + i];
            if (!isfinite(sv) || rv >= 0.999 || sv >= 0.999 || rv <= 0) continue; /* "nothing there", or clamped */
            _sl_stored_texel *e = &texels[count++];
            e->s = sv;
            e->r = rv;
            e->cos_axis = _sl_cos_axis(n, i, j);
            double x = 2.0 * (i + 0.5) / n - 1.0, y = 1.0 - 2.0 * (j + 0.5) / n, d[3], len = 0;
            for (int a = 0; a < 3; a++) {
                d[a] = axis[a] + x * right[a] + y * (face_up ? face_up[a] : 0);
                len += d[a] * d[a];
            }
            for (int a = 0; a < 3; a++) e->point[a] = light[a] + rv * far * d[a] / sqrt(len);
        }
    bool said = false;
    if (count < (long)n * n / 20) goto done;
    /* the affine fit: s = a r + b */
    double sr = 0, ss = 0, srr = 0, srs = 0;
    for (long i = 0; i < count; i++) {
        sr += texels[i].r;
        ss += texels[i].s;
        srr += texels[i].r * texels[i].r;
        srs += texels[i].r * texels[i].s;
    }
    double det = count * srr - sr * sr;
    _sl_fit affine = {0}, squared = {0}, along = {0}, point = {0};
    if (fabs(det) > 1e-12) {
        affine.a = (count * srs - sr * ss) / det;
        affine.b = (ss - affine.a * sr) / count;
        affine.share = _sl_fit_share(texels, count, _sl_predict_affine, &affine);
    }
    squared.a = _sl_scale_fit(texels, count, _sl_x_squared);
    squared.share = _sl_fit_share(texels, count, _sl_predict_squared, &squared);
    along.a = _sl_scale_fit(texels, count, _sl_x_axis);
    along.share = _sl_fit_share(texels, count, _sl_predict_axis, &along);
    if (face_up && _sl_point_fit(texels, count, far, point.q)) {
        point.b = 1.0 / far;
        point.share = _sl_fit_share(texels, count, _sl_predict_point, &point);
    }
    /* a constant (nothing drawn, a cleared face) is no distance: other messages say it */
    double lowest = INFINITY, highest = -INFINITY;
    for (long i = 0; i < count; i++) {
        lowest = fmin(lowest, texels[i].s);
        highest = fmax(highest, texels[i].s);
    }
    if (highest - lowest < 0.01) {
        said = false;
        goto done;
    }
    /* the contract itself holds here: what differs is elsewhere (the geometry a face sees) */
    if (affine.share >= _SL_FIT_SHARE && fabs(affine.a - 1) < 0.01 && fabs(affine.b) < 0.002) goto done;
    double best = fmax(fmax(affine.share, squared.share), fmax(along.share, point.share));
    if (best < _SL_FIT_SHARE) goto done;
    said = true;
    const char *fix = "store length(world position - u_light_position) / u_light_far in gl_FragDepth "
                      "(shaders/cube_depth.frag, TODO lab7.5)";
    if (affine.share == best) {
        if (fabs(affine.b) < 0.002)
            sl_diag_say(out, "face %s stores %.3g times the expected distance / far on %.0f%% of the texels both see: "
                             "the distance divided by %.4g instead of the far plane, %g?",
                        _sl_face(face), affine.a, 100 * affine.share, far / affine.a, far);
        else if (fabs(affine.a + 1) < 0.02 && fabs(affine.b - 1) < 0.02)
            sl_diag_say(out, "face %s stores 1 - distance / far on %.0f%% of the texels both see: reversed, so near "
                             "surfaces hold large values and far ones small", _sl_face(face), 100 * affine.share);
        else
            sl_diag_say(out, "face %s stores %.3g x distance / far %+.3g on %.0f%% of the texels both see: "
                             "(distance %+.3g) / %.4g, where the contract is distance / %g",
                        _sl_face(face), affine.a, affine.b, 100 * affine.share, affine.b * far / affine.a,
                        far / affine.a, far);
    } else if (squared.share == best) {
        sl_diag_say(out, "face %s stores the squared distance on %.0f%% of the texels both see: %.3g x (distance / "
                         "far)^2, that is distance^2 / %.4g, where the lookup compares distance / far",
                    _sl_face(face), 100 * squared.share, squared.a, far * far / squared.a);
    } else if (along.share == best) {
        sl_diag_say(out, "face %s stores the distance along the face's axis (%s), not the length from the light, on "
                         "%.0f%% of the texels both see%s: the two agree only at the face's centre, and its corners "
                         "come out %.0f%% nearer", _sl_face(face), _sl_face(face), 100 * along.share,
                    fabs(along.a - 1) > 0.01 ? " (times a factor)" : "", 100 * (1 - 1 / sqrt(3.0)));
    } else {
        double from_origin = sqrt(point.q[0] * point.q[0] + point.q[1] * point.q[1] + point.q[2] * point.q[2]);
        for (int a = 0; a < 3; a++)
            if (fabs(point.q[a]) < 0.005) point.q[a] = 0; /* printed as 0.00, never -0.00 */
        sl_diag_say(out, "face %s stores the distance from (%.2f, %.2f, %.2f)%s, not from the light at (%g, %g, %g), "
                         "on %.0f%% of the texels both see (the point fitted to its values)",
                    _sl_face(face), point.q[0], point.q[1], point.q[2], from_origin < 0.05 ? ", the world's origin" : "",
                    (double)light[0], (double)light[1], (double)light[2], 100 * point.share);
        fix = "the distance is measured from the light: length(fs_in.world_position - u_light_position) / "
              "u_light_far, the world position from the vertex shader's model matrix (shaders/cube_depth.frag, "
              "TODO lab7.5)";
    }
    sl_diag_cause_in(out, "cube_depth.frag", "%s", fix);
done:
    free(texels);
    return said;
}

void sl_diagnose_cube_face(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                           sl_check_result *out) {
    const char *face = _sl_face(k->face);
    const sl_capture *cap = sl_result_capture(r, sl_check_capture_name(c, k));
    if (!cap) {
        if (r->capture_error[0]) sl_diag_say(out, "%s", r->capture_error);
        else if (!sl_diag_explain_missing(c, r, out))
            sl_diag_say(out, "face %s: no cube map was captured (did the depth passes run?)", face);
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        sl_diag_say(out, "face %s is %dx%d, the reference %dx%d: each face is size x size texels", face, s->width,
                    s->height, t->width, t->height);
        out->settled = true;
        return;
    }
    char what[32];
    snprintf(what, sizeof what, "face %s", face);
    if (sl_diag_image_passes(k, &st, what, out)) {
        out->passed = true;
        return;
    }
    if (out->message[0]) return; /* only the mean is off: said */
    double near = c->scene.light.near, far = c->scene.light.far;
    double empty = sl_fraction_equal(s, 1.0f, 1e-6f), ref_empty = sl_fraction_equal(t, 1.0f, 1e-6f);
    char up[80] = "from GL's table of cube map faces";
    float face_up[3];
    bool have_up = _sl_reference_face_up(ref->path, k->face, face_up);
    if (have_up) _sl_vector(face_up, up, sizeof up);
    bool layered = sl_lab7_drawn_layered(r), others_drawn = false;
    for (int f = 0; f < 6; f++) {
        const sl_capture *other = f == k->face ? NULL : sl_result_capture(r, sl_capture_name(SL_CAPTURE_CUBE_FACE + f));
        others_drawn |= other && other->image.data && sl_fraction_equal(&other->image, 1.0f, 1e-6f) < 0.999;
    }
    if (_sl_layered_unattached(r)) {
        sl_diag_say(out, "face %s differs from the reference: %s", face, _sl_unattached_text);
        sl_diag_cause_in(out, "lab7_begin_cube_pass", "%s", _sl_unattached_fix);
    } else if (empty > 0.999 && ref_empty < 0.99 && layered && others_drawn) {
        sl_diag_say(out, "face %s holds 1.0 everywhere (\"nothing there\") where the reference holds distance / far, "
                         "while other faces hold distances: nothing was drawn into this face. The cube map was drawn in "
                         "one layered pass (lab7_begin_cube_pass attached all six faces)", face);
        sl_diag_cause(out, "in the layered pass shaders/cube_depth.geom chooses each copy's face: set gl_Layer = face "
                           "before every EmitVertex of that copy (left unset, every triangle lands in layer 0, +X)");
    } else if (empty > 0.999 && ref_empty < 0.99 && others_drawn) {
        sl_diag_say(out, "face %s holds 1.0 everywhere (\"nothing there\") where the reference holds distance / far, "
                         "while other faces hold distances: nothing was drawn into this face", face);
        sl_diag_cause_in(out, "lab7_begin_cube_pass", "is this face attached in lab7_begin_cube_pass: GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, cleared, "
                           "with its viewport (TODO lab7.2)?");
    } else if (empty > 0.999 && ref_empty < 0.99) {
        sl_diag_say(out, "face %s holds 1.0 everywhere (\"nothing there\") where the reference holds distance / far, "
                         "and so does every other face%s", face, layered ? " (drawn in one layered pass)" : "");
        sl_diag_cause_in(out, "cube_depth.frag", "is the far plane missing on the depth pass's side? Distances not divided by u_light_far in "
                           "shaders/cube_depth.frag are clamped to 1.0 (TODO lab7.5). Or nothing was drawn at all: %s",
                      layered ? "in the layered pass, does shaders/cube_depth.geom emit each triangle to the six faces?"
                              : "are the faces attached in lab7_begin_cube_pass (TODO lab7.2)?");
    } else if (_sl_follows(s, t, _sl_not_divided, near, far) > 0.95) {
        sl_diag_say(out, "face %s holds the distance itself, clamped to 1.0, where the reference holds distance / far",
                    face);
        sl_diag_cause_in(out, "cube_depth.frag", "the far plane is missing on the depth pass's side: divide by u_light_far in "
                           "shaders/cube_depth.frag (TODO lab7.5), as point_shadow() divides the fragment's distance");
    } else if (_sl_follows(s, t, _sl_ndc_depth, near, far) > 0.9) {
        sl_diag_say(out, "face %s holds the depth buffer's own values (gl_FragCoord.z, the projection's non-linear "
                         "depth along the face's axis), not distance / far", face);
        sl_diag_cause_in(out, "cube_depth.frag", "the lookup compares distances: write length(world position - light) / u_light_far into "
                           "gl_FragDepth in shaders/cube_depth.frag (TODO lab7.5)");
    } else if (_sl_stored_distance_fit(c, k->face, have_up ? face_up : NULL, s, t, out)) {
        /* said: which step of the stored distance departs, fitted to the face's values */
    } else if (_sl_match(s, t, _sl_scale, tan(glm_rad(22.5f)), k->threshold * 5) > 0.95) {
        sl_diag_say(out, "face %s shows a narrower view than the reference: the reference's middle %.0f%%, magnified",
                    face, 100 * tan(glm_rad(22.5f)));
        sl_diag_cause_in(out, "lab7_face_projection", "a field of view of 45 degrees: each face needs 90 (glm_rad(90.0f)) to meet its neighbours "
                           "edge to edge (lab7_face_projection, TODO lab7.4)");
    } else if (_sl_match(s, t, _sl_rotate_180, 0, k->threshold * 5) > 0.95) {
        sl_diag_say(out, "face %s is the reference turned upside down (rotated 180 degrees)", face);
        sl_diag_cause_in(out, "lab7_face_view", "face %s: the up vector should be %s (lab7_face_view, TODO lab7.3)", face, up);
    } else if (_sl_match(s, t, _sl_mirror_y, 0, k->threshold * 5) > 0.95) {
        sl_diag_say(out, "face %s is the reference flipped upside down (mirrored top to bottom)", face);
        sl_diag_cause_in(out, "lab7_face_view", "face %s: the up vector should be %s, and the face looks down %s (lab7_face_view, TODO "
                           "lab7.3)", face, up, face);
    } else if (_sl_match(s, t, _sl_mirror_x, 0, k->threshold * 5) > 0.95) {
        sl_diag_say(out, "face %s is the reference mirrored left to right", face);
        sl_diag_cause_in(out, "lab7_face_view", "face %s: the up vector should be %s (lab7_face_view, TODO lab7.3)", face, up);
    } else if (_sl_match(s, t, _sl_rotate_90, 0, k->threshold * 5) > 0.95 ||
               _sl_match(s, t, _sl_rotate_270, 0, k->threshold * 5) > 0.95) {
        sl_diag_say(out, "face %s is the reference turned by 90 degrees", face);
        sl_diag_cause_in(out, "lab7_face_view", "face %s: the up vector should be %s (lab7_face_view, TODO lab7.3)", face, up);
    } else {
        long nearer = 0, farther = 0, n = (long)s->width * s->height;
        for (long i = 0; i < n; i++) {
            double d = (double)s->data[i] - (double)t->data[i];
            nearer += d < -k->threshold;
            farther += d > k->threshold;
        }
        sl_diag_say(out, "face %s differs from the reference on %.1f%% of texels (allowed %.1f%%): %.1f%% hold nearer "
                         "distances than the reference's, %.1f%% farther", face, 100 * st.failing_fraction,
                    100 * k->fail_fraction, 100.0 * nearer / n, 100.0 * farther / n);
        if (layered) {
            sl_diag_append(out, ". The cube map was drawn in one layered pass (lab7_begin_cube_pass attached all six "
                                "faces), so this face's picture comes from shaders/cube_depth.geom");
            sl_diag_cause(out, "in cube_depth.geom, the copy sent to gl_Layer = f must be projected with "
                               "u_face_view_projection[f], the same f, and carry its world position on (gs_out)");
        } else
            sl_diag_cause_in(out, "lab7_face_view", "does the face look down %s with the up vector %s (lab7_face_view), and does "
                               "shaders/cube_depth.frag store length(world position - light) / far?", face, up);
    }
    if (st.nan_pixels) sl_diag_append(out, "; %ld texels are NaN", st.nan_pixels);
}

/* ---- the visibility ---- */

bool sl_diagnose_lab7_visibility(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                                 sl_check_result *out) {
    sl_visibility_stats v = sl_visibility_compare(s, t);
    const char *fn = c->params.cube.soft ? "point_shadow_soft()" : "point_shadow()";
    const char *todo = c->params.cube.soft ? "lab7.7" : "lab7.6";
    /* Self-shadowing: surfaces facing the light darkened in a fine pattern, not in solid regions. */
    sl_acne acne = sl_measure_acne(s, t, mask);
    if (sl_acne_is_pattern(&acne)) {
        out->symptoms |= 1u << SL_SYMPTOM_ACNE;
        sl_diag_say(out, "shadow acne on %.0f%% of the lit surfaces: they shadow themselves in a fine pattern of "
                         "stripes and specks (%.0f%% of the darkened pixels sit next to lit ones)",
                    100 * acne.fraction, 100 * acne.pattern);
        sl_diag_cause_in(out, fn, "the bias is too small or missing: %s compares length(light_to_fragment) / far_plane - bias "
                           "with the stored distance / far, the bias as given, in units of distance / far (this case: "
                           "%g, %.2g in world units; TODO %s)",
                      fn, c->params.cube.bias, c->params.cube.bias * c->scene.light.far, todo);
        return true;
    }
    if (v.extra_shadow > 0.5 && v.missing_shadow < 0.2) {
        out->symptoms |= 1u << SL_SYMPTOM_EXTRA_SHADOW;
        sl_diag_say(out, "%s is in shadow (%.0f%% of the reference's lit pixels)",
                    sl_diag_shadowed_share_words(v.extra_shadow), 100 * v.extra_shadow);
        sl_diag_cause_in(out, fn, "does %s compare like with like — the fragment's distance divided by far_plane with the "
                           "stored distance / far (TODO %s)?", fn, todo);
        return true;
    }
    if (v.missing_shadow > 0.3 && v.extra_shadow > 0.2) {
        out->symptoms |= 1u << SL_SYMPTOM_SWAPPED;
        sl_diag_say(out, "shadows fall on the wrong side of the room (%.0f%% of the reference's shadows lit, %.0f%% of "
                         "its lit pixels shadowed)", 100 * v.missing_shadow, 100 * v.extra_shadow);
        sl_diag_cause_in(out, fn, "is the lookup direction fragment - light (%s, TODO %s), and do the faces look the right "
                           "way (lab7_face_view)?", fn, todo);
        return true;
    }
    return false;
}

/* ---- the probes ---- */

/* Row `row` of a matrix output (column-major, as stored): m[col * 4 + row]. */
static void _sl_matrix_row(const double *m, int row, double out[3]) {
    for (int i = 0; i < 3; i++) out[i] = m[i * 4 + row];
}

/* ---- lab7_face_view by its contract ----
 *
 * A face's view may be built with glm_lookat (the target one step or ten
 * along the axis) or written out by hand; what it must do is put the eye at
 * the light and turn the face's axis to the image's centre (view -z), its up
 * vector to the image's +y and GL's "image right" of that face (s, the
 * table's column) to +x, without scaling: a rigid motion. */

/* The view's linear part applied to a world direction (column-major 4x4). */
static void _sl_turn(const double *m, const float v[3], double out[3]) {
    for (int i = 0; i < 3; i++) out[i] = m[0 * 4 + i] * v[0] + m[1 * 4 + i] * v[1] + m[2 * 4 + i] * v[2];
}

static bool _sl_is(const double a[3], double x, double y, double z, double eps) {
    return fabs(a[0] - x) <= eps && fabs(a[1] - y) <= eps && fabs(a[2] - z) <= eps;
}

/* What face `face`'s view breaks, into text; false when it keeps the contract. `expected`: the solution's
 * view of the same row, the face's up and right (NULL: unknown, those two promises go unchecked). */
static bool _sl_face_view_broken(const float *in, const double *m, const double *expected, double eps, char *text,
                                 size_t n) {
    int face = (int)in[0];
    const float *light = in + 1;
    if (face < 0 || face > 5) return false;
    /* every entry NaN: the probe's mark of a call that did not return SL_OK (a view matrix keeps its last
     * row (0, 0, 0, 1) even where a hand-made lookat divides by zero) */
    bool refused = true;
    for (int i = 0; i < 16; i++) refused &= isnan(m[i]);
    if (refused) {
        snprintf(text, n, "face %s: it did not return SL_OK, so there is no view for this face — faces 0 to 5 are "
                          "all valid (+X, -X, +Y, -Y, +Z, -Z: GL_TEXTURE_CUBE_MAP_POSITIVE_X + face); refuse only a "
                          "face outside 0..5", _sl_face(face));
        return true;
    }
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i])) {
            snprintf(text, n, "face %s: the matrix is not finite (NaN): with up (0,1,0) on the +-Y faces, glm_lookat "
                              "divides by zero — those faces need up (0,0,1) and (0,0,-1)", _sl_face(face));
            return true;
        }
    float face_up[3] = {0, 0, 0}, face_right[3] = {0, 0, 0};
    bool frame = expected && _sl_face_frame(expected, face_right, face_up);
    char axis[40], up[40], right[40];
    _sl_vector(_sl_axes[face], axis, sizeof axis);
    _sl_vector(face_up, up, sizeof up);
    _sl_vector(face_right, right, sizeof right);
    double a[3], u[3], s[3];
    _sl_turn(m, _sl_axes[face], a);
    _sl_turn(m, face_up, u);
    _sl_turn(m, face_right, s);
    double forward[3], image_up[3], image_right[3];
    _sl_matrix_row(m, 2, forward);
    _sl_matrix_row(m, 1, image_up);
    _sl_matrix_row(m, 0, image_right);
    if (fabs(m[3]) + fabs(m[7]) + fabs(m[11]) > eps || fabs(m[15] - 1) > eps) {
        snprintf(text, n, "face %s: the view is not a rigid motion (its last row is not 0, 0, 0, 1): glm_lookat(light, "
                          "light + axis, up)", _sl_face(face));
        return true;
    }
    if (!_sl_is(a, 0, 0, -1, eps)) {
        /* looking from the light at the axis itself, a point by the world's origin: the target taken for a direction */
        double to_axis[3], length = 0, looks[3] = {-forward[0], -forward[1], -forward[2]};
        for (int i = 0; i < 3; i++) to_axis[i] = _sl_axes[face][i] - light[i], length += to_axis[i] * to_axis[i];
        length = sqrt(length);
        if (length > 1e-3 && _sl_is(looks, to_axis[0] / length, to_axis[1] / length, to_axis[2] / length, 1e-3)) {
            snprintf(text, n, "face %s: the camera looks from the light at the point %s itself, not along it: glm_lookat "
                              "takes a point to look at, so the target is light_position + axis", _sl_face(face), axis);
            return true;
        }
        /* looking along light_position + axis: a point given where a direction belongs (glm_look's second
         * argument is a direction, glm_lookat's a point) */
        double along[3];
        length = 0;
        for (int i = 0; i < 3; i++) along[i] = _sl_axes[face][i] + light[i], length += along[i] * along[i];
        length = sqrt(length);
        if (length > 1e-3 && fabs(light[0]) + fabs(light[1]) + fabs(light[2]) > 1e-3 &&
            _sl_is(looks, along[0] / length, along[1] / length, along[2] / length, 1e-3)) {
            snprintf(text, n, "face %s: the camera looks along light_position + %s, not along %s itself: a point given "
                              "where a direction belongs — glm_look(eye, dir, up) takes the direction %s, "
                              "glm_lookat(eye, center, up) the point light_position + %s (right only for a light at "
                              "the origin)",
                     _sl_face(face), axis, axis, axis, axis);
            return true;
        }
        /* looking down another face's axis: the faces taken in another order than GL's */
        for (int other = 0; other < 6; other++)
            if (other != face && _sl_is(looks, _sl_axes[other][0], _sl_axes[other][1], _sl_axes[other][2], 1e-3)) {
                char its[40];
                _sl_vector(_sl_axes[other], its, sizeof its);
                snprintf(text, n, "face %s: the camera looks down face %s's axis %s, where face %s looks down %s: "
                                  "the faces taken in another order than GL's, +X, -X, +Y, -Y, +Z, -Z (face i is "
                                  "GL_TEXTURE_CUBE_MAP_POSITIVE_X + i, and the lookup reads it as that face), or an "
                                  "axis with the wrong sign",
                         _sl_face(face), _sl_face(other), its, _sl_face(face), axis);
                return true;
            }
        snprintf(text, n, "face %s: the camera should look down %s, it looks down (%.3g,%.3g,%.3g)", _sl_face(face),
                 axis, -forward[0], -forward[1], -forward[2]);
        return true;
    }
    if (frame && !_sl_is(u, 0, 1, 0, eps)) {
        snprintf(text, n, "face %s: the up vector should be %s, not (%.3g,%.3g,%.3g)", _sl_face(face), up,
                 image_up[0], image_up[1], image_up[2]);
        return true;
    }
    if (frame && !_sl_is(s, 1, 0, 0, eps)) {
        snprintf(text, n, "face %s is mirrored: the image's right (+x) must be %s, as GL's table of cube map faces reads "
                          "it; here it is (%.3g,%.3g,%.3g) — a lookAt's right is forward x up", _sl_face(face), right,
                 image_right[0], image_right[1], image_right[2]);
        return true;
    }
    double eye[3] = {m[12], m[13], m[14]};
    for (int i = 0; i < 3; i++) eye[i] += m[0 * 4 + i] * light[0] + m[1 * 4 + i] * light[1] + m[2 * 4 + i] * light[2];
    if (!_sl_is(eye, 0, 0, 0, eps * (1 + fabs(light[0]) + fabs(light[1]) + fabs(light[2])))) {
        snprintf(text, n, "face %s: the axes are right but the eye is not at the light (%g,%g,%g): the light lands at "
                          "(%.3g,%.3g,%.3g) in view space, not at the origin", _sl_face(face), (double)light[0],
                 (double)light[1], (double)light[2], eye[0], eye[1], eye[2]);
        return true;
    }
    return false;
}

bool sl_lab7_probe_contract(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                            char *text, size_t n, int *shown) {
    const sl_probe_function *f = sl_probe_at(k->function);
    if (!f || strcmp(f->name, "lab7_face_view") != 0) return false;
    *broken = 0;
    *shown = -1;
    text[0] = '\0';
    double eps = k->tolerance > 0 ? k->tolerance : 1e-4;
    for (int row = 0; row < k->rows; row++) {
        char why[400];
        if (!_sl_face_view_broken(k->inputs[row], student + row * 16, expected ? expected + row * 16 : NULL, eps, why,
                                  sizeof why))
            continue;
        *broken |= 1u << row;
        if (*shown < 0) {
            *shown = row;
            snprintf(text, n, "%s", why);
        }
    }
    return true;
}

static int _sl_projection_verdict(const sl_check *k, const double *s, const double *e, uint32_t failing, char *text,
                                  size_t n) {
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        const double *sm = s + row * 16, *em = e + row * 16;
        double aspect = sm[5] / sm[0];
        char slip[200];
        /* a slip of units first: the angle the matrix shows (117 degrees for 90 radians) was never written */
        if (fabs(sm[5] - em[5]) > 1e-3 * fabs(em[5]) &&
            sl_diag_angle_slip(sm[5], sl_diag_perspective_fov_deg(em[5]), "90.0f", slip, sizeof slip))
            snprintf(text, n, "%s: a cube face needs 90 degrees, in radians, so the six frusta meet edge to edge", slip);
        else if (fabs(sm[5] - em[5]) > 1e-3 * fabs(em[5]))
            snprintf(text, n, "the field of view is %.3g degrees: a cube face needs 90 (in radians: glm_rad(90.0f)), "
                              "so the six frusta meet edge to edge", sl_diag_perspective_fov_deg(sm[5]));
        else if (fabs(sm[0] - em[0]) > 1e-3 * fabs(em[0]))
            snprintf(text, n, "the aspect ratio is %.3g: a cube face is square, aspect 1", aspect);
        else
            snprintf(text, n, "the depth range differs: use the light's near and far planes as given");
        return row;
    }
    return -1;
}

static double _sl_length3(const float *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

static int _sl_lookup_verdict(const sl_check *k, bool soft, const double *s, const double *e, uint32_t failing,
                              char *text, size_t n) {
    /* rows of the lit map inside the far plane: a lookup that forgets to divide the distance by far shadows them */
    int lit_rows = 0, lit_dark = 0, first_lit = -1;
    /* rows of the cube_positive map, where light_to_fragment and its opposite give different answers */
    int pos_rows = 0, pos_flipped = 0, first_pos = -1;
    int flipped = 0, first_failing = -1, failing_count = 0;
    for (int row = 0; row < k->rows; row++) {
        sl_probe_map map = (sl_probe_map)(int)k->inputs[row][0];
        double sv = s[row], ev = e[row];
        bool fails = (failing >> row) & 1u;
        if (fails) {
            failing_count++;
            if (first_failing < 0) first_failing = row;
        }
        flipped += fabs(sv - (1.0 - ev)) < 0.05;
        double distance = _sl_length3(&k->inputs[row][1]), far = k->inputs[row][4];
        if (map == SL_PROBE_MAP_CUBE_LIT && distance < far && distance > 1.0) {
            lit_rows++;
            if (sv < 0.5) {
                lit_dark++;
                if (first_lit < 0) first_lit = row;
            }
        }
        if (map == SL_PROBE_MAP_CUBE_POSITIVE) {
            pos_rows++;
            if (fails && fabs(sv - (1.0 - ev)) < 0.05) {
                pos_flipped++;
                if (first_pos < 0) first_pos = row;
            }
        }
    }
    if (failing_count == 0) return -1;
    if (flipped == k->rows) {
        snprintf(text, n, "every answer is the opposite of the reference's: the comparison is inverted (shadowed "
                          "where the fragment is FARTHER than the stored distance, minus the bias)");
        return first_failing;
    }
    if (lit_rows > 0 && lit_dark == lit_rows) {
        snprintf(text, n, "an empty map (1.0 everywhere) still shadows: the fragment's distance is compared in world "
                          "units with the stored distance / far — divide it by far_plane too (the far plane is "
                          "missing on the lookup's side)");
        return first_lit;
    }
    /* the empty map's answer is the weights' sum: the same value off 1 on every such row */
    int sum_rows = 0, sum_same = 0, first_sum = -1;
    for (int row = 0; soft && row < k->rows; row++) {
        double distance = _sl_length3(&k->inputs[row][1]), far = k->inputs[row][4];
        if ((sl_probe_map)(int)k->inputs[row][0] != SL_PROBE_MAP_CUBE_LIT || distance >= far || e[row] < 0.999) continue;
        sum_rows++;
        if (first_sum < 0) first_sum = row;
        sum_same += fabs(s[row] - s[first_sum]) <= 1e-4 && fabs(s[row] - 1) > 0.01 && s[row] > 0.05;
    }
    if (sum_rows > 0 && sum_same == sum_rows && fabs(s[first_sum] * 20 - 1) <= 0.005) {
        snprintf(text, n, "only one sample counts: an empty map gives %.4g = 1/20, one lit sample divided by the 20 "
                          "directions' count — the sum is overwritten in the loop (= where += belongs) "
                          "or reset inside it", s[first_sum]);
        return first_sum;
    }
    if (sum_rows > 0 && sum_same == sum_rows) {
        snprintf(text, n, "the weights sum to %.4g, not 1 (an empty map gives %.4g): divide the sum of the results by "
                          "the number of samples taken, all 20 directions", s[first_sum], s[first_sum]);
        return first_sum;
    }
    if (pos_rows > 0 && pos_flipped == pos_rows && pos_flipped == failing_count) {
        snprintf(text, n, "the lookup reads the opposite side of the cube map: its direction is reversed — sample with "
                          "light_to_fragment (from the light to the fragment), not fragment-to-light");
        return first_pos;
    }
    /* Rows just behind the shell of "cube_occluded" (0.25), by less than 0.05 of distance / far: the bias decides
     * them. When they are the only rows that fail, the bias is what is wrong, and how they fail says how. */
    int bias_rows = 0, darker = 0, lighter = 0, first_bias = -1;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        sl_probe_map map = (sl_probe_map)(int)k->inputs[row][0];
        double behind = _sl_length3(&k->inputs[row][1]) / k->inputs[row][4] - sl_probe_cube_depth(map, 0, 0, 0);
        if (map != SL_PROBE_MAP_CUBE_OCCLUDED || behind <= 0 || behind >= 0.05) continue;
        bias_rows++;
        darker += s[row] < e[row];
        lighter += s[row] > e[row];
        if (first_bias < 0) first_bias = row;
    }
    const sl_probe_function *f = sl_probe_at(k->function);
    /* the soft lookup answering 0 or 1 on every row that differs, where the contract's answer is a fraction:
     * no average of 20 comparisons (an integer division, or one sample), whatever the radius */
    int whole = 0, first_whole = -1;
    for (int row = 0; f && f->param_count == 5 && row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        if ((s[row] == 0 || s[row] == 1) && e[row] > 0.02 && e[row] < 0.98) {
            whole++;
            if (first_whole < 0) first_whole = row;
        }
    }
    if (whole > 0 && whole == failing_count) {
        snprintf(text, n, "it answers 0 or 1 on every row that differs, where the contract's answer is a fraction of "
                          "the 20 samples (k lit give k / 20.0): the samples are not averaged — an integer division "
                          "(an int count divided by 20 is 0 until all 20 are lit), or one sample taken");
        return first_whole;
    }
    /* the soft lookup: rows that differ only in the radius, the same answer where the solution's differ */
    for (int a = 0; f && f->param_count == 5 && a < k->rows; a++) {
        if (!((failing >> a) & 1u)) continue;
        for (int b = 0; b < k->rows; b++) {
            const float *ia = k->inputs[a], *ib = k->inputs[b];
            bool twin = b != a && ia[6] != ib[6];
            for (int i = 0; twin && i < 6; i++) twin = ia[i] == ib[i];
            if (twin && fabs(s[a] - s[b]) < 1e-3 && fabs(e[a] - e[b]) > 0.05) {
                /* both answers are what the contract gives at the larger radius: a disk far wider than the
                 * contract's saturates, and then looks like one that ignores its radius */
                bool a_smaller = ia[6] < ib[6];
                if (fabs(s[a] - (a_smaller ? e[b] : e[a])) <= 0.1) { /* 0.1: two of the 20 samples */
                    snprintf(text, n, "the disk is far too wide: at radius %g it answers %.3g, what the contract gives "
                                      "at radius %g, and a larger radius changes nothing — the disk's angle is radius * "
                                      "length(light_to_fragment) / far_plane (radius is its size at the far plane: "
                                      "not divided by far_plane, it is far_plane times too wide)",
                             (double)fmin(ia[6], ib[6]), s[a], (double)fmax(ia[6], ib[6]));
                    return a;
                }
                snprintf(text, n, "the disk ignores radius: radius %g and radius %g give the same — the samples go "
                                  "out to radius * length(light_to_fragment) / far_plane around the direction",
                         (double)ia[6], (double)ib[6]);
                return a;
            }
        }
    }
    /* the soft lookup: rows along the same direction at different distances (all else equal), where the
     * contract's disk covers the same angle and so gives the same answer, and the student's answers differ:
     * the disk's angle changes with the distance (offsets added to the unit direction, or a disk not scaled
     * by the distance) */
    for (int a = 0; f && f->param_count == 5 && a < k->rows; a++) {
        if (!((failing >> a) & 1u)) continue;
        for (int b = 0; b < k->rows; b++) {
            const float *ia = k->inputs[a], *ib = k->inputs[b];
            double la = _sl_length3(&ia[1]), lb = _sl_length3(&ib[1]);
            if (b == a || ia[0] != ib[0] || ia[4] != ib[4] || ia[5] != ib[5] || ia[6] != ib[6] || la <= 0 || lb <= 0 ||
                fabs(la - lb) < 0.1 * fmax(la, lb))
                continue;
            bool parallel = true;
            for (int j = 0; j < 3; j++) parallel &= fabs(ia[1 + j] / la - ib[1 + j] / lb) <= 1e-3;
            if (parallel && fabs(e[a] - e[b]) <= 1e-3 && fabs(s[a] - s[b]) > 0.05) {
                snprintf(text, n, "the disk's angle changes with the distance: along one direction, %.3g and %.3g from "
                                  "the light, it answers %.3g and %.3g where the contract gives %.3g at both — the offsets "
                                  "are radius * length(light_to_fragment) / far_plane, added to light_to_fragment itself, so "
                                  "the disk covers the same angle at any distance (offsets added to the unit direction "
                                  "grow with it, a disk of fixed size shrinks)", fmin(la, lb), fmax(la, lb), la < lb ? s[a] : s[b], la < lb ? s[b] : s[a],
                         e[a]);
                return a;
            }
        }
    }
    if (bias_rows > 0 && bias_rows == failing_count) {
        if (darker == bias_rows)
            snprintf(text, n, "shadow acne: points just behind a surface, within the bias, come out shadowed — the bias "
                              "is missing or too small: compare length(light_to_fragment) / far_plane - bias with the "
                              "stored distance / far, the bias as given (in units of distance / far)");
        else if (lighter == bias_rows)
            snprintf(text, n, "the bias is too large: points behind a surface by more than the bias come out lit — the "
                              "bias is in units of distance / far, subtracted once");
        else
            snprintf(text, n, "the bias is not the one given: within it some points come out shadowed, beyond it some lit "
                              "— a constant of your own, or the bias in world units? Compare length(light_to_fragment) / "
                              "far_plane - bias with the stored distance / far");
        return first_bias;
    }
    return -1;
}

#define _SL_CUBE_POSITIVE_X 0x8515 /* GL_TEXTURE_CUBE_MAP_POSITIVE_X: the grader reads GL's numbers, not GL */

/* lab7_begin_cube_pass leaving attached the face the probe attached before the call ((face + 3) % 6), on every
 * row that differs: its glFramebufferTexture2D went to another framebuffer (the one bound before its bind). */
/* Face +X attached whatever the face, its depth readable only where face is 0: the face given to
 * glFramebufferTexture2D as its mip level (a level with no storage leaves the framebuffer incomplete, so
 * the clear writes nothing there). Outputs 1: attached face, 6: depth after the call. */
static int _sl_face_as_level(const sl_check *k, const double *student, const double *expected, uint32_t failing,
                             char *text, size_t n) {
    int outputs = sl_probe_at(k->function)->output_count, first = -1, zero_right = 0;
    for (int row = 0; row < k->rows; row++) {
        int face = (int)k->inputs[row][0];
        const double *got = student + row * outputs, *want = expected + row * outputs;
        if (face < 0 || face > 5 || got[1] != _SL_CUBE_POSITIVE_X) return -1;
        if (face == 0) zero_right += !((failing >> row) & 1u);
        else if ((failing >> row) & 1u && got[6] != want[6]) {
            if (first < 0) first = row;
        } else return -1;
    }
    if (first < 0 || zero_right == 0) return -1;
    snprintf(text, n, "it attaches face +X whatever face is, and only face 0's framebuffer can be cleared: the face "
                      "went in as the mip level — glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, "
                      "GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, map->depth_cube, 0): the face in the target, level 0 last");
    return first;
}

/* The face's target counted from another enum than GL_TEXTURE_CUBE_MAP_POSITIVE_X: every row whose face would
 * land on a face attaches the face `shift` places off, the same shift on each (GL_TEXTURE_CUBE_MAP + face is
 * two below; faces whose target is no face's leave the attachment as it was, and GL reports an error). */
static int _sl_face_target_shifted(const sl_check *k, const double *student, const double *expected, uint32_t failing,
                                   char *text, size_t n) {
    int outputs = sl_probe_at(k->function)->output_count, first = -1, shift = 0, shifted = 0;
    /* the shift most failing rows show */
    int counts[13] = {0};
    for (int row = 0; row < k->rows; row++) {
        int d = (int)student[row * outputs + 1] - (int)expected[row * outputs + 1];
        if ((failing >> row) & 1u && d >= -6 && d <= 6 && d != 0) counts[d + 6]++;
    }
    for (int d = 0; d < 13; d++)
        if (counts[d] > counts[shift + 6] || (shift == 0 && counts[d] > 0)) shift = d - 6;
    if (shift == 0) return -1;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        int face = (int)k->inputs[row][0];
        const double *got = student + row * outputs, *want = expected + row * outputs;
        if (face < 0 || face > 5 || want[1] != _SL_CUBE_POSITIVE_X + face) return -1;
        if (first < 0) first = row;
        /* the face attached before the call, (face + 3) % 6, is "left as it was", not a shift */
        bool left = got[1] == (double)(_SL_CUBE_POSITIVE_X + (face + 3) % 6);
        if ((int)got[1] - (int)want[1] == shift && !left) {
            shifted++;
            continue;
        }
        if (!left) return -1;
        /* left as it was only where the shifted target is no face's */
        if (face + shift >= 0 && face + shift <= 5) return -1;
    }
    if (first < 0 || shifted < 2) return -1;
    snprintf(text, n, "each face attaches the face %d place%s %s it (GL's number %d %s GL_TEXTURE_CUBE_MAP_POSITIVE_X "
                      "+ face), and a face whose target is no face's keeps what was attached: the target counted from "
                      "another enum%s — the faces' targets are GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, +X first",
             abs(shift), abs(shift) == 1 ? "" : "s", shift > 0 ? "after" : "before", abs(shift),
             shift > 0 ? "above" : "below",
             shift == -2 ? " (GL_TEXTURE_CUBE_MAP + face: GL_TEXTURE_CUBE_MAP, 0x8513, is the cube map's own target, "
                           "two below +X's 0x8515)"
                         : "");
    return first;
}

static int _sl_begin_cube_pass_verdict(const sl_check *k, const double *student, const double *expected,
                                       uint32_t failing, char *text, size_t n) {
    const sl_probe_function *f = sl_probe_at(k->function);
    int outputs = f->output_count, first = -1;
    int level = _sl_face_as_level(k, student, expected, failing, text, n);
    if (level >= 0) return level;
    bool before = true;
    for (int row = 0; row < k->rows && before; row++) {
        if (!((failing >> row) & 1u)) continue;
        int face = (int)k->inputs[row][0];
        const double *got = student + row * outputs, *want = expected + row * outputs;
        before = face >= 0 && face <= 5 && got[0] == 1 && got[1] == (double)(_SL_CUBE_POSITIVE_X + (face + 3) % 6) &&
                 got[1] != want[1];
        if (first < 0) first = row;
    }
    /* not the face attached before on every row: a target counted from another enum, or nothing said */
    if (!before || first < 0) return _sl_face_target_shifted(k, student, expected, failing, text, n);
    snprintf(text, n, "the face attached after it is the one attached before it was called: its glFramebufferTexture2D "
                      "did not reach the map's framebuffer — it attaches to the framebuffer bound when it runs, so bind "
                      "map->framebuffer first, then attach GL_TEXTURE_CUBE_MAP_POSITIVE_X + face");
    return first;
}

int sl_lab7_probe_verdict(const sl_check *k, const double *student, const double *expected, uint32_t failing,
                          char *text, size_t n) {
    text[0] = '\0';
    const sl_probe_function *f = sl_probe_at(k->function);
    if (!f) return -1;
    if (strcmp(f->name, "lab7_face_projection") == 0)
        return _sl_projection_verdict(k, student, expected, failing, text, n);
    if (strcmp(f->name, "lab7_begin_cube_pass") == 0)
        return _sl_begin_cube_pass_verdict(k, student, expected, failing, text, n);
    if (strcmp(f->name, "point_shadow") == 0 || strcmp(f->name, "point_shadow_soft") == 0)
        return _sl_lookup_verdict(k, strcmp(f->name, "point_shadow_soft") == 0, student, expected, failing, text, n);
    return -1;
}

/* ---- what lab 7's cases run ---- */

bool sl_lab7_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    if (strcmp(fn, "cube_depth.frag") == 0) return true;
    /* the geometry shader of the layered pass runs only when the lab's lab7_begin_cube_pass takes all
     * faces, which the case cannot tell: the "path" capture can, and the face checks name it from there */
    if (strcmp(fn, "cube_depth.geom") == 0) return false;
    return sl_lab7_case_calls(c, k, fn);
}

void sl_lab7_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    const sl_capture *path = r ? sl_result_capture(r, sl_capture_name(SL_CAPTURE_PATH)) : NULL;
    const char *pass = path && path->number_count >= SL_PATH_NUMBERS
                           ? (path->numbers[1] != 0 ? "in one layered pass (lab7_begin_cube_pass took all six faces, "
                                                      "and shaders/cube_depth.geom, which has no probe, sent each "
                                                      "triangle to them)"
                                                    : "in six passes, one per face")
                       : c->params.cube.pass == SL_CUBE_PASS_LAYERED ? "in one layered pass"
                       : c->params.cube.pass == SL_CUBE_PASS_SIX     ? "in six passes"
                                                                     : "in one layered pass where lab7_begin_cube_pass "
                                                                       "takes all faces, else six";
    bool lookup = r && (sl_result_capture(r, "visibility") || sl_result_capture(r, "image"));
    snprintf(out, n, "the cube map drawn %s%s%s", pass, lookup ? ", looked up with " : "",
             lookup ? (c->params.cube.soft ? "point_shadow_soft() (20 directions)" : "point_shadow()") : "");
}

/* ---- lab 7 in the diagnosis table (diagnose/table.c) ---- */
/* Lab 7's cases look up in the cube map, hard or soft. */
static void _sl_lab7_lookup_function(const sl_case *c, const char **function, const char **todo) {
    *function = c->params.cube.soft ? "point_shadow_soft()" : "point_shadow()";
    *todo = c->params.cube.soft ? "lab7.7" : "lab7.6";
}

const sl_lab_diagnoses sl_lab7_diagnoses = {
    .lab = 7,
    .lookup_function = _sl_lab7_lookup_function,
    .checks = {{SL_CHECK_CUBE_FACE, sl_diagnose_cube_face}},
    .visibility = sl_diagnose_lab7_visibility,
    .case_runs = sl_lab7_case_runs,
    .case_path = sl_lab7_case_path,
    .probe_contract = sl_lab7_probe_contract,
    .probe_verdict = sl_lab7_probe_verdict,
};
