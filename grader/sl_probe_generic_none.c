/* sl_probe_generic without the contracts' formulas: the handout's grader.
 *
 * The formulas that judge generic probe rows (solutions/grader/sl_probe_generic.c)
 * compute what each lab function must return, so they are the labs' answers and
 * stay with the staff. A student's own grader probes the written rows alone;
 * staff grading adds the generic ones. */
#include "sl_probe_generic.h"

bool sl_probe_generic_known(const char *function) {
    (void)function;
    return false;
}

int sl_probe_generic_add(sl_case *c, uint64_t seed) {
    (void)c;
    (void)seed;
    return 0;
}

bool sl_probe_generic_expected(const sl_check *k, int row, double *out) {
    (void)k;
    (void)row;
    (void)out;
    return false;
}

sl_probe_slip sl_probe_generic_slip(const sl_check *k, const double *student, const double *expected, char *out,
                                    size_t n) {
    (void)k;
    (void)student;
    (void)expected;
    if (n) out[0] = '\0';
    return SL_PROBE_SLIP_NONE;
}

bool sl_probe_generic_formulas_agree(char *err, size_t n) {
    if (n) err[0] = '\0';
    return true;
}
