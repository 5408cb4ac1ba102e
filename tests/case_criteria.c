/* case_criteria CASE.json...
 *
 * Prints what each graded check of the given case files applies, as the
 * grader reads them (sl_case_load: the case's own numbers over the defaults of
 * sl_case.c's table), for scripts/readme-criteria.sh, which writes the lab
 * READMEs' criteria from it. One line per check, tab-separated:
 *
 *   check LAB CASE NAME KIND THRESHOLD FAIL_FRACTION MEAN_TOLERANCE EPSILON BINARISE BONUS
 *
 * and, first, the rules every case of a kind shares (sl_compare.h), one a line,
 * and each kind's defaults (sl_case.c's table), tab-separated:
 *
 *   rule NAME VALUE
 *   default KIND THRESHOLD FAIL_FRACTION MEAN_TOLERANCE EPSILON
 *
 * Probes are left out: each row of a probe states its own tolerance. Exit 1
 * when a case does not load. */
#include <stdio.h>

#include "sl_case.h"
#include "sl_compare.h"

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: case_criteria CASE.json...\n");
        return 2;
    }
    printf("rule neighbourhood %d\n", 2 * SL_COMPARE_RADIUS + 1);
    printf("rule visibility_max_shadow_lost %.17g\n", SL_VISIBILITY_MAX_SHADOW_LOST);
    printf("rule visibility_min_shadow_pixels %d\n", SL_VISIBILITY_MIN_SHADOW_PIXELS);
    printf("rule lit_max_lost %.17g\n", SL_LIT_MAX_LOST);
    printf("rule lit_min_pixels %d\n", SL_LIT_MIN_PIXELS);
    printf("rule flicker_min_shadow_kept %.17g\n", SL_FLICKER_MIN_SHADOW_KEPT);
    printf("rule flicker_min_reference_shadow %.17g\n", SL_FLICKER_MIN_REFERENCE_SHADOW);
    printf("rule bleeding_umbra %.17g\n", SL_BLEEDING_UMBRA);
    printf("rule bleeding_max_kept %.17g\n", SL_BLEEDING_MAX_KEPT);
    printf("rule bleeding_negligible %.17g\n", SL_BLEEDING_NEGLIGIBLE);
    printf("rule bleeding_min_umbra_pixels %d\n", SL_BLEEDING_MIN_UMBRA_PIXELS);
    for (int kind = 0; kind < SL_CHECK_KIND_COUNT; kind++) {
        double threshold, fail, epsilon, mean;
        sl_check_kind_defaults((sl_check_kind)kind, &threshold, &fail, &epsilon, &mean);
        printf("default\t%s\t%.17g\t%.17g\t%.17g\t%.17g\n", sl_check_kind_name((sl_check_kind)kind), threshold, fail,
               mean, epsilon);
    }
    static sl_case c; /* large: off the stack */
    int status = 0;
    for (int i = 1; i < argc; i++) {
        char err[2048];
        if (!sl_case_load(&c, argv[i], err, sizeof err)) {
            fprintf(stderr, "case_criteria: %s\n", err);
            status = 1;
            continue;
        }
        for (int j = 0; j < c.check_count; j++) {
            const sl_check *k = &c.checks[j];
            if (k->kind == SL_CHECK_PROBE) continue;
            printf("check\t%d\t%s\t%s\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%d\n", c.lab, c.name, k->name,
                   sl_check_kind_name(k->kind), k->threshold, k->fail_fraction, k->mean_tolerance, k->epsilon,
                   k->binarise, k->bonus);
        }
    }
    return status;
}
