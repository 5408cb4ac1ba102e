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
#include "sl_files.h"
#include "sl_json.h"

/* Frames taking this many times the solutions' CPU time (and this many
 * seconds more) run a loop that does not end: far beyond what another
 * machine or a slower but correct implementation explains. */
#define _SL_SLOW_FACTOR 50.0
#define _SL_SLOW_MARGIN 0.1

/* The TODO tags a stub's message points to. */
static const struct { const char *function, *todo, *file; } _sl_stubs[] = {
    {"lab1_create_shadow_map", "TODO(lab1.1), TODO(lab1.2)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab1_begin_depth_pass", "TODO(lab1.3)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab2_light_view", "TODO(lab2.1)", "labs/lab2_projective/lab2.c"},
    {"lab2_light_projection", "TODO(lab2.2)", "labs/lab2_projective/lab2.c"},
    {"lab2_shadow_matrix", "TODO(lab2.3)", "labs/lab2_projective/lab2.c"},
    {"lab3_depth_pass_state", "TODO(lab3.1)", "labs/lab3_bias/lab3.c"},
    {"lab3_second_depth_state", "TODO(lab3.4), the optional extension,", "labs/lab3_bias/lab3.c"},
    {"lab4_configure_shadow_texture", "TODO(lab4.1)", "labs/lab4_pcf/lab4.c"},
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

/* Adds a case's hint after the message. */
static void _sl_append_hint(sl_check_result *out, const char *hint) {
    if (!hint[0]) return;
    size_t n = strlen(out->message);
    bool ends_sentence = n > 0 && strchr(".?!", out->message[n - 1]) != NULL;
    _sl_append(out, "%s Hint: %s", ends_sentence ? "" : ".", hint);
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
    if (r->interrupted) {
        _sl_say(out, "not graded: the grader was stopped before this case finished");
    } else if (r->protocol_error[0]) {
        _sl_say(out, "the case's results broke the rules of the grader's channel (%s): nothing it sent counts. "
                     "Lab code must not write to file descriptor 3 or replace the process", r->protocol_error);
    } else if (r->timed_out) {
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
    /* What the process printed last often says why (a library missing, an assertion). */
    if (!r->interrupted && !r->protocol_error[0] && !r->error[0] && r->output_tail[0]) {
        const char *end = r->output_tail + strlen(r->output_tail);
        while (end > r->output_tail && end[-1] == '\n') end--;
        const char *start = end;
        while (start > r->output_tail && start[-1] != '\n') start--;
        if (end > start) _sl_append(out, "; its output ended with: %.*s", (int)(end - start > 300 ? 300 : end - start), start);
    }
}

/* ---- references ---- */

/* A reference must fit its case: an image of the camera's size, a depth map of the map's. */
static bool _sl_reference_fits(sl_reference *ref, const sl_case *c, const sl_check *k) {
    const sl_image *img = &ref->image;
    int w = c->width, h = c->height, channels = k->kind == SL_CHECK_IMAGE ? 3 : 1;
    if (k->kind == SL_CHECK_DEPTH_MAP) w = h = c->params.shadow_map_size;
    if (img->width == w && img->height == h && img->channels == channels) return true;
    snprintf(ref->error, sizeof ref->error, "reference does not fit its case: %s is %dx%dx%d, the case makes %dx%dx%d",
             ref->path, img->width, img->height, img->channels, w, h, channels);
    sl_image_free(&ref->image);
    return false;
}

void sl_reference_load(sl_reference *ref, const char *dir, const sl_manifest *manifest, const char *manifest_error,
                       const sl_case *c, const sl_check *k) {
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
        char json_err[600] = "";
        cJSON *json = sl_json_load_file(ref->path, "reference", json_err, sizeof json_err);
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
        if (!ok && !json_err[0])
            snprintf(json_err, sizeof json_err, "%s: expected light_view, light_projection, shadow_matrix: 16 numbers each", ref->path);
        if (!ok) {
            snprintf(ref->error, sizeof ref->error, "reference corrupt: %s", json_err);
            return;
        }
        ref->number_count = 48;
    } else {
        char err[512];
        if (!sl_image_read(ref->path, &ref->image, err, sizeof err)) {
            snprintf(ref->error, sizeof ref->error, "reference corrupt: %s", err);
            return;
        }
        if (!_sl_reference_fits(ref, c, k)) return;
    }
    char why[1500];
    if (!manifest) {
        snprintf(ref->error, sizeof ref->error, "references cannot be verified: %s", manifest_error);
        sl_image_free(&ref->image);
        return;
    }
    if (!sl_manifest_verify(manifest, c->name, file, ref->path, why, sizeof why)) {
        snprintf(ref->error, sizeof ref->error, "%s", why);
        sl_image_free(&ref->image);
        return;
    }
    ref->loaded = true;
}

void sl_reference_free(sl_reference *ref) { sl_image_free(&ref->image); }

bool sl_reference_write(const char *dir, sl_manifest *manifest, const sl_case *c, const sl_check *k,
                        const sl_case_result *r, char *err, size_t err_size) {
    const char *file = sl_check_reference_file(k->kind);
    if (!file) return true;
    char folder[1100], path[1200];
    snprintf(folder, sizeof folder, "%s/%s", dir, c->name);
    if (!sl_mkdirs(folder)) {
        snprintf(err, err_size, "%s: cannot create the folder", folder);
        return false;
    }
    snprintf(path, sizeof path, "%s/%s", folder, file);
    const char *capture = sl_check_capture_name(k->kind);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        snprintf(err, err_size, "%s: the solutions captured no %s (%s)", c->name, capture,
                 r->not_implemented_count ? "a stub is not implemented" : r->error[0] ? r->error : "see the case");
        return false;
    }
    bool ok;
    if (k->kind == SL_CHECK_MATRICES) {
        static const char *keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        sl_atomic_file f;
        if (!sl_atomic_open(&f, path, err, err_size)) return false;
        fprintf(f.f, "{\n");
        for (int m = 0; m < 3; m++) {
            fprintf(f.f, "  \"%s\": [", keys[m]);
            for (int i = 0; i < 16; i++) fprintf(f.f, "%s%.9g", i ? ", " : "", cap->numbers[m * 16 + i]);
            fprintf(f.f, "]%s\n", m < 2 ? "," : "");
        }
        fprintf(f.f, "}\n");
        ok = sl_atomic_commit(&f, err, err_size);
    } else {
        ok = sl_atomic_write_image(path, &cap->image, err, err_size);
    }
    return ok && sl_manifest_record(manifest, c->name, file, path, r->render_seconds, err, err_size);
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

/* The GLSL function that computes visibility for this case, and its TODO. */
static void _sl_lookup_function(const sl_case *c, const char **function, const char **todo) {
    static const char *const filters[SL_FILTER_MODE_COUNT][2] = {
        {"shadow_compare_manual() (lab 2)", "lab2.5"}, {"pcf_hardware()", "lab4.2"}, {"pcf_grid()", "lab4.3"},
        {"pcf_poisson()", "lab4.4"}, {"pcss()", "lab4.5"},
    };
    if (c->lab >= 4) {
        *function = filters[c->params.filter.mode][0];
        *todo = filters[c->params.filter.mode][1];
    } else if (c->lab == 3 && c->params.bias.mode == SL_BIAS_MIDPOINT) {
        *function = "midpoint_compare()";
        *todo = "lab3.5";
    } else if (c->params.compare == SL_COMPARE_HARDWARE) {
        *function = "shadow_compare_hardware()";
        *todo = "lab2.6";
    } else {
        *function = "shadow_compare_manual()";
        *todo = "lab2.5";
    }
}

/* Chamfer distance (in pixels) from every pixel to the nearest pixel where `seed` is set. */
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

static bool _sl_explain_lab3(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                             sl_check_result *out) {
    _sl_artifacts a = _sl_measure_artifacts(s, t, mask);
    sl_bias_mode mode = c->params.bias.mode;
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
        _sl_say(out, "shadow acne on %.0f%% of lit surfaces: bias too small or missing — %s", 100 * a.acne,
                tips[mode] ? tips[mode] : "compare with a bias");
        return true;
    }
    if (a.missing > 0.02 && a.gap_px >= 1.5f) {
        static const char *const tips[SL_BIAS_MODE_COUNT] = {
            [SL_BIAS_SLOPE_SCALED] = "is the slope term clamped to max_bias?",
            [SL_BIAS_POLYGON_OFFSET] = "are factor and units passed in the right order?",
            [SL_BIAS_NORMAL_OFFSET] = "the offset is texels * texel size * (1 - N.L), along the normal",
            [SL_BIAS_FRONT_FACE_CULLING] = "with culling on, the lookup needs no extra bias",
        };
        _sl_say(out, "shadows detached from their casters by about %.0f px (%.0f%% of the reference's shadow missing): "
                     "bias too large (Peter Panning)%s%s",
                a.gap_px, 100 * a.missing, tips[mode] ? " — " : "", tips[mode] ? tips[mode] : "");
        return true;
    }
    return false;
}

static bool _sl_explain_lab4(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                             sl_check_result *out) {
    long n = (long)t->width * t->height, soft_ref = 0, soft_stu = 0, lit = 0, lit_exact = 0, penumbra = 0;
    long histogram[256] = {0}, core = 0, core_kept = 0;
    double lit_sum = 0, pen_s = 0, pen_t = 0;
    for (long i = 0; i < n; i++) {
        if (mask && mask->data[i] < 0.5f) continue;
        float vs = s->data[i], vt = t->data[i];
        soft_ref += vt > 0.1f && vt < 0.9f;
        soft_stu += vs > 0.1f && vs < 0.9f;
        if (vt >= 0.99f) {
            lit++;
            lit_sum += vs;
            lit_exact += vs >= 0.99f;
            histogram[(int)(glm_clamp(vs, 0, 1) * 255.0f + 0.5f)]++;
        }
        if (vt <= 0.01f) {
            core++;
            core_kept += vs <= 0.01f;
        }
        if (vt > 0.1f && vt < 0.9f) {
            penumbra++;
            pen_s += vs;
            pen_t += vt;
        }
    }
    double lit_mean = lit ? lit_sum / (double)lit : 1;
    long mode_count = 0;
    int mode = 255;
    for (int i = 0; i < 256; i++)
        if (histogram[i] > mode_count) {
            mode_count = histogram[i];
            mode = i;
        }
    const char *fn, *todo;
    _sl_lookup_function(c, &fn, &todo);
    /* Weights summing to less than 1 scale every lit pixel to one value; a
     * kernel reaching too far darkens them unevenly (it compares the receiver
     * with depths of the surface far away: self-shadowing). */
    bool cores_intact = core_kept >= core * 9 / 10; /* too few weights keep 0 at 0; a wide kernel does not */
    if (lit_mean < 0.93 && lit_exact < lit / 5 && mode_count > lit * 7 / 10 && cores_intact) {
        _sl_say(out, "lit surfaces are too dark (visibility %.2f where the reference is fully lit): the kernel's "
                     "weights sum to less than 1 — divide by the number of samples in %s", mode / 255.0, fn);
    } else if (lit_mean < 0.93) {
        _sl_say(out, "lit surfaces are darkened (mean visibility %.2f where the reference is fully lit): the "
                     "kernel reaches too far and compares with distant depths — are the sample offsets scaled by the "
                     "texel size, 1.0 / textureSize(map, 0)?", lit_mean);
    } else if (c->params.filter.mode == SL_FILTER_HARDWARE && soft_ref > n / 500 && soft_stu < soft_ref / 4) {
        _sl_say(out, "hard edges where the 2x2 hardware filter blends: the depth texture needs GL_LINEAR filtering "
                     "with compare mode on (lab4_configure_shadow_texture, TODO lab4.1)");
    } else if (penumbra > n / 1000 && pen_s - pen_t > 0.12 * (double)penumbra) {
        _sl_say(out, "penumbrae too bright (mean %.2f, reference %.2f): the kernel's weights sum to more than 1 — "
                     "divide by the number of samples in %s", pen_s / (double)penumbra, pen_t / (double)penumbra, fn);
    } else if (c->params.filter.mode == SL_FILTER_PCSS && soft_ref > n / 200 && soft_stu < soft_ref / 2) {
        _sl_say(out, "penumbrae too narrow for this light (%.1f%% of pixels in penumbra, reference %.1f%%): does pcss() "
                     "filter with the width from the blocker search, w = (d_receiver - d_blocker) * w_light / d_blocker "
                     "(TODO lab4.5)?", 100.0 * (double)soft_stu / (double)n, 100.0 * (double)soft_ref / (double)n);
    } else if (soft_ref > n / 200 && soft_stu < soft_ref / 4) {
        _sl_say(out, "hard edges where soft ones are expected (%.1f%% of pixels in penumbra, reference %.1f%%): are "
                     "you filtering depths instead of comparison results (Reeves 1987)? Average the 0/1 results of "
                     "the comparisons in %s", 100.0 * (double)soft_stu / (double)n, 100.0 * (double)soft_ref / (double)n, fn);
    } else if (soft_stu > 3 * soft_ref && soft_stu > n / 50) {
        _sl_say(out, "the kernel is far too wide (%.1f%% of pixels in penumbra, reference %.1f%%): are the sample "
                     "offsets scaled by the texel size, 1.0 / textureSize(map, 0)?",
                100.0 * (double)soft_stu / (double)n, 100.0 * (double)soft_ref / (double)n);
    } else {
        return false;
    }
    return true;
}

static void _sl_check_image(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            sl_check_result *out) {
    const char *capture = sl_check_capture_name(k->kind);
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
    if (_sl_explain_missing(c, r, out)) return; /* the hint is about a mistake, not a missing stub */
    bool said = false;
    if (k->kind == SL_CHECK_VISIBILITY) {
        sl_visibility_stats v = sl_visibility_compare(s, t);
        const sl_capture *mask = sl_result_capture(r, "lit_mask");
        bool has_shadows = v.reference_shadowed > 0.005;
        const char *fn, *todo;
        _sl_lookup_function(c, &fn, &todo);
        said = true;
        /* On surfaces facing the light when the mask is there: surfaces facing
         * away are dark in both images and would hide a missing shadow. */
        double ref_shadowed = v.reference_shadowed, stu_shadowed = v.student_shadowed;
        if (mask) {
            long facing = 0, ref_dark = 0, stu_dark = 0;
            for (long i = 0; i < (long)t->width * t->height; i++) {
                if (mask->image.data[i] < 0.5f) continue;
                facing++;
                ref_dark += t->data[i] < 0.5f;
                stu_dark += !(s->data[i] >= 0.5f);
            }
            ref_shadowed = facing ? (double)ref_dark / (double)facing : 0;
            stu_shadowed = facing ? (double)stu_dark / (double)facing : 0;
            has_shadows = ref_shadowed > 0.005;
        }
        if (has_shadows && stu_shadowed < 0.1 * ref_shadowed) {
            _sl_say(out, "no shadows at all: %s returns 1.0 everywhere — not implemented (TODO %s), or every point "
                         "taken for outside the light's frustum?", fn, todo);
        } else if (c->lab == 3 && mask && _sl_explain_lab3(c, s, t, &mask->image, out)) {
        } else if (c->lab >= 4 && _sl_explain_lab4(c, s, t, mask ? &mask->image : NULL, out)) {
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
    _sl_append_hint(out, k->hint);
}

/* Width in pixels of the soft part (0.1 < v < 0.9) along a probe line. */
static float _sl_penumbra_width(const sl_image *img, const sl_probe *p) {
    float dx = p->to[0] - p->from[0], dy = p->to[1] - p->from[1];
    float length = sqrtf(dx * dx + dy * dy);
    int steps = (int)ceilf(length * 4);
    int soft = 0;
    for (int i = 0; i <= steps; i++) {
        float f = steps ? (float)i / (float)steps : 0;
        int x = (int)lroundf(p->from[0] + f * dx), y = (int)lroundf(p->from[1] + f * dy);
        if (x < 0 || y < 0 || x >= img->width || y >= img->height) continue;
        float v = sl_image_pixel(img, x, y)[0];
        soft += v > 0.1f && v < 0.9f;
    }
    return steps ? (float)soft * length / (float)steps : 0;
}

static void _sl_check_penumbra(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "visibility");
    if (!cap) {
        if (!_sl_explain_missing(c, r, out)) _sl_say(out, "no visibility image was captured");
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    if (s->width != t->width || s->height != t->height) {
        _sl_say(out, "the image is %dx%d, the reference %dx%d", s->width, s->height, t->width, t->height);
        return;
    }
    float ws[SL_CHECK_MAX_PROBES], wt[SL_CHECK_MAX_PROBES];
    bool ok = true;
    char widths[512] = "";
    for (int i = 0; i < k->probe_count; i++) {
        ws[i] = _sl_penumbra_width(s, &k->probes[i]);
        wt[i] = _sl_penumbra_width(t, &k->probes[i]);
        ok &= fabsf(ws[i] - wt[i]) <= fmaxf(2.0f, (float)k->threshold * wt[i]);
        snprintf(widths + strlen(widths), sizeof widths - strlen(widths), "%s%s %.0f px (reference %.0f)",
                 i ? ", " : "", k->probes[i].name, ws[i], wt[i]);
    }
    if (ok) {
        out->passed = true;
        return;
    }
    if (_sl_explain_missing(c, r, out)) return;
    int last = k->probe_count - 1;
    float most = 0, least = 1e9f;
    for (int i = 0; i < k->probe_count; i++) {
        most = fmaxf(most, ws[i] / fmaxf(wt[i], 1));
        least = fminf(least, ws[i]);
    }
    const char *fn, *todo;
    _sl_lookup_function(c, &fn, &todo);
    if (last > 0 && wt[0] < wt[last] && ws[0] > ws[last] + 1)
        _sl_say(out, "penumbra formula inverted: wide at the contact, narrow far from it (%s) — w = (d_receiver - "
                     "d_blocker) * w_light / d_blocker (TODO %s)", widths, todo);
    else if (least <= 1 && wt[last] >= 3)
        _sl_say(out, "hard edges where soft ones are expected (%s): %s filters depths instead of comparison results, "
                     "or finds no blockers?", widths, fn);
    else if (most > 2.5f)
        _sl_say(out, "penumbrae far too wide (%s): are the offsets scaled by the texel size, and the penumbra projected "
                     "onto the map (* near / d_receiver)?", widths);
    else if (last > 0 && wt[last] > 1.5f * wt[0] && ws[last] <= 1.2f * ws[0])
        _sl_say(out, "no contact hardening: the penumbra does not widen away from the contact (%s) — does the filter "
                     "radius come from the blocker search (TODO %s)?", widths, todo);
    else
        _sl_say(out, "penumbra widths differ from the reference: %s", widths);
    _sl_append_hint(out, k->hint);
}

void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    out->bonus = k->bonus;
    if (ref->needed && !ref->loaded) {
        out->reference_problem = true;
        _sl_say(out, "%s", ref->error);
        return;
    }
    if (!r->finished && !(r->capture_count > 0 && !r->signal && !r->timed_out && !r->error[0])) {
        _sl_explain_run_failure(r, out);
        return;
    }
    /* The software renderer cuts endless shader loops short, so such a case
     * can end with a plausible picture, only many times slower (a GPU would
     * hang instead). */
    double usual = c->reference_render_seconds;
    if (usual > 0 && r->render_seconds > fmax(_SL_SLOW_FACTOR * usual, usual + _SL_SLOW_MARGIN)) {
        _sl_say(out, "a frame took %.2f s of CPU time where the solutions' takes %.3f s (%.0fx): a shader loop that "
                     "does not end? The software renderer stops long loops, so the picture may even look right; a GPU "
                     "would hang", r->render_seconds, usual, r->render_seconds / usual);
        return;
    }
    /* A stub of this lab (or an earlier one) fails the check even if the picture
     * happens to match: the framework's stand-in must never earn the points. */
    for (int i = 0; i < r->not_implemented_count; i++)
        if (_sl_function_lab(r->not_implemented[i]) <= c->lab && _sl_explain_missing(c, r, out)) return;
    switch (k->kind) {
    case SL_CHECK_FBO: _sl_check_fbo(c, r, out); break;
    case SL_CHECK_DEPTH_MAP: _sl_check_depth(c, k, r, ref, out); break;
    case SL_CHECK_MATRICES: _sl_check_matrices(c, k, r, ref, out); break;
    case SL_CHECK_VISIBILITY:
    case SL_CHECK_IMAGE: _sl_check_image(c, k, r, ref, out); break;
    case SL_CHECK_PENUMBRA: _sl_check_penumbra(c, k, r, ref, out); break;
    default: _sl_say(out, "unknown check kind"); break;
    }
    if (out->passed) {
        out->points = k->points;
        out->message[0] = '\0';
    }
}
