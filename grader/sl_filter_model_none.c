/* sl_filter_model without the models: the handout's grader. Lab 4's filters computed in C are lab 4's
 * answers, so they stay with the staff (solutions/grader/sl_filter_model.c); a student's own grader says
 * what the probes' rows show (a penumbra or a kernel too wide or narrow, a blocker search that finds
 * nothing, ...). */
#include <math.h>

#include "sl_filter_model.h"

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

double sl_poisson_model(const sl_probe_function *f, const float *in, int row, int slip) {
    (void)f;
    (void)in;
    (void)row;
    (void)slip;
    return NAN;
}

int sl_poisson_slip_count(void) { return 0; }

int sl_poisson_slip_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    (void)v;
    if (n) text[0] = '\0';
    return -1;
}

int sl_grid_spacing_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    (void)v;
    if (n) text[0] = '\0';
    return -1;
}
