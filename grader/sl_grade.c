#define _POSIX_C_SOURCE 200809L
#include "sl_grade.h"

#include <ctype.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "sl_compare.h"
#include "sl_diag_words.h"
#include "sl_diagnose.h"
#include "sl_files.h"
#include "sl_json.h"
#include "sl_probe.h"
#include "sl_utf8.h"

/* A runner taking this many times the CPU time of the solutions' for the
 * case (and this many seconds more) runs a loop that does not end: far
 * beyond what another machine or a slower but correct implementation
 * explains. The whole run is measured (context, shader compiles, every
 * frame), so the factor is smaller than a frame's would be: an endless loop
 * in one shader makes the case's run about 25 times the solutions'. */
#define _SL_SLOW_FACTOR 10.0
#define _SL_SLOW_MARGIN 1.0

bool sl_grade_too_slow(const sl_case *c, const sl_case_result *r) {
    double usual = c->reference_cpu_seconds;
    return usual > 0 && r->cpu_seconds > fmax(_SL_SLOW_FACTOR * usual, usual + _SL_SLOW_MARGIN);
}

static void _sl_explain_run_failure(const sl_case_result *r, sl_check_result *out) {
    int drawing_lab = 0; /* the runner stopped in a draw of the case's frames (sl_runner.c) */
    if (sscanf(r->crashed_in, "drawing_lab%d", &drawing_lab) != 1 || drawing_lab < 1 || drawing_lab > SL_LAB_MAX)
        drawing_lab = 0;
    if (r->interrupted) {
        sl_diag_say(out, "not graded: the grader was stopped before this case finished");
    } else if (r->staff_error[0]) {
        sl_diag_say(out, "not graded: %s (the grading machine's fault, not this submission's)", r->staff_error);
    } else if (r->protocol_error[0]) {
        sl_diag_say(out, "the case's results broke the rules of the grader's channel (%s): nothing it sent counts. "
                     "Lab code must not write to file descriptor 3 or replace the process", r->protocol_error);
    } else if (r->timed_out && drawing_lab > 0) {
        sl_diag_say(out, "timed out after %.0f s while drawing with the shaders of labs 1-%d: a shader loop that does "
                         "not end?", r->seconds, drawing_lab);
    } else if (r->timed_out) {
        sl_diag_say(out, "timed out after %.0f s%s%s%s", r->seconds, r->crashed_in[0] ? " in " : "",
                r->crashed_in, r->crashed_in[0] ? "() (an endless loop?)" : "");
    } else if (r->signal && drawing_lab > 0) {
        sl_diag_say(out, "crashed (%s) while drawing with the shaders of labs 1-%d (in the GL driver: state set by lab "
                         "code, or a shader)", strsignal(r->signal), drawing_lab);
    } else if (r->signal) {
        sl_diag_say(out, "crashed (%s)%s%s%s", strsignal(r->signal), r->crashed_in[0] ? " in " : " outside lab code",
                r->crashed_in, r->crashed_in[0] ? "()" : "");
    } else if (r->error[0]) {
        if (!sl_diag_compile_error(out, r->error)) sl_diag_say(out, "%s", r->error);
    } else {
        sl_diag_say(out, "the case stopped early (exit status %d)%s%s%s", r->exit_code, r->crashed_in[0] ? " in " : "",
                r->crashed_in, r->crashed_in[0] ? "()" : "");
    }
    /* What the process printed last often says why (a library missing, an assertion). */
    if (!r->interrupted && !r->staff_error[0] && !r->protocol_error[0] && !r->error[0] && r->output_tail[0]) {
        const char *end = r->output_tail + strlen(r->output_tail);
        while (end > r->output_tail && end[-1] == '\n') end--;
        const char *start = end;
        while (start > r->output_tail && start[-1] != '\n') start--;
        size_t len = end - start > 300 ? sl_utf8_cut(start, 300) : (size_t)(end - start);
        if (end > start) sl_diag_append(out, "; its output ended with: %.*s", (int)len, start);
    }
    /* a lab function the runner died or was stopped in (not a draw, whose shaders are several labs') */
    bool students = !r->interrupted && !r->staff_error[0] && !r->protocol_error[0] && !r->error[0];
    if (students && r->crashed_in[0] && !drawing_lab)
        sl_diag_set_cause(out, r->crashed_in, r->timed_out ? SL_CAUSE_TIMEOUT : SL_CAUSE_CRASH);
}

/* ---- checks ---- */

/* The shadowed fraction of the surfaces facing the light (every pixel without a mask). */
static void _sl_shadowed(const sl_image *s, const sl_image *t, const sl_image *mask, double *student, double *reference) {
    long facing = 0, ref_dark = 0, stu_dark = 0;
    for (long i = 0; i < (long)t->width * t->height; i++) {
        if (mask && mask->data[i] < 0.5f) continue;
        facing++;
        ref_dark += t->data[i] < 0.5f;
        stu_dark += !(s->data[i] >= 0.5f);
    }
    *reference = facing ? (double)ref_dark / (double)facing : 0;
    *student = facing ? (double)stu_dark / (double)facing : 0;
}

static void _sl_check_visibility(const sl_case *c, const sl_check *k, const sl_image *s, const sl_image *t,
                                 const sl_image *mask, const sl_compare_stats *st, sl_check_result *out) {
    sl_visibility_stats v = sl_visibility_compare(s, t);
    const char *fn, *todo;
    sl_case_lookup_function(c, &fn, &todo);
    /* On surfaces facing the light when the mask is there: surfaces facing
     * away are dark in both images and would hide a missing shadow. */
    double ref_shadowed, stu_shadowed;
    _sl_shadowed(s, t, mask, &stu_shadowed, &ref_shadowed);
    bool has_shadows = ref_shadowed > 0.005;
    if (v.missing_shadow > 0.02) out->symptoms |= 1u << SL_SYMPTOM_MISSING_SHADOW;
    if (v.extra_shadow > 0.02) out->symptoms |= 1u << SL_SYMPTOM_EXTRA_SHADOW;
    /* Exactly 1.0 where the reference has shadow: the stub, or every point
     * taken for outside; a filter whose samples mostly miss gives faint shadows instead. */
    long ref_dark = 0, exactly_lit = 0;
    for (long i = 0; i < (long)t->width * t->height; i++) {
        if ((mask && mask->data[i] < 0.5f) || t->data[i] >= 0.5f) continue;
        ref_dark++;
        exactly_lit += s->data[i] >= 0.995f;
    }
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
    if (has_shadows && stu_shadowed < 0.1 * ref_shadowed) {
        out->symptoms |= 1u << SL_SYMPTOM_NO_SHADOWS;
        if (lab && lab->filtered_lookup && exactly_lit < ref_dark / 2) {
            sl_diag_say(out, "shadows far too faint: where the reference is shadowed, %s leaves most pixels nearly lit", fn);
            sl_diag_cause_in(out, fn, "most samples land off the map, where the border counts as lit — are the offsets "
                                      "scaled by the texel size, 1.0 / textureSize(map, 0) (TODO %s)?", todo);
        } else {
            sl_diag_say(out, "no shadows at all");
            sl_diag_cause_in(out, fn, "%s returns 1.0 everywhere — not implemented (TODO %s), or every point taken for "
                                      "outside the light's frustum?", fn, todo);
        }
        return;
    }
    if (lab && lab->visibility && lab->visibility(c, s, t, mask, out)) return;
    if (has_shadows && v.missing_shadow > 0.3 && v.extra_shadow > 0.2) {
        out->symptoms |= 1u << SL_SYMPTOM_SWAPPED;
        sl_diag_say(out, "lit and shadowed are swapped (%.0f%% of shadows lit, %.0f%% of lit pixels shadowed)",
                    100 * v.missing_shadow, 100 * v.extra_shadow);
        sl_diag_cause(out, "is the comparison inverted?");
    } else if (v.extra_shadow > 0.5) {
        sl_diag_say(out, "%s is in shadow (%.0f%% of lit pixels)", sl_diag_shadowed_share_words(v.extra_shadow),
                    100 * v.extra_shadow);
        sl_diag_cause(out, "is the comparison inverted, the depth map empty, or the shadow coordinate wrong (W, divide)?");
    } else {
        /* the breakdown in the headline's own unit, pixels of the image, so that its parts add up to it */
        double pixels = st->pixels ? (double)st->pixels : 1;
        long brightness = st->failing - st->nan_pixels - st->failing_shadow_lost - st->failing_shadow_gained;
        char allowed[16];
        sl_diag_say(out, "shadows differ from the reference on %.1f%% of pixels (allowed %s%%): %.1f%% of pixels "
                         "lost their shadow, %.1f%% gained one, %.1f%% only differ in brightness (both lit or both "
                         "shadowed)",
                    100 * st->failing_fraction, sl_criterion_percent(k->fail_fraction, allowed, sizeof allowed),
                    100 * (double)st->failing_shadow_lost / pixels, 100 * (double)st->failing_shadow_gained / pixels,
                    100 * (double)brightness / pixels);
    }
}

/* A visibility check fails, whatever its pixel count, when more than half of
 * the reference's shadow (of at least this many pixels) is missing. */
#define _SL_MIN_SHADOW_PIXELS SL_VISIBILITY_MIN_SHADOW_PIXELS
#define _SL_MAX_SHADOW_LOST SL_VISIBILITY_MAX_SHADOW_LOST

static void _sl_compare_image(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_image *s,
                              const sl_image *t, const sl_image *lit_mask, sl_check_result *out);

/* An image read as 0 below `level` and 1 from it on (NaN stays NaN). */
static sl_image _sl_binarised(const sl_image *img, double level) {
    sl_image out = sl_image_alloc(img->width, img->height, img->channels);
    long n = (long)img->width * img->height * img->channels;
    for (long i = 0; out.data && i < n; i++)
        out.data[i] = isnan(img->data[i]) ? img->data[i] : img->data[i] >= level ? 1.0f : 0.0f;
    return out;
}

static void _sl_check_image(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            sl_check_result *out) {
    const char *capture = sl_check_capture_name(c, k);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no %s image was captured", capture);
        out->settled = true;
        return;
    }
    const sl_image *lit_mask = ref->lit_mask.data ? &ref->lit_mask : NULL; /* the solutions', never the runner's */
    if (k->binarise > 0 && k->kind == SL_CHECK_VISIBILITY) {
        /* where the shadows are, not how soft their edges are (lab 6: a filter in the lookup is allowed) */
        sl_image s = _sl_binarised(&cap->image, k->binarise), t = _sl_binarised(&ref->image, k->binarise);
        if (s.data && t.data) _sl_compare_image(c, k, r, &s, &t, lit_mask, out);
        else sl_diag_say(out, "out of memory comparing the images");
        sl_image_free(&s);
        sl_image_free(&t);
        return;
    }
    _sl_compare_image(c, k, r, &cap->image, &ref->image, lit_mask, out);
}

static void _sl_compare_image(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_image *s,
                              const sl_image *t, const sl_image *lit_mask, sl_check_result *out) {
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        sl_diag_say(out, "the image is %dx%dx%d, the reference %dx%dx%d", s->width, s->height, s->channels, t->width,
                t->height, t->channels);
        out->settled = true;
        return;
    }
    bool passes = sl_diag_image_passes(k, &st, k->kind == SL_CHECK_VISIBILITY ? "visibility" : "image", out);
    long shadowed = 0;
    double lost = 0;
    if (passes && k->kind == SL_CHECK_VISIBILITY) {
        /* Small shadows: a picture without them can stay under the failing fraction. */
        lost = sl_visibility_shadow_lost(s, t, lit_mask, &shadowed);
        passes = !(shadowed >= _SL_MIN_SHADOW_PIXELS && lost > _SL_MAX_SHADOW_LOST);
    }
    if (passes) {
        out->passed = true;
        return;
    }
    if (shadowed >= _SL_MIN_SHADOW_PIXELS && lost > _SL_MAX_SHADOW_LOST) { /* passed the count, lost the shadows */
        if (sl_diag_explain_missing(c, r, out)) return;
        const char *fn, *todo;
        sl_case_lookup_function(c, &fn, &todo);
        out->symptoms |= 1u << SL_SYMPTOM_MISSING_SHADOW;
        sl_diag_say(out, "the reference's shadows are missing: %.0f%% of its %ld shadowed pixels are lit in yours, even "
                         "allowing a pixel's shift (they cover %.2f%% of the image, so the pixel count alone would pass)",
                    100 * lost, shadowed, 100.0 * (double)shadowed / ((double)t->width * t->height));
        sl_diag_cause_in(out, fn, "does %s return 1.0 there — not implemented (TODO %s), or those points taken for "
                                  "outside the light's frustum?", fn, todo);
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return; /* the hint is about a mistake, not a missing stub */
    if (out->message[0]) return;                      /* only the mean is off: said */
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
    if (k->kind == SL_CHECK_VISIBILITY && lab && lab->capture_explains && lab->capture_explains(c, r, out)) return;
    if (k->kind == SL_CHECK_VISIBILITY) {
        _sl_check_visibility(c, k, s, t, lit_mask, &st, out);
    } else {
        char allowed[16];
        sl_diag_say(out, "the image differs from the reference on %.1f%% of pixels (allowed %s%%)",
                    100 * st.failing_fraction, sl_criterion_percent(k->fail_fraction, allowed, sizeof allowed));
    }
    if (st.nan_pixels) sl_diag_append(out, "; %ld pixels are NaN (a division by zero?)", st.nan_pixels);
}

/* ---- what to fix first: blame on evidence (grader/diagnose/README.md) ---- */

/* The failure of a function of `lab` that explains this check's symptoms, or NULL. */
static const sl_probe_failure *_sl_explaining_failure(const sl_case *c, const sl_check *k,
                                                     const sl_grade_context *context, int lab, uint32_t symptoms) {
    for (int i = 0; i < context->probe_failure_count; i++) {
        const sl_probe_failure *f = &context->probe_failures[i];
        if (sl_probe_at(f->function)->lab == lab &&
            sl_probe_failure_explains(c, k, f, symptoms, context->isolated))
            return f;
    }
    return NULL;
}

/* Whether an earlier lab's failed check `lf` can be behind this check: the
 * case draws with all of that lab's code the failed check drew with, along
 * the same path (the light's kind, and what that lab's descriptor asks: same_path),
 * and the symptoms point the same way. */
static bool _sl_shares_failure(const sl_case *c, const sl_check *k, const sl_lab_failure *lf, uint32_t symptoms) {
    if (!lf->c || !lf->k || lf->k->kind == SL_CHECK_PROBE) return false; /* probes: their own evidence */
    if ((lf->c->scene.light.type == SL_LIGHT_DIRECTIONAL) != (c->scene.light.type == SL_LIGHT_DIRECTIONAL)) return false;
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(lf->lab);
    if (lab && lab->same_path && !lab->same_path(lf->c, c)) return false;
    for (int i = 0; i < sl_lab_function_count(); i++) {
        sl_lab_function fn = sl_lab_function_at(i);
        if (fn.lab == lf->lab && sl_case_runs(lf->c, lf->k, fn.name) && !sl_case_runs(c, k, fn.name)) return false;
    }
    return sl_prediction_meets(lf->symptoms ? lf->symptoms : SL_SYMPTOMS_ANY, symptoms);
}

/* What to fix before this check's own symptoms mean anything, as the lead
 * of its message, from the root: an earlier lab this one builds on (a
 * function of it whose failed probe explains the symptoms, or else a failed
 * check drawn with the same code), a failed earlier check of the case (the
 * framebuffer, the matrices), a failed probe of a function of this lab that
 * explains the symptoms. False when nothing is known. */
static bool _sl_root_cause(const sl_case *c, const sl_check *k, const sl_grade_context *context, uint32_t symptoms,
                           char *lead, size_t n, sl_check_result *out) {
    if (!context || k->kind == SL_CHECK_PROBE || k->kind == SL_CHECK_FBO || k->kind == SL_CHECK_MATRICES) return false;
    for (int lab = 1; lab < c->lab && !context->isolated; lab++) {
        if (!sl_lab_shows(c->lab, lab)) continue;
        const sl_probe_failure *f = _sl_explaining_failure(c, k, context, lab, symptoms);
        if (f) {
            snprintf(lead, n, "needs lab %d first: %s%s is wrong on its own (%s: %s)", lab,
                     sl_probe_at(f->function)->name, sl_probe_parens(sl_probe_at(f->function)->name), f->where,
                     f->summary);
            sl_diag_set_cause(out, sl_probe_at(f->function)->name, f->stub ? SL_CAUSE_STUB : SL_CAUSE_WRONG);
            return true;
        }
        for (int i = 0; context->lab_failures && i < context->lab_failure_count; i++) {
            const sl_lab_failure *lf = &context->lab_failures[i];
            if (lf->lab != lab || !lf->failed || !_sl_shares_failure(c, k, lf, symptoms)) continue;
            snprintf(lead, n, "needs lab %d first: its %s fails (%s)", lab, lf->where, lf->summary);
            return true;
        }
    }
    for (int i = 0; i < context->earlier_count && i < (int)(k - c->checks); i++) {
        const sl_check *e = &c->checks[i];
        const sl_check_result *er = &context->earlier[i];
        if (er->passed || er->reference_problem || er->bonus) continue;
        /* the lead is that check's failure: so is its cause, when it named one */
        if (er->cause_kind && (e->kind == SL_CHECK_MATRICES || e->kind == SL_CHECK_FBO ||
                               (e->kind == SL_CHECK_CUBE_FACE && k->kind != SL_CHECK_CUBE_FACE)))
            sl_diag_set_cause(out, er->cause_function, er->cause_kind);
        if (e->kind == SL_CHECK_MATRICES) {
            snprintf(lead, n, "the light's matrices are wrong (%s / %s: %s): fix the matrices first", c->name, e->name,
                     er->summary);
            return true;
        }
        if (e->kind == SL_CHECK_CUBE_FACE && k->kind != SL_CHECK_CUBE_FACE) {
            snprintf(lead, n, "the cube map is wrong (%s / %s: %s): fix the cube map first", c->name, e->name,
                     er->summary);
            return true;
        }
        if (e->kind == SL_CHECK_FBO) {
            snprintf(lead, n, "the shadow map's framebuffer is wrong (%s / %s: %s): fix the framebuffer first", c->name,
                     e->name, er->summary);
            return true;
        }
    }
    const sl_probe_failure *f = _sl_explaining_failure(c, k, context, c->lab, symptoms);
    if (!f) return false;
    if (f->stub) snprintf(lead, n, "%s (%s)", f->summary, f->where);
    else snprintf(lead, n, "%s%s is wrong on its own (%s: %s): fix it first", sl_probe_at(f->function)->name,
                  sl_probe_parens(sl_probe_at(f->function)->name), f->where, f->summary);
    sl_diag_set_cause(out, sl_probe_at(f->function)->name, f->stub ? SL_CAUSE_STUB : SL_CAUSE_WRONG);
    return true;
}

/* The failure of `function`'s probe, or NULL. */
static const sl_probe_failure *_sl_failure_of(const sl_grade_context *context, const char *function) {
    const sl_probe_function *f = sl_probe_find(function);
    for (int i = 0; f && context && i < context->probe_failure_count; i++)
        if (context->probe_failures[i].function == sl_probe_index(f)) return &context->probe_failures[i];
    return NULL;
}

static bool _sl_probe_passed(const sl_grade_context *context, const char *function) {
    const sl_probe_function *f = sl_probe_find(function);
    int i = f ? sl_probe_index(f) : -1;
    return context && i >= 0 && i < 64 && ((context->probes_passed >> i) & 1u) && !_sl_failure_of(context, function);
}

/* Whether `function`'s passing probe ran generic rows too (sl_probe_generic.h): only then does it rule the
 * function out of a symptom whose cause a term its written rows leave at 0 could be. */
static bool _sl_probe_generic(const sl_grade_context *context, const char *function) {
    const sl_probe_function *f = sl_probe_find(function);
    int i = f ? sl_probe_index(f) : -1;
    return context && i >= 0 && i < 64 && ((context->probes_generic >> i) & 1u);
}

/* Whether a diagnosis may give `function` as the cause: the case runs it,
 * and its probe, if graded, failed in a way that explains the symptoms. */
static bool _sl_blame_allowed(const sl_case *c, const sl_check *k, const sl_grade_context *context,
                              const char *function, uint32_t symptoms) {
    bool isolated = context && context->isolated;
    if (!sl_function_may_be_blamed(c, k, function, isolated)) return false;
    if (_sl_probe_passed(context, function)) return false;
    const sl_probe_failure *f = _sl_failure_of(context, function);
    return !f || sl_probe_failure_explains(c, k, f, symptoms, isolated);
}

/* No cause on evidence: the path the case took, the candidates in order of
 * likelihood (a function whose probe fails, then code without a probe, this
 * lab's first), and what was ruled out (the probes that pass). */
static void _sl_candidates(const sl_case *c, const sl_check *k, const sl_case_result *r,
                           const sl_grade_context *context, const char *dropped, char *out, size_t n) {
    bool isolated = context && context->isolated;
    char path[300], failing[400] = "", others[400] = "", ruled[500] = "", written_only[300] = "";
    int candidates = 0, ruled_count = 0, written_only_count = 0;
    sl_case_path(c, r, path, sizeof path);
    for (int pass = 0; pass < 2; pass++)
        for (int lab = c->lab; lab >= 1; lab--)
            for (int i = 0; i < sl_lab_function_count(); i++) {
                sl_lab_function fn = sl_lab_function_at(i);
                if (fn.lab != lab || !sl_function_may_be_blamed(c, k, fn.name, isolated)) continue;
                bool passed = _sl_probe_passed(context, fn.name), fails = _sl_failure_of(context, fn.name) != NULL;
                bool probe = sl_probe_find(fn.name) != NULL;
                const char *suffix = probe ? sl_probe_parens(fn.name) : "";
                if (pass == 0 && passed && !_sl_probe_generic(context, fn.name)) {
                    if (dropped && strcmp(dropped, fn.name) == 0) continue; /* said already, just before */
                    /* its written rows alone: a term they leave at 0 may be the cause, so it is not ruled out */
                    if (written_only_count++ < 4)
                        snprintf(written_only + strlen(written_only), sizeof written_only - strlen(written_only), "%s%s%s",
                                 written_only[0] ? ", " : "", fn.name, suffix);
                } else if (pass == 0 && passed) {
                    if (ruled_count++ < 6)
                        snprintf(ruled + strlen(ruled), sizeof ruled - strlen(ruled), "%s%s%s", ruled[0] ? ", " : "",
                                 fn.name, suffix);
                } else if (pass == 0 && fails) {
                    if (candidates++ < 4)
                        snprintf(failing + strlen(failing), sizeof failing - strlen(failing),
                                 "%s%s%s (its probe fails, though not in a way that shows here alone)",
                                 failing[0] ? ", " : "", fn.name, sl_probe_parens(fn.name));
                } else if (pass == 1 && !passed && !fails) {
                    if (candidates++ < 4)
                        snprintf(others + strlen(others), sizeof others - strlen(others), "%s%s%s", others[0] ? ", " : "",
                                 fn.name, probe ? sl_probe_parens(fn.name) : "");
                }
            }
    size_t used = 0;
    out[0] = '\0';
    if (path[0]) used += (size_t)snprintf(out + used, n - used, "This case ran %s. ", path);
    if (used < n && dropped && dropped[0])
        used += (size_t)snprintf(out + used, n - used, "%s%s, which this symptom suggests, %s. ", dropped,
                                 sl_probe_parens(dropped),
                                 !_sl_probe_passed(context, dropped) ? "fails its probe in a way that does not explain it"
                                 : _sl_probe_generic(context, dropped) ? "passes its probe, on generic inputs too"
                                                                       : "passes its probe on its written inputs only");
    if (used < n && (failing[0] || others[0]))
        used += (size_t)snprintf(out + used, n - used, "Candidates: %s%s%s", failing, failing[0] && others[0] ? ", " : "",
                                 others);
    if (used < n && ruled[0])
        used += (size_t)snprintf(out + used, n - used, "%s: %s%s (%s)", failing[0] || others[0] ? "; ruled out" : "Ruled out",
                                 ruled, ruled_count > 6 ? " and more" : "",
                                 ruled_count > 1 ? "their probes pass, on generic inputs too"
                                                 : "its probe passes, on generic inputs too");
    if (used < n && written_only[0])
        used += (size_t)snprintf(out + used, n - used, "%s%s%s %s only on %s written inputs, not on generic ones: not "
                                 "ruled out", failing[0] || others[0] || ruled[0] ? "; " : "", written_only, written_only_count > 4 ? " and more" : "",
                                 written_only_count > 1 ? "pass their probes" : "passes its probe",
                                 written_only_count > 1 ? "their" : "its");
    if (used > 0 && used < n && out[used - 1] != ' ') snprintf(out + used, n - used, ".");
}

/* A capture of the checked picture, and what it shows against its reference. */
static uint32_t _sl_measured_symptoms(const sl_case *c, const sl_check *k, const sl_case_result *r,
                                      const sl_reference *ref) {
    if (!ref->loaded || !ref->image.data) return 0;
    double threshold = k->threshold > 0 ? k->threshold : 0.05;
    bool visibility = k->kind == SL_CHECK_VISIBILITY || k->kind == SL_CHECK_IMAGE || k->kind == SL_CHECK_PENUMBRA ||
                      k->kind == SL_CHECK_BLEEDING;
    bool depth = k->kind == SL_CHECK_DEPTH_MAP || k->kind == SL_CHECK_CUBE_FACE || k->kind == SL_CHECK_MOMENTS ||
                 k->kind == SL_CHECK_MOMENTS_BLURRED;
    if (!visibility && !depth) return 0;
    if (k->kind == SL_CHECK_PENUMBRA || k->kind == SL_CHECK_BLEEDING) threshold = 0.1;
    const sl_capture *cap = sl_result_capture(r, sl_check_capture_name(c, k));
    if (!cap || !cap->is_image) return 0;
    const sl_image *mask = visibility && ref->lit_mask.data ? &ref->lit_mask : NULL;
    return sl_measure_symptoms(&cap->image, &ref->image, mask, threshold, visibility);
}

/* Joins the diagnosis: the known root cause and the symptom, or the symptom
 * and its likely cause, then the case's hint if the symptom is its own. A
 * likely cause that names a function stands only on evidence; without one,
 * the candidates. */
static void _sl_compose(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_grade_context *context,
                        sl_check_result *out) {
    char symptom[sizeof out->message], lead[1200];
    snprintf(symptom, sizeof symptom, "%s", out->message);
    /* An experiment's answer is evidence no probe gives: it leads alone, and no function
     * it did not find fixing this check is blamed beside it. */
    if (!out->settled && context && context->experiment_lead && context->experiment_lead[0]) {
        size_t len = strlen(symptom);
        bool ends_sentence = len > 0 && strchr(".?!", symptom[len - 1]) != NULL;
        /* the function the experiment found, when its own probe failed too: what that probe says is wrong
         * (two pieces of evidence that agree, the second naming the mistake) */
        char probe_says[700] = "";
        const sl_probe_failure *probe = context->experiment_probe;
        if (probe && !probe->stub && probe->summary[0])
            snprintf(probe_says, sizeof probe_says, ". Its probe agrees (%s): %s", probe->where, probe->summary);
        snprintf(out->message, sizeof out->message, "%s%s. What the check measured: %s%s", context->experiment_lead,
                 probe_says, symptom, ends_sentence ? "" : ".");
        sl_utf8_trim(out->message);
        sl_utf8_copy(out->summary, sizeof out->summary, context->experiment_lead);
        out->cause_kind = NULL;
        out->cause_function[0] = '\0';
        if (context->experiment_function && context->experiment_function[0])
            sl_diag_set_cause(out, context->experiment_function, SL_CAUSE_WRONG);
        out->cause[0] = '\0';
        return;
    }
    bool root = !out->settled && _sl_root_cause(c, k, context, out->symptoms, lead, sizeof lead, out);
    char dropped[64] = "";
    if (out->cause[0] && out->blamed[0] && !_sl_blame_allowed(c, k, context, out->blamed, out->symptoms)) {
        snprintf(dropped, sizeof dropped, "%s", sl_function_may_be_blamed(c, k, out->blamed, context && context->isolated)
                                                    ? out->blamed : "");
        out->cause[0] = '\0';
    }
    /* a cause that names a function on evidence (sl_diag_cause_in), when no lead names one */
    if (!root && out->cause[0] && out->blamed[0] && !out->cause_kind) sl_diag_set_cause(out, out->blamed, SL_CAUSE_WRONG);
    if (root) {
        snprintf(out->message, sizeof out->message, "%s. Here: %s", lead, symptom); /* cuts: trimmed below */
    } else if (out->cause[0]) {
        snprintf(out->message, sizeof out->message, "%s: %s", symptom, out->cause);
    } else if (!out->settled && k->kind != SL_CHECK_PROBE && k->kind != SL_CHECK_FBO && k->kind != SL_CHECK_MATRICES) {
        char candidates[1200];
        _sl_candidates(c, k, r, context, dropped, candidates, sizeof candidates);
        if (candidates[0]) {
            size_t len = strlen(symptom);
            bool ends_sentence = len > 0 && strchr(".?!", symptom[len - 1]) != NULL;
            snprintf(out->message, sizeof out->message, "%s%s %s", symptom, ends_sentence ? "" : ".", candidates);
        }
    }
    sl_utf8_trim(out->message);
    if (!out->summary[0]) sl_utf8_copy(out->summary, sizeof out->summary, out->cause[0] ? out->cause : symptom);
    /* A hint is a guess: never over a known cause, and only for its own symptoms
     * (without "hint_when": only when nothing more specific was found). */
    bool hint_fits = k->hint_when ? (k->hint_when & out->symptoms) != 0 : !out->cause[0];
    if (!root && !out->settled && hint_fits) sl_diag_hint(out, k->hint);
    out->cause[0] = '\0';
}

bool sl_probe_failure_of(const sl_case *c, const sl_check *k, const sl_check_result *result, sl_probe_failure *out) {
    /* a probe its shader's compile error kept from running is no evidence about its function */
    if (k->kind != SL_CHECK_PROBE || result->passed || result->reference_problem || result->not_compiled[0])
        return false;
    memset(out, 0, sizeof *out);
    out->function = k->function;
    snprintf(out->where, sizeof out->where, "%s / %s", c->name, k->name);
    sl_utf8_copy(out->summary, sizeof out->summary, result->summary[0] ? result->summary : result->message);
    out->stub = result->stub;
    out->check = k;
    out->failing_rows = result->failing_rows;
    memcpy(out->row_predicts, result->row_predicts, sizeof out->row_predicts);
    memcpy(out->row_outputs, result->row_outputs, sizeof out->row_outputs);
    const sl_probe_function *f = sl_probe_at(k->function);
    bool by_mode = f && f->param_count > 0 && strcmp(f->params[0].name, "mode") == 0;
    for (int row = 0; row < k->rows; row++) {
        if (!((result->failing_rows >> row) & 1u)) continue;
        int mode = by_mode ? (int)k->inputs[row][0] : -1;
        out->failing_modes |= mode >= 0 && mode < 32 ? 1u << mode : 0xffffffffu;
    }
    if (!result->failing_rows) out->failing_modes = 0xffffffffu; /* it failed as a whole (not called, not implemented) */
    return true;
}

/* ---- the diagnosis a failed check got, as the class report counts it ---- */

/* text with every number that is not part of a name ("23%", "0.5", "(1, 2)";
 * not "lab3", "TODO(lab3.2)", "lab 2", "cos^2") written as "…", so that one
 * diagnosis reads the same for every student. */
static void _sl_without_numbers(const char *text, char *out, size_t n) {
    size_t used = 0;
    for (const char *p = text; *p && used + 4 < n;) { /* room for a character of 4 bytes and the NUL */
        bool starts_number = (*p >= '0' && *p <= '9') || ((*p == '-' || *p == '+') && p[1] >= '0' && p[1] <= '9');
        bool in_name = p > text && (isalnum((unsigned char)p[-1]) || p[-1] == '_' || p[-1] == '.' || p[-1] == '^');
        /* "lab 2", "labs 1-3": which lab, not a measure */
        for (const char *word = "lab "; !in_name && word; word = strcmp(word, "lab ") == 0 ? "labs " : NULL) {
            size_t n_word = strlen(word);
            in_name = (size_t)(p - text) >= n_word && strncasecmp(p - n_word, word, n_word) == 0;
        }
        if (starts_number && !in_name) {
            if (*p == '-' || *p == '+') p++;
            while ((*p >= '0' && *p <= '9') || (*p == '.' && p[1] >= '0' && p[1] <= '9')) p++;
            if ((*p == 'e' || *p == 'E') && (isdigit((unsigned char)p[1]) || ((p[1] == '-' || p[1] == '+') && isdigit((unsigned char)p[2]))))
                for (p += 2; isdigit((unsigned char)*p); p++) {}
            memcpy(out + used, "\xe2\x80\xa6", 3); /* … */
            used += 3;
            continue;
        }
        size_t len = sl_utf8_sequence(p, strnlen(p, 4), NULL); /* a character whole, or one byte that is none */
        len = len ? len : 1;
        memcpy(out + used, p, len);
        used += len;
        p += len;
    }
    out[used] = '\0';
}

/* Names the diagnosis from its text: the first words as a slug, and a hash
 * of the whole so that two diagnoses never share an id. */
static void _sl_name_diagnosis(sl_check_result *out, const char *text, bool follows) {
    _sl_without_numbers(text, out->diagnosis_text, sizeof out->diagnosis_text);
    uint32_t hash = 2166136261u; /* FNV-1a */
    for (const unsigned char *p = (const unsigned char *)out->diagnosis_text; *p; p++) hash = (hash ^ *p) * 16777619u;
    char slug[48] = "";
    size_t used = 0;
    int words = 0;
    bool gap = false;
    for (const char *p = out->diagnosis_text; *p && words < 7 && used + 2 < 40; p++) {
        if (isalnum((unsigned char)*p) && !((unsigned char)*p & 0x80)) {
            if (gap && used) slug[used++] = '-', words++;
            slug[used++] = (char)tolower((unsigned char)*p);
            gap = false;
        } else {
            gap = true;
        }
    }
    while (used && slug[used - 1] == '-') used--;
    slug[used] = '\0';
    snprintf(out->diagnosis, sizeof out->diagnosis, "%s%s-%06x", follows ? "follows-" : "", slug[0] ? slug : "failed",
             (unsigned)(hash & 0xffffffu));
}

static void _sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            const sl_grade_context *context, sl_check_result *out);

/* A text of a check's result made valid and printable, newlines kept (sl_utf8_clean), in place: what came
 * in was cleaned where it came in, and cuts fall between characters, so this is a last guard for every report. */
static void _sl_clean_in_place(char *text, size_t size) {
    size_t len = strlen(text);
    if (sl_utf8_is_clean(text, len, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB)) return;
    char *clean = malloc(3 * len + 1);
    if (!clean) {
        text[0] = '\0';
        return;
    }
    sl_utf8_clean(clean, 3 * len + 1, text, len, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB);
    sl_utf8_copy(text, size, clean);
    free(clean);
}

static void _sl_grade_and_name(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               const sl_grade_context *context, sl_check_result *out);

void sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                    const sl_grade_context *context, sl_check_result *out) {
    _sl_grade_and_name(c, k, r, ref, context, out);
    _sl_clean_in_place(out->message, sizeof out->message);
    _sl_clean_in_place(out->summary, sizeof out->summary);
    _sl_clean_in_place(out->diagnosis_text, sizeof out->diagnosis_text);
}

static void _sl_grade_and_name(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                               const sl_grade_context *context, sl_check_result *out) {
    _sl_grade_check(c, k, r, ref, context, out);
    if (out->passed) return;
    /* led by an earlier failure ("needs lab 2 first: ... Here: ..."): that lead is the diagnosis */
    const char *here = strstr(out->message, ". Here: ");
    if (here) {
        char lead[sizeof out->message];
        snprintf(lead, sizeof lead, "%.*s", (int)(here - out->message), out->message);
        _sl_name_diagnosis(out, lead, true);
        return;
    }
    const char *what = out->summary[0] ? out->summary : out->message;
    const sl_probe_function *f = k->kind == SL_CHECK_PROBE ? sl_probe_at(k->function) : NULL;
    if (f && !out->not_compiled[0] && strncmp(what, f->name, strlen(f->name)) != 0) {
        char named[sizeof out->summary + 80];
        snprintf(named, sizeof named, "%s%s: %s", f->name, sl_probe_parens(f->name), what); /* one verdict, told apart per function */
        _sl_name_diagnosis(out, named, false);
    } else {
        _sl_name_diagnosis(out, what, false);
    }
}

static void _sl_grade_check(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            const sl_grade_context *context, sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    out->bonus = k->bonus;
    if (ref->needed && !ref->loaded) {
        out->reference_problem = true;
        sl_diag_say(out, "%s", ref->error);
        return;
    }
    if (!r->finished && !(r->capture_count > 0 && !r->signal && !r->timed_out && !r->error[0] && !r->staff_error[0])) {
        _sl_explain_run_failure(r, out);
        out->reference_problem = r->staff_error[0] != '\0'; /* the staff's to solve, as a reference's */
        if (!out->summary[0]) sl_utf8_copy(out->summary, sizeof out->summary, out->message);
        return;
    }
    /* The software renderer cuts endless shader loops short, so such a case
     * can end with a plausible picture, only many times slower (a GPU would
     * hang instead). The time is the grader's measure of the runner process
     * (wait4's rusage), never a number the runner sends: lab code cannot
     * make it smaller. */
    double usual = c->reference_cpu_seconds;
    if (sl_grade_too_slow(c, r)) {
        sl_diag_say(out, "the case took %.2f s of CPU time where the solutions' take %.2f s (%.0fx): a shader loop that "
                     "does not end? The software renderer stops long loops, so the picture may even look right; a GPU "
                     "would hang", r->cpu_seconds, usual, r->cpu_seconds / usual);
        snprintf(out->summary, sizeof out->summary, "a shader loop that does not end");
        return;
    }
    /* A stub of this lab (or an earlier one) fails the check even if the picture
     * happens to match: the framework's stand-in must never earn the points.
     * (A probe calls one function alone: only its own stub matters there.) */
    for (int i = 0; k->kind != SL_CHECK_PROBE && i < r->not_implemented_count; i++)
        if (sl_diag_function_lab(r->not_implemented[i]) <= c->lab && sl_diag_explain_missing(c, r, out)) {
            sl_utf8_copy(out->summary, sizeof out->summary, out->message);
            return;
        }
    sl_check_diagnosis_fn lab_diagnosis = sl_check_diagnosis_of(k->kind); /* a lab's own check kind */
    switch (k->kind) {
    case SL_CHECK_VISIBILITY:
    case SL_CHECK_IMAGE: _sl_check_image(c, k, r, ref, out); break;
    case SL_CHECK_PROBE:
        sl_diagnose_probe(c, k, r, ref, out);
        /* a function its shader's compile error kept from running is not wrong: it was not reached */
        if (!out->passed && !out->not_compiled[0]) sl_diag_set_cause(out, sl_probe_at(k->function)->name, out->stub ? SL_CAUSE_STUB : SL_CAUSE_WRONG);
        if (!out->passed && !out->stub && !out->not_compiled[0]) sl_diag_gl_error(out, r, sl_probe_at(k->function)->name);
        break;
    default:
        if (lab_diagnosis) lab_diagnosis(c, k, r, ref, out);
        else sl_diag_say(out, "unknown check kind");
        break;
    }
    if (out->passed) {
        out->points = k->points;
        out->message[0] = '\0';
        out->cause[0] = '\0';
        /* a passing probe with generic rows says so: what it can rule out is no more than its inputs (one
         * without, as every probe of the handout's grader, says nothing: a line under each PASS is noise) */
        if (k->kind == SL_CHECK_PROBE && k->generic_rows > 0)
            sl_diag_say(out, "passes on %d written and %d generic inputs", k->rows - k->generic_rows, k->generic_rows);
        return;
    }
    out->symptoms |= _sl_measured_symptoms(c, k, r, ref);
    _sl_compose(c, k, r, context, out);
}

/* ---- no point without evidence ---- */

bool sl_check_is_state(const sl_check *k) { return k->kind == SL_CHECK_FBO; }

/* A state check whose picture fails: what that picture's check found, said here too (the state's check comes
 * first in the report). */
static void _sl_say_unbacked(const sl_case *c, int k, int unproved, sl_check_result *results) {
    sl_diag_say(&results[k], "the %s's state looks right, but the picture that would show it used, %s / %s, fails, "
                              "and the state alone earns no point. There: %s", c->checks[k].name, c->name,
                c->checks[unproved].name, results[unproved].message);
}

void sl_grade_quote_evidence(const sl_case *c, sl_check_result *results) {
    for (int k = 0; k < c->check_count; k++) {
        char backed[160];
        snprintf(backed, sizeof backed, "the %s's state is not backed by its picture", c->checks[k].name);
        if (!sl_check_is_state(&c->checks[k]) || results[k].passed || strcmp(results[k].summary, backed) != 0) continue;
        for (int e = 0; e < c->check_count; e++) {
            if (e == k || sl_check_is_state(&c->checks[e]) || c->checks[e].bonus || results[e].passed) continue;
            _sl_say_unbacked(c, k, e, results);
            _sl_clean_in_place(results[k].message, sizeof results[k].message);
            break;
        }
    }
}

void sl_grade_require_evidence(const sl_case *c, sl_check_result *results) {
    for (int k = 0; k < c->check_count; k++) {
        sl_check_result *out = &results[k];
        if (!sl_check_is_state(&c->checks[k]) || !out->passed) continue;
        /* the pictures that show the state at work: here, the depth map drawn through the framebuffer */
        int unproved = -1, evidence = 0;
        for (int e = 0; e < c->check_count; e++) {
            if (e == k || sl_check_is_state(&c->checks[e]) || c->checks[e].bonus) continue;
            evidence++;
            if (!results[e].passed && unproved < 0) unproved = e;
        }
        if (evidence > 0 && unproved < 0) continue;
        out->passed = false;
        out->points = 0;
        out->reference_problem = unproved >= 0 && results[unproved].reference_problem; /* not graded, as that one */
        if (out->reference_problem)
            sl_diag_say(out, "not graded: the picture that would show the %s used, %s / %s, has a reference problem "
                             "(see there); staff: repair that reference and grade again", c->checks[k].name, c->name,
                        c->checks[unproved].name);
        else if (unproved >= 0)
            _sl_say_unbacked(c, k, unproved, results);
        else
            sl_diag_say(out, "the %s's state looks right, but this case has no picture that shows it was used, and "
                             "the state alone earns no point", c->checks[k].name);
        if (out->reference_problem)
            snprintf(out->summary, sizeof out->summary, "not graded: its picture's reference is broken");
        else
            snprintf(out->summary, sizeof out->summary, "the %s's state is not backed by its picture", c->checks[k].name);
        _sl_name_diagnosis(out, out->summary, false);
        _sl_clean_in_place(out->message, sizeof out->message);
        _sl_clean_in_place(out->summary, sizeof out->summary);
        _sl_clean_in_place(out->diagnosis_text, sizeof out->diagnosis_text);
    }
}
