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
