/* sl_filter_model: lab 4's filters on the probe's synthetic maps, computed as the contract says and as
 * a slip would (PCSS with one term written another way, pcf_grid with its samples another distance
 * apart), so a failed probe can name the slip whose answers are every row's. The models are lab 4's
 * answers, so they are staff code (solutions/grader/sl_filter_model.c); the handout's grader names no
 * such slip (sl_filter_model_none.c) and says what the rows show instead. */
#ifndef SL_FILTER_MODEL_H
#define SL_FILTER_MODEL_H

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

/* pcf_poisson() at one probe row as the contract gives it (turned by pcf_rotation(pixel)) or with slip
 * `slip` (1 .. sl_poisson_slip_count()): the disk turned the other way, unrotated, turned by the map's
 * texel, offsets in uv, half the radius, the bias left out or added, no divide by w; NaN for a row the model
 * does not cover. */
double sl_poisson_model(const sl_probe_function *f, const float *in, int row, int slip);
int sl_poisson_slip_count(void);

/* The one slip that gives every row of a failed pcf_poisson probe what the student's gave, said as for
 * PCSS; a disk turned by gl_FragCoord in place of `pixel` is no slip (a picture passes the pixel). The first
 * failing row, or -1. */
int sl_poisson_slip_verdict(const sl_verdict_rows *v, char *text, size_t n);

/* pcf_grid's samples another distance apart than one texel (a scale of 1.5, a fixed step in uv): the
 * spacings at which a grid gives every failing row the student's answer, said as "the kernel is too wide:
 * its samples are 1.3 to 1.5 texels apart ..."; the first failing row, or -1. */
int sl_grid_spacing_verdict(const sl_verdict_rows *v, char *text, size_t n);

#endif
