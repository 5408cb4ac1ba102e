/* sl_pcss_model without the model: the handout's grader. PCSS computed in C is lab 4's answer, so it
 * stays with the staff (solutions/grader/sl_pcss_model.c); a student's own grader says what the pcss
 * probe's rows show (a penumbra too wide or narrow, a blocker search that finds nothing, ...). */
#include <math.h>

#include "sl_pcss_model.h"

double sl_pcss_model(const sl_probe_function *f, const float *in, int row, int slip) {
    (void)f;
    (void)in;
    (void)row;
    (void)slip;
    return NAN;
}

int sl_pcss_slip_count(void) { return 0; }

int sl_pcss_slip_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    (void)v;
    if (n) text[0] = '\0';
    return -1;
}
