/* Verdicts on a failed probe of a filter (verdict.c): a GLSL function of a
 * shadow map, a shadow coordinate and a bias, 1 lit, 0 shadowed. Its rows
 * read as one kind of a few: outside the light, an empty map, on the stored
 * surface, under an occluder, across the synthetic step edge. */
#ifndef SL_VERDICT_FILTER_H
#define SL_VERDICT_FILTER_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_probe.h"
#include "sl_verdict.h"

typedef enum _sl_row_kind {
    _SL_ROW_OUTSIDE,     /* behind the light, or off the map or past its far plane: lit */
    _SL_ROW_HOMOGENEOUS, /* inside, w not 1: the divide matters */
    _SL_ROW_EMPTY_MAP,   /* nothing in front anywhere: 1, whatever the kernel */
    _SL_ROW_OWN_SURFACE, /* on the stored surface itself: lit thanks to the bias alone */
    _SL_ROW_OCCLUDED,    /* an occluder over every sample: 0 */
    _SL_ROW_EDGE,        /* the step map: an occluder's edge */
    _SL_ROW_OTHER
} _sl_row_kind;

typedef struct _sl_filter_row {
    _sl_row_kind kind;
    double p[3];   /* the divided coordinate */
    double bias;
    double centre; /* one comparison at p.xy, as an unfiltered lookup gives it */
} _sl_filter_row;

/* What a filter's row is, from its inputs alone. */
_sl_filter_row _sl_filter_row_of(const sl_probe_function *f, const float *in);

/* The verdict on a filter's rows (sl_probe_verdict's, for a filter). */
int _sl_verdict_filter(const sl_verdict_rows *v, char *text, size_t n);

#endif
