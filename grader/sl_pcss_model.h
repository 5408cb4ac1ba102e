/* sl_pcss_model: PCSS on the probe's synthetic maps, computed as the contract says and as a slip in
 * one of its terms would, so a failed pcss probe can name the term whose slip gives every row's answer.
 * The model is lab 4's answer, so it is staff code (solutions/grader/sl_pcss_model.c); the handout's
 * grader names no slip here (sl_pcss_model_none.c) and says what the rows show instead. */
#ifndef SL_PCSS_MODEL_H
#define SL_PCSS_MODEL_H

#include <stddef.h>

#include "diagnose/sl_verdict.h"

/* pcss() at one probe row (its inputs, and the row's index: the pixel it is drawn at, gl_FragCoord
 * (0.5, 2 row + 0.5), picks the disk's rotation), as the contract gives it or with slip `slip` (1 ..
 * sl_pcss_slip_count()); NaN for a row the model does not cover (another map kind). */
double sl_pcss_model(const sl_probe_function *f, const float *in, int row, int slip);
int sl_pcss_slip_count(void);

/* The slip that gives every row of a failed pcss probe what the student's gave, said as "on every row
 * it answers as if it computed ..., where the contract says ...": the first failing row, or -1 when
 * no slip (or the contract itself, on these rows) fits. */
int sl_pcss_slip_verdict(const sl_verdict_rows *v, char *text, size_t n);

#endif
