/* image_check: what a picture must show, for the viewer's overlay and the
 * slides' tests.
 *   image_check text WITH.png WITHOUT.png X Y W H
 *     the rectangle of WITH holds text on a dark backing that WITHOUT lacks:
 *     at least 20% of its pixels differ from WITHOUT, at least 25% are dark
 *     (the backing) and 2-40% are bright (the glyphs).
 *   image_check not-blank IMAGE.png
 *     at least 1% of the pixels differ from the top-left one (a page that is
 *     not empty).
 *   image_check label IMAGE.png X Y W H
 *     the rectangle holds text on a dark backing, whatever is under it: at
 *     least 25% of its pixels are dark and 2-40% bright.
 *   image_check differ A.png B.png
 *     prints the percentage of pixels that differ (by more than 0.1 in a
 *     channel); exit 0 if any do.
 *   image_check changed A.png B.png
 *     prints the percentage of pixels that differ at all (by more than half
 *     an 8-bit step in a channel: a translucent line or backing counts);
 *     exit 0.
 *   image_check mean IMAGE.png X Y W H
 *     prints the rectangle's mean luminance (0..1); exit 0.
 *   image_check halves SPLIT.png LEFT.png RIGHT.png BAND DIVIDER
 *     SPLIT is LEFT over its left half and RIGHT over its right half (the
 *     viewer's --split), but for the labels in the bottom BAND rows and the
 *     divider, DIVIDER columns either side of the middle: there every pixel
 *     is within 2/255 of the single picture of its half. In the band 1-60% of
 *     each half's pixels changed (a label, not a covered band), and most of
 *     the divider's; and LEFT and RIGHT differ in each half (else a swap of
 *     the halves would pass unseen).
 *   image_check -
 *     one of the above a line from stdin (words split at tabs, so paths may hold spaces), each
 *     answered by its output and a line "image_check: exit N": a test makes
 *     many checks in one process, which loads the image module once (most of
 *     what a check costs). */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_image.h"
#include "check_lines.h"

static float _luma(const sl_image *im, int x, int y) {
    const float *p = sl_image_pixel(im, x, y);
    return im->channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
}

static bool _differs(const sl_image *a, const sl_image *b, int x, int y, int bx, int by) {
    const float *p = sl_image_pixel(a, x, y), *q = sl_image_pixel(b, bx, by);
    int n = a->channels < b->channels ? a->channels : b->channels;
    if (n > 3) n = 3;
    for (int c = 0; c < n; c++)
        if (fabsf(p[c] - q[c]) > 0.1f) return true;
    return false;
}

static int _check(int argc, char **argv);

/* A channel of p and q apart by more than `by`. */
static bool _apart(const float *p, const float *q, int channels, float by) {
    for (int c = 0; c < channels && c < 3; c++)
        if (fabsf(p[c] - q[c]) > by) return true;
    return false;
}

/* image_check halves: see the top of the file. */
static int _check_halves(char **argv) {
    char err[1024];
    sl_image split = {0}, single[2] = {{0}, {0}};
    bool read = sl_image_read(argv[2], &split, err, sizeof err) && sl_image_read(argv[3], &single[0], err, sizeof err) &&
                sl_image_read(argv[4], &single[1], err, sizeof err);
    int band = atoi(argv[5]), divider = atoi(argv[6]), status = 2;
    int w = split.width, h = split.height, half = w / 2;
    if (!read) fprintf(stderr, "image_check: %s\n", err);
    else if (single[0].width != w || single[1].width != w || single[0].height != h || single[1].height != h)
        fprintf(stderr, "image_check: %s, %s and %s are not one size\n", argv[2], argv[3], argv[4]);
    else if (band < 1 || band >= h || divider < 1 || divider >= half)
        fprintf(stderr, "image_check: the band (%d rows) or the divider (%d columns) does not fit %dx%d\n", band,
                divider, w, h);
    else {
        const float step = 1.0f / 255.0f;
        long mismatched[2] = {0, 0}, compared[2] = {0, 0}, unlike[2] = {0, 0}, labelled[2] = {0, 0},
             band_pixels[2] = {0, 0}, divided = 0, divider_pixels = 0;
        int first_x = -1, first_y = -1;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int side = x < half ? 0 : 1;
                const float *p = sl_image_pixel(&split, x, y), *q = sl_image_pixel(&single[side], x, y);
                bool changed = _apart(p, q, split.channels, 0.5f * step);
                if (x >= half - divider && x < half + divider) {
                    divider_pixels++;
                    divided += changed;
                } else if (y >= h - band) {
                    band_pixels[side]++;
                    labelled[side] += changed;
                } else {
                    compared[side]++;
                    bool off = _apart(p, q, split.channels, 2 * step);
                    if (off && first_x < 0) first_x = x, first_y = y;
                    mismatched[side] += off;
                    unlike[side] += _apart(sl_image_pixel(&single[0], x, y), sl_image_pixel(&single[1], x, y),
                                           split.channels, 2 * step);
                }
            }
        status = 0;
        for (int side = 0; side < 2; side++) {
            const char *name = side ? "right" : "left";
            double off = 100.0 * mismatched[side] / compared[side], apart = 100.0 * unlike[side] / compared[side],
                   label = 100.0 * labelled[side] / band_pixels[side];
            printf("image_check: %s half: %ld of its pixels outside the label band (%.3f%%) differ from %s; the two "
                   "singles differ on %.3f%% of them; %.1f%% of the label band changed\n", name, mismatched[side], off,
                   argv[3 + side], apart, label);
            if (mismatched[side] > 0) status = 1;
            if (unlike[side] == 0 || apart < 0.1) {
                printf("image_check: %s and %s are alike in the %s half: this check could not tell the halves apart\n",
                       argv[3], argv[4], name);
                status = 1;
            }
            if (label < 1 || label > 60) status = 1;
        }
        double line = 100.0 * divided / divider_pixels;
        printf("image_check: %.1f%% of the divider's columns changed\n", line);
        if (line < 50) status = 1;
        if (first_x >= 0)
            printf("image_check: %ld pixels off, the first at %d,%d\n", mismatched[0] + mismatched[1], first_x, first_y);
    }
    sl_image_free(&split);
    sl_image_free(&single[0]);
    sl_image_free(&single[1]);
    return status;
}

int main(int argc, char **argv) {
    if (argc != 2 || strcmp(argv[1], "-") != 0) return _check(argc, argv);
    return sl_test_check_lines("image_check", argv[0], 9, _check);
}

static int _check(int argc, char **argv) {
    char err[1024];
    if (argc == 3 && strcmp(argv[1], "not-blank") == 0) {
        sl_image im;
        if (!sl_image_read(argv[2], &im, err, sizeof err)) {
            fprintf(stderr, "image_check: %s\n", err);
            return 2;
        }
        long differ = 0;
        for (int y = 0; y < im.height; y++)
            for (int x = 0; x < im.width; x++) differ += _differs(&im, &im, x, y, 0, 0);
        double pct = 100.0 * (double)differ / ((double)im.width * im.height);
        printf("image_check: %s (%dx%d): %.2f%% of the pixels differ from the corner's colour\n", argv[2], im.width,
               im.height, pct);
        sl_image_free(&im);
        return pct >= 1.0 ? 0 : 1;
    }
    if ((argc == 7 && (strcmp(argv[1], "label") == 0 || strcmp(argv[1], "mean") == 0))) {
        sl_image im;
        if (!sl_image_read(argv[2], &im, err, sizeof err)) {
            fprintf(stderr, "image_check: %s\n", err);
            return 2;
        }
        int x0 = atoi(argv[3]), y0 = atoi(argv[4]), w = atoi(argv[5]), h = atoi(argv[6]);
        if (x0 < 0 || y0 < 0 || w <= 0 || h <= 0 || x0 + w > im.width || y0 + h > im.height) {
            fprintf(stderr, "image_check: the rectangle %d,%d %dx%d is not inside %s (%dx%d)\n", x0, y0, w, h, argv[2],
                    im.width, im.height);
            sl_image_free(&im);
            return 2;
        }
        long dark = 0, bright = 0;
        double sum = 0;
        for (int y = y0; y < y0 + h; y++)
            for (int x = x0; x < x0 + w; x++) {
                float l = _luma(&im, x, y);
                sum += l;
                dark += l < 0.3f;
                bright += l > 0.6f;
            }
        sl_image_free(&im);
        double n = (double)w * h, k = 100 * dark / n, b = 100 * bright / n;
        if (strcmp(argv[1], "mean") == 0) {
            printf("%.4f\n", sum / n);
            return 0;
        }
        printf("image_check: %s, rectangle %d,%d %dx%d: %.1f%% dark, %.1f%% bright\n", argv[2], x0, y0, w, h, k, b);
        return k >= 25 && b >= 2 && b <= 40 ? 0 : 1;
    }
    if (argc == 4 && strcmp(argv[1], "changed") == 0) {
        sl_image a, b;
        if (!sl_image_read(argv[2], &a, err, sizeof err) || !sl_image_read(argv[3], &b, err, sizeof err)) {
            fprintf(stderr, "image_check: %s\n", err);
            sl_image_free(&a);
            return 2;
        }
        bool same_size = a.width == b.width && a.height == b.height && a.channels == b.channels;
        if (!same_size)
            fprintf(stderr, "image_check: %s is %dx%d, %s %dx%d\n", argv[2], a.width, a.height, argv[3], b.width, b.height);
        else {
            long changed = 0;
            for (int y = 0; y < a.height; y++)
                for (int x = 0; x < a.width; x++) {
                    const float *p = sl_image_pixel(&a, x, y), *q = sl_image_pixel(&b, x, y);
                    bool d = false;
                    for (int c = 0; c < a.channels && c < 3; c++) d = d || fabsf(p[c] - q[c]) > 0.5f / 255.0f;
                    changed += d;
                }
            printf("%.3f\n", 100.0 * (double)changed / ((double)a.width * a.height));
        }
        sl_image_free(&a);
        sl_image_free(&b);
        return same_size ? 0 : 2;
    }
    if (argc == 4 && strcmp(argv[1], "differ") == 0) {
        sl_image a, b;
        if (!sl_image_read(argv[2], &a, err, sizeof err) || !sl_image_read(argv[3], &b, err, sizeof err)) {
            fprintf(stderr, "image_check: %s\n", err);
            sl_image_free(&a);
            return 2;
        }
        long differ = -1;
        if (a.width != b.width || a.height != b.height) {
            fprintf(stderr, "image_check: %s is %dx%d, %s %dx%d\n", argv[2], a.width, a.height, argv[3], b.width, b.height);
        } else {
            differ = 0;
            for (int y = 0; y < a.height; y++)
                for (int x = 0; x < a.width; x++) differ += _differs(&a, &b, x, y, x, y);
            printf("%.3f\n", 100.0 * (double)differ / ((double)a.width * a.height));
        }
        sl_image_free(&a);
        sl_image_free(&b);
        return differ < 0 ? 2 : differ > 0 ? 0 : 1;
    }
    if (argc == 7 && strcmp(argv[1], "halves") == 0) return _check_halves(argv);
    if (argc == 8 && strcmp(argv[1], "text") == 0) {
        sl_image with, without;
        if (!sl_image_read(argv[2], &with, err, sizeof err) || !sl_image_read(argv[3], &without, err, sizeof err)) {
            fprintf(stderr, "image_check: %s\n", err);
            sl_image_free(&with);
            return 2;
        }
        int x0 = atoi(argv[4]), y0 = atoi(argv[5]), w = atoi(argv[6]), h = atoi(argv[7]);
        if (with.width != without.width || with.height != without.height || x0 < 0 || y0 < 0 || w <= 0 || h <= 0 ||
            x0 + w > with.width || y0 + h > with.height) {
            fprintf(stderr, "image_check: the sizes do not fit (%dx%d, %dx%d, rectangle %d,%d %dx%d)\n", with.width,
                    with.height, without.width, without.height, x0, y0, w, h);
            sl_image_free(&with);
            sl_image_free(&without);
            return 2;
        }
        long differ = 0, dark = 0, bright = 0;
        for (int y = y0; y < y0 + h; y++)
            for (int x = x0; x < x0 + w; x++) {
                differ += _differs(&with, &without, x, y, x, y);
                float l = _luma(&with, x, y);
                dark += l < 0.3f;
                bright += l > 0.6f;
            }
        sl_image_free(&with);
        sl_image_free(&without);
        double n = (double)w * h, d = 100 * differ / n, k = 100 * dark / n, b = 100 * bright / n;
        printf("image_check: %s, rectangle %d,%d %dx%d: %.1f%% of pixels differ from %s, %.1f%% dark, %.1f%% bright\n",
               argv[2], x0, y0, w, h, d, argv[3], k, b);
        return d >= 20 && k >= 25 && b >= 2 && b <= 40 ? 0 : 1;
    }
    fprintf(stderr, "usage: image_check text WITH.png WITHOUT.png X Y W H | not-blank IMAGE.png |\n"
                    "       label IMAGE.png X Y W H | differ A.png B.png | changed A.png B.png | mean IMAGE.png X Y W H |\n"
                    "       halves SPLIT.png LEFT.png RIGHT.png BAND DIVIDER |\n"
                    "       - (one of these a line from stdin)\n");
    return 2;
}
