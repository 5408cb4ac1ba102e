#define _POSIX_C_SOURCE 200809L
#include "sl_case_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_capture.h"
#include "sl_case.h"
#include "sl_compare.h"
#include "sl_context.h"
#include "sl_platform.h"
#include "sl_serve.h"
#include <cjson/cJSON.h>
#include "sl_overlay.h"
#include "sl_renderer.h"
#include "sl_case_view_draw.h"
#include "sl_case_view_pictures.h"
#include "sl_case_view_state.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#ifndef SL_GRADER_DIR
#define SL_GRADER_DIR "grader"
#endif

/* An image as RGB texels for a panel, bottom row first (GL's order), in the
 * check's colours: cascade numbers as the viewer's K key colours them, the two
 * moments as red and green; the difference panel (kind < 0) as it is. */
static void _sl_upload(_sl_case_view *v, int panel, const sl_image *img, int kind) {
    static const float no_cascade[3] = {0.3f, 0.3f, 0.3f};
    GLuint texture = v->textures[panel];
    v->panel_size[panel][0] = img->width;
    v->panel_size[panel][1] = img->height;
    /* depths and distances: black at the picture's nearest, white at its farthest */
    float lo = 0, scale = 1;
    v->stretched[panel] = kind >= 0 && _sl_case_view_is_distance((sl_check_kind)kind) &&
                          _sl_case_view_value_range(img, (sl_check_kind)kind, v->range[panel]);
    if (v->stretched[panel]) {
        lo = v->range[panel][0];
        scale = v->range[panel][1] > lo ? 1.0f / (v->range[panel][1] - lo) : 0;
    }
    float *rgb = malloc(sizeof(float) * 3 * (size_t)img->width * (size_t)img->height);
    if (!rgb) return;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            const float *p = sl_image_pixel(img, x, img->height - 1 - y);
            float *q = rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
            if (kind == SL_CHECK_CASCADE_INDEX) {
                int i = (int)floorf(p[0] + 0.5f); /* -1: no cascade */
                const float *c = i >= 0 && i < SL_MAX_CASCADES ? sl_cascade_colours[i] : no_cascade;
                for (int k = 0; k < 3; k++) q[k] = c[k];
            } else if (v->stretched[panel]) {
                float g = scale > 0 ? (p[0] - lo) * scale : p[0]; /* one value throughout: as it is */
                q[0] = q[1] = q[2] = g > 1 ? 1 : g; /* a cleared texel: white */
            } else if (img->channels == 2) {
                q[0] = p[0], q[1] = p[1], q[2] = 0;
            } else {
                for (int c = 0; c < 3; c++) q[c] = p[img->channels >= 3 ? c : 0];
            }
        }
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, img->width, img->height, 0, GL_RGB, GL_FLOAT, rgb);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    free(rgb);
}

/* Renders the case as the grader's runner does, and takes the same capture. */
static bool _sl_render_student(_sl_case_view *v, sl_image *out) {
    const sl_case *c = &v->c;
    sl_scene scene = c->scene;
    sl_render_params p = c->params;
    sl_check_kind kind = v->check->kind;
    p.output = kind == SL_CHECK_IMAGE ? SL_OUTPUT_SHADED : kind == SL_CHECK_CASCADE_INDEX ? SL_OUTPUT_CASCADE_INDEX
                                                                                       : SL_OUTPUT_VISIBILITY;
    if (kind == SL_CHECK_MOMENTS) p.vsm.blur_radius = 0; /* the moments pass alone, as the runner takes it */
    for (int f = 0; f < c->frame_count; f++) {
        scene.light = c->frame_lights[f];
        if (c->camera_path) { /* lab 6: the cascades follow the path, the picture stays */
            p.cascades.use_camera = true;
            p.cascades.camera = c->frame_cameras[f];
        }
        sl_renderer_draw(&v->renderer, &scene, &p, v->target_fbo, c->width, c->height);
        if (kind == SL_CHECK_FLICKER) { /* every frame, stacked top to bottom, as the runner sends them */
            if (f == 0) *out = sl_image_alloc(c->width, c->height * c->frame_count, 1);
            sl_image frame;
            if (out->data && sl_capture_framebuffer(v->target_fbo, c->width, c->height, 1, &frame)) {
                memcpy(out->data + (size_t)f * (size_t)c->width * (size_t)c->height, frame.data,
                       sizeof(float) * (size_t)c->width * (size_t)c->height);
                sl_image_free(&frame);
            }
        }
    }
    if (kind == SL_CHECK_FLICKER) return out->data != NULL;
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    if (_sl_case_view_is_map(kind)) {
        char err[256];
        bool ok = false;
        if (kind == SL_CHECK_DEPTH_MAP)
            ok = info->shadow_map_ready && sl_capture_depth_texture(info->shadow_map.depth_texture, out, err, sizeof err);
        else if (kind == SL_CHECK_CUBE_FACE)
            ok = info->cube_map_ready && sl_capture_cube_face(info->cube_map.depth_cube, v->check->face, out, err, sizeof err);
        else
            ok = info->moments_ready && sl_vsm_capture_moments(info->moments_target.moments[0], out, err, sizeof err);
        if (!ok) { /* nothing drawn yet: black, the reference's size */
            *out = sl_image_alloc(v->reference.width, v->reference.height, v->reference.channels);
            return false;
        }
        return true;
    }
    return sl_capture_framebuffer(v->target_fbo, c->width, c->height, kind == SL_CHECK_IMAGE ? 3 : 1, out);
}

/* The surfaces facing the light, where the runner captures them for this check (sl_check_captures says
 * when: the case decides, the same for the runner and here). */
static bool _sl_render_lit_mask(_sl_case_view *v, sl_image *out) {
    const sl_case *c = &v->c;
    if (!(sl_check_captures(c, v->check) & 1u << SL_CAPTURE_LIT_MASK)) return false;
    sl_scene scene = c->scene;
    sl_render_params p = c->params;
    scene.light = c->frame_lights[c->frame_count > 0 ? c->frame_count - 1 : 0];
    p.output = SL_OUTPUT_LIT_MASK;
    sl_renderer_draw(&v->renderer, &scene, &p, v->target_fbo, c->width, c->height);
    return sl_capture_framebuffer(v->target_fbo, c->width, c->height, 1, out);
}

/* The check's verdict on these pictures, counted as the grader counts it: the
 * failing pixels (sl_compare's neighbourhood and the check's threshold), NaN,
 * the mean difference where the case bounds it, per channel for the moments,
 * and for visibility the reference's shadow that is lost. Says it in
 * v->summary and v->criterion; `diff` receives the difference picture. */
static void _sl_judge(_sl_case_view *v, const sl_image *student, sl_image *diff) {
    const sl_check *k = v->check;
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    char missing[160] = "";
    if (info->not_implemented_count)
        snprintf(missing, sizeof missing, "; not implemented: %s", info->not_implemented[0]);
    bool moments = k->kind == SL_CHECK_MOMENTS || k->kind == SL_CHECK_MOMENTS_BLURRED;
    int channels = moments && student->channels == 2 && v->reference.channels == 2 ? 2 : 1;
    sl_compare_stats st[2];
    bool size_mismatch = false, passes = true;
    double failing = 0, mean = 0;
    long nan_pixels = 0;
    for (int ch = 0; ch < channels; ch++) {
        sl_image a = channels == 2 ? _sl_case_view_channel(student, ch) : *student;
        sl_image b = channels == 2 ? _sl_case_view_channel(&v->reference, ch) : v->reference;
        sl_image d = {0};
        st[ch] = sl_compare_images(&a, &b, k->threshold, &d);
        if (channels == 2) {
            sl_image_free(&a);
            sl_image_free(&b);
        }
        /* the first channel's difference, or the first that fails (as the grader's report shows) */
        bool fails = st[ch].failing_fraction > k->fail_fraction || st[ch].nan_pixels > 0;
        if (!diff->data || (fails && passes)) {
            sl_image_free(diff);
            *diff = d;
        } else {
            sl_image_free(&d);
        }
        size_mismatch |= st[ch].size_mismatch;
        bool ok = !fails && (k->mean_tolerance <= 0 || st[ch].mean_difference <= k->mean_tolerance);
        passes &= ok;
        if (st[ch].failing_fraction > failing) failing = st[ch].failing_fraction;
        if (st[ch].mean_difference > mean) mean = st[ch].mean_difference;
        nan_pixels += st[ch].nan_pixels;
    }
    if (size_mismatch) {
        snprintf(v->summary, sizeof v->summary, "%s / %s: yours is %dx%d, the reference %dx%d: fails", v->c.name,
                 k->name, student->width, student->height, v->reference.width, v->reference.height);
        snprintf(v->criterion, sizeof v->criterion, "criterion: the same size as the reference");
        return;
    }
    /* visibility: the reference's shadow may not be lost, whatever the pixel count */
    char lost_text[200] = "";
    if (k->kind == SL_CHECK_VISIBILITY) {
        sl_image mask = {0};
        bool have_mask = _sl_render_lit_mask(v, &mask);
        long shadowed = 0;
        double lost = sl_visibility_shadow_lost(student, &v->reference, have_mask ? &mask : NULL, &shadowed);
        bool lost_fails = shadowed >= SL_VISIBILITY_MIN_SHADOW_PIXELS && lost > SL_VISIBILITY_MAX_SHADOW_LOST;
        passes &= !lost_fails;
        snprintf(lost_text, sizeof lost_text, "; at most %.0f%% of the reference's shadow lost, where it has %d or "
                 "more pixels (here %.1f%% of %ld lost)", 100 * SL_VISIBILITY_MAX_SHADOW_LOST,
                 SL_VISIBILITY_MIN_SHADOW_PIXELS, 100 * lost, shadowed);
        sl_image_free(&mask);
    }
    char figures[200], allowed_share[16];
    sl_criterion_percent(k->fail_fraction, allowed_share, sizeof allowed_share); /* as the grader prints it */
    if (channels == 2)
        snprintf(figures, sizeof figures, "%.2f%% of pixels differ (depth %.2f%%, depth squared %.2f%%; allowed %s%% "
                 "each)", 100 * failing, 100 * st[0].failing_fraction, 100 * st[1].failing_fraction, allowed_share);
    else
        snprintf(figures, sizeof figures, "%.2f%% of pixels differ (allowed %s%%)", 100 * failing, allowed_share);
    char extra[200] = "";
    if (k->kind == SL_CHECK_PENUMBRA || k->kind == SL_CHECK_BLEEDING) {
        snprintf(v->summary, sizeof v->summary, "%s / %s: %.2f%% of pixels differ from the reference's by more than "
                 "%g: for the eye, not the grade%s", v->c.name, k->name, 100 * failing, k->threshold, missing);
        if (k->kind == SL_CHECK_PENUMBRA)
            snprintf(v->criterion, sizeof v->criterion, "criterion: the penumbra widths along the case's %d probe "
                     "lines, each within %g of the reference's (shadowlab-grade --case %s gives the verdict)",
                     k->probe_count, k->threshold, v->c.name);
        else
            snprintf(v->criterion, sizeof v->criterion, "criterion: light bleeding in the reference's umbra, with the "
                     "reduction (amount %.2f) and without it (shadowlab-grade --case %s gives the verdict)",
                     (double)v->c.params.vsm.bleeding, v->c.name);
        return;
    }
    if (k->mean_tolerance > 0)
        snprintf(extra, sizeof extra, "; mean difference at most %g (here %.4f)", k->mean_tolerance, mean);
    snprintf(v->summary, sizeof v->summary, "%s / %s: %s: %s%s%s", v->c.name, k->name, figures,
             passes ? "passes" : "fails", nan_pixels ? ", NaN pixels" : "", missing);
    snprintf(v->criterion, sizeof v->criterion, "criterion: a pixel differs when no pixel of the other picture's "
             "%dx%d neighbourhood is within %g of it%s (both ways); no NaN%s%s",
             2 * SL_COMPARE_RADIUS + 1, 2 * SL_COMPARE_RADIUS + 1, k->threshold, channels == 2 ? ", per channel" : "",
             extra, lost_text);
}

/* Flicker's verdict as the grader's (grader/diagnose/lab6.c): the share of the
 * world-fixed receivers that change between lit and shadowed from one frame
 * to the next (sl_flicker_measure, on the solutions' lit mask), the shadows
 * kept, the lit surfaces lit. */
static void _sl_judge_flicker(_sl_case_view *v, const sl_image *student) {
    const sl_check *k = v->check;
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    char allowed[16], kept[16], lit[16];
    sl_criterion_percent(k->threshold, allowed, sizeof allowed);
    sl_criterion_percent(SL_FLICKER_MIN_SHADOW_KEPT, kept, sizeof kept);
    sl_criterion_percent(SL_LIT_MAX_LOST, lit, sizeof lit);
    snprintf(v->criterion, sizeof v->criterion, "criterion: at most %s%% of the receivers (surfaces facing the light) "
             "change per frame; in shadow at least %s%% as often as the reference; at most %s%% of its lit pixels dark",
             allowed, kept, lit);
    if (!v->lit_mask.data) {
        snprintf(v->summary, sizeof v->summary, "%s / %s: no lit mask of the receivers beside the reference: "
                 "nothing to measure on", v->c.name, k->name);
        return;
    }
    sl_flicker yours = sl_flicker_measure(student, &v->lit_mask, v->c.frame_count);
    const sl_flicker *reference = &v->reference_flicker;
    bool passes = yours.score <= k->threshold && sl_flicker_shadows_kept(&yours, reference) &&
                  !sl_visibility_lit_lost(student, &v->reference, &v->lit_mask).failed;
    snprintf(v->summary, sizeof v->summary, "%s / %s: %.3f%% of the world-fixed receiver pixels change per frame "
             "(allowed %s%%, the reference %.3f%%): %s%s%s", v->c.name, k->name, 100 * yours.score,
             allowed, 100 * reference->score, passes ? "passes" : "fails",
             info->not_implemented_count ? "; not implemented: " : "",
             info->not_implemented_count ? info->not_implemented[0] : "");
}

static void _sl_update(_sl_case_view *v) {
    sl_image student = {0}, diff = {0};
    _sl_render_student(v, &student);
    if (v->check->kind == SL_CHECK_FLICKER) {
        _sl_judge_flicker(v, &student);
        sl_image marks = _sl_case_view_flicker_marks(&student, &v->lit_mask, v->c.frame_count);
        sl_image last = _sl_case_view_last_frame(&student, v->c.frame_count), ref_last = _sl_case_view_last_frame(&v->reference, v->c.frame_count);
        /* for the eye: the last frames compared as a visibility check compares them */
        double threshold, fail, epsilon, mean;
        sl_check_kind_defaults(SL_CHECK_VISIBILITY, &threshold, &fail, &epsilon, &mean);
        sl_compare_images(&last, &ref_last, threshold, &diff);
        if (marks.data) _sl_upload(v, _SL_STUDENT, &marks, -1);
        if (diff.data) _sl_upload(v, _SL_DIFF, &diff, -1);
        sl_image_free(&marks);
        sl_image_free(&student);
        sl_image_free(&diff);
        return;
    }
    _sl_judge(v, &student, &diff);
    if (student.data) _sl_upload(v, _SL_STUDENT, &student, v->check->kind);
    if (diff.data && _sl_case_view_is_distance(v->check->kind) && v->stretched[_SL_REFERENCE]) {
        /* the reference under the marks, darkened, in its stretched greys (sl_compare leaves grey where
         * nothing differs: 0.35 of the raw value, nearly black for distances) */
        float lo = v->range[_SL_REFERENCE][0], span = v->range[_SL_REFERENCE][1] - lo;
        for (long i = 0; i < (long)diff.width * diff.height; i++) {
            float *q = diff.data + i * 3;
            if (q[0] != q[1] || q[1] != q[2]) continue; /* a mark */
            float r = v->reference.data[i * v->reference.channels];
            float g = span > 0 && isfinite(r) ? 0.35f * fminf((r - lo) / span, 1) : 0;
            q[0] = q[1] = q[2] = g;
        }
    }
    if (diff.data) _sl_upload(v, _SL_DIFF, &diff, -1);
    sl_image_free(&student);
    sl_image_free(&diff);
}

/* The reference's panel: flicker's frames as what changed along the path. */
static void _sl_upload_reference(_sl_case_view *v) {
    if (v->check->kind != SL_CHECK_FLICKER) {
        _sl_upload(v, _SL_REFERENCE, &v->reference, v->check->kind);
        return;
    }
    /* the receivers: the solutions' lit mask, which the grader measures on too */
    char path[1400], err[1024];
    snprintf(path, sizeof path, "%s/%s/lit_mask.exr", v->references_dir, v->c.name);
    sl_image_free(&v->lit_mask);
    if (!sl_image_read(path, &v->lit_mask, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --case: %s\n", err);
        v->lit_mask = (sl_image){0};
    }
    v->reference_flicker = sl_flicker_measure(&v->reference, &v->lit_mask, v->c.frame_count);
    sl_image marks = _sl_case_view_flicker_marks(&v->reference, &v->lit_mask, v->c.frame_count);
    if (marks.data) _sl_upload(v, _SL_REFERENCE, &marks, -1);
    sl_image_free(&marks);
}

/* Shows check `index` of the shown ones: its reference, and a summary for it. */
static bool _sl_show_check(_sl_case_view *v, int index) {
    char err[1024], file[200], reference[1400];
    const sl_check *k = v->shown[index];
    sl_check_reference_file(k, file, sizeof file);
    snprintf(reference, sizeof reference, "%s/%s/%s", v->references_dir, v->c.name, file);
    sl_image img;
    if (!sl_image_read(reference, &img, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --case: %s\n", err);
        return false;
    }
    sl_image_free(&v->reference);
    v->reference = img;
    v->check = k;
    v->shown_index = index;
    if (v->textures[_SL_REFERENCE]) _sl_upload_reference(v);
    printf("shadowlab: showing check %s (%d of %d): %s\n", k->name, index + 1, v->shown_count, _sl_case_view_legend(k->kind));
    return true;
}

/* The keys, one table: what --help says and what the polling below reads. */
static const struct {
    int key;
    sl_case_view_key about;
} _sl_case_keys[] = {
    {GLFW_KEY_TAB, {"Tab", "yours | reference | difference side by side, or one at a time"}},
    {GLFW_KEY_SPACE, {"Space", "one at a time: yours or the reference"}},
    {GLFW_KEY_D, {"D", "one at a time: the difference"}},
    {GLFW_KEY_C, {"C", "the case's next check with a picture"}},
    {GLFW_KEY_ESCAPE, {"Esc", "quit"}},
};
#define _SL_CASE_KEY_COUNT (int)(sizeof _sl_case_keys / sizeof _sl_case_keys[0])

const sl_case_view_key *sl_case_view_keys(void) {
    static sl_case_view_key keys[_SL_CASE_KEY_COUNT + 1];
    for (int i = 0; i < _SL_CASE_KEY_COUNT; i++) keys[i] = _sl_case_keys[i].about;
    return keys;
}

/* What a key does (a window's, polled below, or a --serve page's). */
static void _sl_case_key(_sl_case_view *v, GLFWwindow *w, int key) {
    switch (key) {
        case GLFW_KEY_C: _sl_show_check(v, (v->shown_index + 1) % v->shown_count); break;
        case GLFW_KEY_TAB: v->side_by_side = !v->side_by_side; break;
        case GLFW_KEY_SPACE:
            v->show_reference = !v->show_reference;
            v->show_diff = false;
            v->side_by_side = false;
            break;
        case GLFW_KEY_D:
            v->show_diff = !v->show_diff;
            v->side_by_side = false;
            break;
        case GLFW_KEY_ESCAPE: if (w) glfwSetWindowShouldClose(w, GLFW_TRUE); break;
        }
}

/* Keys, read by polling. */
static bool _sl_keys(_sl_case_view *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    static int previous[GLFW_KEY_LAST + 1];
    bool changed = false;
    for (int i = 0; i < _SL_CASE_KEY_COUNT; i++) {
        int key = _sl_case_keys[i].key, now = glfwGetKey(w, key);
        bool pressed = now == GLFW_PRESS && previous[key] != GLFW_PRESS;
        previous[key] = now;
        if (!pressed) continue;
        changed = true;
        _sl_case_key(v, w, key);
    }
    return changed;
}

/* --serve's key table for the page: the case view's keys but Esc (a page is
 * closed in the browser), as the viewer's table is sent (sl_viewer_keys.c). */
static char *_sl_case_keys_json(int lab) {
    cJSON *root = cJSON_CreateObject();
    cJSON_AddNumberToObject(root, "lab", lab); /* the page lists the keys before the first frame */
    cJSON *keys = cJSON_AddArrayToObject(root, "keys");
    char code[16];
    for (int i = 0; i < _SL_CASE_KEY_COUNT; i++) {
        if (_sl_case_keys[i].key == GLFW_KEY_ESCAPE) continue;
        cJSON *k = cJSON_CreateObject();
        cJSON_AddNumberToObject(k, "lab", lab);
        cJSON_AddStringToObject(k, "names", _sl_case_keys[i].about.names);
        cJSON_AddStringToObject(k, "label", _sl_case_keys[i].about.names);
        cJSON_AddStringToObject(k, "help", _sl_case_keys[i].about.help);
        cJSON *codes = cJSON_AddArrayToObject(k, "codes"), *c = cJSON_CreateObject();
        cJSON_AddStringToObject(c, "code", sl_serve_key_code(_sl_case_keys[i].key, code));
        cJSON_AddNumberToObject(c, "key", _sl_case_keys[i].key);
        cJSON_AddItemToArray(codes, c);
        cJSON_AddItemToArray(keys, k);
    }
    cJSON_AddArrayToObject(root, "held");
    char *json = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return json;
}

static bool _sl_setup(_sl_case_view *v, const sl_case_view_desc *d, char *err, size_t n) {
    static char path[1200];
    const char *cases = d->cases_dir ? d->cases_dir : SL_GRADER_DIR "/cases";
    const char *refs = d->references_dir ? d->references_dir : SL_GRADER_DIR "/references";
    bool is_path = strchr(d->case_name, '/') || strstr(d->case_name, ".json");
    if (is_path) snprintf(path, sizeof path, "%s", d->case_name);
    else snprintf(path, sizeof path, "%s/%s.json", cases, d->case_name);
    if (!sl_case_load(&v->c, path, err, n)) return false;
    v->references_dir = refs;
    int first = -1;
    bool maps_only = true;
    for (int i = 0; i < v->c.check_count && v->shown_count < _SL_MAX_SHOWN; i++) {
        const sl_check *k = &v->c.checks[i];
        if (!_sl_case_view_has_picture(k->kind)) continue;
        if (d->check_name && strcmp(k->name, d->check_name) == 0) first = v->shown_count;
        maps_only &= _sl_case_view_is_map(k->kind);
        v->shown[v->shown_count++] = k;
    }
    if (v->shown_count == 0) {
        snprintf(err, n, "%s has no picture to show (its checks are probes or numbers): "
                 "run shadowlab-grade --case %s", v->c.name, v->c.name);
        return false;
    }
    if (d->check_name && first < 0) {
        char names[600] = "";
        for (int i = 0; i < v->shown_count; i++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "", v->shown[i]->name);
        snprintf(err, n, "%s has no check with a picture named %s (it has: %s)", v->c.name, d->check_name, names);
        return false;
    }
    for (int i = 0; first < 0 && i < v->shown_count; i++) /* what the camera sees first, then the maps */
        if (v->shown[i]->kind == SL_CHECK_VISIBILITY || v->shown[i]->kind == SL_CHECK_PENUMBRA) first = i;
    if (first < 0) first = 0;
    if (!_sl_show_check(v, first)) {
        snprintf(err, n, "the reference of %s / %s does not load (said above)", v->c.name, v->shown[first]->name);
        return false;
    }
    int panel_w = v->c.width, panel_h = v->c.height;
    if (maps_only) panel_w = panel_h = 384; /* maps alone: square panels, shown scaled */
    v->scale = panel_w * 3 * 2 <= 1800 ? 2 : 1;
    /* under the panels, a band for the summary and the criterion: the font's cell at scale 2 from 800 wide */
    int text_scale = panel_w * v->scale * 3 >= 800 ? 2 : 1;
    v->band = (_SL_BAND_LINES * SL_OVERLAY_CELL_H + 10) * text_scale;
    sl_context_desc cd = {
        .backend = d->headless ? (sl_backend)d->backend : SL_BACKEND_GLFW,
        .width = panel_w * v->scale * 3,
        .height = panel_h * v->scale + v->band,
        .title = "shadowlab",
    };
    v->ctx = sl_context_create(&cd, err, n);
    if (!v->ctx) return false;
    char overlay_err[1024];
    v->overlay = sl_overlay_create(sl_framework_dir(), overlay_err, sizeof overlay_err);
    v->text_scale = text_scale;
    if (v->overlay) {
        sl_overlay_set_scale(v->overlay, text_scale);
        sl_overlay_set_lecture(v->overlay, true); /* white on black: readable on a white picture too */
    }
    else fprintf(stderr, "shadowlab: --case: no labels: %s\n", overlay_err);
    sl_renderer_desc rd = {.labs_dir = d->labs_dir};
    if (!sl_renderer_init(&v->renderer, &rd, err, n) || !sl_renderer_set_scene(&v->renderer, &v->c.scene, err, n))
        return false;
    /* the grader's image size, off screen, in floats as the runner reads it */
    glGenTextures(1, &v->target_texture);
    glBindTexture(GL_TEXTURE_2D, v->target_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, v->c.width, v->c.height, 0, GL_RGBA, GL_FLOAT, NULL);
    glGenRenderbuffers(1, &v->target_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, v->target_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, v->c.width, v->c.height);
    glGenFramebuffers(1, &v->target_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, v->target_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, v->target_texture, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, v->target_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    char vs[SL_PATH_MAX + 32], fs[SL_PATH_MAX + 32];
    snprintf(vs, sizeof vs, "%s/debug_quad.vert", v->renderer.shaders_dir);
    snprintf(fs, sizeof fs, "%s/case_panel.frag", v->renderer.shaders_dir);
    sl_shader_desc sd = {.vertex_path = vs, .fragment_path = fs, .search_dirs = {v->renderer.shaders_dir}};
    if (!sl_program_build(&v->panel_program, &sd, err, n)) return false;
    glGenTextures(_SL_PANELS, v->textures);
    glGenVertexArrays(1, &v->vao);
    _sl_upload_reference(v);
    return true;
}

int sl_case_view_main(const sl_case_view_desc *d) {
    static _sl_case_view v;
    memset(&v, 0, sizeof v);
    v.side_by_side = true;
    char err[8192];
    int status = 0;
    if (!_sl_setup(&v, d, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --case: %s\n", err);
        status = 1;
    } else {
        printf("shadowlab: case %s (%s), lab %d: %s\n", v.c.name, v.c.title, v.c.lab, sl_context_renderer_name());
        GLFWwindow *window = sl_context_window(v.ctx);
        sl_serve *serve = NULL;
        unsigned long keys_acted = 0;
        if (d->serve_port) {
            char *keys = _sl_case_keys_json(v.c.lab);
            sl_serve_desc sd = {.port = d->serve_port, .address = d->serve_address, .hello = keys};
            serve = sl_serve_start(&sd, err, sizeof err);
            cJSON_free(keys);
            if (!serve) {
                fprintf(stderr, "shadowlab: %s\n", err);
                status = 1;
                goto done;
            }
            printf("shadowlab: serving the case view at %s (open it in a browser; Ctrl-C stops)\n", sl_serve_url(serve));
            fflush(stdout);
        }
        if (window) {
            printf("shadowlab: keys:");
            for (int i = 0; i < _SL_CASE_KEY_COUNT; i++)
                if (_sl_case_keys[i].key != GLFW_KEY_C || v.shown_count > 1)
                    printf("%s %s %s", i ? ";" : "", _sl_case_keys[i].about.names, _sl_case_keys[i].about.help);
            printf("\n");
        }
        int rendered = 0;
        double last_reload = 0;
        const char *reported_error = NULL;
        char last_summary[sizeof v.summary] = "";
        while (!sl_context_should_close(v.ctx)) {
            double now = window ? glfwGetTime() : serve ? sl_platform_seconds() : 0;
            if ((window || serve) && now - last_reload > 0.25) {
                last_reload = now;
                bool reloaded = false;
                if (!sl_renderer_reload_changed(&v.renderer, &reloaded, err, sizeof err))
                    fprintf(stderr, "shadowlab: shader reload failed, keeping the previous version:\n%s\n", err);
            }
            _sl_update(&v);
            const sl_frame_info *info = sl_renderer_info(&v.renderer);
            if (info->shader_error != reported_error) {
                reported_error = info->shader_error;
                if (reported_error) fprintf(stderr, "shadowlab: %s\n", reported_error);
            }
            if (strcmp(last_summary, v.summary) != 0) {
                snprintf(last_summary, sizeof last_summary, "%s", v.summary);
                printf("shadowlab: %s\n", v.summary);
                printf("shadowlab: %s\n", v.criterion);
                int bw, bh;
                sl_context_framebuffer_size(v.ctx, &bw, &bh);
                if (!_sl_case_view_band_fits(&v, bw, bh))
                    printf("shadowlab: the summary and criterion are cut short under the panels (%dx%d)\n", bw, bh);
                if (v.stretched[_SL_STUDENT] || v.stretched[_SL_REFERENCE])
                    printf("shadowlab: each picture stretched black to white over its own range: yours %.4f - %.4f, "
                           "the reference %.4f - %.4f\n", (double)v.range[_SL_STUDENT][0],
                           (double)v.range[_SL_STUDENT][1], (double)v.range[_SL_REFERENCE][0],
                           (double)v.range[_SL_REFERENCE][1]);
            }
            if (window && _sl_keys(&v)) {}
            if (serve) { /* the page's keys; drags and the wheel mean nothing here */
                sl_serve_event events[32];
                int count = sl_serve_poll(serve, events, 32);
                for (int i = 0; i < count; i++)
                    for (int k = 0; k < _SL_CASE_KEY_COUNT; k++)
                        if (events[i].kind == SL_SERVE_KEY_DOWN && events[i].key == _sl_case_keys[k].key &&
                            events[i].key != GLFW_KEY_ESCAPE) {
                            _sl_case_key(&v, NULL, events[i].key);
                            keys_acted++;
                        }
            }
            _sl_case_view_title(&v);
            int fw, fh;
            sl_context_framebuffer_size(v.ctx, &fw, &fh);
            _sl_case_view_draw(&v, fw, fh);
            rendered++;
            if (serve) {
                static char text[16384]; /* the labels and the band's summary, in words */
                text[0] = '\0';
                if (v.overlay) sl_overlay_text(v.overlay, text, sizeof text);
                sl_serve_frame_desc fd = {.text = text, .lab = v.c.lab, .keys_acted = keys_acted};
                if (!sl_serve_frame(serve, sl_context_default_framebuffer(v.ctx), fw, fh, &fd, err, sizeof err))
                    fprintf(stderr, "shadowlab: --serve: %s\n", err);
                sl_serve_idle(serve);
            }
            if (d->frames > 0 && rendered >= d->frames) {
                if (d->screenshot) {
                    sl_image shot;
                    glFinish();
                    if (!sl_capture_framebuffer(0, fw, fh, 3, &shot) || !sl_image_write(d->screenshot, &shot, err, sizeof err)) {
                        fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
                        status = 1;
                    } else {
                        printf("shadowlab: saved %s (%dx%d)\n", d->screenshot, fw, fh);
                    }
                    sl_image_free(&shot);
                }
                break;
            }
            sl_context_end_frame(v.ctx);
        }
        sl_serve_stop(serve);
    }
done:
    if (v.ctx) {
        sl_overlay_destroy(v.overlay);
        sl_program_destroy(&v.panel_program);
        sl_renderer_destroy(&v.renderer);
        sl_context_destroy(v.ctx);
    }
    sl_image_free(&v.reference);
    sl_image_free(&v.lit_mask);
    return status;
}
