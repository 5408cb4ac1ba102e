/* sl_probe_formula: a contract formula written as an expression, and every variant of it one edit away.
 *
 * A hand-written catalogue of slips names the mistakes someone thought of. The mistakes students make
 * on a formula are mostly one edit of it: an operator replaced (/ for *), operands swapped (cot for tan),
 * parentheses moved ((c + s) * t for c + s * t), a term or factor left out, a square added or dropped, a
 * function replaced (sin for tan), a constant changed, an integer division. So each formula is written
 * here once, in a small expression language, and its one-edit variants are generated, evaluated and
 * printed ("(constant_bias + slope) * tan_theta in place of constant_bias + slope * tan_theta").
 *
 * Language: numbers, names (a probe input; `name[e]` one component of a vector input; `i` the output's
 * index), + - * / (integers divide as reals), unary -, comparisons < <= > >= == (1 or 0), calls
 * sqrt acos tan sin cos exp log pow min max clamp abs floor if(c, a, b), length(v) and major_positive(v)
 * of a whole vector input (1 where its largest component is positive). Definitions come first, each
 * `name = expression;`, and later parts may use them; the last part is the output.
 * Staff builds only (solutions/grader/): these are the labs' answers. */
#ifndef SL_PROBE_FORMULA_H
#define SL_PROBE_FORMULA_H

#include <stdbool.h>
#include <stddef.h>

#define SL_FORMULA_MAX_NODES 96
#define SL_FORMULA_MAX_DEFS 8

/* What a name means: the formula asks its resolver. */
typedef struct sl_formula_inputs {
    const void *context;
    /* the value of component `component` of input `name`; false when no input has that name */
    bool (*value)(const void *context, const char *name, int component, double *out);
    /* the number of components of input `name` (0: no such input) */
    int (*size)(const void *context, const char *name);
} sl_formula_inputs;

typedef struct sl_formula_node {
    int kind, op;  /* kind: a private enum; op: the operator or function */
    int a, b, c;   /* operand nodes (-1: none) */
    double number; /* a number's value */
    char name[32]; /* an input's or a definition's name */
} sl_formula_node;

typedef struct sl_formula {
    sl_formula_node nodes[SL_FORMULA_MAX_NODES];
    int node_count;
    int defs[SL_FORMULA_MAX_DEFS]; /* each definition's root node */
    char def_names[SL_FORMULA_MAX_DEFS][32];
    int def_count;
    int root;
} sl_formula;

/* Parses text; false with a message naming the position where it cannot. */
bool sl_formula_parse(sl_formula *f, const char *text, char *err, size_t n);

/* The formula's value for output `index` on the given inputs (NaN where a name is unknown). */
double sl_formula_eval(const sl_formula *f, const sl_formula_inputs *in, int index);

/* How many one-edit variants the formula has, numbered from 1 (some numbers do not apply). */
int sl_formula_edit_count(const sl_formula *f);

/* How likely a student is to make edit `edit`, as a rank (0 the most likely: a division of integers,
 * parentheses moved, operands swapped; the largest: a part replaced by a constant). Where edits give the
 * same formula, the likeliest names it ("i / count divided as integers", not "0 / count"). */
int sl_formula_edit_rank(int edit);

/* The formula with edit `edit` applied, into out; false when that edit does not apply to this formula. */
bool sl_formula_edited(const sl_formula *f, int edit, sl_formula *out);

/* Edit `edit` in words: what the edited formula computes ("(constant_bias + slope) * tan_theta", with
 * " in tan_theta" where the edit lies inside a definition) and what the contract's does there. False when
 * the edit does not apply. */
bool sl_formula_edit_words(const sl_formula *f, int edit, char *computed, char *contract, size_t n);

#endif
