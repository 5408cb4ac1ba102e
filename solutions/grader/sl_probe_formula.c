#include "sl_probe_formula.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- nodes ---- */

enum { _SL_NUMBER, _SL_INPUT, _SL_DEFINED, _SL_NEGATE, _SL_BINARY, _SL_CALL };

enum { _SL_ADD, _SL_SUB, _SL_MUL, _SL_DIV, _SL_LT, _SL_LE, _SL_GT, _SL_GE, _SL_EQ };

enum {
    _SL_SQRT, _SL_ACOS, _SL_TAN, _SL_SIN, _SL_COS, _SL_EXP, _SL_LOG, _SL_ABS, _SL_FLOOR, _SL_TRUNC, /* one argument */
    _SL_POW, _SL_MIN, _SL_MAX,                                                                      /* two */
    _SL_CLAMP, _SL_IF,                                                                              /* three */
    _SL_LENGTH, _SL_MAJOR_POSITIVE,                                                                 /* a vector */
    _SL_FUNCTIONS
};

static const char *const _sl_function_names[_SL_FUNCTIONS] = {
    "sqrt", "acos", "tan", "sin", "cos", "exp", "log", "abs", "floor", "trunc",
    "pow", "min", "max", "clamp", "if", "length", "major_positive"};

static int _sl_arity(int function) {
    return function <= _SL_TRUNC ? 1 : function <= _SL_MAX ? 2 : function <= _SL_IF ? 3 : 1;
}

static const char *const _sl_operator_text[] = {"+", "-", "*", "/", "<", "<=", ">", ">=", "=="};

static int _sl_new(sl_formula *f, int kind, int op, int a, int b, int c) {
    if (f->node_count >= SL_FORMULA_MAX_NODES) return -1;
    sl_formula_node *node = &f->nodes[f->node_count];
    memset(node, 0, sizeof *node);
    node->kind = kind, node->op = op, node->a = a, node->b = b, node->c = c;
    return f->node_count++;
}

/* ---- parsing: recursive descent over the text ---- */

typedef struct _sl_parser {
    sl_formula *f;
    const char *text, *at;
    char *err;
    size_t n;
    bool failed;
} _sl_parser;

static void _sl_fail(_sl_parser *p, const char *what) {
    if (!p->failed) snprintf(p->err, p->n, "formula: %s at character %d", what, (int)(p->at - p->text));
    p->failed = true;
}

static void _sl_space(_sl_parser *p) {
    while (isspace((unsigned char)*p->at)) p->at++;
}

static bool _sl_take(_sl_parser *p, const char *token) {
    _sl_space(p);
    size_t length = strlen(token);
    if (strncmp(p->at, token, length) != 0) return false;
    /* "<" is not "<=", "=" is not "==" */
    if ((token[0] == '<' || token[0] == '>' || token[0] == '=') && length == 1 && p->at[1] == '=') return false;
    p->at += length;
    return true;
}

static bool _sl_name(_sl_parser *p, char *out) {
    _sl_space(p);
    if (!isalpha((unsigned char)*p->at) && *p->at != '_') return false;
    size_t length = 0;
    while ((isalnum((unsigned char)p->at[length]) || p->at[length] == '_') && length < 31) length++;
    memcpy(out, p->at, length);
    out[length] = '\0';
    p->at += length;
    return true;
}

static int _sl_expression(_sl_parser *p);

static int _sl_primary(_sl_parser *p) {
    _sl_space(p);
    if (isdigit((unsigned char)*p->at) || *p->at == '.') {
        char *end;
        double value = strtod(p->at, &end);
        p->at = end;
        int node = _sl_new(p->f, _SL_NUMBER, 0, -1, -1, -1);
        if (node >= 0) p->f->nodes[node].number = value;
        return node;
    }
    if (_sl_take(p, "(")) {
        int inner = _sl_expression(p);
        if (!_sl_take(p, ")")) _sl_fail(p, "')' expected");
        return inner;
    }
    char name[32];
    if (!_sl_name(p, name)) {
        _sl_fail(p, "a number, a name or '(' expected");
        return -1;
    }
    if (_sl_take(p, "(")) {
        int function = 0;
        while (function < _SL_FUNCTIONS && strcmp(_sl_function_names[function], name) != 0) function++;
        if (function == _SL_FUNCTIONS) {
            _sl_fail(p, "unknown function");
            return -1;
        }
        int args[3] = {-1, -1, -1};
        for (int i = 0; i < _sl_arity(function); i++) {
            if (i > 0 && !_sl_take(p, ",")) _sl_fail(p, "',' expected");
            args[i] = _sl_expression(p);
        }
        if (!_sl_take(p, ")")) _sl_fail(p, "')' expected");
        return _sl_new(p->f, _SL_CALL, function, args[0], args[1], args[2]);
    }
    for (int d = 0; d < p->f->def_count; d++)
        if (strcmp(p->f->def_names[d], name) == 0) {
            int node = _sl_new(p->f, _SL_DEFINED, d, -1, -1, -1);
            if (node >= 0) snprintf(p->f->nodes[node].name, sizeof p->f->nodes[node].name, "%s", name);
            return node;
        }
    int component = -1;
    if (_sl_take(p, "[")) {
        component = _sl_expression(p);
        if (!_sl_take(p, "]")) _sl_fail(p, "']' expected");
    }
    int node = _sl_new(p->f, _SL_INPUT, 0, component, -1, -1);
    if (node >= 0) snprintf(p->f->nodes[node].name, sizeof p->f->nodes[node].name, "%s", name);
    return node;
}

static int _sl_unary(_sl_parser *p) {
    if (_sl_take(p, "-")) return _sl_new(p->f, _SL_NEGATE, 0, _sl_unary(p), -1, -1);
    return _sl_primary(p);
}

static int _sl_product(_sl_parser *p) {
    int left = _sl_unary(p);
    for (;;) {
        int op = _sl_take(p, "*") ? _SL_MUL : _sl_take(p, "/") ? _SL_DIV : -1;
        if (op < 0) return left;
        left = _sl_new(p->f, _SL_BINARY, op, left, _sl_unary(p), -1);
    }
}

static int _sl_sum(_sl_parser *p) {
    int left = _sl_product(p);
    for (;;) {
        int op = _sl_take(p, "+") ? _SL_ADD : _sl_take(p, "-") ? _SL_SUB : -1;
        if (op < 0) return left;
        left = _sl_new(p->f, _SL_BINARY, op, left, _sl_product(p), -1);
    }
}

static int _sl_expression(_sl_parser *p) {
    int left = _sl_sum(p);
    int op = _sl_take(p, "<=") ? _SL_LE : _sl_take(p, ">=") ? _SL_GE : _sl_take(p, "==") ? _SL_EQ
           : _sl_take(p, "<") ? _SL_LT : _sl_take(p, ">") ? _SL_GT : -1;
    return op < 0 ? left : _sl_new(p->f, _SL_BINARY, op, left, _sl_sum(p), -1);
}

bool sl_formula_parse(sl_formula *f, const char *text, char *err, size_t n) {
    memset(f, 0, sizeof *f);
    _sl_parser p = {f, text, text, err, n, false};
    for (;;) {
        /* a definition "name = ...;", or the output */
        const char *start = p.at;
        char name[32];
        if (_sl_name(&p, name) && _sl_take(&p, "=")) {
            if (f->def_count >= SL_FORMULA_MAX_DEFS) _sl_fail(&p, "too many definitions");
            int root = _sl_expression(&p);
            if (!_sl_take(&p, ";")) _sl_fail(&p, "';' expected");
            if (p.failed) return false;
            snprintf(f->def_names[f->def_count], sizeof f->def_names[0], "%s", name);
            f->defs[f->def_count++] = root;
            continue;
        }
        p.at = start;
        f->root = _sl_expression(&p);
        _sl_space(&p);
        if (*p.at) _sl_fail(&p, "end of formula expected");
        if (f->node_count >= SL_FORMULA_MAX_NODES) _sl_fail(&p, "too many nodes");
        return !p.failed;
    }
}

/* ---- evaluation ---- */

static double _sl_eval(const sl_formula *f, int node, const sl_formula_inputs *in, int index, int depth) {
    if (node < 0 || depth > 64) return NAN;
    const sl_formula_node *x = &f->nodes[node];
    switch (x->kind) {
    case _SL_NUMBER: return x->number;
    case _SL_DEFINED: return _sl_eval(f, f->defs[x->op], in, index, depth + 1);
    case _SL_INPUT: {
        int component = x->a < 0 ? 0 : (int)lround(_sl_eval(f, x->a, in, index, depth + 1));
        double value;
        if (in->value(in->context, x->name, component, &value)) return value;
        return strcmp(x->name, "i") == 0 ? index : NAN;
    }
    case _SL_NEGATE: return -_sl_eval(f, x->a, in, index, depth + 1);
    case _SL_BINARY: {
        double a = _sl_eval(f, x->a, in, index, depth + 1), b = _sl_eval(f, x->b, in, index, depth + 1);
        switch (x->op) {
        case _SL_ADD: return a + b;
        case _SL_SUB: return a - b;
        case _SL_MUL: return a * b;
        case _SL_DIV: return a / b;
        case _SL_LT: return a < b;
        case _SL_LE: return a <= b;
        case _SL_GT: return a > b;
        case _SL_GE: return a >= b;
        default: return a == b;
        }
    }
    default: break;
    }
    /* a call */
    if (x->op == _SL_LENGTH || x->op == _SL_MAJOR_POSITIVE) {
        const sl_formula_node *v = x->a >= 0 ? &f->nodes[x->a] : NULL;
        int size = v && v->kind == _SL_INPUT ? in->size(in->context, v->name) : 0;
        double sum = 0, major = 0, value;
        for (int j = 0; j < size; j++) {
            if (!in->value(in->context, v->name, j, &value)) return NAN;
            sum += value * value;
            if (fabs(value) > fabs(major)) major = value;
        }
        return size == 0 ? NAN : x->op == _SL_LENGTH ? sqrt(sum) : major > 0;
    }
    if (x->op == _SL_IF) {
        double c = _sl_eval(f, x->a, in, index, depth + 1);
        return isnan(c) ? NAN : _sl_eval(f, c != 0 ? x->b : x->c, in, index, depth + 1);
    }
    double a = _sl_eval(f, x->a, in, index, depth + 1);
    double b = _sl_arity(x->op) > 1 ? _sl_eval(f, x->b, in, index, depth + 1) : 0;
    switch (x->op) {
    case _SL_SQRT: return sqrt(a);
    case _SL_ACOS: return acos(a);
    case _SL_TAN: return tan(a);
    case _SL_SIN: return sin(a);
    case _SL_COS: return cos(a);
    case _SL_EXP: return exp(a);
    case _SL_LOG: return log(a);
    case _SL_ABS: return fabs(a);
    case _SL_FLOOR: return floor(a);
    case _SL_TRUNC: return trunc(a);
    case _SL_POW: return pow(a, b);
    case _SL_MIN: return fmin(a, b);
    case _SL_MAX: return fmax(a, b);
    case _SL_CLAMP: return fmin(fmax(a, b), _sl_eval(f, x->c, in, index, depth + 1));
    default: return NAN;
    }
}

double sl_formula_eval(const sl_formula *f, const sl_formula_inputs *in, int index) {
    return _sl_eval(f, f->root, in, index, 0);
}

/* ---- one edit ---- */

/* The kinds of edit, each at one node, with up to _SL_VARIANTS variants. */
enum {
    _SL_EDIT_OPERATOR,  /* + and -, * and /, < and >, <= and >=, min and max swapped for each other */
    _SL_EDIT_SWAP,      /* the operands of - / pow or a comparison swapped; if's branches swapped */
    _SL_EDIT_LEFT,      /* a op b as a alone: the right term or factor left out */
    _SL_EDIT_RIGHT,     /* a op b as b alone */
    _SL_EDIT_REGROUP,   /* a op (b op c) as (a op b) op c, and back: parentheses moved */
    _SL_EDIT_UNWRAP,    /* f(x) as x: a function, a clamp or a negation left out */
    _SL_EDIT_FUNCTION,  /* sin, cos, tan for one another */
    _SL_EDIT_SQUARE,    /* x as x * x */
    _SL_EDIT_ONE_MINUS, /* x as 1 - x */
    _SL_EDIT_NEGATE,    /* x as -x */
    _SL_EDIT_NUMBER,    /* a number as 0, 1, twice it or half of it */
    _SL_EDIT_CONSTANT,  /* a part as 0 or 1 */
    _SL_EDIT_TRUNCATE,  /* a / b divided as integers */
    _SL_EDIT_INPUT,     /* one input read in place of another */
    _SL_EDIT_COMPONENT, /* v[j] read as v[k]: another component of the same vector */
    _SL_EDITS
};
enum { _SL_VARIANTS = 8 };

int sl_formula_edit_count(const sl_formula *f) { return f->node_count * _SL_EDITS * _SL_VARIANTS; }

int sl_formula_edit_rank(int edit) {
    static const int rank[_SL_EDITS] = {
        [_SL_EDIT_TRUNCATE] = 0, [_SL_EDIT_REGROUP] = 1,  [_SL_EDIT_SWAP] = 2,     [_SL_EDIT_OPERATOR] = 3,
        [_SL_EDIT_FUNCTION] = 4, [_SL_EDIT_UNWRAP] = 5,   [_SL_EDIT_SQUARE] = 6,   [_SL_EDIT_LEFT] = 7,
        [_SL_EDIT_RIGHT] = 7,    [_SL_EDIT_INPUT] = 8,    [_SL_EDIT_ONE_MINUS] = 9, [_SL_EDIT_NEGATE] = 10,
        [_SL_EDIT_NUMBER] = 11,  [_SL_EDIT_CONSTANT] = 12, [_SL_EDIT_COMPONENT] = 8};
    return edit < 1 ? _SL_EDITS : rank[(edit - 1) / _SL_VARIANTS % _SL_EDITS];
}

static bool _sl_arithmetic(int op) { return op <= _SL_DIV; }

/* The scalar inputs the formula reads, in order of first use, and the components it reads of a vector by
 * a constant index (moments[1]): the candidates for an input read in place of another. index[j] is the
 * component, or -1 for a scalar. */
static int _sl_inputs(const sl_formula *f, int count, char out[][32], int *index) {
    int found = 0;
    for (int i = 0; i < f->node_count && found < count; i++) {
        const sl_formula_node *x = &f->nodes[i];
        if (x->kind != _SL_INPUT || strcmp(x->name, "i") == 0) continue;
        int component = -1;
        if (x->a >= 0) {
            if (f->nodes[x->a].kind != _SL_NUMBER) continue;
            component = (int)f->nodes[x->a].number;
        }
        bool seen = false;
        for (int j = 0; j < found; j++) seen |= strcmp(out[j], x->name) == 0 && index[j] == component;
        if (!seen) {
            index[found] = component;
            snprintf(out[found++], 32, "%s", x->name);
        }
    }
    return found;
}

/* Whether node is used as a whole vector (length's or major_positive's argument): no scalar edit applies. */
static bool _sl_whole_vector(const sl_formula *f, int node) {
    for (int i = 0; i < f->node_count; i++)
        if (f->nodes[i].kind == _SL_CALL && f->nodes[i].a == node &&
            (f->nodes[i].op == _SL_LENGTH || f->nodes[i].op == _SL_MAJOR_POSITIVE))
            return true;
    return false;
}

/* Whether node is a component index (name[i]): edits there are not slips of the formula. */
static bool _sl_index(const sl_formula *f, int node) {
    for (int i = 0; i < f->node_count; i++) {
        if (f->nodes[i].kind != _SL_INPUT || f->nodes[i].a < 0) continue;
        /* the index subtree: its root and anything beneath it */
        int stack[SL_FORMULA_MAX_NODES], top = 0;
        stack[top++] = f->nodes[i].a;
        while (top > 0) {
            int at = stack[--top];
            if (at == node) return true;
            const sl_formula_node *x = &f->nodes[at];
            if (x->kind == _SL_DEFINED) continue;
            if (x->a >= 0 && top < SL_FORMULA_MAX_NODES) stack[top++] = x->a;
            if (x->b >= 0 && top < SL_FORMULA_MAX_NODES) stack[top++] = x->b;
            if (x->c >= 0 && top < SL_FORMULA_MAX_NODES) stack[top++] = x->c;
        }
    }
    return false;
}

/* Replaces node `site` of g by a new node wrapping a copy of it: kind/op with the copy as operand a (and
 * `other` as b). */
static bool _sl_wrap(sl_formula *g, int site, int kind, int op, int other, bool copy_first) {
    int copy = _sl_new(g, 0, 0, -1, -1, -1);
    if (copy < 0) return false;
    g->nodes[copy] = g->nodes[site];
    sl_formula_node *s = &g->nodes[site];
    memset(s, 0, sizeof *s);
    s->kind = kind, s->op = op;
    s->a = copy_first ? copy : other;
    s->b = copy_first ? other : copy;
    s->c = -1;
    return true;
}

bool sl_formula_edited(const sl_formula *f, int edit, sl_formula *g) {
    if (edit < 1 || edit > sl_formula_edit_count(f)) return false;
    int site = (edit - 1) / (_SL_EDITS * _SL_VARIANTS), kind = (edit - 1) / _SL_VARIANTS % _SL_EDITS;
    int variant = (edit - 1) % _SL_VARIANTS;
    *g = *f;
    sl_formula_node *s = &g->nodes[site];
    if (kind == _SL_EDIT_COMPONENT) {
        /* a constant index, name[j], read as name[variant] (a component the input has: another reads NaN) */
        if (s->kind != _SL_INPUT || s->a < 0 || g->nodes[s->a].kind != _SL_NUMBER || variant > 3) return false;
        if (g->nodes[s->a].number == variant) return false;
        int index = _sl_new(g, _SL_NUMBER, 0, -1, -1, -1);
        if (index < 0) return false;
        g->nodes[index].number = variant;
        g->nodes[site].a = index;
        return true;
    }
    if (_sl_whole_vector(f, site) || _sl_index(f, site)) return false;
    bool binary = s->kind == _SL_BINARY, call = s->kind == _SL_CALL;
    switch (kind) {
    case _SL_EDIT_OPERATOR:
        if (variant > 0) return false;
        if (binary) {
            static const int partner[] = {_SL_SUB, _SL_ADD, _SL_DIV, _SL_MUL, _SL_GT, _SL_GE, _SL_LT, _SL_LE, -1};
            if (partner[s->op] < 0) return false;
            s->op = partner[s->op];
            return true;
        }
        if (call && (s->op == _SL_MIN || s->op == _SL_MAX)) {
            s->op = s->op == _SL_MIN ? _SL_MAX : _SL_MIN;
            return true;
        }
        return false;
    case _SL_EDIT_SWAP: {
        if (variant > 0) return false;
        bool commutes = binary && (s->op == _SL_ADD || s->op == _SL_MUL || s->op == _SL_EQ);
        if (binary && !commutes) {
            int t = s->a;
            s->a = s->b, s->b = t;
            return true;
        }
        if (call && (s->op == _SL_POW || s->op == _SL_IF)) {
            int *x = s->op == _SL_IF ? &s->b : &s->a, *y = s->op == _SL_IF ? &s->c : &s->b, t = *x;
            *x = *y, *y = t;
            return true;
        }
        return false;
    }
    case _SL_EDIT_LEFT:
    case _SL_EDIT_RIGHT: {
        if (variant > 0) return false;
        bool two = binary ? _sl_arithmetic(s->op) : call && (s->op == _SL_POW || s->op == _SL_MIN || s->op == _SL_MAX);
        if (!two) return false;
        int keep = kind == _SL_EDIT_LEFT ? s->a : s->b;
        *s = g->nodes[keep];
        return true;
    }
    case _SL_EDIT_REGROUP: {
        if (variant > 1 || !binary || !_sl_arithmetic(s->op)) return false;
        int inner = variant == 0 ? s->b : s->a;
        sl_formula_node *t = &g->nodes[inner];
        if (t->kind != _SL_BINARY || !_sl_arithmetic(t->op)) return false;
        int outer_op = s->op, inner_op = t->op;
        if (variant == 0) { /* a o1 (b o2 c) -> (a o1 b) o2 c */
            int a = s->a, b = t->a, c = t->b;
            int left = _sl_new(g, _SL_BINARY, outer_op, a, b, -1);
            if (left < 0) return false;
            s = &g->nodes[site];
            s->op = inner_op, s->a = left, s->b = c;
        } else { /* (a o1 b) o2 c -> a o1 (b o2 c) */
            int a = t->a, b = t->b, c = s->b;
            int right = _sl_new(g, _SL_BINARY, outer_op, b, c, -1);
            if (right < 0) return false;
            s = &g->nodes[site];
            s->op = inner_op, s->a = a, s->b = right;
        }
        return true;
    }
    case _SL_EDIT_UNWRAP:
        if (variant > 0) return false;
        if (s->kind == _SL_NEGATE || (call && (_sl_arity(s->op) == 1 || s->op == _SL_CLAMP) && s->op != _SL_LENGTH &&
                                      s->op != _SL_MAJOR_POSITIVE)) {
            *s = g->nodes[s->a];
            return true;
        }
        return false;
    case _SL_EDIT_FUNCTION: {
        static const int trig[] = {_SL_SIN, _SL_COS, _SL_TAN};
        if (!call || variant > 1 || (s->op != _SL_SIN && s->op != _SL_COS && s->op != _SL_TAN)) return false;
        int at = s->op == _SL_SIN ? 0 : s->op == _SL_COS ? 1 : 2;
        s->op = trig[(at + 1 + variant) % 3];
        return true;
    }
    case _SL_EDIT_SQUARE:
    case _SL_EDIT_NEGATE:
        if (variant > 0 || s->kind == _SL_NUMBER) return false;
        if (kind == _SL_EDIT_NEGATE && s->kind == _SL_NEGATE) return false;
        return kind == _SL_EDIT_SQUARE ? _sl_wrap(g, site, _SL_BINARY, _SL_MUL, -1, true) &&
                                             (g->nodes[site].b = g->nodes[site].a, true)
                                       : _sl_wrap(g, site, _SL_NEGATE, 0, -1, true);
    case _SL_EDIT_ONE_MINUS: {
        if (variant > 0 || (s->kind != _SL_INPUT && s->kind != _SL_DEFINED)) return false;
        int one = _sl_new(g, _SL_NUMBER, 0, -1, -1, -1);
        if (one < 0) return false;
        g->nodes[one].number = 1;
        return _sl_wrap(g, site, _SL_BINARY, _SL_SUB, one, false);
    }
    case _SL_EDIT_NUMBER: {
        if (s->kind != _SL_NUMBER || variant > 3) return false;
        double was = s->number, now = variant == 0 ? 0 : variant == 1 ? 1 : variant == 2 ? 2 * was : was / 2;
        if (now == was) return false;
        s->number = now;
        return true;
    }
    case _SL_EDIT_CONSTANT:
        if (variant > 1 || s->kind == _SL_NUMBER) return false;
        memset(s, 0, sizeof *s);
        s->kind = _SL_NUMBER, s->a = s->b = s->c = -1, s->number = variant;
        return true;
    case _SL_EDIT_TRUNCATE:
        if (variant > 0 || !binary || s->op != _SL_DIV) return false;
        return _sl_wrap(g, site, _SL_CALL, _SL_TRUNC, -1, true) && (g->nodes[site].c = -1, true);
    case _SL_EDIT_INPUT: {
        /* an input, or a definition's use (split_near where the formula reads start) */
        if (!(s->kind == _SL_INPUT || s->kind == _SL_DEFINED) || s->a >= 0 || strcmp(s->name, "i") == 0) return false;
        char names[_SL_VARIANTS + 1][32];
        int index[_SL_VARIANTS + 1];
        int count = _sl_inputs(f, _SL_VARIANTS + 1, names, index), choice = -1;
        for (int j = 0, seen = 0; j < count; j++) {
            if (strcmp(names[j], s->name) == 0 && index[j] < 0) continue;
            if (seen++ == variant) choice = j;
        }
        if (choice < 0) return false;
        int component = -1;
        if (index[choice] >= 0) {
            component = _sl_new(g, _SL_NUMBER, 0, -1, -1, -1);
            if (component < 0) return false;
            g->nodes[component].number = index[choice];
        }
        s = &g->nodes[site];
        snprintf(s->name, sizeof s->name, "%s", names[choice]);
        s->kind = _SL_INPUT, s->op = 0, s->a = component;
        return true;
    }
    default: return false;
    }
}

/* ---- printing ---- */

static int _sl_precedence(const sl_formula_node *x) {
    if (x->kind == _SL_BINARY) return x->op >= _SL_LT ? 1 : x->op <= _SL_SUB ? 2 : 3;
    if (x->kind == _SL_NEGATE) return 4;
    if (x->kind == _SL_NUMBER && x->number < 0) return 4;
    return 5;
}

static void _sl_print(const sl_formula *f, int node, char *out, size_t n, int depth);

static void _sl_print_operand(const sl_formula *f, int node, int parent_precedence, bool right, bool strict, char *out,
                              size_t n, int depth) {
    int p = node >= 0 ? _sl_precedence(&f->nodes[node]) : 5;
    bool parens = p < parent_precedence || (right && strict && p == parent_precedence);
    size_t used = strlen(out);
    if (parens) snprintf(out + used, n - used, "(");
    _sl_print(f, node, out, n, depth);
    used = strlen(out);
    if (parens) snprintf(out + used, n - used, ")");
}

static void _sl_print(const sl_formula *f, int node, char *out, size_t n, int depth) {
    size_t used = strlen(out);
    if (used + 1 >= n) return;
    if (node < 0 || depth > 64) {
        snprintf(out + used, n - used, "?");
        return;
    }
    const sl_formula_node *x = &f->nodes[node];
    switch (x->kind) {
    case _SL_NUMBER: snprintf(out + used, n - used, "%.6g", x->number); return;
    case _SL_DEFINED: snprintf(out + used, n - used, "%s", f->def_names[x->op]); return;
    case _SL_INPUT:
        snprintf(out + used, n - used, "%s", x->name);
        if (x->a >= 0) {
            used = strlen(out);
            snprintf(out + used, n - used, "[");
            _sl_print(f, x->a, out, n, depth + 1);
            used = strlen(out);
            snprintf(out + used, n - used, "]");
        }
        return;
    case _SL_NEGATE:
        snprintf(out + used, n - used, "-");
        _sl_print_operand(f, x->a, 4, false, false, out, n, depth + 1);
        return;
    case _SL_BINARY: {
        int p = _sl_precedence(x);
        _sl_print_operand(f, x->a, p, false, false, out, n, depth + 1);
        used = strlen(out);
        snprintf(out + used, n - used, " %s ", _sl_operator_text[x->op]);
        _sl_print_operand(f, x->b, p, true, x->op == _SL_SUB || x->op == _SL_DIV || p == 1 || p == 3, out, n,
                          depth + 1);
        return;
    }
    default: break;
    }
    snprintf(out + used, n - used, "%s(", _sl_function_names[x->op]);
    int args[3] = {x->a, x->b, x->c};
    for (int i = 0; i < _sl_arity(x->op); i++) {
        used = strlen(out);
        if (i) snprintf(out + used, n - used, ", ");
        _sl_print(f, args[i], out, n, depth + 1);
    }
    used = strlen(out);
    snprintf(out + used, n - used, ")");
}

/* The node whose operand `node` is (-1: a root). */
static int _sl_parent(const sl_formula *f, int node) {
    for (int i = 0; i < f->node_count; i++) {
        const sl_formula_node *x = &f->nodes[i];
        if (x->kind != _SL_DEFINED && (x->a == node || x->b == node || x->c == node)) return i;
    }
    return -1;
}

bool sl_formula_edit_words(const sl_formula *f, int edit, char *computed, char *contract, size_t n) {
    static sl_formula g;
    computed[0] = contract[0] = '\0';
    if (!sl_formula_edited(f, edit, &g)) return false;
    int site = (edit - 1) / (_SL_EDITS * _SL_VARIANTS), kind = (edit - 1) / _SL_VARIANTS % _SL_EDITS;
    /* the definition the edit lies in, if any */
    int root = site;
    while (_sl_parent(f, root) >= 0) root = _sl_parent(f, root);
    int in_def = -1;
    for (int d = 0; d < f->def_count; d++)
        if (f->defs[d] == root) in_def = d;
    /* the whole definition or output where it is short enough to read; else the part edited (a lone
     * name or number with the part it belongs to) */
    char whole[600] = "";
    _sl_print(f, root, whole, sizeof whole, 0);
    int shown = root;
    if (strlen(whole) > 90) {
        int parent = _sl_parent(f, site);
        shown = site;
        if ((f->nodes[site].kind == _SL_NUMBER || f->nodes[site].kind == _SL_INPUT ||
             f->nodes[site].kind == _SL_DEFINED) &&
            parent >= 0)
            shown = parent;
    }
    if (in_def >= 0 && shown == root) {
        snprintf(computed, n, "%s = ", f->def_names[in_def]);
        snprintf(contract, n, "%s = ", f->def_names[in_def]);
    }
    _sl_print(&g, shown, computed, n, 0);
    _sl_print(f, shown, contract, n, 0);
    if (in_def >= 0 && shown != root) {
        size_t used = strlen(computed);
        snprintf(computed + used, n - used, " in %s", f->def_names[in_def]);
        used = strlen(contract);
        snprintf(contract + used, n - used, " for %s", f->def_names[in_def]);
    }
    const char *hint = kind == _SL_EDIT_TRUNCATE ? " (a division of integers)"
                     : kind == _SL_EDIT_REGROUP  ? " (the parentheses moved)"
                                                 : "";
    size_t used = strlen(computed);
    snprintf(computed + used, n - used, "%s", hint);
    return true;
}
