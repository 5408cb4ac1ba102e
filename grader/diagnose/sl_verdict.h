/* sl_verdict: what a failed function probe's rows say is wrong (grader/diagnose/verdict.c). */
#ifndef SL_VERDICT_H
#define SL_VERDICT_H

#include <stddef.h>
#include <stdint.h>

#include "sl_case.h"
#include "sl_probe.h"

typedef struct sl_verdict_rows {
    const sl_probe_function *f;
    const sl_check *k;         /* the rows' inputs, tolerances, abouts */
    const double *student;     /* rows x outputs */
    const double *expected;    /* rows x outputs, the solution's */
    uint32_t failing;          /* 1 << row for each row that differs */
} sl_verdict_rows;

/* The verdict in a few words into text, and the row that shows it best;
 * -1 (and an empty text, or one without a row) when the rows name no mistake. */
int sl_probe_verdict(const sl_verdict_rows *rows, char *text, size_t text_size);
/* Lab 5's functions (grader/diagnose/lab5.c), likewise. */
int sl_verdict_lab5(const sl_verdict_rows *rows, char *text, size_t text_size);
/* Lab 6's functions (grader/diagnose/lab6.c), likewise. */
int sl_verdict_lab6(const sl_verdict_rows *rows, char *text, size_t text_size);

#endif
