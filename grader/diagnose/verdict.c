/* Verdicts on a failed function probe: what the pattern of its rows says is
 * wrong, in a few words, before the row that shows it is quoted. Each
 * verdict reads only the rows' inputs and the two sets of outputs, never a
 * guess at the student's code: a filter's weight sum is what it gives on an
 * empty map, its width how far its results depart from a single comparison
 * across the synthetic step edge, and so on. Filters are read here
 * (verdict_filter.c); a lab's other functions by the verdicts its descriptor
 * registers for them (its `functions` by name, then its `rows_verdict`). */
#define _POSIX_C_SOURCE 200809L
#include "sl_verdict.h"
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "verdict_filter.h"
#include "verdict_rows.h"

int sl_probe_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    text[0] = '\0';
    if (v->f->glsl && _sl_param(v->f, v->k->inputs[0], "shadow_map") && _sl_param(v->f, v->k->inputs[0], "shadow_coord"))
        return _sl_verdict_filter(v, text, n);
    const sl_function_verdict *own = sl_function_verdict_of(v->f);
    if (own && own->verdict) return own->verdict(v, text, n);
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(v->f->lab);
    return lab && lab->rows_verdict ? lab->rows_verdict(v, text, n) : -1;
}

/* ---- what a failing row predicts a picture shows ---- */

#define _SL_DARK (1u << SL_SYMPTOM_TOO_DARK)
#define _SL_LIGHT (1u << SL_SYMPTOM_TOO_LIGHT)
#define _SL_GROSS (1u << SL_SYMPTOM_GROSS)
#define _SL_NARROW (1u << SL_SYMPTOM_NARROW_PENUMBRA)
#define _SL_WIDE (1u << SL_SYMPTOM_WIDE_PENUMBRA)

uint32_t sl_probe_row_predicts(const sl_verdict_rows *v, int row) {
    const sl_probe_function *f = v->f;
    const sl_function_verdict *own = sl_function_verdict_of(f);
    if (own && own->row_predicts) return own->row_predicts(v, row);
    if (f->output_count != 1) return SL_SYMPTOMS_ANY;
    /* a visibility (a lighter one), or a bias (a larger one lightens) */
    bool visibility = strcmp(f->outputs, "visibility") == 0 || strcmp(f->outputs, "p_max") == 0;
    bool bias = strcmp(f->outputs, "bias") == 0;
    if (!visibility && !bias) return SL_SYMPTOMS_ANY;
    double s = _sl_got(v, row, 0), e = _sl_want(v, row, 0);
    if (isnan(s) || isinf(s)) return SL_SYMPTOMS_ANY;
    uint32_t p = s < e ? _SL_DARK : _SL_LIGHT;
    if (bias) {
        if (s <= 0.25 * e || s >= 4 * e + 1e-6) p |= _SL_GROSS;
        return p;
    }
    if (fabs(s - e) >= 0.5) p |= _SL_GROSS;
    /* across an edge: nearer a single comparison's 0 or 1 than the solution is narrower; a width
     * off by much there grows with the kernel (a wide light, a large radius): gross in a picture */
    if (e > 0.02 && e < 0.98 && _sl_param(f, v->k->inputs[row], "shadow_map")) {
        _sl_filter_row fr = _sl_filter_row_of(f, v->k->inputs[row]);
        p |= fabs(s - fr.centre) < fabs(e - fr.centre) ? _SL_NARROW : _SL_WIDE;
        if (fabs(s - e) >= 0.15) p |= _SL_GROSS;
    }
    return p;
}
