/* Lab 5's diagnoses: the moments (format, each channel, the blur's two
 * directions), light bleeding, and what a wrong Chebyshev bound does to lit
 * surfaces; what lab 5's function probes show together is lab5_verdict.c's. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_diag_words.h"
#include "sl_gl.h"
#include "sl_probe.h"
#include "sl_verdict.h"
#include "verdict_rows.h"

/* One channel of an image, as an image of its own (the compare's threshold then holds per channel). */
static sl_image _sl_channel(const sl_image *img, int channel) {
    sl_image out = sl_image_alloc(img->width, img->height, 1);
    if (!out.data) return out;
    for (long i = 0; i < (long)img->width * img->height; i++) out.data[i] = img->data[i * img->channels + channel];
    return out;
}

/* Mean squared difference between neighbours along x (dx 1) or y: a blur lowers it in its own direction only. */
static double _sl_gradient_energy(const sl_image *m, int dx, int dy) {
    double sum = 0;
    long n = 0;
    for (int y = 0; y + dy < m->height; y++)
        for (int x = 0; x + dx < m->width; x++) {
            float a = m->data[((long)y * m->width + x) * m->channels];
            float b = m->data[((long)(y + dy) * m->width + x + dx) * m->channels];
            if (isnan(a) || isnan(b)) continue;
            sum += (double)(a - b) * (a - b);
            n++;
        }
    return n ? sum / (double)n : 0;
}

/* The target's format: 32-bit floats in red and green, or the variance drowns in rounding. */
static bool _sl_format_ok(const sl_case_result *r, sl_check_result *out) {
    const sl_capture *t = sl_result_capture(r, "moments_target");
    if (!t || t->number_count < SL_MOMENTS_TARGET_NUMBERS) return true; /* nothing made: the image says so */
    const double *v = t->numbers;
    GLenum format = (GLenum)v[1];
    int red = (int)v[4], green = (int)v[5];
    bool is_float = v[6] != 0;
    if (v[0] != GL_FRAMEBUFFER_COMPLETE) {
        sl_diag_say(out, "framebuffer[0] of the moments target is not complete (%s)", sl_gl_enum_name((GLenum)v[0]));
        sl_diag_cause_in(out, "lab5_create_moments_target", "moments[0] as GL_COLOR_ATTACHMENT0 and a depth renderbuffer as GL_DEPTH_ATTACHMENT "
                           "(TODO(lab5.1) in labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (v[13] == 0) {
        sl_diag_say(out, "moments[0] is not framebuffer[0]'s GL_COLOR_ATTACHMENT0: the moments pass draws into "
                         "framebuffer[0], and nothing it draws reaches moments[0], which the blur reads");
        sl_diag_cause_in(out, "lab5_create_moments_target", "attach moments[i] to framebuffer[i] at GL_COLOR_ATTACHMENT0, and "
                           "the depth renderbuffer to framebuffer[0] at GL_DEPTH_ATTACHMENT (TODO(lab5.1) in "
                           "labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (red >= 32 && green >= 32 && is_float) return true;
    if (green == 0) { /* one channel: not a precision, a moment lost */
        sl_diag_say(out, "the moments are stored as %s, which has no green channel: the second moment E[x^2] is "
                         "dropped (it reads 0), so the variance E[x^2] - E[x]^2 comes out negative and the bound has "
                         "nothing to work with — two channels, the depth in red and its square in green",
                    sl_gl_enum_name(format));
        sl_diag_cause_in(out, "lab5_create_moments_target", "create moments[0] and moments[1] as GL_RG32F, format GL_RG "
                           "(TODO(lab5.1) in labs/lab5_vsm/lab5.c)");
        return false;
    }
    sl_diag_say(out, "the moments are stored as %s (%d-bit %s per channel): the variance E[x^2] - E[x]^2 is the "
                     "difference of two nearly equal numbers, and %d bits round it away, so shadows show bands and "
                     "light leaks where the variance comes out wrong (precision)",
                sl_gl_enum_name(format), red, is_float ? "float" : "fixed point", red);
    sl_diag_cause_in(out, "lab5_create_moments_target", "create moments[0] and moments[1] as GL_RG32F (TODO(lab5.1) in labs/lab5_vsm/lab5.c)");
    return false;
}

/* lab5_create_moments_target's probe: its textures' internal formats alone wrong, said as the moments' capture
 * says them (a lost channel, or too few bits for the variance). */
static int _sl_verdict_moments_target(const sl_verdict_rows *v, char *text, size_t n) {
    int first = -1;
    /* framebuffer[0] with neither its texture nor the depth buffer, the textures themselves right: the
     * attachments were made to a name that framebuffer[0] no longer holds, or with another one bound */
    for (int r = 0; r < v->k->rows && v->f->output_count >= 16; r++) {
        if (!_sl_failed(v, r)) continue;
        bool textures_right = true;
        for (int o = 0; o < 11; o++) textures_right &= fabs(_sl_got(v, r, o) - _sl_want(v, r, o)) <= 1e-6;
        if (!textures_right || _sl_got(v, r, 15) != 0 || _sl_got(v, r, 12) != 0) break;
        snprintf(text, n, "framebuffer[0] holds neither moments[0] nor the depth buffer when the function returns "
                          "(%g of 2 framebuffers complete): its attachments went to another framebuffer — a name "
                          "generated again after attaching (glGenFramebuffers inside the loop replaces framebuffer[0]) "
                          "or framebuffer[0] not bound while attaching. Generate both names once, then bind "
                          "framebuffer[i] before attaching moments[i]",
                 _sl_got(v, r, 13));
        return r;
    }
    /* framebuffer[0] right (its texture, its depth buffer), the textures right, and only one framebuffer complete
     * without its own texture: framebuffer[1] never got moments[1] (a name never generated, or not bound) */
    for (int r = 0; r < v->k->rows && v->f->output_count >= 16; r++) {
        if (!_sl_failed(v, r)) continue;
        bool textures_right = true;
        for (int o = 0; o < 11; o++) textures_right &= fabs(_sl_got(v, r, o) - _sl_want(v, r, o)) <= 1e-6;
        if (!textures_right || _sl_got(v, r, 15) != 1 || _sl_got(v, r, 12) != 1 || _sl_got(v, r, 11) != 0 ||
            _sl_got(v, r, 13) != 1)
            break;
        snprintf(text, n, "framebuffer[0] is right but framebuffer[1] is not complete and holds no moments[1] at "
                          "GL_COLOR_ATTACHMENT0: the second framebuffer was never made (glGenFramebuffers(2, "
                          "target->framebuffer) makes both names) or moments[1] was attached with another one bound");
        return r;
    }
    GLenum format = 0;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        for (int o = 2; o < v->f->output_count; o++)
            if (fabs(_sl_got(v, r, o) - _sl_want(v, r, o)) > 1e-6) return -1; /* more than the format */
        for (int o = 0; o < 2; o++)
            if (_sl_got(v, r, o) != _sl_want(v, r, o) && !format) format = (GLenum)_sl_got(v, r, o);
        if (first < 0) first = r;
    }
    if (first < 0 || !format) return -1;
    int bits = format == GL_RG16F || format == GL_RG16 || format == GL_R16F || format == GL_R16 ? 16
               : format == GL_RG8 || format == GL_R8                                           ? 8
                                                                                                : 0;
    bool one_channel = format == GL_R32F || format == GL_R16F || format == GL_R16 || format == GL_R8;
    if (one_channel)
        snprintf(text, n, "the moments are stored as %s, which has no green channel: the second moment E[x^2] is "
                          "dropped — create moments[0] and moments[1] as GL_RG32F, format GL_RG",
                 sl_gl_enum_name(format));
    else if (bits)
        snprintf(text, n, "the moments are stored as %s (%d-bit %s per channel): the variance E[x^2] - E[x]^2 is the "
                          "difference of two nearly equal numbers, and %d bits round it away (precision): create "
                          "moments[0] and moments[1] as GL_RG32F",
                 sl_gl_enum_name(format), bits, format == GL_RG16F || format == GL_R16F ? "float" : "fixed point", bits);
    else
        snprintf(text, n, "the moments are stored as %s: create moments[0] and moments[1] as GL_RG32F, two 32-bit "
                          "float channels for the depth and its square", sl_gl_enum_name(format));
    return first;
}

/* lab5_begin_moments_pass's probe: which framebuffer it binds (0 or 1, -1 another), then the state and what
 * framebuffer[0] holds after it, each said as the contract's step that sets it. */
static int _sl_verdict_moments_pass(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 0))) continue;
        double bound = _sl_got(v, r, 0);
        if (bound != 0)
            snprintf(text, n, "it binds %s, where the moments pass draws into framebuffer[0]: moments[0] with the depth "
                              "buffer, which the horizontal blur then reads — framebuffer[1] is the blur's",
                     bound == 1 ? "framebuffer[1]" : "neither of the target's framebuffers");
        else if (_sl_got(v, r, 1) != _sl_want(v, r, 1) || _sl_got(v, r, 2) != _sl_want(v, r, 2))
            _sl_viewport_said(text, n, _sl_got(v, r, 1), _sl_got(v, r, 2), _sl_want(v, r, 1), _sl_want(v, r, 2),
                              "the target's", "glViewport(0, 0, target->size, target->size) after binding");
        else if (_sl_got(v, r, 7) != _sl_want(v, r, 7) || _sl_got(v, r, 8) != _sl_want(v, r, 8))
            snprintf(text, n, "framebuffer[0]'s moments are (%.3g, %.3g) after it, not (1, 1): clear the colour to the "
                              "moments of \"nothing in front\", glClearColor(1, 1, 0, 0) before glClear(GL_COLOR_BUFFER_BIT "
                              "| GL_DEPTH_BUFFER_BIT), with framebuffer[0] bound",
                     _sl_got(v, r, 7), _sl_got(v, r, 8));
        else if (_sl_got(v, r, 6) != _sl_want(v, r, 6))
            snprintf(text, n, "framebuffer[0]'s depth is %.3g after it, not 1.0: clear the depth too (GL_DEPTH_BUFFER_BIT, "
                              "with depth writes on), or the last frame's depths hide this frame's surfaces",
                     _sl_got(v, r, 6));
        else
            return -1;
        sl_verdict_predicts(v, SL_SYMPTOMS_ANY);
        return r;
    }
    return -1;
}

/* lab5_begin_blur_pass's probe: the ping-pong, framebuffer and texture, in the contract's words. */
static int _sl_verdict_blur_pass(const sl_verdict_rows *v, char *text, size_t n) {
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r) || isnan(_sl_got(v, r, 0))) continue;
        int direction = (int)v->k->inputs[r][0];
        double drawn = _sl_got(v, r, 0), read = _sl_got(v, r, 1);
        if (drawn != _sl_want(v, r, 0) || read != _sl_want(v, r, 1)) {
            char drawn_text[40], read_text[60];
            snprintf(drawn_text, sizeof drawn_text, drawn < 0 ? "neither framebuffer" : "framebuffer[%.0f]", drawn);
            snprintf(read_text, sizeof read_text, read < 0 ? "neither moments texture on unit 0" : "moments[%.0f]", read);
            snprintf(text, n, "direction %d draws into %s and reads %s, where it reads moments[%d] (bound on texture "
                              "unit 0: glActiveTexture(GL_TEXTURE0) first) and draws into framebuffer[%d] — the "
                              "ping-pong: direction 0 from [0] into [1], direction 1 from [1] into [0]",
                     direction, drawn_text, read_text, direction, 1 - direction);
        } else if (_sl_got(v, r, 2) != _sl_want(v, r, 2) || _sl_got(v, r, 3) != _sl_want(v, r, 3)) {
            _sl_viewport_said(text, n, _sl_got(v, r, 2), _sl_got(v, r, 3), _sl_want(v, r, 2), _sl_want(v, r, 3),
                              "the target's", "glViewport(0, 0, size, size), every pass");
        } else if (_sl_got(v, r, 4) != _sl_want(v, r, 4)) {
            snprintf(text, n, "the depth test is still on: a full-screen pass tests nothing, glDisable(GL_DEPTH_TEST)");
        } else {
            return -1;
        }
        sl_verdict_predicts(v, SL_SYMPTOMS_ANY);
        return r;
    }
    return -1;
}

static bool _sl_mipmapped(double filter) {
    return filter == GL_LINEAR_MIPMAP_LINEAR || filter == GL_LINEAR_MIPMAP_NEAREST || filter == GL_NEAREST_MIPMAP_LINEAR ||
           filter == GL_NEAREST_MIPMAP_NEAREST;
}

/* The blur reads moments[0], then moments[1], and draws into framebuffer[1], then [0]. A texture whose min
 * filter wants mipmaps it lacks is incomplete and reads as 0; an incomplete framebuffer[1] takes no pass.
 * Either leaves (0, 0) in the blurred moments, which must not be taken for a clear to (0, 0). (moments[0]
 * without mipmaps is said by _sl_mipmaps_ok.) */
static bool _sl_blur_targets_ok(const sl_case_result *r, sl_check_result *out) {
    const sl_capture *t = sl_result_capture(r, "moments_target");
    if (!t || t->number_count < SL_MOMENTS_TARGET_NUMBERS) return true;
    const double *v = t->numbers;
    if (v[0] == GL_FRAMEBUFFER_COMPLETE && v[12] != GL_FRAMEBUFFER_COMPLETE) {
        if (v[12] == 0)
            sl_diag_say(out, "framebuffer[1] of the moments target, which the blur's first pass draws into, is not a "
                             "framebuffer object: that pass writes nothing, and the second reads moments[1] unwritten");
        else
            sl_diag_say(out, "framebuffer[1] of the moments target, which the blur's first pass draws into, is not "
                             "complete (%s): that pass writes nothing, and the second reads moments[1] unwritten",
                        sl_gl_enum_name((GLenum)v[12]));
        sl_diag_cause_in(out, "lab5_create_moments_target", "both framebuffers complete, moments[i] as framebuffer[i]'s "
                           "GL_COLOR_ATTACHMENT0, and SL_FAILED when one is not (TODO(lab5.1) in labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (v[10] <= 0 && _sl_mipmapped(v[11])) {
        sl_diag_say(out, "moments[1], which the blur's second pass reads, is filtered with %s but has no mipmaps: an "
                         "incomplete texture, which reads as 0, so the blurred moments are (0, 0)",
                    sl_gl_enum_name((GLenum)v[11]));
        sl_diag_cause_in(out, "lab5_create_moments_target", "give each moments texture the min filter GL_LINEAR when "
                           "lab5_create_moments_target() makes it: GL's default, GL_NEAREST_MIPMAP_LINEAR, wants mipmaps (TODO(lab5.1) in "
                           "labs/lab5_vsm/lab5.c)");
        return false;
    }
    return true;
}

/* Where nothing is drawn the moments must say "nothing in front", (1, 1); cleared to (0, 0) they say "an
 * occluder at the light". Exactly (0, 0) survives the blur inside such a region, so the blurred moments show it. */
/* what a clear to (1, 1) takes: the colour is the one set when glClear runs, and the colour bit */
#define _SL_CLEAR_RULE                                                                                              \
    "glClearColor(1, 1, 0, 0) before glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT), which clears with the "  \
    "colour set when it runs"

static double _sl_zero_share(const sl_image *m) {
    long n = (long)m->width * m->height, zero = 0;
    for (long i = 0; i < n; i++) zero += m->data[2 * i] == 0.0f && m->data[2 * i + 1] == 0.0f;
    return n ? (double)zero / (double)n : 0;
}

static bool _sl_moments_pass_cleared_to_zero(const sl_case_result *r);

static bool _sl_cleared_to_zero(const sl_case_result *r, sl_check_result *out) {
    const sl_capture *m = sl_result_capture(r, "moments_blurred");
    if (!_sl_moments_pass_cleared_to_zero(r)) return false; /* the zeros came later: a blur pass's */
    if (!m || !m->image.data || m->image.channels != 2) return false;
    double zero = _sl_zero_share(&m->image);
    if (zero < 0.02) return false;
    sl_diag_say(out, "the moments hold exactly (0, 0) on %.0f%% of the map: \"an occluder at the light\" wherever "
                     "nothing is drawn, so everything outside the objects' footprint seen from the light is shadowed "
                     "— the colour clear did not write (1, 1) there: %s",
                100 * zero, _SL_CLEAR_RULE);
    sl_diag_cause_in(out, "lab5_begin_moments_pass", "the moments target is cleared to (0, 0): lab5_begin_moments_pass() clears it to (1, 1), the "
                       "moments of \"nothing in front\" (glClearColor(1, 1, 0, 0); TODO(lab5.2) in labs/lab5_vsm/lab5.c)");
    return true;
}

/* The camera pass reads moments[0] with its mipmaps: made for it, and its min filter mipmapped. */
static bool _sl_mipmaps_ok(const sl_case_result *r, sl_check_result *out) {
    const sl_capture *t = sl_result_capture(r, "moments_target");
    if (!t || t->number_count < SL_MOMENTS_TARGET_NUMBERS) return true;
    const double *v = t->numbers;
    double level1[2] = {v[8], v[10]}, filter0 = v[9];
    bool mipmapped = _sl_mipmapped(filter0);
    if (level1[0] <= 0 && level1[1] > 0) {
        sl_diag_say(out, "moments[0], which the camera pass reads, has no mipmaps (min filter %s), while moments[1], the "
                         "blur's intermediate, has: distant receivers read unfiltered moments and alias",
                    sl_gl_enum_name((GLenum)filter0));
        sl_diag_cause_in(out, "lab5_filter_moments", "the mipmaps were made for the wrong texture: lab5_filter_moments() binds moments[0] before "
                           "glGenerateMipmap and sets its GL_LINEAR_MIPMAP_LINEAR (TODO(lab5.6) in labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (level1[0] <= 0 && mipmapped) {
        sl_diag_say(out, "moments[0] is filtered with %s but has no mipmaps: an incomplete texture, which reads as 0 "
                         "(every receiver shadowed)", sl_gl_enum_name((GLenum)filter0));
        sl_diag_cause_in(out, "lab5_filter_moments", "glGenerateMipmap on moments[0] in lab5_filter_moments() (TODO(lab5.6) in "
                           "labs/lab5_vsm/lab5.c), after the blur wrote it");
        return false;
    }
    if (level1[0] > 0 && (filter0 == GL_NEAREST_MIPMAP_LINEAR || filter0 == GL_NEAREST_MIPMAP_NEAREST)) {
        sl_diag_say(out, "moments[0] is minified with %s: within each mipmap level the lookup takes the one nearest "
                         "texel, so its result steps at texel edges where a filtered shadow must blend",
                    sl_gl_enum_name((GLenum)filter0));
        sl_diag_cause_in(out, "lab5_filter_moments", "GL_LINEAR_MIPMAP_LINEAR as moments[0]'s min filter in "
                         "lab5_filter_moments(): linear within a level and between levels (TODO(lab5.6) in "
                         "labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (v[18] == GL_NEAREST) {
        sl_diag_say(out, "moments[0] is magnified with GL_NEAREST: where a texel covers several pixels, the lookup's "
                         "result steps at texel edges instead of blending between texels");
        sl_diag_cause_in(out, "lab5_filter_moments", "GL_LINEAR as moments[0]'s GL_TEXTURE_MAG_FILTER in "
                         "lab5_filter_moments(), which sets how the camera pass samples the moments (TODO(lab5.6) in "
                         "labs/lab5_vsm/lab5.c)");
        return false;
    }
    if (level1[0] > 0 && filter0 != 0 && !mipmapped) {
        sl_diag_say(out, "moments[0] has mipmaps but is read with %s: distant receivers read level 0 alone and alias",
                    sl_gl_enum_name((GLenum)filter0));
        sl_diag_cause_in(out, "lab5_filter_moments", "GL_LINEAR_MIPMAP_LINEAR as moments[0]'s min filter in lab5_filter_moments() (TODO(lab5.6) "
                           "in labs/lab5_vsm/lab5.c)");
        return false;
    }
    return true;
}

/* Whether the moments pass's own output (where it was captured) holds (0, 0) on more than 2% of the map:
 * without it, zeros in the blurred moments cannot be the clear's. True when it was not captured. */
static bool _sl_moments_pass_cleared_to_zero(const sl_case_result *r) {
    const sl_capture *cap = sl_result_capture(r, sl_capture_name(SL_CAPTURE_MOMENTS_PASSES));
    if (!cap || !cap->image.data || cap->image.channels != 2 || cap->image.height != 3 * cap->image.width) return true;
    sl_image m = {cap->image.width, cap->image.width, 2, cap->image.data};
    return isnan(m.data[0]) || _sl_zero_share(&m) >= 0.02;
}

/* ---- the passes, one after the other ----
 *
 * The runner reads back what each pass drew (SL_CAPTURE_MOMENTS_PASSES): the moments pass, the blur's
 * horizontal pass, its vertical pass. Each blur pass is compared with what the contract computes from
 * the student's OWN previous stage (README: a Gaussian with sigma = radius / 2, radius texels each side,
 * the edge texels repeated), so an earlier pass's mistake is never blamed on a later one. */

/* Stage `stage` of the stacked capture, as an image that borrows its rows. */
static sl_image _sl_stage(const sl_image *passes, int stage) {
    int size = passes->width;
    return (sl_image){size, size, 2, passes->data + (size_t)stage * size * size * 2};
}

static bool _sl_stage_drawn(const sl_image *m) {
    long n = (long)m->width * m->height;
    for (long i = 0; i < n; i++)
        if (!isnan(m->data[2 * i])) return true;
    return false;
}

/* The contract's 1-D blur of `in` along x (dx 1) or y, into a new image. */
static sl_image _sl_contract_blur(const sl_image *in, int radius, int dx, int dy) {
    sl_image out = sl_image_alloc(in->width, in->height, 2);
    if (!out.data) return out;
    double sigma = fmax(radius * 0.5, 0.5), weights[2 * 32 + 1], total = 0;
    for (int i = -radius; i <= radius; i++) total += weights[i + radius] = exp(-(double)(i * i) / (2 * sigma * sigma));
    for (int y = 0; y < in->height; y++)
        for (int x = 0; x < in->width; x++)
            for (int ch = 0; ch < 2; ch++) {
                double sum = 0;
                for (int i = -radius; i <= radius; i++) {
                    int sx = x + i * dx, sy = y + i * dy;
                    sx = sx < 0 ? 0 : sx >= in->width ? in->width - 1 : sx;
                    sy = sy < 0 ? 0 : sy >= in->height ? in->height - 1 : sy;
                    sum += weights[i + radius] * in->data[((long)sy * in->width + sx) * 2 + ch];
                }
                out.data[((long)y * in->width + x) * 2 + ch] = (float)(sum / total);
            }
    return out;
}

/* The share of texels where `a` departs from `b` by more than `tolerance` in either moment (NaN departs),
 * and the largest such difference. */
static double _sl_departs(const sl_image *a, const sl_image *b, double tolerance, double *largest) {
    long n = (long)a->width * a->height, off = 0;
    double worst = 0;
    for (long i = 0; i < 2 * n; i += 2) {
        double d = fmax(fabs((double)a->data[i] - b->data[i]), fabs((double)a->data[i + 1] - b->data[i + 1]));
        if (isnan(d)) d = INFINITY;
        if (d > tolerance) {
            off++;
            if (d > worst) worst = d;
        }
    }
    if (largest) *largest = worst;
    return n ? (double)off / (double)n : 0;
}

/* The tolerance of "equals" between two stages: far above float noise, far below a blur's effect. */
#define _SL_STAGE_TOLERANCE 2e-3
#define _SL_STAGE_SHARE 0.01

static bool _sl_equals(const sl_image *a, const sl_image *b) {
    return _sl_departs(a, b, _SL_STAGE_TOLERANCE, NULL) <= _SL_STAGE_SHARE;
}

static const char *_sl_moments_name(double which) {
    return which == 0 ? "moments[0]" : which == 1 ? "moments[1]" : which == -1 ? "a texture not of the target"
                                                                                : "no texture";
}

static const char *_sl_framebuffer_name(double which) {
    return which == 0 ? "framebuffer[0]" : which == 1 ? "framebuffer[1]" : which == -1 ? "a framebuffer not of the target"
                                                                                       : "the default framebuffer";
}

/* The first of lab 5's passes that departs from what it must compute from its own input, said; false when
 * every blur pass does what the contract asks of what it read (then the moments pass is what differs). */
static bool _sl_passes_depart(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    const sl_capture *cap = sl_result_capture(r, sl_capture_name(SL_CAPTURE_MOMENTS_PASSES));
    int radius = c->params.vsm.blur_radius < 32 ? c->params.vsm.blur_radius : 32;
    if (!cap || !cap->image.data || cap->image.channels != 2 || cap->image.height != 3 * cap->image.width ||
        radius <= 0 || c->params.vsm_off)
        return false;
    const sl_capture *t = sl_result_capture(r, "moments_target");
    double read[2] = {-3, -3}, drew[2] = {-3, -3}; /* -3: not known */
    if (t && t->number_count >= SL_MOMENTS_TARGET_NUMBERS)
        for (int i = 0; i < 2; i++) {
            read[i] = t->numbers[14 + i];
            drew[i] = t->numbers[16 + i];
        }
    sl_image m = _sl_stage(&cap->image, 0), x = _sl_stage(&cap->image, 1), y = _sl_stage(&cap->image, 2);
    if (!_sl_stage_drawn(&m)) return false; /* the moments pass drew into no framebuffer object: said elsewhere */
    static const char *const pass_names[2] = {"first (horizontal)", "second (vertical)"};
    const sl_image *outputs[2] = {&x, &y};
    for (int pass = 0; pass < 2; pass++)
        if (!_sl_stage_drawn(outputs[pass])) {
            sl_diag_say(out, "the blur's %s pass drew into %s, not one of the moments target's complete framebuffers: "
                             "nothing it computed reaches the moments", pass_names[pass], _sl_framebuffer_name(drew[pass]));
            sl_diag_cause_in(out, "lab5_begin_blur_pass", "lab5_begin_blur_pass() binds framebuffer[1] for direction 0 "
                             "and framebuffer[0] for direction 1 (TODO(lab5.4) in labs/lab5_vsm/lab5.c)");
            return true;
        }
    bool said = false;
    double largest = 0;
    sl_image hm = _sl_contract_blur(&m, radius, 1, 0), vm = _sl_contract_blur(&m, radius, 0, 1), vx = {0}, hx = {0};
    if (!hm.data || !vm.data) goto done;
    double off1 = _sl_departs(&x, &hm, _SL_STAGE_TOLERANCE, &largest);
    if (off1 > _SL_STAGE_SHARE) {
        said = true;
        if (read[0] != -3 && read[0] != 0) {
            sl_diag_say(out, "the blur's first (horizontal) pass departs from a blur of the moments pass's output on "
                             "%.0f%% of the texels: it read %s on unit 0, where the moments pass drew into moments[0]",
                        100 * off1, _sl_moments_name(read[0]));
            sl_diag_cause_in(out, "lab5_begin_blur_pass", "for direction 0, lab5_begin_blur_pass() binds moments[0] "
                             "on GL_TEXTURE0 and draws into framebuffer[1] (TODO(lab5.4) in labs/lab5_vsm/lab5.c)");
        } else if (_sl_equals(&x, &m)) {
            sl_diag_say(out, "the blur's first (horizontal) pass leaves its input as it is: its output equals the "
                             "moments pass's on %.0f%% of the texels, where a blur of radius %d changes %.0f%% of them",
                        100 * (1 - _sl_departs(&x, &m, _SL_STAGE_TOLERANCE, NULL)), radius,
                        100 * _sl_departs(&hm, &m, _SL_STAGE_TOLERANCE, NULL));
            sl_diag_cause_in(out, "blur_moments", "blur_moments() returns the weighted sum of 2 * radius + 1 texels along "
                             "direction, not the centre texel alone (TODO(lab5.5) in labs/lab5_vsm/shaders/blur.glsl)");
        } else if (_sl_equals(&x, &vm)) {
            sl_diag_say(out, "the blur's first pass, asked for direction (1, 0), blurs along y: its output equals a "
                             "vertical blur of the moments pass's");
            sl_diag_cause_in(out, "blur_moments", "blur_moments() steps along `direction` (x for (1, 0)) (TODO(lab5.5) in "
                             "labs/lab5_vsm/shaders/blur.glsl)");
        } else {
            /* a narrower or wider kernel: edges along x sharper or softer than the contract's blur of the same input */
            double sharp = _sl_gradient_energy(&x, 1, 0) / fmax(_sl_gradient_energy(&hm, 1, 0), 1e-12);
            if (sharp > 1.2 || sharp < 0.83)
                sl_diag_say(out, "the blur's first (horizontal) pass blurs %s than the Gaussian of radius %d along x of its "
                                 "input (the moments pass's output, which is right): its edges along x are %.2fx as sharp "
                                 "as the contract's blur of the same input (it departs on %.0f%% of the texels, by up to "
                                 "%.3g)",
                            sharp > 1 ? "less" : "more", radius, sharp, 100 * off1, largest);
            else
                sl_diag_say(out, "the blur's first (horizontal) pass departs from the Gaussian blur of radius %d along x "
                                 "of its input (the moments pass's output, as captured) on %.0f%% of the texels, by up to "
                                 "%.3g; the passes before it are right",
                            radius, 100 * off1, largest);
            sl_diag_cause_in(out, "blur_moments", "blur_moments(): sigma = max(float(radius) * 0.5, 0.5), offsets of one "
                             "texel along direction, radius texels each side, weights that sum to 1 (TODO(lab5.5))");
        }
        goto done;
    }
    vx = _sl_contract_blur(&x, radius, 0, 1);
    hx = _sl_contract_blur(&x, radius, 1, 0);
    if (!vx.data || !hx.data) goto done;
    double off2 = _sl_departs(&y, &vx, _SL_STAGE_TOLERANCE, &largest);
    if (off2 > _SL_STAGE_SHARE) {
        said = true;
        bool feedback = read[1] != -3 && read[1] >= 0 && read[1] == drew[1];
        if (_sl_equals(&y, &vm) && !_sl_equals(&vm, &vx)) {
            sl_diag_say(out, "the first blur pass is right, but the second blur pass reads the unblurred moments: its "
                             "output equals a 1-D (vertical) blur of the moments pass's, not of the first pass's output%s%s%s",
                        read[1] != -3 ? " (it read " : "", read[1] != -3 ? _sl_moments_name(read[1]) : "",
                        read[1] != -3 ? " on unit 0)" : "");
            sl_diag_cause_in(out, "lab5_begin_blur_pass", "for direction 1, lab5_begin_blur_pass() binds moments[1], "
                             "the first pass's output, on GL_TEXTURE0 and draws into framebuffer[0] (TODO(lab5.4) in "
                             "labs/lab5_vsm/lab5.c)");
        } else if (_sl_equals(&y, &hx)) {
            sl_diag_say(out, "the first blur pass is right, but the second, asked for direction (0, 1), blurs along x "
                             "again: the moments are blurred along x only (its output equals a horizontal blur of the "
                             "first pass's)");
            sl_diag_cause_in(out, "blur_moments", "blur_moments() steps along `direction`, (0, 1) in the second pass "
                             "(TODO(lab5.5) in labs/lab5_vsm/shaders/blur.glsl)");
        } else if (_sl_equals(&y, &x)) {
            sl_diag_say(out, "the first blur pass is right, but the second leaves the first's output as it is: no "
                             "vertical blur");
            sl_diag_cause_in(out, "blur_moments", "blur_moments() blurs along `direction` in both passes (TODO(lab5.5)), "
                             "and lab5_begin_blur_pass() runs the second pass from moments[1] into framebuffer[0] "
                             "(TODO(lab5.4))");
        } else {
            /* some texels right, the rest as the target held them before the pass: not written */
            long n = (long)y.width * y.height, right = 0, kept = 0;
            const sl_image *before = drew[1] == 0 ? &m : drew[1] == 1 ? &x : NULL;
            for (long i = 0; i < 2 * n; i += 2) {
                bool is_right = fabs(y.data[i] - vx.data[i]) <= _SL_STAGE_TOLERANCE &&
                                fabs(y.data[i + 1] - vx.data[i + 1]) <= _SL_STAGE_TOLERANCE;
                right += is_right;
                kept += !is_right && before && fabs(y.data[i] - before->data[i]) <= 1e-6 &&
                        fabs(y.data[i + 1] - before->data[i + 1]) <= 1e-6;
            }
            if (before && kept > n / 100 && right + kept > n * 98 / 100 && !feedback) {
                sl_diag_say(out, "the first blur pass is right, but the second left %.0f%% of the texels of %s as they "
                                 "were before it (%s): only the other %.0f%% hold the vertical blur. Those texels were "
                                 "not written — a test still on from the moments pass (the depth test, with "
                                 "framebuffer[0]'s depth buffer, keeps every texel whose depth is nearer than the "
                                 "full-screen triangle's)",
                            100.0 * kept / n, _sl_framebuffer_name(drew[1]),
                            drew[1] == 0 ? "the moments pass's output" : "the first pass's output", 100.0 * right / n);
                sl_diag_cause_in(out, "lab5_begin_blur_pass", "a full-screen pass writes every texel: "
                                 "lab5_begin_blur_pass() disables the depth test (glDisable(GL_DEPTH_TEST); TODO(lab5.4) "
                                 "in labs/lab5_vsm/lab5.c)");
            } else {
                sl_diag_say(out, "the first blur pass is right, but the second (vertical) departs from the Gaussian "
                                 "blur of radius %d along y of the first pass's output on %.0f%% of the texels, by up to "
                                 "%.3g%s",
                            radius, 100 * off2, largest,
                            feedback ? "; it reads the texture it draws into (a feedback loop: undefined results)" : "");
                sl_diag_cause_in(out, feedback ? "lab5_begin_blur_pass" : "blur_moments",
                                 feedback ? "for direction 1, lab5_begin_blur_pass() binds moments[1] on GL_TEXTURE0 "
                                            "and draws into framebuffer[0] (TODO(lab5.4))"
                                          : "blur_moments() along (0, 1): sigma = max(float(radius) * 0.5, 0.5), "
                                            "offsets of one texel, radius texels each side (TODO(lab5.5))");
            }
        }
        goto done;
    }
    const sl_capture *camera = sl_result_capture(r, "moments_blurred");
    if (camera && camera->image.data && camera->image.width == y.width && camera->image.height == y.height &&
        camera->image.channels == 2 && !_sl_equals(&camera->image, &y)) {
        said = true;
        const char *holds = _sl_equals(&camera->image, &m) ? "the moments pass's output, unblurred"
                            : _sl_equals(&camera->image, &x) ? "the first blur pass's output, blurred along x only"
                                                              : "neither blur pass's output";
        sl_diag_say(out, "both blur passes compute what they must from their inputs, but the second drew into %s, and "
                         "moments[0], which the camera pass reads, holds %s",
                    _sl_framebuffer_name(drew[1]), holds);
        sl_diag_cause_in(out, "lab5_begin_blur_pass", "the second pass (direction 1) draws into framebuffer[0], whose "
                         "colour attachment is moments[0] (TODO(lab5.4) in labs/lab5_vsm/lab5.c)");
    }
done:
    sl_image_free(&hm);
    sl_image_free(&vm);
    sl_image_free(&vx);
    sl_image_free(&hx);
    return said;
}

bool sl_diagnose_lab5_format(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    /* an incomplete texture or framebuffer leaves (0, 0) too: said before the clear is blamed */
    return !_sl_format_ok(r, out) || !_sl_blur_targets_ok(r, out) || !_sl_mipmaps_ok(r, out) ||
           _sl_cleared_to_zero(r, out) || _sl_passes_depart(c, r, out);
}

void sl_diagnose_moments(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                         sl_check_result *out) {
    bool blurred = k->kind == SL_CHECK_MOMENTS_BLURRED;
    const char *capture = sl_check_capture_name(c, k);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no moments were captured");
        out->settled = true;
        return;
    }
    const sl_image *s = &cap->image, *t = &ref->image;
    if (s->width != t->width || s->height != t->height || s->channels != 2 || t->channels != 2) {
        sl_diag_say(out, "the moments are %dx%dx%d, the reference %dx%dx%d", s->width, s->height, s->channels,
                    t->width, t->height, t->channels);
        out->settled = true;
        return;
    }
    bool format_ok = _sl_format_ok(r, out);
    static const char *const names[2] = {"the first moment (depth)", "the second moment (depth^2)"};
    sl_compare_stats st[2];
    bool ok[2];
    for (int ch = 0; ch < 2; ch++) {
        sl_image a = _sl_channel(s, ch), b = _sl_channel(t, ch), diff = {0};
        st[ch] = sl_compare_images(&a, &b, k->threshold, &diff);
        ok[ch] = st[ch].failing_fraction <= k->fail_fraction && st[ch].nan_pixels == 0 &&
                 (k->mean_tolerance <= 0 || st[ch].mean_difference <= k->mean_tolerance);
        if (!ok[ch] && !out->diff.data) out->diff = diff;
        else sl_image_free(&diff);
        sl_image_free(&a);
        sl_image_free(&b);
    }
    if (format_ok && ok[0] && ok[1]) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    if (!format_ok) return; /* said: the format comes first */
    long n = (long)s->width * s->height, stub = 0, unsquared = 0, covered = 0;
    for (long i = 0; i < n; i++) {
        float m1 = s->data[2 * i], m2 = s->data[2 * i + 1];
        stub += m1 == 1.0f && m2 == 1.0f;
        if (m1 < 0.98f && t->data[2 * i] < 0.98f) {
            covered++;
            unsquared += fabsf(m2 - m1) < 1e-4f && fabsf(m1 - m1 * m1) > 1e-3f;
        }
    }
    if (blurred && (!_sl_blur_targets_ok(r, out) || !_sl_mipmaps_ok(r, out))) return;
    long empty = 0, zeroed = 0; /* the reference's texels with nothing drawn, (1, 1): here (0, 0)? */
    for (long i = 0; i < n; i++)
        if (t->data[2 * i] > 0.999f && t->data[2 * i + 1] > 0.999f) {
            empty++;
            zeroed += s->data[2 * i] == 0.0f && s->data[2 * i + 1] == 0.0f;
        }
    if (empty > n / 100 && zeroed > empty / 2 && (!blurred || _sl_moments_pass_cleared_to_zero(r))) {
        sl_diag_say(out, "%.0f%% of the texels where nothing is drawn hold (0, 0), the reference (1, 1): \"an occluder "
                         "at the light\" instead of \"nothing in front\" — the colour clear did not write (1, 1) there: "
                         "%s", 100.0 * (double)zeroed / (double)empty, _SL_CLEAR_RULE);
        sl_diag_cause_in(out, "lab5_begin_moments_pass", "the moments target is cleared to (0, 0): lab5_begin_moments_pass() clears it to (1, 1) "
                           "(glClearColor(1, 1, 0, 0); TODO(lab5.2) in labs/lab5_vsm/lab5.c)");
        return;
    }
    if (blurred) {
        /* a blur whose weights do not sum to 1 scales every texel by their sum (squared: two passes) */
        double ratio_sum = 0;
        long ratios = 0, consistent = 0;
        for (long i = 0; i < n; i++)
            if (t->data[2 * i] > 0.05f && isfinite(s->data[2 * i])) {
                ratio_sum += s->data[2 * i] / t->data[2 * i];
                ratios++;
            }
        double ratio = ratios ? ratio_sum / (double)ratios : 1;
        for (long i = 0; i < n; i++)
            if (t->data[2 * i] > 0.05f) consistent += fabs(s->data[2 * i] / t->data[2 * i] - ratio) < 0.05 * ratio;
        if (ratios > n / 2 && (ratio > 1.2 || ratio < 0.8) && consistent > ratios * 0.9) {
            sl_diag_say(out, "the blurred moments are %.3g times the reference's on %.0f%% of the texels: every texel "
                             "scaled alike, where a blur keeps a flat region as it is", ratio,
                        100.0 * (double)consistent / (double)ratios);
            sl_diag_cause_in(out, "blur_moments", "the blur's weights do not sum to 1 (%.3g per pass, as two passes multiply): divide "
                               "blur_moments()'s weighted sum by the sum of its weights (TODO(lab5.5) in "
                               "labs/lab5_vsm/shaders/blur.glsl)", sqrt(ratio));
            return;
        }
    }
    if (stub == n) {
        sl_diag_say(out, "the moments are (1, 1) on every texel: nothing in front of anything");
        sl_diag_cause_in(out, "compute_moments", "compute_moments() still returns its stub's vec2(1.0) (TODO(lab5.3) in "
                           "labs/lab5_vsm/shaders/moments.glsl), or nothing was drawn into framebuffer[0]");
        return;
    }
    if (covered > 0 && unsquared > covered / 2) {
        sl_diag_say(out, "the second moment equals the first on %.0f%% of the scene's texels: depth is stored where "
                         "depth^2 belongs, so the variance depth - depth^2 is large everywhere",
                    100.0 * (double)unsquared / (double)covered);
        sl_diag_cause_in(out, "compute_moments", "compute_moments() must return vec2(depth, depth * depth) (TODO(lab5.3) in "
                           "labs/lab5_vsm/shaders/moments.glsl)");
        return;
    }
    if (blurred && _sl_passes_depart(c, r, out)) return;
    if (blurred && ok[0] + ok[1] < 2) {
        /* a blur lowers the differences between neighbours in its direction: compare both directions' */
        double sharp_x = _sl_gradient_energy(s, 1, 0) / fmax(_sl_gradient_energy(t, 1, 0), 1e-12);
        double sharp_y = _sl_gradient_energy(s, 0, 1) / fmax(_sl_gradient_energy(t, 0, 1), 1e-12);
        if (sharp_x > 1.5 && sharp_y > 1.5) {
            sl_diag_say(out, "the moments are sharper than the reference's along both x and y (%.1fx and %.1fx the "
                             "differences between neighbours): not blurred, or blurred less",
                        sharp_x, sharp_y);
            sl_diag_cause_in(out, "blur_moments", "blur_moments() (TODO(lab5.5) in labs/lab5_vsm/shaders/blur.glsl): 2 * radius + 1 "
                               "Gaussian weights, offsets of one texel (1.0 / textureSize) along direction");
            return;
        }
        if ((sharp_x > 1.5) != (sharp_y > 1.5)) {
            bool only_x = sharp_y > 1.5;
            sl_diag_say(out, "the moments are blurred along %s only: along %s their edges are %.1fx as sharp as the "
                             "reference's, so a penumbra is wide one way and hard the other",
                        only_x ? "x" : "y", only_x ? "y" : "x", only_x ? sharp_y : sharp_x);
            sl_diag_cause_in(out, "blur_moments", "the vertical pass must read moments[1] and step along (0, 1): does blur_moments() use "
                               "`direction` (TODO(lab5.5)), and lab5_begin_blur_pass() read and write the other "
                               "target for direction 1 (TODO(lab5.4))?");
            return;
        }
        if (sharp_x < 0.67 && sharp_y < 0.67) {
            sl_diag_say(out, "the moments are blurrier than the reference's (%.2fx and %.2fx its differences between "
                             "neighbours along x and y)", sharp_x, sharp_y);
            sl_diag_cause_in(out, "blur_moments", "blur_moments(): sigma = max(float(radius) * 0.5, 0.5), offsets of one texel, radius texels "
                               "each side (TODO(lab5.5))");
            return;
        }
    }
    int ch = ok[0] ? 1 : 0;
    sl_diag_say(out, "%s differs from the reference on %.2f%% of texels (allowed %.2f%%, threshold %g; mean "
                     "difference %.5f)", names[ch], 100 * st[ch].failing_fraction, 100 * k->fail_fraction,
                k->threshold, st[ch].mean_difference);
    if (st[ch].nan_pixels) sl_diag_append(out, "; %ld texels are NaN", st[ch].nan_pixels);
    /* no finding of its own: the core lists the candidates, and what their probes ruled out */
}

/* Light bleeding: where the reference (with the reduction) is in umbra, the
 * fraction of pixels lit above the check's threshold here, with and without it. */
static double _sl_bleed(const sl_image *v, const sl_image *t, const sl_image *mask, double threshold, long *umbra) {
    long n = (long)t->width * t->height, in = 0, lit = 0;
    for (long i = 0; i < n; i++) {
        if ((mask && mask->data[i] < 0.5f) || t->data[i] > (float)SL_BLEEDING_UMBRA) continue;
        in++;
        lit += !(v->data[i] <= (float)threshold);
    }
    *umbra = in;
    return in ? (double)lit / (double)in : 0;
}

void sl_diagnose_bleeding(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                          sl_check_result *out) {
    const sl_capture *on = sl_result_capture(r, "visibility"), *off = sl_result_capture(r, "visibility_unreduced");
    if (!on || !off) {
        if (!sl_diag_explain_missing(c, r, out)) sl_diag_say(out, "no visibility was captured");
        out->settled = true;
        return;
    }
    const sl_image *t = &ref->image;
    if (on->image.width != t->width || on->image.height != t->height || off->image.width != t->width ||
        off->image.height != t->height) {
        sl_diag_say(out, "the visibility is %dx%d, the reference %dx%d", on->image.width, on->image.height, t->width,
                    t->height);
        out->settled = true;
        return;
    }
    long umbra = 0;
    /* the lit surfaces as the solutions drew them (the runner's mask would be its own word) */
    const sl_image *m = ref->lit_mask.data && ref->lit_mask.width == t->width && ref->lit_mask.height == t->height
                            ? &ref->lit_mask
                            : NULL;
    double with = _sl_bleed(&on->image, t, m, k->threshold, &umbra),
           without = _sl_bleed(&off->image, t, m, k->threshold, &umbra);
    /* A scene (or a hidden variant of it) whose reference has next to no umbra
     * has no bleeding to measure: nothing to lose. */
    /* an umbra without light is also a picture without light: it must be lit where the reference is */
    bool light_ok = !sl_visibility_lit_lost(&on->image, t, m).failed;
    bool measured_ok = umbra < SL_BLEEDING_MIN_UMBRA_PIXELS ||
                       with <= fmax(SL_BLEEDING_MAX_KEPT * without, SL_BLEEDING_NEGLIGIBLE);
    if (measured_ok && light_ok) {
        out->passed = true;
        return;
    }
    if (sl_diag_explain_missing(c, r, out)) return;
    if (measured_ok && sl_diag_lit_lost(&on->image, t, m, "light bleeding", out)) return;
    if (sl_diagnose_lab5_format(c, r, out)) return;
    if (with > 0.9 && without > 0.9) {
        /* the whole umbra lit either way: the reduction has nothing to act on, the lookup is what is wrong */
        sl_diag_say(out, "%.0f%% of the reference's umbra is lit, with the reduction and without it: there is no "
                         "shadow here for the reduction to act on — the case's visibility check says why", 100 * with);
        out->settled = true;
        return;
    }
    sl_diag_say(out, "light bleeding: %.1f%% of the reference's umbra is lit above %.2f with the reduction (amount "
                     "%.2f), %.1f%% without it; the reduction must at least halve it",
                100 * with, k->threshold, c->params.vsm.bleeding, 100 * without);
    if (with > without) {
        sl_diag_append(out, ", and the reduction adds light to the umbra instead");
        sl_diag_cause_in(out, "reduce_light_bleeding", "are linstep's arguments swapped? reduce_light_bleeding() returns linstep(amount, 1.0, "
                           "p_max) (TODO(lab5.8))");
    } else
        sl_diag_cause_in(out, "reduce_light_bleeding", "reduce_light_bleeding() must cut p_max below `amount` off and stretch the rest: "
                           "linstep(amount, 1.0, p_max) (TODO(lab5.8))");
}

bool sl_diagnose_lab5_visibility(const sl_case *c, const sl_image *s, const sl_image *t, const sl_image *mask,
                                 sl_check_result *out) {
    (void)c;
    sl_acne acne = sl_measure_acne(s, t, mask);
    long nan = 0;
    for (long i = 0; i < (long)s->width * s->height; i++) nan += isnan(s->data[i]);
    if (nan > 0 || sl_acne_is_pattern(&acne)) {
        sl_diag_say(out, "dark speckles on %.1f%% of the lit surfaces%s", 100 * acne.fraction,
                    nan ? " and NaN pixels" : "");
        sl_diag_cause_in(out, "chebyshev_upper_bound", "where t is just beyond mu and the moments are from one flat surface, the variance is 0 "
                           "(or a rounding error below it): is it clamped to min_variance in "
                           "chebyshev_upper_bound() (TODO(lab5.7))?");
        return true;
    }
    if (acne.fraction > 0.2 && acne.mean > 0.5 && acne.mean < 0.97) {
        sl_diag_say(out, "lit surfaces are %s darkened everywhere (mean visibility %.3f where the reference "
                         "is 1)", sl_diag_darkening_word(acne.mean), acne.mean);
        sl_diag_cause_in(out, "chebyshev_upper_bound", "the bound only holds for t > mu: chebyshev_upper_bound() returns 1.0 when t <= mu "
                           "(TODO(lab5.7))");
        return true;
    }
    return false;
}

/* ---- what lab 5's cases run (a first account from the renderer: sl_lab5_vsm.c) ---- */

bool sl_lab5_case_runs(const sl_case *c, const sl_check *k, const char *fn) {
    /* The bleeding check compares the case's visibility with and without the reduction: the moments and
     * their blur are the same in both, so only the lookup's last two steps and the target can explain it. */
    if (k->kind == SL_CHECK_BLEEDING && !c->params.vsm_off)
        return strcmp(fn, "reduce_light_bleeding") == 0 || strcmp(fn, "chebyshev_upper_bound") == 0 ||
               strcmp(fn, "lab5_create_moments_target") == 0;
    /* lab 2's light camera and shadow coordinate; the moments instead of lab 1's map */
    if (strcmp(fn, "lab2_light_view") == 0 || strcmp(fn, "lab2_light_projection") == 0 ||
        strcmp(fn, "lab2_shadow_matrix") == 0)
        return true;
    if (strcmp(fn, "lab5_create_moments_target") == 0 || strcmp(fn, "lab5_begin_moments_pass") == 0 ||
        strcmp(fn, "compute_moments") == 0)
        return true;
    if (k->kind == SL_CHECK_MOMENTS) return false;
    bool blur = c->params.vsm.blur_radius > 0;
    if (strcmp(fn, "lab5_begin_blur_pass") == 0 || strcmp(fn, "blur_moments") == 0) return blur;
    if (strcmp(fn, "lab5_filter_moments") == 0) return true;
    if (k->kind == SL_CHECK_MOMENTS_BLURRED) return false;
    if (strcmp(fn, "shadow_coord") == 0) return true;
    if (c->params.vsm_off) return sl_lab4_case_runs(c, k, fn); /* lab 4's filter draws instead */
    return strcmp(fn, "chebyshev_upper_bound") == 0 || strcmp(fn, "reduce_light_bleeding") == 0;
}

void sl_lab5_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    (void)r;
    if (c->params.vsm_off) sl_lab4_case_path(c, r, out, n);
}

/* ---- lab 5 in the diagnosis table (diagnose/table.c) ---- */
/* With the moments off (--no-vsm), a lab 5 case filters as lab 4's do. */
static bool _sl_lab5_filters_past_edge(const sl_case *c) {
    return c->params.vsm_off && c->params.filter.mode != SL_FILTER_NONE;
}

/* Lab 5's cases look up through the Chebyshev bound. */
static void _sl_lab5_lookup_function(const sl_case *c, const char **function, const char **todo) {
    (void)c;
    *function = "chebyshev_upper_bound()";
    *todo = "lab5.7";
}

const sl_lab_diagnoses sl_lab5_diagnoses = {
    .lab = 5,
    .lookup_function = _sl_lab5_lookup_function,
    .functions = {{"lab5_create_moments_target", _sl_verdict_moments_target},
                  {"lab5_begin_moments_pass", _sl_verdict_moments_pass},
                  {"lab5_begin_blur_pass", _sl_verdict_blur_pass}},
    .unprobed = {{"lab5_filter_moments", 5, "TODO(lab5.6)", false}},
    .filtered_lookup = true,
    .filters_past_edge = _sl_lab5_filters_past_edge,
    .checks = {{SL_CHECK_MOMENTS, sl_diagnose_moments},
               {SL_CHECK_MOMENTS_BLURRED, sl_diagnose_moments},
               {SL_CHECK_BLEEDING, sl_diagnose_bleeding}},
    .visibility = sl_diagnose_lab5_visibility,
    .capture_explains = sl_diagnose_lab5_format,
    .case_runs = sl_lab5_case_runs,
    .case_path = sl_lab5_case_path,
    .rows_verdict = sl_verdict_lab5,
};
