#define _POSIX_C_SOURCE 200809L
#include "sl_grade.h"

#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "sl_compare.h"

/* The TODO tags a stub's message points to. */
static const struct { const char *function, *todo, *file; } _sl_stubs[] = {
    {"lab1_create_shadow_map", "TODO(lab1.1), TODO(lab1.2)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab1_begin_depth_pass", "TODO(lab1.3)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab2_light_view", "TODO(lab2.1)", "labs/lab2_projective/lab2.c"},
    {"lab2_light_projection", "TODO(lab2.2)", "labs/lab2_projective/lab2.c"},
    {"lab2_shadow_matrix", "TODO(lab2.3)", "labs/lab2_projective/lab2.c"},
};

static void _sl_say(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void _sl_say(sl_check_result *out, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->message, sizeof out->message, fmt, args);
    va_end(args);
}

static void _sl_append(sl_check_result *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void _sl_append(sl_check_result *out, const char *fmt, ...) {
    size_t used = strlen(out->message);
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->message + used, sizeof out->message - used, fmt, args);
    va_end(args);
}

static int _sl_function_lab(const char *function) {
    return strncmp(function, "lab", 3) == 0 ? atoi(function + 3) : 0;
}

/* "not implemented" for this lab's stubs first, then "needs lab K". */
static bool _sl_explain_missing(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < r->not_implemented_count; i++) {
            const char *fn = r->not_implemented[i];
            int lab = _sl_function_lab(fn);
            if ((pass == 0) != (lab == c->lab)) continue;
            const char *todo = "", *file = "";
            for (size_t s = 0; s < sizeof _sl_stubs / sizeof _sl_stubs[0]; s++)
                if (strcmp(_sl_stubs[s].function, fn) == 0) {
                    todo = _sl_stubs[s].todo;
                    file = _sl_stubs[s].file;
                }
            if (lab == c->lab)
                _sl_say(out, "not implemented: %s() still returns SL_NOT_IMPLEMENTED (%s in %s)", fn, todo, file);
            else
                _sl_say(out, "not implemented: needs lab %d first, and %s() still returns SL_NOT_IMPLEMENTED", lab, fn);
            return true;
        }
    }
    if (r->failed[0]) {
        _sl_say(out, "%s() returned SL_FAILED", r->failed);
        if (strcmp(r->failed, "lab1_create_shadow_map") == 0)
            _sl_append(out, " (is the framebuffer complete? glCheckFramebufferStatus tells why not)");
        return true;
    }
    return false;
}

static void _sl_explain_run_failure(const sl_case_result *r, sl_check_result *out) {
    if (r->timed_out) {
        _sl_say(out, "timed out after %.0f s%s%s%s", r->seconds, r->crashed_in[0] ? " in " : "",
                r->crashed_in, r->crashed_in[0] ? "() (an endless loop?)" : "");
    } else if (r->signal) {
        _sl_say(out, "crashed (%s)%s%s%s", strsignal(r->signal), r->crashed_in[0] ? " in " : " outside lab code",
                r->crashed_in, r->crashed_in[0] ? "()" : "");
    } else if (r->error[0]) {
        _sl_say(out, "%s", r->error);
    } else {
        _sl_say(out, "the case stopped early (exit status %d)%s%s%s", r->exit_code, r->crashed_in[0] ? " in " : "",
                r->crashed_in, r->crashed_in[0] ? "()" : "");
    }
}

/* ---- references ---- */

void sl_reference_load(sl_reference *ref, const char *dir, const sl_case *c, const sl_check *k) {
    memset(ref, 0, sizeof *ref);
    const char *file = sl_check_reference_file(k->kind);
    if (!file) return;
    ref->needed = true;
    snprintf(ref->path, sizeof ref->path, "%s/%s/%s", dir, c->name, file);
    struct stat st;
    if (stat(ref->path, &st) != 0) {
        snprintf(ref->error, sizeof ref->error, "reference missing: %s (staff: run shadowlab-grade --update-references on a solutions build)", ref->path);
        return;
    }
    if (k->kind == SL_CHECK_MATRICES) {
        FILE *f = fopen(ref->path, "rb");
        char text[16384];
        size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
        if (f) fclose(f);
        text[n] = '\0';
        cJSON *json = cJSON_Parse(text);
        static const char *keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        bool ok = json != NULL;
        for (int m = 0; ok && m < 3; m++) {
            const cJSON *a = cJSON_GetObjectItemCaseSensitive(json, keys[m]);
            ok = cJSON_IsArray(a) && cJSON_GetArraySize(a) == 16;
            for (int i = 0; ok && i < 16; i++) {
                const cJSON *v = cJSON_GetArrayItem(a, i);
                ok = cJSON_IsNumber(v);
                if (ok) ref->numbers[m * 16 + i] = v->valuedouble;
            }
        }
        cJSON_Delete(json);
        if (!ok) {
            snprintf(ref->error, sizeof ref->error, "reference corrupt: %s (expected light_view, light_projection, shadow_matrix: 16 numbers each)", ref->path);
            return;
        }
        ref->number_count = 48;
    } else {
        char err[512];
        if (!sl_image_read(ref->path, &ref->image, err, sizeof err)) {
            snprintf(ref->error, sizeof ref->error, "reference corrupt: %s", err);
            return;
        }
        if (k->kind == SL_CHECK_VISIBILITY && ref->image.channels != 1) {
            snprintf(ref->error, sizeof ref->error, "reference corrupt: %s has %d channels, expected 1", ref->path, ref->image.channels);
            sl_image_free(&ref->image);
            return;
        }
    }
    ref->loaded = true;
}

void sl_reference_free(sl_reference *ref) { sl_image_free(&ref->image); }

bool sl_mkdirs(const char *path) {
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s", path);
    for (char *p = tmp + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        mkdir(tmp, 0755);
        *p = '/';
    }
    struct stat st;
    return mkdir(tmp, 0755) == 0 || (stat(tmp, &st) == 0 && S_ISDIR(st.st_mode));
}

bool sl_reference_write(const char *dir, const sl_case *c, const sl_check *k, const sl_case_result *r, char *err,
                        size_t err_size) {
    const char *file = sl_check_reference_file(k->kind);
    if (!file) return true;
    char folder[1100], path[1200];
    snprintf(folder, sizeof folder, "%s/%s", dir, c->name);
    if (!sl_mkdirs(folder)) {
        snprintf(err, err_size, "%s: cannot create the folder", folder);
        return false;
    }
    snprintf(path, sizeof path, "%s/%s", folder, file);
    const char *capture = k->kind == SL_CHECK_MATRICES ? "matrices" : sl_check_kind_name(k->kind);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        snprintf(err, err_size, "%s: the solutions captured no %s (%s)", c->name, capture,
                 r->not_implemented_count ? "a stub is not implemented" : r->error[0] ? r->error : "see the case");
        return false;
    }
    if (k->kind == SL_CHECK_MATRICES) {
        static const char *keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        FILE *f = fopen(path, "w");
        if (!f) {
            snprintf(err, err_size, "%s: cannot write", path);
            return false;
        }
        fprintf(f, "{\n");
        for (int m = 0; m < 3; m++) {
            fprintf(f, "  \"%s\": [", keys[m]);
            for (int i = 0; i < 16; i++) fprintf(f, "%s%.9g", i ? ", " : "", cap->numbers[m * 16 + i]);
            fprintf(f, "]%s\n", m < 2 ? "," : "");
        }
        fprintf(f, "}\n");
        return fclose(f) == 0;
    }
    return sl_image_write(path, &cap->image, err, err_size);
}

/* ---- checks ---- */

static void _sl_check_fbo(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "fbo");
    if (!cap || cap->number_count < 10) {
        if (!_sl_explain_missing(c, r, out))
            _sl_say(out, "lab1_create_shadow_map() left map->framebuffer and map->depth_texture at 0");
        return;
    }
    const double *v = cap->numbers;
    GLenum status = (GLenum)v[0];
    if (v[0] == 0) {
        _sl_say(out, "map->framebuffer is not a framebuffer object (glGenFramebuffers + glBindFramebuffer)");
    } else if (v[1] != GL_TEXTURE) {
        _sl_say(out, "nothing is attached as GL_DEPTH_ATTACHMENT: attach the depth texture with glFramebufferTexture2D");
    } else if (!v[2]) {
        _sl_say(out, "the texture attached as GL_DEPTH_ATTACHMENT is not map->depth_texture");
    } else if (v[3] <= 0) {
        _sl_say(out, "map->depth_texture has no depth format: use GL_DEPTH_COMPONENT24 (internal format) with GL_DEPTH_COMPONENT");
    } else if (v[4] != v[9] || v[5] != v[9]) {
        _sl_say(out, "the depth texture is %.0fx%.0f, but the requested map size is %.0f: use the size argument", v[4], v[5], v[9]);
    } else if (v[8] != GL_NONE) {
        _sl_say(out, "the framebuffer has a colour attachment: a depth-only pass needs none");
    } else if (v[6] != GL_NONE || v[7] != GL_NONE) {
        _sl_say(out, "draw/read buffer is %s, not GL_NONE: call glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE) while the framebuffer is bound",
                v[6] != GL_NONE ? "set" : "set for reading");
    } else if (status != GL_FRAMEBUFFER_COMPLETE) {
        _sl_say(out, "the framebuffer is incomplete: %s", sl_gl_enum_name(status));
    } else if (r->failed[0] && strcmp(r->failed, "lab1_create_shadow_map") == 0) {
        _sl_say(out, "lab1_create_shadow_map() returned SL_FAILED, although its framebuffer is complete");
    } else {
        out->passed = true;
    }
}

static void _sl_check_depth(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "depth_map");
    if (!cap) {
        if (r->capture_error[0]) _sl_say(out, "%s", r->capture_error);
        else if (!_sl_explain_missing(c, r, out)) _sl_say(out, "no depth map was captured");
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        _sl_say(out, "the depth map is %dx%d, the reference %dx%d", s->width, s->height, t->width, t->height);
        return;
    }
    if (st.failing_fraction <= k->fail_fraction && st.nan_pixels == 0) {
        out->passed = true;
        return;
    }
    double ref_empty = sl_fraction_equal(t, 1.0f, 1e-6f);
    double stu_empty = sl_fraction_equal(s, 1.0f, 1e-6f);
    double stu_zero = sl_fraction_equal(s, 0.0f, 1e-6f);
    if (stu_empty > 0.999 && ref_empty < 0.99) {
        _sl_say(out, "the depth map is empty (all 1.0): nothing was drawn into it — not implemented? "
                     "shaders/depth.vert must output u_light_view_projection * u_model * position (TODO lab1.4)");
    } else if (stu_zero > 0.9) {
        _sl_say(out, "the depth map is all 0.0: no fragment passed the depth test — is the depth buffer cleared "
                     "(glClear(GL_DEPTH_BUFFER_BIT)) after binding the framebuffer, with depth writes on?");
    } else if (sl_content_only_in_lower_left(s, 1.0f, c->width, c->height)) {
        _sl_say(out, "only the lower-left %dx%d texels of the %dx%d map hold depths: the viewport is still the "
                     "window's — call glViewport(0, 0, size, size) in lab1_begin_depth_pass (TODO lab1.3)",
                c->width, c->height, s->width, s->height);
    } else {
        /* Stale depths from earlier frames: many texels nearer than they should be, few farther. */
        long nearer = 0, farther = 0, n = (long)s->width * s->height;
        for (long i = 0; i < n; i++) {
            double d = (double)s->data[i] - (double)t->data[i];
            nearer += d < -k->threshold;
            farther += d > k->threshold;
        }
        if (nearer > 20 * (farther + 1) && (double)nearer / (double)n > k->fail_fraction)
            _sl_say(out, "%.1f%% of texels hold depths nearer than the scene's: depths from earlier frames "
                         "remain — clear the depth buffer at the start of every depth pass",
                    100.0 * (double)nearer / (double)n);
        else
            _sl_say(out, "the depth map differs from the reference on %.1f%% of texels (allowed %.1f%%)",
                    100 * st.failing_fraction, 100 * k->fail_fraction);
    }
    if (st.nan_pixels) _sl_append(out, "; %ld texels are NaN", st.nan_pixels);
}

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

static void _sl_check_matrices(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "matrices");
    if (!cap) {
        if (!_sl_explain_missing(c, r, out)) _sl_say(out, "lab 2's matrices were not used");
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
        _sl_say(out, "the light's view matrix differs from the reference (largest error %.3g): check eye, target and "
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
        if (outside)
            _sl_say(out, "the orthographic fit is too small: scene corners fall outside the light's frustum, so shadows "
                         "are cut off at its edge (TODO lab2.2)");
        else
            _sl_say(out, "the light's projection differs from the reference (largest error %.3g): %s (TODO lab2.2)", ep,
                    c->scene.light.type == SL_LIGHT_SPOT
                        ? "a spot light's field of view is twice the cone's half-angle, in radians, aspect 1"
                        : "fit left/right/bottom/top/near/far to the scene box's corners in light view space, padded");
    } else if (_sl_matrix_error(sm, pv) <= k->epsilon) {
        _sl_say(out, "the shadow matrix is Lp * Lv without the bias matrix W: coordinates stay in [-1,1] instead of "
                     "[0,1] (TODO lab2.3)");
    } else if (_sl_matrix_error(sm, wvp) <= k->epsilon) {
        _sl_say(out, "the shadow matrix multiplies Lv * Lp: the order is reversed, it must be W * Lp * Lv (TODO lab2.3)");
    } else {
        _sl_mul(pv, bias, tmp);
        if (_sl_matrix_error(sm, tmp) <= k->epsilon)
            _sl_say(out, "the shadow matrix is Lp * Lv * W: W must come first (leftmost), W * Lp * Lv (TODO lab2.3)");
        else
            _sl_say(out, "the shadow matrix differs from W * Lp * Lv (largest error %.3g) (TODO lab2.3)", em);
    }
}

static void _sl_check_image(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            sl_check_result *out) {
    const char *capture = sl_check_kind_name(k->kind);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        if (!_sl_explain_missing(c, r, out)) _sl_say(out, "no %s image was captured", capture);
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        _sl_say(out, "the image is %dx%dx%d, the reference %dx%dx%d", s->width, s->height, s->channels, t->width,
                t->height, t->channels);
        return;
    }
    if (st.failing_fraction <= k->fail_fraction && st.nan_pixels == 0) {
        out->passed = true;
        return;
    }
    bool said = false;
    if (_sl_explain_missing(c, r, out)) {
        return; /* the hint is about a mistake, not a missing stub */
    } else if (k->kind == SL_CHECK_VISIBILITY) {
        sl_visibility_stats v = sl_visibility_compare(s, t);
        bool has_shadows = v.reference_shadowed > 0.005;
        said = true;
        if (has_shadows && v.student_shadowed < 0.1 * v.reference_shadowed) {
            _sl_say(out, "no shadows at all: %s in shadow_lookup.glsl returns 1.0 everywhere — not implemented "
                         "(TODO lab2.5/lab2.6), or every point taken for outside the light's frustum?",
                    c->params.compare == SL_COMPARE_HARDWARE ? "shadow_compare_hardware()" : "shadow_compare_manual()");
        } else if (has_shadows && v.missing_shadow > 0.3 && v.extra_shadow > 0.2) {
            _sl_say(out, "lit and shadowed are swapped (%.0f%% of shadows lit, %.0f%% of lit pixels shadowed): is the "
                         "comparison inverted?", 100 * v.missing_shadow, 100 * v.extra_shadow);
        } else if (v.extra_shadow > 0.5) {
            _sl_say(out, "almost everything is in shadow (%.0f%% of lit pixels): is the comparison inverted, the depth "
                         "map empty, or the shadow coordinate wrong (W, divide)?", 100 * v.extra_shadow);
        } else {
            _sl_say(out, "shadows differ from the reference on %.1f%% of pixels (allowed %.1f%%): %.0f%% of the "
                         "reference's shadow is missing, %.1f%% of its lit area is shadowed",
                    100 * st.failing_fraction, 100 * k->fail_fraction, 100 * v.missing_shadow, 100 * v.extra_shadow);
        }
    }
    if (!said)
        _sl_say(out, "the image differs from the reference on %.1f%% of pixels (allowed %.1f%%)",
                100 * st.failing_fraction, 100 * k->fail_fraction);
    if (st.nan_pixels) _sl_append(out, "; %ld pixels are NaN (a division by zero?)", st.nan_pixels);
    if (k->hint[0]) _sl_append(out, ". Hint: %s", k->hint);
}

void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    if (ref->needed && !ref->loaded) {
        out->reference_problem = true;
        _sl_say(out, "%s", ref->error);
        return;
    }
    if (!r->finished && !(r->capture_count > 0 && !r->signal && !r->timed_out && !r->error[0])) {
        _sl_explain_run_failure(r, out);
        return;
    }
    switch (k->kind) {
    case SL_CHECK_FBO: _sl_check_fbo(c, r, out); break;
    case SL_CHECK_DEPTH_MAP: _sl_check_depth(c, k, r, ref, out); break;
    case SL_CHECK_MATRICES: _sl_check_matrices(c, k, r, ref, out); break;
    case SL_CHECK_VISIBILITY:
    case SL_CHECK_IMAGE: _sl_check_image(c, k, r, ref, out); break;
    default: _sl_say(out, "unknown check kind"); break;
    }
    if (out->passed) {
        out->points = k->points;
        out->message[0] = '\0';
    }
}
