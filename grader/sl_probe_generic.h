/* sl_probe_generic: probe rows on generic inputs (staff builds: solutions/grader/sl_probe_generic.c;
 * the handout's grader, without the formulas, has none: sl_probe_generic_none.c).
 *
 * A probe's written rows are edge cases someone chose, and many of them sit
 * where a term of the formula vanishes (w = 1, a radius of 1, a far plane of
 * 10, a near plane of 1). A wrong function can pass them all. So each probed
 * function that has a formula here also runs on rows drawn from a seed, where
 * every term of its contract is non-zero and matters (w != 1, radii above 1,
 * far planes and near planes of any size, sizes that are no scene's), and
 * those rows are compared with the contract's formula, written here from the
 * lab READMEs: never with the solution's numbers.
 *
 * The seed is the grading run's hidden seed (--hidden --seed S), so a student
 * cannot tune to the rows; otherwise --probe-seed S, or a fixed one, so that a
 * run can be repeated. The rows travel to the runner with the written ones,
 * in the same probe pass; the references hold only the written rows. */
#ifndef SL_PROBE_GENERIC_H
#define SL_PROBE_GENERIC_H

#include <stdbool.h>
#include <stdint.h>

#include "sl_case.h"

/* Rows drawn per check (fewer where the written rows leave less room). */
#define SL_PROBE_GENERIC_ROWS 8
/* The seed a run without --hidden or --probe-seed draws from. */
#define SL_PROBE_GENERIC_DEFAULT_SEED 20260421u

/* Whether `function` has a contract formula here (and so generic rows). */
bool sl_probe_generic_known(const char *function);

/* Appends generic rows to every probe check of c whose function has a formula, drawn from the seed (one
 * stream per case and check, so a case's rows do not depend on which other cases run). Returns the rows
 * added. The check's first rows - generic_rows rows stay the written ones. */
int sl_probe_generic_add(sl_case *c, uint64_t seed);

/* The contract's outputs for generic row `row` of check k (output_count numbers into out). False when
 * the row is not a generic one. */
bool sl_probe_generic_expected(const sl_check *k, int row, double *out);

/* A slip that the student's outputs (rows x outputs, every row of k, written and generic) follow: either
 * of one input (the contract's formula with that input negated, a component of it negated, its x and y
 * swapped, doubled, halved, 1 - it, 0 (or a component of it 0), 1, an integer off by one, or two inputs
 * swapped), or of the formula itself (each formula's own catalogue: a term dropped or not squared, sin
 * for tan, a loop one short, a reversed comparison...). It must give every modelled row's outputs (the
 * generic rows, and the written rows where the contract's formula gives `expected`, the reference's
 * answers; NULL: all rows), explain at least one the contract does not. Where the formula is written in
 * sl_probe_formula's language, every one-edit variant of it is a slip too. Slips that give the same
 * outputs on rows the check never saw are one formula, named once. Writes "on every row it answers as
 * the contract does with view_position negated" (or "... as if it computed X, where the contract says
 * Y"; or, where two to four fit alike, a list of them) and says which; SL_PROBE_SLIP_NONE where none or
 * more than four fit (or the function has no formula here). */
typedef enum sl_probe_slip {
    SL_PROBE_SLIP_NONE,      /* nothing written */
    SL_PROBE_SLIP_LIST,      /* two to four slips fit alike: listed */
    SL_PROBE_SLIP_OF_INPUT,  /* one slip of one input (the formula right, an input wrong) */
    SL_PROBE_SLIP_OF_FORMULA, /* one slip of the formula in its catalogue (most have a verdict of their own) */
    SL_PROBE_SLIP_EDIT       /* one edit of the formula that no catalogue lists: a mistake no one wrote down */
} sl_probe_slip;
sl_probe_slip sl_probe_generic_slip(const sl_check *k, const double *student, const double *expected, char *out,
                                    size_t n);

/* Whether every contract formula written in sl_probe_formula's language parses and gives the contract's
 * outputs on rows drawn as the generic rows are (a formula that does not is never edited; this names
 * it: the function and the row). True where there are none (the handout). */
bool sl_probe_generic_formulas_agree(char *err, size_t n);

#endif
