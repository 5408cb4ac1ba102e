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
    /* out: what the mistake a verdict names can show in a picture (1 << sl_symptom), for
     * every failing row; left 0, each row's own prediction stands (sl_probe_row_predicts) */
    uint32_t *predicts;
} sl_verdict_rows;

/* A flag in a prediction: the mistake the verdict names does not depend on the rows' settings (a
 * kernel's spacing shows at every radius, even where the rows at one radius happen to pass), so a
 * case at another setting than the failing rows' still runs it. */
#define SL_PREDICTS_EVERY_SETTING (1u << 31)

/* A verdict's prediction (see predicts above). */
static inline void sl_verdict_predicts(const sl_verdict_rows *v, uint32_t symptoms) {
    if (v->predicts) *v->predicts = symptoms;
}
/* What one failing row's outputs predict, read from the row alone: a
 * visibility (or a bias) lower than the solution's darkens, higher lightens,
 * by a whole 0/1 step grossly; across an edge, nearer a single comparison's
 * 0/1 narrows the penumbra, farther widens it; a matrix or GL state: anything. */
uint32_t sl_probe_row_predicts(const sl_verdict_rows *v, int row);

/* The verdict in a few words into text, and the row that shows it best;
 * -1 (and an empty text, or one without a row) when the rows name no mistake. */
int sl_probe_verdict(const sl_verdict_rows *rows, char *text, size_t text_size);
/* Lab 5's functions (grader/diagnose/lab5.c), likewise. */
int sl_verdict_lab5(const sl_verdict_rows *rows, char *text, size_t text_size);
/* Lab 6's functions (grader/diagnose/lab6.c), likewise. */
int sl_verdict_lab6(const sl_verdict_rows *rows, char *text, size_t text_size);

#endif
