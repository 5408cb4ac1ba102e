/* Lab 1's diagnoses: the framebuffer and the depth map. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_gl.h"
#include "verdict_rows.h"

/* The depth resolution lab 1's README asks of the shadow map (GL_TEXTURE_DEPTH_SIZE). */
#define _SL_LAB1_MIN_DEPTH_BITS 24

/* The faults of a framebuffer whose depth texture is attached: its format, size, colour attachment and
 * draw/read buffers. They are independent of each other, so all that are measured are said, joined;
 * returns how many. v: the "fbo" capture's numbers. */
static int _sl_fbo_faults(const double *v, sl_check_result *out) {
    int faults = 0;
    out->message[0] = '\0';
#define _SL_FAULT(...)                                                                                                 \
    (sl_diag_append(out, "%s", faults++ ? "; also, " : "lab1_create_shadow_map(): "), sl_diag_append(out, __VA_ARGS__))
    if (v[3] <= 0) {
        _SL_FAULT("map->depth_texture has no depth format: use GL_DEPTH_COMPONENT24 (internal format) with "
                  "GL_DEPTH_COMPONENT");
    } else if (v[3] < _SL_LAB1_MIN_DEPTH_BITS) {
        /* The README's contract is 24 bits or more. A 16-bit map still draws this case's pictures within
         * their tolerance, so only the texture's own resolution shows it. */
        _SL_FAULT("map->depth_texture has %.0f bits of depth, and the lab asks for at least %d: use "
                  "GL_DEPTH_COMPONENT24 (GL_DEPTH_COMPONENT32F or GL_DEPTH24_STENCIL8 will do too) — 16 bits keep "
                  "65536 depths, and a perspective light spends most of them near itself",
                  v[3], _SL_LAB1_MIN_DEPTH_BITS);
    }
    if (v[4] != v[9] || v[5] != v[9])
        _SL_FAULT("the depth texture is %.0fx%.0f, but the requested map size is %.0f: use the size argument", v[4],
                  v[5], v[9]);
    if (v[8] != GL_NONE) _SL_FAULT("the framebuffer has a colour attachment: a depth-only pass needs none");
    if (v[6] != GL_NONE || v[7] != GL_NONE)
        _SL_FAULT("draw/read buffer is %s, not GL_NONE: call glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE) while "
                  "the framebuffer is bound",
                  v[6] != GL_NONE ? "set" : "set for reading");
#undef _SL_FAULT
    return faults;
}

void sl_diagnose_fbo(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "fbo");
    if (!cap || cap->number_count < 10) {
        if (!sl_diag_explain_missing(c, r, out))
            sl_diag_say(out, "lab1_create_shadow_map() left map->framebuffer and map->depth_texture at 0");
        return;
    }
    const double *v = cap->numbers;
    GLenum status = (GLenum)v[0];
    if (v[0] == 0) {
        sl_diag_say(out, "lab1_create_shadow_map(): map->framebuffer is not a framebuffer object (glGenFramebuffers + glBindFramebuffer)");
    } else if (v[1] != GL_TEXTURE) {
        sl_diag_say(out, "lab1_create_shadow_map(): nothing is attached as GL_DEPTH_ATTACHMENT: attach the depth texture with glFramebufferTexture2D");
    } else if (!v[2]) {
        sl_diag_say(out, "lab1_create_shadow_map(): the texture attached as GL_DEPTH_ATTACHMENT is not map->depth_texture");
    } else if (_sl_fbo_faults(v, out)) {
        /* said: every fault of the texture and the buffers at once, so one round of fixes is enough */
    } else if (status != GL_FRAMEBUFFER_COMPLETE) {
        sl_diag_say(out, "lab1_create_shadow_map(): the framebuffer is incomplete: %s", sl_gl_enum_name(status));
    } else if (r->failed[0] && strcmp(r->failed, "lab1_create_shadow_map") == 0) {
        sl_diag_say(out, "lab1_create_shadow_map() returned SL_FAILED, although its framebuffer is complete");
    } else {
        out->passed = true;
    }
}

/* Whether the student's depths are one affine function a d + b of the reference's d, on texels written in
 * both, with the reference's texels written: the geometry in its place, its depth remapped. A least-squares fit, held to a quarter of the check's threshold everywhere. */
static bool _sl_depth_remapped(const sl_image *s, const sl_image *t, double threshold, double *scale, double *offset) {
    long n = (long)s->width * s->height, both = 0, missing = 0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, lo = 1, hi = 0;
    for (long i = 0; i < n; i++) {
        double x = t->data[i], y = s->data[i];
        bool written_t = x < 1 - 1e-6, written_s = y < 1 - 1e-6;
        if (!isfinite(y)) return false;
        missing += written_t && !written_s;
        if (!written_t || !written_s) continue;
        both++;
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        lo = fmin(lo, x), hi = fmax(hi, x);
    }
    /* a range of depths to fit over, and the reference's texels written (a remap past 1 drops a few; one
     * that brings geometry past the far plane into range writes texels the reference leaves at 1.0) */
    if (both < 100 || hi - lo < 0.05 || missing > both / 50) return false;
    double d = both * sxx - sx * sx;
    if (fabs(d) < 1e-12) return false;
    double a = (both * sxy - sx * sy) / d, b = (sy - a * sx) / both;
    if (fabs(a - 1) < 0.01 && fabs(b) < threshold) return false; /* the reference's depths, near enough */
    for (long i = 0; i < n; i++) {
        double x = t->data[i], y = s->data[i];
        if (x < 1 - 1e-6 && y < 1 - 1e-6 && fabs(a * x + b - y) > threshold / 4) return false;
    }
    *scale = a, *offset = b;
    return true;
}

void sl_diagnose_depth(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                            sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, "depth_map");
    if (!cap) {
        if (r->capture_error[0]) sl_diag_say(out, "%s", r->capture_error);
        else if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no depth map was captured");
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    sl_compare_stats st = sl_compare_images(s, t, k->threshold, &out->diff);
    if (st.size_mismatch) {
        /* the map's size is lab1_create_shadow_map's alone: the reference's is the size the case asked for */
        sl_diag_say(out, "the depth map is %dx%d, the reference %dx%d", s->width, s->height, t->width, t->height);
        if (s->width == s->height)
            sl_diag_append(out, ": lab1_create_shadow_map() made a %dx%d map when the case asked for size %d — a size "
                                "of its own instead of its size argument? Use the size argument (TODO(lab1.1) in "
                                "labs/lab1_depth_fbo/lab1.c)",
                           s->width, s->height, t->width);
        else
            sl_diag_append(out, ": lab1_create_shadow_map() made a %dx%d map when the case asked for %dx%d — use the "
                                "size argument for both sides (TODO(lab1.1) in labs/lab1_depth_fbo/lab1.c)",
                           s->width, s->height, t->width, t->width);
        out->settled = true;
        return;
    }
    if (sl_diag_image_passes(k, &st, "depth map", out)) {
        out->passed = true;
        return;
    }
    if (out->message[0]) return; /* only the mean is off: said */
    double ref_empty = sl_fraction_equal(t, 1.0f, 1e-6f);
    double stu_empty = sl_fraction_equal(s, 1.0f, 1e-6f);
    double stu_zero = sl_fraction_equal(s, 0.0f, 1e-6f);
    /* Texels nearer than the reference's (something where nothing should be,
     * or depths left from earlier frames) and farther (something missing). */
    long nearer = 0, farther = 0, n = (long)s->width * s->height;
    for (long i = 0; i < n; i++) {
        double d = (double)s->data[i] - (double)t->data[i];
        nearer += d < -k->threshold;
        farther += d > k->threshold;
    }
    double near_fraction = (double)nearer / (double)n, far_fraction = (double)farther / (double)n;
    double scale = 1, offset = 0;
    if (stu_empty > 0.999 && ref_empty < 0.99) {
        sl_diag_say(out, "the depth map is empty (all 1.0): nothing was written into it");
        sl_diag_cause_in(out, "depth.vert", "no fragment reached it — shaders/depth.vert must output u_light_view_projection * u_model * "
                           "position (still the stub? TODO lab1.4); with the depth test off, or a depth function no "
                           "fragment passes, nothing is written either (TODO lab1.3)");
    } else if (stu_zero > 0.9) {
        sl_diag_say(out, "the depth map is all 0.0: no fragment passed the depth test");
        sl_diag_cause_in(out, "lab1_begin_depth_pass", "is the depth buffer cleared (glClear(GL_DEPTH_BUFFER_BIT)) after binding the framebuffer, "
                           "with depth writes on (TODO lab1.3)?");
    } else if (sl_content_only_in_lower_left(s, 1.0f, c->width, c->height)) {
        sl_diag_say(out, "only the lower-left %dx%d texels of the %dx%d map hold depths", c->width, c->height, s->width,
                    s->height);
        sl_diag_cause_in(out, "lab1_begin_depth_pass", "the viewport is still the window's — call glViewport(0, 0, size, size) in "
                           "lab1_begin_depth_pass (TODO lab1.3)");
    } else if (_sl_depth_remapped(s, t, k->threshold, &scale, &offset)) {
        /* the fit is the evidence: the geometry in place, its depth not as the projection gives it */
        sl_diag_say(out, "every written texel holds %.3g d + %.3g (to within %.2g) where the reference holds d: the "
                         "map covers the reference's texels, but each depth is remapped — gl_Position's z changed "
                         "after the projection? depth.vert's gl_Position is the clip-space u_light_view_projection * "
                         "u_model * position, z unchanged: glDepthRange maps depth to [0, 1] after the divide",
                    scale, offset, k->threshold / 4);
        sl_diag_cause_in(out, "depth.vert", "look at the z of gl_Position in shaders/depth.vert (TODO lab1.4)");
    } else if (nearer > 20 * (farther + 1) && near_fraction > k->fail_fraction) {
        /* stale depths from earlier frames: many texels nearer than they should be, few farther */
        out->symptoms |= 1u << SL_SYMPTOM_STALE_DEPTH;
        sl_diag_say(out, "%.1f%% of texels hold depths nearer than the scene's", 100.0 * near_fraction);
        sl_diag_cause_in(out, "lab1_begin_depth_pass", "depths from earlier frames remain — clear the depth buffer at the start of every depth pass");
    } else if (far_fraction > k->fail_fraction / 2 && far_fraction > near_fraction && st.failing_fraction < 0.25) {
        /* the background (the floor, whose model matrix is the identity) right, the objects missing or elsewhere */
        sl_diag_say(out, "objects are missing from the map while the floor agrees: %.1f%% of texels are farther than "
                         "the reference's (an object missing there), %.1f%% nearer (one where none should be)",
                    100 * far_fraction, 100 * near_fraction);
        sl_diag_cause_in(out, "depth.vert", "is each object's u_model applied, in the order u_light_view_projection * u_model * "
                           "position (shaders/depth.vert, TODO lab1.4)?");
    } else {
        sl_diag_say(out, "the depth map differs from the reference on %.1f%% of texels (allowed %.1f%%): %.1f%% are "
                         "nearer than the reference's, %.1f%% farther",
                    100 * st.failing_fraction, 100 * k->fail_fraction, 100 * near_fraction, 100 * far_fraction);
    }
    if (st.nan_pixels) sl_diag_append(out, "; %ld texels are NaN", st.nan_pixels);
}

/* ---- what lab 1's cases run ---- */

bool sl_depth_pass_runs(const sl_case *c, const sl_check *k, const char *fn) {
    if (strcmp(fn, "lab1_create_shadow_map") == 0) return true;
    if (k->kind == SL_CHECK_FBO) return false;
    if (strcmp(fn, "lab1_begin_depth_pass") == 0 || strcmp(fn, "depth.vert") == 0) return true;
    /* from lab 2 on the light's camera is lab 2's, from lab 3 on the pass's state lab 3's */
    if (c->lab >= 2 && (strcmp(fn, "lab2_light_view") == 0 || strcmp(fn, "lab2_light_projection") == 0 ||
                        strcmp(fn, "lab2_shadow_matrix") == 0))
        return true;
    if (c->lab >= 3 && strcmp(fn, "lab3_depth_pass_state") == 0) return true;
    /* the extension's second map: only in its own mode, in lab 3 */
    if (c->lab == 3 && c->params.bias.mode == SL_BIAS_MIDPOINT && strcmp(fn, "lab3_second_depth_state") == 0)
        return true;
    return false;
}

bool sl_lab1_case_runs(const sl_case *c, const sl_check *k, const char *fn) { return sl_depth_pass_runs(c, k, fn); }

/* ---- verdicts on its probes' rows (verdict.c asks by the probe's name) ---- */

/* Outputs: min filter, mag filter, wrap S, wrap T, the border's depth (-1 without a border), the texture's
 * width and height, map->size. */
/* The framebuffer lab1_create_shadow_map made, read as GL reports it (outputs 8-11: its status while bound,
 * the depth texture at the stencil attachment too, whether the function asked the status of the map's
 * framebuffer, whether it returned SL_OK): the first thing that breaks the contract, on the first row. */
static int _sl_verdict_map_framebuffer(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 8)) || v->f->output_count < 12) continue;
        GLenum status = (GLenum)_sl_got(v, r, 8);
        double stencil = _sl_got(v, r, 9), asked = _sl_got(v, r, 10), ok = _sl_got(v, r, 11);
        if (status == 0) {
            snprintf(text, n, "map->framebuffer is not a framebuffer object: glGenFramebuffers, then "
                              "glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer) before anything is attached");
        } else if (status != GL_FRAMEBUFFER_COMPLETE && stencil == 1) {
            snprintf(text, n, "the framebuffer is incomplete (%s): map->depth_texture is attached as a stencil buffer "
                              "too — GL_DEPTH_STENCIL_ATTACHMENT attaches at both points, and a depth-only format has "
                              "no stencil: attach it at GL_DEPTH_ATTACHMENT", sl_gl_enum_name(status));
        } else if (status == GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT) {
            snprintf(text, n, "the framebuffer is incomplete (%s): nothing is attached to it — "
                              "glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, "
                              "map->depth_texture, 0) while map->framebuffer is bound", sl_gl_enum_name(status));
        } else if (status == GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER || status == GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER) {
            snprintf(text, n, "the framebuffer is incomplete (%s): its draw or read buffer names a colour attachment "
                              "it does not have — glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE) while it is bound",
                     sl_gl_enum_name(status));
        } else if (status != GL_FRAMEBUFFER_COMPLETE && _sl_got(v, r, 5) == 0) {
            snprintf(text, n, "the framebuffer is incomplete (%s) because map->depth_texture has no storage (0x0): "
                              "glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, "
                              "GL_UNSIGNED_INT, NULL) was refused or never made (GL's own words below say which)",
                     sl_gl_enum_name(status));
        } else if (status != GL_FRAMEBUFFER_COMPLETE) {
            snprintf(text, n, "the framebuffer is incomplete (%s): one depth texture of the map's size at "
                              "GL_DEPTH_ATTACHMENT, no colour, draw and read buffer GL_NONE make it complete",
                     sl_gl_enum_name(status));
        } else if (isnan(_sl_got(v, r, 0))) {
            snprintf(text, n, "map->depth_texture names no texture when the function returns (0, deleted, or another "
                              "name stored), though the framebuffer is complete: it still renders into the image it "
                              "attached, but nothing can read or sample the map — the framebuffer does not own the "
                              "texture; keep it until lab1_destroy_shadow_map deletes it");
        } else if (asked != 1) {
            snprintf(text, n, "%s — ask glCheckFramebufferStatus(GL_FRAMEBUFFER) while map->framebuffer is still "
                              "bound, then bind 0, so an incomplete map is caught (and a complete one not refused "
                              "where framebuffer 0 does not exist)",
                     asked < 0 ? "glCheckFramebufferStatus is never called"
                               : "glCheckFramebufferStatus is asked about another framebuffer than the map's (0, "
                                 "bound again before the check?)");
        } else if (ok != _sl_want(v, r, 11)) {
            snprintf(text, n, "it returns %s, where its framebuffer is complete: SL_OK when glCheckFramebufferStatus "
                              "gives GL_FRAMEBUFFER_COMPLETE, SL_FAILED otherwise", ok ? "SL_OK" : "SL_FAILED");
        } else {
            continue;
        }
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_GROSS | 1u << SL_SYMPTOM_NO_SHADOWS);
        return r;
    }
    return -1;
}

static int _sl_verdict_create_shadow_map(const sl_verdict_rows *v, char *text, size_t n) {
    int framebuffer = _sl_verdict_map_framebuffer(v, text, n);
    if (framebuffer >= 0) return framebuffer;
    /* the size first: a map of a size of its own is wrong on every row whose size is not that one */
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 5))) continue;
        double size = v->k->inputs[r][0], width = _sl_got(v, r, 5), height = _sl_got(v, r, 6);
        if (width == size && height == size) continue;
        bool constant = true; /* the same size whatever the argument, on every row */
        for (int q = 0; q < v->k->rows; q++) constant &= _sl_got(v, q, 5) == width && _sl_got(v, q, 6) == height;
        if (constant)
            snprintf(text, n, "the map is %gx%g whatever its size argument (%g here): a size of its own, not the "
                              "argument's — make the texture size x size (glTexImage2D(..., size, size, ...))",
                     width, height, size);
        else
            snprintf(text, n, "the map is %gx%g, not size x size (%g): use the size argument for both sides of "
                              "the texture", width, height, size);
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_GROSS);
        return r;
    }
    /* then map->size: the depth pass's viewport is sized by it, so a map whose texture is right but whose record
     * is not draws into a viewport of the wrong size (0x0 when it is never set) */
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 7)) || _sl_got(v, r, 7) == _sl_want(v, r, 7)) continue;
        if (_sl_got(v, r, 7) == 0)
            snprintf(text, n, "map->size is never set (0, the size argument is %g): lab1_begin_depth_pass sizes the "
                              "viewport by it, so the depth pass draws into 0x0 pixels and the map stays empty — "
                              "map->size = size", _sl_want(v, r, 7));
        else
            snprintf(text, n, "map->size is %g, not the size argument %g: lab1_begin_depth_pass sizes the viewport by "
                              "it — map->size = size", _sl_got(v, r, 7), _sl_want(v, r, 7));
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_GROSS);
        return r;
    }
    /* every parameter where a new texture has it (filters, wraps and border all GL's defaults, each not the
     * contract's): not one choice wrong, but calls that set another texture, or none */
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 0))) continue;
        /* the border reads -1 where no wrap mode uses it (sl_probe_calls.c), as with a new texture's GL_REPEAT */
        const double defaults[5] = {GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT, -1};
        bool all_defaults = true;
        for (int o = 0; o < 5; o++)
            all_defaults &= _sl_got(v, r, o) == defaults[o] && _sl_want(v, r, o) != defaults[o];
        if (!all_defaults) break;
        snprintf(text, n, "none of the texture's parameters took: filters, wrap modes and border are all a new "
                          "texture's defaults (GL_NEAREST_MIPMAP_LINEAR, GL_REPEAT, border 0) — glTexParameter* "
                          "changes the texture bound to GL_TEXTURE_2D when it is called: set them while "
                          "map->depth_texture is bound");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_GROSS);
        return r;
    }
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
        /* a border of integers: glTexParameteriv reads each as a fraction of the largest int, 1 as 1 / (2^31 - 1) */
        if (border > 0 && border < 1e-6 && fabs(_sl_want(v, r, 4) - 1) < 1e-6) {
            snprintf(text, n, "the border's depth is %g, not 1.0: the border colour was given as integers — "
                              "glTexParameteriv reads each as a fraction of the largest int, so 1 becomes 1 / 2147483647 "
                              "and a lookup past the edge finds an occluder at the near plane; give it as floats, "
                              "glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, (float[]){1, 1, 1, 1})",
                     border);
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
        if (_sl_got(v, r, 0) == 2) {
            snprintf(text, n, "the map's framebuffer is bound for reading only (GL_READ_FRAMEBUFFER): a pass draws into "
                              "the GL_DRAW_FRAMEBUFFER binding, so the depths go elsewhere — glBindFramebuffer("
                              "GL_FRAMEBUFFER, map->framebuffer) binds it for both");
        } else if (_sl_got(v, r, 0) != 1) {
            snprintf(text, n, "the map's framebuffer is not bound: glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer) "
                              "first, or the depth pass draws into another one");
        } else if (_sl_got(v, r, 1) != size || _sl_got(v, r, 2) != size) {
            _sl_viewport_said(text, n, _sl_got(v, r, 1), _sl_got(v, r, 2), size, size, "the map's",
                              "glViewport(0, 0, map->size, map->size)");
        } else if (!_sl_got(v, r, 3)) {
            snprintf(text, n, "the depth test is off: with GL_DEPTH_TEST disabled no depth is written at all — "
                              "glEnable(GL_DEPTH_TEST)");
        } else if (_sl_got(v, r, 4) != _sl_want(v, r, 4)) {
            snprintf(text, n, "the depth function is not GL_LESS (nor GL_LEQUAL): each texel must keep the nearest "
                              "depth — glDepthFunc(GL_LESS)");
        } else if (!_sl_got(v, r, 5)) {
            snprintf(text, n, "depth writes are off: glDepthMask(GL_TRUE), before the clear too (glClear respects it)");
        } else if (_sl_got(v, r, 6) != 1) {
            /* the probe starts with depth writes off: a clear before glDepthMask(GL_TRUE) clears nothing */
            snprintf(text, n, "the depths are not cleared to 1.0 at the start of the pass: glClear(GL_DEPTH_BUFFER_BIT) "
                              "after binding the map's framebuffer and after glDepthMask(GL_TRUE) (glClear writes no "
                              "depth while depth writes are off, as they are when this probe starts), every pass");
        } else {
            continue;
        }
        return r;
    }
    return -1;
}

/* ---- lab 1 in the diagnosis table (diagnose/table.c) ---- */
static void _sl_diagnose_fbo_check(const sl_case *c, const sl_check *k, const sl_case_result *r,
                                   const sl_reference *ref, sl_check_result *out) {
    sl_diagnose_fbo(c, r, out);
}
/* A failed check of a moving light's case (more than one frame) is not behind a still one's. */
static bool _sl_lab1_same_path(const sl_case *failed, const sl_case *c) {
    return !(failed->frame_count > 1 && c->frame_count <= 1);
}

const sl_lab_diagnoses sl_lab1_diagnoses = {
    .lab = 1,
    /* outputs 2-4 (wrap S, wrap T, the border) matter only to a filter that reads past the map's edge: lab 2's
     * lookups call a point off the map lit before they read it */
    .functions = {{"lab1_create_shadow_map", _sl_verdict_create_shadow_map, .edge_outputs = 0x1Cu},
                  {"lab1_begin_depth_pass", _sl_verdict_begin_depth_pass}},
    .checks = {{SL_CHECK_FBO, _sl_diagnose_fbo_check}, {SL_CHECK_DEPTH_MAP, sl_diagnose_depth}},
    .case_runs = sl_lab1_case_runs,
    .same_path = _sl_lab1_same_path,
};
