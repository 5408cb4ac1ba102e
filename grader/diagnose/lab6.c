/* Lab 6's diagnoses: the cascade-index image, the flicker score along a
 * camera path; what lab 6's function probes show together is lab6_verdict.c's. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_probe.h"
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
    /* Pixel by pixel, on surfaces (the reference's index >= 0): how the student's index differs, and where
     * across the picture: a split at the wrong depth moves a border that runs across the whole picture (the
     * splits are planes across the view direction), a choice by distance bends it towards the camera at the
     * sides, so the middle third of the picture hardly differs. */
    long covered = 0, differ = 0, above = 0, below = 0, by_one = 0, nan_pixels = 0, middle = 0;
    for (int y = 0; y < t->height; y++)
        for (int x = 0; x < t->width; x++) {
            long i = (long)y * t->width + x;
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
            middle += 3 * x >= t->width && 3 * x < 2 * t->width;
        }
    double fraction = covered ? (double)differ / (double)covered : 0;
    bool sides = differ > 0 && (double)middle < 0.15 * (double)differ;
    if (covered && differ > 0.9 * covered && by_one > 0.95 * differ && (above > 0.95 * differ || below > 0.95 * differ)) {
        sl_diag_say(out, "the cascade index is off by one on %.0f%% of the surfaces (layer %s where the reference uses i)",
                    100 * fraction, above > below ? "i + 1" : "i - 1");
        sl_diag_cause_in(out, "cascade_index", "cascade_index() must return the FIRST cascade whose far split is beyond the depth: 0..count-1 "
                           "(an off-by-one layer; TODO lab6.4)");
    } else if (differ && above > 0.95 * differ && sides) {
        sl_diag_say(out, "%.1f%% of the surfaces use a farther cascade than the reference's, at the sides of the picture "
                         "only: the cascades' borders bend towards the camera there", 100 * fraction);
        sl_diag_cause_in(out, "cascade_index", "cascades chosen by the distance to the camera (length of the view position), not by view "
                           "depth (-view_position.z): the splits are planes across the view direction (TODO lab6.4)");
    } else if (differ && (above > 0.95 * differ || below > 0.95 * differ)) {
        bool farther = above > below;
        sl_diag_say(out, "%.1f%% of the surfaces use a %s cascade than the reference's, across the whole picture: the "
                         "borders between cascades run where the reference's do not",
                    100 * fraction, farther ? "farther" : "nearer");
        sl_diag_cause_in(out, "lab6_split_distances", "the cascades end %s than the reference's: are the split distances right (lambda, TODO lab6.1), "
                           "and does cascade_index() compare with each cascade's FAR split (TODO lab6.4)?",
                      farther ? "nearer" : "farther out");
    } else {
        sl_diag_say(out, "the cascade index differs from the reference on %.1f%% of the surfaces (allowed %.1f%% of "
                         "pixels)", 100 * fraction, 100 * k->fail_fraction);
        /* no finding of its own: the core lists the candidates (the splits, cascade_index) */
    }
    if (nan_pixels) sl_diag_append(out, "; %ld pixels are NaN", nan_pixels);
}

/* ---- the flicker score along a camera path ---- */

/* The measure is sl_compare's (sl_flicker_measure), shared with the viewer's --case. */

/* Only the camera's aim changes along the path: it turns. */
static bool _sl_path_turns(const sl_case *c) {
    for (int f = 1; f < c->frame_count; f++)
        if (glm_vec3_distance((float *)c->frame_cameras[f].position, (float *)c->frame_cameras[0].position) > 1e-6f)
            return false;
    return true;
}

void sl_diagnose_flicker(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "flicker");
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no frames of the camera path were captured");
        out->settled = true;
        return;
    }
    /* the receivers facing the light as the solutions drew them (sl_reference loads it with the frames) */
    const sl_image *s = &cap->image, *t = &ref->image, *m = &ref->lit_mask;
    if (s->width != t->width || s->height != t->height || m->width != c->width || m->height != c->height) {
        sl_diag_say(out, "the frames are %dx%d, the reference's %dx%d", s->width, s->height, t->width, t->height);
        out->settled = true;
        return;
    }
    sl_flicker got = sl_flicker_measure(s, m, c->frame_count), want = sl_flicker_measure(t, m, c->frame_count);
    bool shadows_ok = sl_flicker_shadows_kept(&got, &want);
    /* frames that never change pass the score: they must also be lit where the reference's are */
    bool light_ok = !sl_visibility_lit_lost(s, t, m).failed;
    bool measured_ok = got.score <= k->threshold && shadows_ok;
    if (measured_ok && light_ok) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    if (measured_ok && sl_diag_lit_lost(s, t, m, "flicker", out)) return;
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
        sl_diag_cause_in(out, "lab6_cascade_matrices", "here the camera only turns: keep each cascade's size fixed as it turns (a bounding sphere, "
                           "TODO lab6.2) and move its origin by whole texels (TODO lab6.3)");
    else
        sl_diag_cause_in(out, "lab6_cascade_matrices", "the camera moves by less than a texel per frame: move the projection's origin by whole "
                           "texels of the map (TODO lab6.3)");
}

/* ---- what lab 6's cases run (a first account from the renderer: sl_lab6_cascades.c) ---- */

bool sl_lab6_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    /* The flicker check: what changes between frames while only the camera the cascades are fitted to moves:
     * each cascade's sphere and its light camera (the snapping), turned into shadow matrices */
    if (k->kind == SL_CHECK_FLICKER)
        return strcmp(fn, "lab6_slice_sphere") == 0 || strcmp(fn, "lab6_cascade_matrices") == 0 ||
               strcmp(fn, "lab2_shadow_matrix") == 0;
    /* The cascade-index picture: where the splits are, and which cascade each pixel picks; nothing of
     * the light cameras, the depth passes or the lookup. */
    if (k->kind == SL_CHECK_CASCADE_INDEX)
        return strcmp(fn, "lab6_split_distances") == 0 || strcmp(fn, "cascade_index") == 0;
    /* The pictures of visibility (and the flicker's frames): every cascade fitted, drawn with lab 1's
     * depth shaders, turned into a shadow matrix by lab 2's function, then looked up */
    if (strcmp(fn, "depth.vert") == 0 || strcmp(fn, "lab2_shadow_matrix") == 0) return true;
    if (strcmp(fn, "cascade_blend") == 0) return c->params.cascades.blend_band > 0; /* the bonus: only where it is on */
    const sl_probe_function *f = sl_probe_find(fn);
    return f && f->lab == 6;
}

void sl_lab6_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    const sl_cascade_params *p = &c->params.cascades;
    snprintf(out, n, "%d cascades of %d texels, lambda %g%s", p->count, c->params.shadow_map_size, (double)p->lambda,
             p->blend_band > 0 ? ", blended across their borders" : ", no blend band");
}

/* ---- lab 6 in the diagnosis table (diagnose/table.c) ---- */
/* Lab 6's cases look up through its own cascade comparison. */
static void _sl_lab6_lookup_function(const sl_case *c, const char **function, const char **todo) {
    (void)c;
    *function = "cascade_compare()";
    *todo = "lab6.5";
}

const sl_lab_diagnoses sl_lab6_diagnoses = {
    .lab = 6,
    .lookup_function = _sl_lab6_lookup_function,
    .filtered_lookup = true,
    .checks = {{SL_CHECK_CASCADE_INDEX, sl_diagnose_cascade_index}, {SL_CHECK_FLICKER, sl_diagnose_flicker}},
    .case_runs = sl_lab6_case_runs,
    .case_path = sl_lab6_case_path,
    .probe_contract = sl_lab6_probe_contract,
    .rows_verdict = sl_verdict_lab6,
};
