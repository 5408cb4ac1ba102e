/* image_compare A B [threshold] [max failing percent]: exit 0 when the two
 * images match under the grader's neighbourhood compare.
 * image_compare -: one such compare a line from stdin (words split at tabs, so paths may hold spaces),
 * each answered by its output and a line "image_compare: exit N", so a test
 * compares many pictures in one process, which loads the image module once
 * (most of what a compare costs). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_compare.h"
#include "sl_image.h"

#include "check_lines.h"

static int _compare(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: image_compare A B [threshold 0.1] [max failing percent 0.5] | image_compare -\n");
        return 2;
    }
    double threshold = argc > 3 ? atof(argv[3]) : 0.1, percent = argc > 4 ? atof(argv[4]) : 0.5;
    sl_image a, b;
    char err[1024];
    if (!sl_image_read(argv[1], &a, err, sizeof err) || !sl_image_read(argv[2], &b, err, sizeof err)) {
        fprintf(stderr, "image_compare: %s\n", err);
        sl_image_free(&a);
        return 2;
    }
    sl_compare_stats s = sl_compare_images(&a, &b, threshold, NULL);
    sl_image_free(&a);
    sl_image_free(&b);
    printf("image_compare: %s vs %s: %s%.3f%% of pixels differ (allowed %.3f%%), largest difference %.3f, mean %.6f\n",
           argv[1], argv[2], s.size_mismatch ? "sizes differ; " : "", 100 * s.failing_fraction, percent, s.max_difference,
           s.mean_difference);
    return !s.size_mismatch && 100 * s.failing_fraction <= percent ? 0 : 1;
}

int main(int argc, char **argv) {
    if (argc != 2 || strcmp(argv[1], "-") != 0) return _compare(argc, argv);
    return sl_test_check_lines("image_compare", argv[0], 6, _compare);
}
