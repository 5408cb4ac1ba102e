/* What the verdicts on a probe's rows read of them (verdict.c, verdict_filter.c, the labs' verdicts):
 * a parameter's inputs, whether a row failed, its outputs and the solution's. */
#ifndef SL_VERDICT_ROWS_H
#define SL_VERDICT_ROWS_H

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "sl_probe.h"
#include "sl_verdict.h"

/* Where one parameter's inputs start in a row (floats), or -1 if the function has none of that name. */
static inline int _sl_param_offset(const sl_probe_function *f, const char *name) {
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        if (strcmp(f->params[i].name, name) == 0) return offset;
        offset += sl_probe_type_size(f->params[i].type);
    }
    return -1;
}

/* The inputs of one parameter of a row, or NULL if the function has none of that name. */
static inline const float *_sl_param(const sl_probe_function *f, const float *row, const char *name) {
    int offset = _sl_param_offset(f, name);
    return offset >= 0 ? row + offset : NULL;
}

static inline bool _sl_failed(const sl_verdict_rows *v, int row) { return (v->failing >> row) & 1u; }
static inline double _sl_got(const sl_verdict_rows *v, int row, int o) { return v->student[row * v->f->output_count + o]; }
static inline double _sl_want(const sl_verdict_rows *v, int row, int o) { return v->expected[row * v->f->output_count + o]; }
static inline bool _sl_near(double a, double b, double tolerance) { return fabs(a - b) <= tolerance; }

/* A pass's viewport that is not the size it must be, in words: where it is the one the probe set before the
 * call, the function never set it (the last pass's viewport would stay); `fix` is the call to make. */
static inline void _sl_viewport_said(char *text, size_t n, double w, double h, double want_w, double want_h,
                                     const char *whose, const char *fix) {
    if (w == SL_PROBE_STALE_VIEWPORT_WIDTH && h == SL_PROBE_STALE_VIEWPORT_HEIGHT)
        snprintf(text, n, "the viewport is never set: after the call it is still %gx%g, the one set before it, where "
                          "%s %gx%g is needed (whatever pass ran last, its viewport would stay): %s",
                 w, h, whose, want_w, want_h, fix);
    else
        snprintf(text, n, "the viewport is %gx%g, not %s %gx%g: %s", w, h, whose, want_w, want_h, fix);
}

#endif
