#include "sl_compare.h"

#include <math.h>
#include <stddef.h>

static bool _sl_close_to_neighbourhood(const sl_image *a, const sl_image *b, int x, int y, double t) {
    const float *pa = sl_image_pixel(a, x, y);
    for (int c = 0; c < a->channels; c++)
        if (isnan(pa[c])) return false;
    for (int dy = -SL_COMPARE_RADIUS; dy <= SL_COMPARE_RADIUS; dy++) {
        int yy = y + dy;
        if (yy < 0 || yy >= b->height) continue;
        for (int dx = -SL_COMPARE_RADIUS; dx <= SL_COMPARE_RADIUS; dx++) {
            int xx = x + dx;
            if (xx < 0 || xx >= b->width) continue;
            const float *pb = sl_image_pixel(b, xx, yy);
            bool close = true;
            for (int c = 0; c < a->channels && close; c++) close = fabs((double)pa[c] - (double)pb[c]) <= t;
            if (close) return true;
        }
    }
    return false;
}

sl_compare_stats sl_compare_images(const sl_image *student, const sl_image *reference, double threshold,
                                   sl_image *diff) {
    sl_compare_stats s = {0};
    if (diff) *diff = (sl_image){0};
    if (!student->data || !reference->data || student->width != reference->width ||
        student->height != reference->height || student->channels != reference->channels) {
        s.size_mismatch = true;
        s.failing_fraction = 1;
        return s;
    }
    if (diff) *diff = sl_image_alloc(reference->width, reference->height, 3);
    s.pixels = (long)reference->width * reference->height;
    double sum_s = 0, sum_r = 0, sum_d = 0;
    for (int y = 0; y < reference->height; y++) {
        for (int x = 0; x < reference->width; x++) {
            const float *ps = sl_image_pixel(student, x, y), *pr = sl_image_pixel(reference, x, y);
            bool nan = false;
            for (int c = 0; c < reference->channels; c++) {
                if (isnan(ps[c])) {
                    nan = true;
                    continue;
                }
                double d = fabs((double)ps[c] - (double)pr[c]);
                if (d > s.max_difference) s.max_difference = d;
                sum_d += d / reference->channels;
            }
            s.nan_pixels += nan;
            if (!nan) sum_s += ps[0];
            sum_r += pr[0];
            bool fail = nan || !_sl_close_to_neighbourhood(student, reference, x, y, threshold) ||
                        !_sl_close_to_neighbourhood(reference, student, x, y, threshold);
            s.failing += fail;
            s.failing_shadow_lost += fail && !nan && pr[0] < 0.5f && ps[0] >= 0.5f;
            s.failing_shadow_gained += fail && !nan && pr[0] >= 0.5f && ps[0] < 0.5f;
            if (diff && diff->data) {
                float *pd = sl_image_pixel(diff, x, y);
                float grey = 0;
                for (int c = 0; c < reference->channels && c < 3; c++) grey += pr[c];
                grey = 0.35f * grey / (float)(reference->channels < 3 ? reference->channels : 3);
                if (grey > 1) grey = 0.35f;
                /* by kind: red where the student's is brighter (a missing
                 * shadow), blue where darker (an extra one), magenta for NaN */
                float brighter = nan ? 0 : ps[0] - pr[0];
                static const float missing[3] = {1.0f, 0.15f, 0.1f}, extra[3] = {0.15f, 0.45f, 1.0f},
                                   not_a_number[3] = {1.0f, 0.0f, 1.0f};
                const float *colour = nan ? not_a_number : brighter > 0 ? missing : extra;
                for (int c = 0; c < 3; c++) pd[c] = fail ? colour[c] : grey;
            }
        }
    }
    s.failing_fraction = s.pixels ? (double)s.failing / (double)s.pixels : 0;
    s.mean_student = s.pixels ? sum_s / (double)s.pixels : 0;
    s.mean_difference = s.pixels > s.nan_pixels ? sum_d / (double)(s.pixels - s.nan_pixels) : 0;
    s.mean_reference = s.pixels ? sum_r / (double)s.pixels : 0;
    return s;
}

sl_visibility_stats sl_visibility_compare(const sl_image *student, const sl_image *reference) {
    sl_visibility_stats v = {0};
    if (!student->data || !reference->data || student->width != reference->width ||
        student->height != reference->height)
        return v;
    long n = (long)reference->width * reference->height;
    long ref_shadow = 0, stu_shadow = 0, missing = 0, extra = 0;
    for (long i = 0; i < n; i++) {
        float r = reference->data[i * reference->channels];
        float s = student->data[i * student->channels];
        bool rs = r < 0.5f, ss = !(s >= 0.5f); /* NaN counts as shadow */
        ref_shadow += rs;
        stu_shadow += ss;
        missing += rs && !ss;
        extra += !rs && ss;
    }
    v.reference_shadowed = n ? (double)ref_shadow / (double)n : 0;
    v.student_shadowed = n ? (double)stu_shadow / (double)n : 0;
    v.missing_shadow = ref_shadow ? (double)missing / (double)ref_shadow : 0;
    v.extra_shadow = n - ref_shadow ? (double)extra / (double)(n - ref_shadow) : 0;
    return v;
}

double sl_visibility_shadow_lost(const sl_image *student, const sl_image *reference, const sl_image *lit_mask,
                                 long *shadowed) {
    *shadowed = 0;
    if (!student->data || !reference->data || student->width != reference->width ||
        student->height != reference->height)
        return 0;
    if (lit_mask && (!lit_mask->data || lit_mask->width != reference->width || lit_mask->height != reference->height))
        lit_mask = NULL;
    int w = reference->width, h = reference->height;
    long lost = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (!(sl_image_pixel(reference, x, y)[0] < 0.5f)) continue;
            if (lit_mask && sl_image_pixel(lit_mask, x, y)[0] < 0.5f) continue;
            (*shadowed)++;
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; dy++)
                for (int dx = -1; dx <= 1 && !near; dx++) {
                    int sx = x + dx, sy = y + dy;
                    if (sx >= 0 && sy >= 0 && sx < w && sy < h) near = !(sl_image_pixel(student, sx, sy)[0] >= 0.5f);
                }
            lost += !near;
        }
    return *shadowed ? (double)lost / (double)*shadowed : 0;
}

sl_lit_lost sl_visibility_lit_lost(const sl_image *student, const sl_image *reference, const sl_image *lit_mask) {
    sl_lit_lost l = {0};
    if (!student->data || !reference->data || student->width != reference->width ||
        student->height != reference->height)
        return l;
    long n = (long)reference->width * reference->height, frame = n;
    if (lit_mask) {
        frame = (long)lit_mask->width * lit_mask->height;
        /* a mask of another width, or whose frames do not tile the reference, is no mask of it */
        if (!lit_mask->data || lit_mask->width != reference->width || frame == 0 || n % frame) lit_mask = NULL;
    }
    for (long i = 0; i < n; i++) {
        if (!(reference->data[i * reference->channels] >= 0.5f)) continue;
        if (lit_mask && lit_mask->data[(i % frame) * lit_mask->channels] < 0.5f) continue;
        l.lit++;
        float v = student->data[i * student->channels];
        if (isnan(v)) l.nan++;
        else if (v < 0.5f) l.dark++;
    }
    l.fraction = l.lit ? (double)(l.dark + l.nan) / (double)l.lit : 0;
    l.failed = l.lit >= SL_LIT_MIN_PIXELS && l.fraction > SL_LIT_MAX_LOST;
    return l;
}

sl_flicker sl_flicker_measure(const sl_image *stacked, const sl_image *lit_mask, int frames) {
    sl_flicker f = {0, 0, 0};
    if (!stacked->data || !lit_mask->data || frames < 1) return f;
    long pixels = (long)lit_mask->width * lit_mask->height, changes = 0, dark = 0;
    if (stacked->width != lit_mask->width || (long)stacked->height != (long)lit_mask->height * frames) return f;
    for (long i = 0; i < pixels; i++) {
        if (lit_mask->data[i * lit_mask->channels] < 0.5f) continue;
        f.receivers++;
        for (int frame = 0; frame < frames; frame++) {
            float v = stacked->data[(frame * pixels + i) * stacked->channels];
            dark += !(v >= 0.5f);
            if (frame > 0) {
                float before = stacked->data[((frame - 1) * pixels + i) * stacked->channels];
                changes += (v >= 0.5f) != (before >= 0.5f) || isnan(v) != isnan(before);
            }
        }
    }
    if (f.receivers && frames > 1) f.score = (double)changes / ((double)f.receivers * (frames - 1));
    if (f.receivers) f.shadowed = (double)dark / ((double)f.receivers * frames);
    return f;
}

bool sl_flicker_shadows_kept(const sl_flicker *yours, const sl_flicker *reference) {
    return reference->shadowed < SL_FLICKER_MIN_REFERENCE_SHADOW ||
           yours->shadowed >= SL_FLICKER_MIN_SHADOW_KEPT * reference->shadowed;
}

double sl_fraction_equal(const sl_image *image, float value, float tolerance) {
    long n = (long)image->width * image->height, count = 0;
    if (!image->data || n == 0) return 0;
    for (long i = 0; i < n; i++) count += fabsf(image->data[i * image->channels] - value) <= tolerance;
    return (double)count / (double)n;
}

bool sl_content_only_in_lower_left(const sl_image *image, float clear, int w, int h) {
    if (!image->data || w >= image->width || h >= image->height) return false;
    bool inside_content = false;
    for (int y = 0; y < image->height; y++) {
        bool lower = y >= image->height - h; /* rows are stored top first */
        for (int x = 0; x < image->width; x++) {
            bool content = fabsf(sl_image_pixel(image, x, y)[0] - clear) > 1e-6f;
            if (content && !(lower && x < w)) return false;
            inside_content |= content;
        }
    }
    return inside_content;
}
