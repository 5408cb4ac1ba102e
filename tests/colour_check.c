/* colour_check: whether a report's false-colour picture is in colour, for
 * the report tests (tests/report_colours.sh).
 *   colour_check colour IMAGE.png R G B PERCENT
 *     a colour picture (RGB, not grey) with at least PERCENT % of its pixels
 *     within 0.05 of the colour R G B (0..1): a legend's colour is there.
 *   colour_check red-green IMAGE.png
 *     a colour picture with no blue, whose red and green differ somewhere
 *     (two channels shown as red and green, not as grey and alpha). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_image.h"

int main(int argc, char **argv) {
    bool colour = argc == 7 && strcmp(argv[1], "colour") == 0, red_green = argc == 3 && strcmp(argv[1], "red-green") == 0;
    if (!colour && !red_green) {
        fprintf(stderr, "usage: colour_check colour IMAGE.png R G B PERCENT | colour_check red-green IMAGE.png\n");
        return 2;
    }
    char err[1024];
    sl_image im;
    if (!sl_image_read(argv[2], &im, err, sizeof err)) {
        fprintf(stderr, "colour_check: %s\n", err);
        return 2;
    }
    if (im.channels < 3) {
        printf("colour_check: %s has %d channel%s, not a colour picture\n", argv[2], im.channels,
               im.channels == 1 ? "" : "s");
        return 1;
    }
    long count = 0, blue = 0;
    double n = (double)im.width * im.height;
    for (int y = 0; y < im.height; y++)
        for (int x = 0; x < im.width; x++) {
            const float *p = sl_image_pixel(&im, x, y);
            if (colour) {
                bool near = true;
                for (int c = 0; c < 3; c++) near &= fabsf(p[c] - (float)atof(argv[3 + c])) <= 0.05f;
                count += near;
            } else {
                count += fabsf(p[0] - p[1]) > 0.05f;
                blue += p[2] > 0.02f;
            }
        }
    printf("colour_check: %s (%dx%d): %.2f%% of the pixels %s%s\n", argv[2], im.width, im.height, 100 * count / n,
           colour ? "have the colour" : "have red and green apart", colour ? "" : blue ? ", some blue" : ", no blue");
    sl_image_free(&im);
    return colour ? (100 * count / n >= atof(argv[6]) ? 0 : 1) : (count > 0 && blue == 0 ? 0 : 1);
}
