/* Measures on the visibility term shared by the labs that compare one. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdlib.h>

/* A pixel of the reference's fully lit surface is darkened here by more than this. */
#define _SL_DARKENED 0.1f
/* ... and belongs to a pattern when a neighbour of the same surface differs from it by more than this. */
#define _SL_PATTERN_STEP 0.15f

sl_acne sl_measure_acne(const sl_image *s, const sl_image *t, const sl_image *mask) {
    sl_acne a = {0};
    int w = t->width, h = t->height;
    long lit = 0, darkened = 0, patterned = 0;
    double sum = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            long i = (long)y * w + x;
            if ((mask && mask->data[i] < 0.5f) || t->data[i] < 0.99f) continue;
            float v = isnan(s->data[i]) ? 0.0f : s->data[i];
            lit++;
            sum += v;
            if (v > t->data[i] - _SL_DARKENED) continue;
            darkened++;
            /* a neighbour on the same lit surface, much brighter or darker */
            static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
            for (int d = 0; d < 4; d++) {
                int nx = x + dx[d], ny = y + dy[d];
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                long j = (long)ny * w + nx;
                if ((mask && mask->data[j] < 0.5f) || t->data[j] < 0.99f) continue;
                if (fabsf(s->data[j] - v) > _SL_PATTERN_STEP) {
                    patterned++;
                    break;
                }
            }
        }
    a.fraction = lit ? (double)darkened / (double)lit : 0;
    a.pattern = darkened ? (double)patterned / (double)darkened : 0;
    a.mean = lit ? sum / (double)lit : 1;
    return a;
}

/* Self-shadowing comes in stripes a pixel or two wide: most darkened pixels
 * sit next to lit ones. A shadow in the wrong place is a solid region, with
 * such pixels along its border only. */
bool sl_acne_is_pattern(const sl_acne *acne) { return acne->fraction > 0.01 && acne->pattern > 0.35; }

uint32_t sl_measure_symptoms(const sl_image *s, const sl_image *t, const sl_image *mask, double threshold, bool soft) {
    if (!s || !t || s->width != t->width || s->height != t->height || s->channels != t->channels) return 0;
    int w = t->width, h = t->height, ch = t->channels;
    if (mask && (mask->width != w || mask->height != h)) mask = NULL;
    long counted = 0, darker = 0, lighter = 0, ref_dark = 0, ref_lit = 0, lost = 0, gained = 0;
    long soft_s = 0, soft_t = 0;
    double drift = 0; /* the mean difference, for an error too small for any pixel to show */
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            long i = (long)y * w + x;
            if (mask && mask->data[i * mask->channels] < 0.5f) continue;
            counted++;
            float v = s->data[i * ch], want = t->data[i * ch];
            if (isnan(v)) {
                darker++;
                lighter++;
                continue;
            }
            drift += (double)v - (double)want;
            float lo = INFINITY, hi = -INFINITY;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    float r = t->data[((long)ny * w + nx) * ch];
                    lo = fminf(lo, r);
                    hi = fmaxf(hi, r);
                }
            darker += v < lo - threshold;
            lighter += v > hi + threshold;
            ref_dark += want < 0.5f;
            ref_lit += want >= 0.5f;
            lost += want < 0.5f && v >= 0.5f && v > hi + threshold;
            gained += want >= 0.5f && v < 0.5f && v < lo - threshold;
            soft_s += v > 0.1f && v < 0.9f;
            soft_t += want > 0.1f && want < 0.9f;
        }
    uint32_t symptoms = 0;
    long differ = darker + lighter;
    /* a direction of its own, not the noise along the other side's edges */
    if (darker > 0 && darker * 5 >= differ) symptoms |= 1u << SL_SYMPTOM_TOO_DARK;
    if (lighter > 0 && lighter * 5 >= differ) symptoms |= 1u << SL_SYMPTOM_TOO_LIGHT;
    if (differ == 0 && counted) {
        drift /= (double)counted;
        if (drift < -1e-4) symptoms |= 1u << SL_SYMPTOM_TOO_DARK;
        if (drift > 1e-4) symptoms |= 1u << SL_SYMPTOM_TOO_LIGHT;
    }
    /* gross: lit and shadowed exchanged over most of the shadow, or a quarter of the lit area (a uniform
     * error that flips nothing is not gross, however many pixels it covers) */
    if (soft && ((ref_dark > 25 && lost * 2 > ref_dark) || (ref_lit > 25 && gained * 4 > ref_lit)))
        symptoms |= 1u << SL_SYMPTOM_GROSS;
    if (soft && soft_t * 200 > counted) {
        if (soft_s * 4 < soft_t * 3) symptoms |= 1u << SL_SYMPTOM_NARROW_PENUMBRA;
        if (soft_s * 3 > soft_t * 4) symptoms |= 1u << SL_SYMPTOM_WIDE_PENUMBRA;
    }
    return symptoms;
}
