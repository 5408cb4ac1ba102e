/* Function probes: a student's function on a table of inputs, against the
 * solution's outputs. The failure quotes the first row that differs, its
 * inputs, both outputs, and what that row is there to test (its "about"). */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "sl_files.h"
#include "sl_json.h"
#include "sl_probe.h"
#include "sl_probe_generic.h"
#include "verdict_rows.h"
#include "camera.h"
#include "sl_verdict.h"
#include "sl_utf8.h"

/* A number as a message shows it: a GL enum by its name where the output is one. */

/* A 4x4 matrix, column-major (m00, m10, ...): sixteen outputs named as one; GL state may have sixteen too. */
static bool _sl_is_matrix(const sl_probe_function *f) {
    return f->output_count == 16 && strncmp(f->outputs, "m00,", 4) == 0;
}

static void _sl_value_named(double v, bool gl_enum, char *out, size_t n) {
    if (isnan(v)) {
        snprintf(out, n, "NaN");
        return;
    }
    if (gl_enum && v >= 0x0200 && v <= 0x9000 && v == floor(v)) {
        const char *name = sl_diag_enum_name((unsigned)v);
        if (strncmp(name, "unknown", 7) != 0) {
            snprintf(out, n, "%s", name);
            return;
        }
    }
    /* an enum without a name is still a whole number: never rounded to 4 digits */
    if (gl_enum && fabs(v) < 1e9 && v == floor(v)) snprintf(out, n, "%.0f", v);
    else snprintf(out, n, "%.4g", v);
}

static void _sl_value(double v, char *out, size_t n) { _sl_value_named(v, false, out, n); }

/* Outputs that hold GL enums: a filter, a face, a function, a wrap mode. */
static bool _sl_output_is_enum(const char *name) {
    return strstr(name, "filter") || strstr(name, "face") || strstr(name, "function") || strstr(name, "wrap") ||
           strstr(name, "internal format") || strstr(name, "framebuffer status");
}

/* "n_dot_l = 0.05, constant_bias = 0.0005, shadow_map = step" */
static void _sl_inputs(const sl_probe_function *f, const float *in, char *out, size_t n) {
    size_t used = 0;
    int offset = 0;
    out[0] = '\0';
    for (int i = 0; i < f->param_count && used < n; i++) {
        const sl_probe_param *p = &f->params[i];
        int size = sl_probe_type_size(p->type);
        char value[160] = "";
        if (SL_PROBE_IS_MAP(p->type)) {
            snprintf(value, sizeof value, "the \"%s\" map", sl_probe_map_name((sl_probe_map)(int)in[offset]));
        } else if (p->type == SL_PROBE_MAT4) {
            snprintf(value, sizeof value, "a matrix");
        } else if (size == 1) {
            snprintf(value, sizeof value, "%g", (double)in[offset]);
        } else {
            size_t v = 0;
            for (int k = 0; k < size && v < sizeof value; k++)
                v += (size_t)snprintf(value + v, sizeof value - v, "%s%g", k ? ", " : "(", (double)in[offset + k]);
            if (v < sizeof value) snprintf(value + v, sizeof value - v, ")");
        }
        used += (size_t)snprintf(out + used, n - used, "%s%s = %s", i ? ", " : "", p->name, value);
        offset += size;
    }
}

/* The name of output o ("bias", "m30"). */
static void _sl_output_name(const sl_probe_function *f, int o, char *out, size_t n) {
    const char *p = f->outputs;
    for (int i = 0; i < o && p; i++) {
        p = strchr(p, ',');
        if (p) p++;
    }
    size_t len = p ? strcspn(p, ",") : 0;
    snprintf(out, n, "%.*s", (int)len, p ? p : "");
}

/* Within the check's tolerances; a GL enum (a filter, a face, a function) only when it is the same one. */
static bool _sl_close_enough(const sl_check *k, int row, int output, double student, double expected) {
    if (isnan(expected)) return isnan(student);
    if (isnan(student) || isinf(student)) return false;
    char name[64];
    _sl_output_name(sl_probe_at(k->function), output, name, sizeof name);
    if (_sl_output_is_enum(name)) return student == expected;
    double tolerance = k->row_tolerance[row] > 0 ? k->row_tolerance[row] : k->tolerance;
    /* "above": a value the README lets students round up may be that much larger, never smaller */
    double above = student > expected ? k->above[output] : 0;
    return fabs(student - expected) <= tolerance + above + k->relative * fabs(expected);
}

/* What the stub of f returns for output o of a row. */
static double _sl_stub_output(const sl_probe_function *f, const float *in, int o) {
    if (f->stub_outputs) return f->stub_outputs[o];
    if (f->stub_param < 0) return f->stub_value;
    int offset = 0;
    for (int i = 0; i < f->stub_param; i++) offset += sl_probe_type_size(f->params[i].type);
    return in[offset + o];
}

/* "f(inputs) = got, expected want — about": one row, the outputs that differ named where there are several. */
static void _sl_row_evidence(const sl_probe_function *f, const sl_check *k, int row, const double *s, const double *e,
                             char *out, size_t n) {
    char inputs[600], got[300] = "", want[300] = "";
    _sl_inputs(f, k->inputs[row], inputs, sizeof inputs);
    if (f->output_count == 1) {
        _sl_value(s[0], got, sizeof got);
        _sl_value(e[0], want, sizeof want);
    } else if (f->glsl && f->output_count <= 4) {
        /* a vector: all of it */
        size_t g = 0, w = 0;
        for (int o = 0; o < f->output_count; o++) {
            char a[48], b[48];
            _sl_value(s[o], a, sizeof a);
            _sl_value(e[o], b, sizeof b);
            g += (size_t)snprintf(got + g, sizeof got - g, "%s%s", o ? ", " : "(", a);
            w += (size_t)snprintf(want + w, sizeof want - w, "%s%s", o ? ", " : "(", b);
        }
        if (g < sizeof got) snprintf(got + g, sizeof got - g, ")");
        if (w < sizeof want) snprintf(want + w, sizeof want - w, ")");
    } else {
        /* a matrix, or GL state: the values that differ, by name (a matrix's largest difference first) */
        int order[SL_PROBE_MAX_OUTPUTS], count = 0;
        for (int o = 0; o < f->output_count; o++)
            if (!_sl_close_enough(k, row, o, s[o], e[o])) order[count++] = o;
        for (int a = 0; a < count && _sl_is_matrix(f); a++)
            for (int b = a + 1; b < count; b++) {
                double da = isnan(s[order[a]]) ? INFINITY : fabs(s[order[a]] - e[order[a]]);
                double db = isnan(s[order[b]]) ? INFINITY : fabs(s[order[b]] - e[order[b]]);
                if (db > da) {
                    int t = order[a];
                    order[a] = order[b];
                    order[b] = t;
                }
            }
        const char *about = k->about[row], *dash = about[0] ? " — " : "";
        if (_sl_is_matrix(f) && count > 0) {
            char a[48], b[48], name[16];
            _sl_value(s[order[0]], a, sizeof a);
            _sl_value(e[order[0]], b, sizeof b);
            _sl_output_name(f, order[0], name, sizeof name);
            snprintf(out, n, "%s(%s) = a matrix whose %s is %s, expected %s%s%s", f->name, inputs, name, a, b, dash, about);
            return;
        }
        size_t g = 0;
        for (int i = 0; i < count; i++) {
            char a[48], b[48], name[64];
            _sl_output_name(f, order[i], name, sizeof name);
            _sl_value_named(s[order[i]], _sl_output_is_enum(name), a, sizeof a);
            _sl_value_named(e[order[i]], _sl_output_is_enum(name), b, sizeof b);
            g += (size_t)snprintf(got + g, sizeof got - g, "%s%s %s (expected %s)", i ? ", " : "", name, a, b);
            if (g >= sizeof got) break;
        }
        snprintf(out, n, "%s(%s) gives %s%s%s", f->name, inputs, got, dash, about);
        return;
    }
    snprintf(out, n, "%s(%s) = %s, expected %s%s%s", f->name, inputs, got, want, k->about[row][0] ? " — " : "",
             k->about[row]);
}

/* What the rows a function refused have in common that the rows it answered never have: an integer
 * parameter whose one value on every refused row appears on no answered row (" (count = 4 on each, a
 * value it accepts on no row)"), so a refusal of a valid input is named by that input. "" otherwise. */
static void _sl_failed_rows_share(const sl_probe_function *f, const sl_check *k, uint32_t failing, char *out, size_t n) {
    out[0] = '\0';
    if (failing == 0 || (failing == (k->rows >= 32 ? ~0u : (1u << k->rows) - 1u))) return;
    int offset = 0;
    for (int i = 0; i < f->param_count; offset += sl_probe_type_size(f->params[i].type), i++) {
        if (f->params[i].type != SL_PROBE_INT) continue;
        float value = 0;
        bool same = true, first = true, elsewhere = false;
        for (int row = 0; row < k->rows && same; row++) {
            float in = k->inputs[row][offset];
            if ((failing >> row) & 1u) {
                if (first) value = in, first = false;
                same = in == value;
            }
        }
        for (int row = 0; row < k->rows && same; row++)
            if (!((failing >> row) & 1u) && k->inputs[row][offset] == value) elsewhere = true;
        if (same && !first && !elsewhere) {
            snprintf(out, n, " (%s = %g on each, and on no row it answered)", f->params[i].name, (double)value);
            return;
        }
    }
}

/* ---- what the failing rows' answers are, read against the contract's answers on every row ----
 * Where no verdict names the mistake, three relations that hold on every failing row (its outputs that
 * differ) are told as what they are, for any function: the answers negated, the answers scaled by one
 * factor (over at least two different expected values: one value has every ratio), or the answers the
 * contract gives another row whose inputs differ in one parameter. Each is said only when it holds on
 * every failing row, and as the fact it is: the code behind it is the student's to find. */

/* The parameter in which rows a and b differ, if exactly one does (-1: none or several). */
static int _sl_one_param_apart(const sl_probe_function *f, const sl_check *k, int a, int b) {
    int offset = 0, differs = -1;
    for (int p = 0; p < f->param_count; p++) {
        int size = sl_probe_type_size(f->params[p].type);
        bool same = memcmp(&k->inputs[a][offset], &k->inputs[b][offset], sizeof(float) * (size_t)size) == 0;
        offset += size;
        if (same) continue;
        if (differs >= 0) return -1;
        differs = p;
    }
    return differs;
}

/* Whether rows a and b give parameter p the same value. */
static bool _sl_same_param(const sl_probe_function *f, const sl_check *k, int p, int a, int b) {
    int offset = 0;
    for (int q = 0; q < p; q++) offset += sl_probe_type_size(f->params[q].type);
    int size = sl_probe_type_size(f->params[p].type);
    return memcmp(&k->inputs[a][offset], &k->inputs[b][offset], sizeof(float) * (size_t)size) == 0;
}

/* Appends "name" of output o to a list of names, once. */
static void _sl_name_once(const sl_probe_function *f, int o, char *names, size_t n, int *count) {
    char name[64];
    _sl_output_name(f, o, name, sizeof name);
    if (!name[0] || strstr(names, name)) return;
    size_t used = strlen(names);
    if (*count < 4) snprintf(names + used, n - used, "%s%s", *count ? ", " : "", name);
    (*count)++;
}

/* What the contract asks of one state a C function sets, where that state alone is wrong: the GL rule
 * behind it, for the outputs whose rule is not their name. */
static const struct {
    const char *output, *rule;
} _sl_state_rules[] = {
    {"depth after the call", "a clear writes to the framebuffer bound, and the texture attached, when it runs, and "
                             "writes no depth while depth writes are off: bind (and attach), glDepthMask(GL_TRUE), "
                             "then glClear(GL_DEPTH_BUFFER_BIT)"},
    {"depth function", "each texel keeps the nearest surface's depth: glDepthFunc(GL_LESS) (or GL_LEQUAL), so the "
                       "depth test lets a fragment through only when it is nearer than what is stored"},
    {"filters nearest", "GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER, each set to GL_NEAREST: left unset, the "
                        "min filter is GL_NEAREST_MIPMAP_LINEAR, which wants mipmaps the map does not have, so the "
                        "texture is incomplete and every lookup in it reads 0"},
    {"faces with storage", "each of the six faces needs its own glTexImage2D, at GL_TEXTURE_CUBE_MAP_POSITIVE_X + i "
                           "for i = 0 to 5"},
    {"min filter", "the minification filter is its own parameter, glTexParameteri(..., GL_TEXTURE_MIN_FILTER, ...)"},
    {"mag filter", "the magnification filter is its own parameter, glTexParameteri(..., GL_TEXTURE_MAG_FILTER, ...)"},
    {"border depth", "a lookup past the edge reads the border colour's first component: GL_TEXTURE_BORDER_COLOR "
                     "(1, 1, 1, 1), with GL_CLAMP_TO_BORDER"},
    {"culling on", "lab 1's depth pass draws every face it is given: whether to cull is lab 3's choice "
                   "(lab3_depth_pass_state), and a culled face writes no depth"},
    {"map's framebuffer bound", "a pass draws into the GL_DRAW_FRAMEBUFFER binding: glBindFramebuffer(GL_FRAMEBUFFER, "
                                "map->framebuffer) sets it (and the read binding); 2 here is bound for reading alone "
                                "(GL_READ_FRAMEBUFFER), 0 not bound"},
    {"map's depth texture deleted", "glDeleteTextures gives a texture back, glDeleteFramebuffers a framebuffer: each "
                                    "kind of object has names of its own"},
    {"map's cube map deleted", "glDeleteTextures gives a texture back, glDeleteFramebuffers a framebuffer: each kind "
                               "of object has names of its own"},
    {"map's framebuffer deleted", "glDeleteFramebuffers(1, &map->framebuffer) gives the framebuffer back"},
    {"map's framebuffer field 0", "after the objects are deleted their names are stale: set map->framebuffer to 0, "
                                  "so nothing uses it again"},
    {"map's depth_texture field 0", "after the objects are deleted their names are stale: set map->depth_texture to 0, "
                                    "so nothing uses it again"},
    {"map's depth_cube field 0", "after the objects are deleted their names are stale: set map->depth_cube to 0, so "
                                 "nothing uses it again"},
    {"map's size field 0", "set map->size to 0 as well: the contract zeroes every field, so a destroyed map reads "
                           "as empty and is never taken for a live one"},
    {"a depth buffer on framebuffer[0]", "the moments pass tests depth on its own: a depth renderbuffer at "
                                     "GL_DEPTH_ATTACHMENT of framebuffer[0], attached while framebuffer[0] is bound"},
    {"each framebuffer's own texture at GL_COLOR_ATTACHMENT0", "a framebuffer draws into the attachment its draw "
                                                               "buffer names, GL_COLOR_ATTACHMENT0 for both"},
};

/* The scalar input whose value output o takes on every failing row, where the contract's value differs
 * (a parameter passed where another belongs: the factor given for the units); -1 when none. With `want`,
 * the input whose value the contract gives there instead. */
static int _sl_output_is_input(const sl_probe_function *f, const sl_check *k, const double *values, int o,
                               uint32_t failing) {
    int outputs = f->output_count;
    for (int p = 0, offset = 0; p < f->param_count; offset += sl_probe_type_size(f->params[p].type), p++) {
        if (sl_probe_type_size(f->params[p].type) != 1 || SL_PROBE_IS_MAP(f->params[p].type)) continue;
        int rows = 0;
        bool all = true;
        for (int row = 0; row < k->rows && all; row++) {
            if (!((failing >> row) & 1u)) continue;
            double in = k->inputs[row][offset], v = values[row * outputs + o];
            all = fabs(v - in) <= 1e-6 * fmax(1, fabs(in));
            rows++;
        }
        if (all && rows > 0) return p;
    }
    return -1;
}

/* One state alone wrong: the same single output differs on every failing row of a C function that sets
 * several (GL state, a sphere's radius), everything else it sets right. Said as that fact, with the GL
 * rule behind the output where it has one. */
static bool _sl_single_output(const sl_probe_function *f, const sl_check *k, const double *s, const double *e,
                              uint32_t failing, const uint32_t *differs, char *out, size_t n) {
    int outputs = f->output_count;
    if (f->glsl || outputs < 2 || _sl_is_matrix(f)) return false;
    uint32_t mask = 0;
    int rows = 0, example = -1;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        if (rows == 0) mask = differs[row], example = row;
        if (differs[row] != mask) return false;
        rows++;
    }
    if (rows == 0 || mask == 0 || (mask & (mask - 1)) != 0) return false; /* exactly one output */
    int o = __builtin_ctz(mask);
    char name[64], got[48], want[48];
    _sl_output_name(f, o, name, sizeof name);
    _sl_value_named(s[example * outputs + o], _sl_output_is_enum(name), got, sizeof got);
    _sl_value_named(e[example * outputs + o], _sl_output_is_enum(name), want, sizeof want);
    const char *rule = NULL;
    for (size_t i = 0; i < sizeof _sl_state_rules / sizeof _sl_state_rules[0]; i++)
        if (strcmp(_sl_state_rules[i].output, name) == 0) rule = _sl_state_rules[i].rule;
    /* "only its depth buffer on framebuffer[0]", not "only its a depth buffer ..." */
    const char *said = strncmp(name, "a ", 2) == 0 ? name + 2 : strncmp(name, "an ", 3) == 0 ? name + 3 : name;
    /* the value of another input on every such row, where the contract's is this one's: passed in its place */
    int taken = _sl_output_is_input(f, k, s, o, failing), meant = _sl_output_is_input(f, k, e, o, failing);
    if (taken >= 0 && meant >= 0 && taken != meant) {
        snprintf(out, n, "of everything it sets, only its %s is wrong, on every row that differs (%s where the contract "
                 "gives %s): it is %s's value on each of them, where %s's belongs — %s passed in %s's place",
                 said, got, want, f->params[taken].name, f->params[meant].name, f->params[taken].name,
                 f->params[meant].name);
        return true;
    }
    snprintf(out, n, "of everything it sets, only its %s is wrong, on every row that differs (%s where the contract "
             "gives %s)%s%s", said, got, want, rule ? ": " : "", rule ? rule : "");
    return true;
}

/* A pass whose viewport alone is wrong (its "viewport width" and "viewport height" outputs, and nothing else,
 * differ on every failing row): said as the viewport, and as never set where it is the probe's own. */
static bool _sl_viewport_only(const sl_probe_function *f, const sl_check *k, const double *s, const double *e,
                              uint32_t failing, const uint32_t *differs, char *out, size_t n) {
    int width = -1, height = -1;
    for (int o = 0; o < f->output_count; o++) {
        char name[64];
        _sl_output_name(f, o, name, sizeof name);
        if (strcmp(name, "viewport width") == 0) width = o;
        if (strcmp(name, "viewport height") == 0) height = o;
    }
    if (width < 0 || height < 0 || failing == 0) return false;
    uint32_t viewport = 1u << width | 1u << height;
    int example = -1;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        if (differs[row] == 0 || (differs[row] & ~viewport) != 0) return false;
        if (example < 0) example = row;
    }
    const double *got = s + example * f->output_count, *want = e + example * f->output_count;
    _sl_viewport_said(out, n, got[width], got[height], want[width], want[height], "the pass's",
                      "glViewport(0, 0, size, size) after binding the framebuffer");
    return true;
}

/* A destroy function whose map's fields end 0 while none of the map's objects was deleted, on every failing
 * row: the names were zeroed before glDelete* was given them (deleting the name 0 does nothing). Read from
 * the outputs' names ("... deleted", "map's ... field 0"), for every lab's destroy. */
static bool _sl_zeroed_before_deleted(const sl_probe_function *f, const sl_check *k, const double *s, const double *e,
                                      uint32_t failing, char *out, size_t n) {
    int zeroed[4], zeroed_count = 0, deleted[4], deleted_count = 0;
    for (int o = 0; o < f->output_count; o++) {
        char name[64];
        _sl_output_name(f, o, name, sizeof name);
        size_t length = strlen(name);
        if (strncmp(name, "map's ", 6) == 0 && length > 8 && strcmp(name + length - 8, " field 0") == 0 &&
            zeroed_count < 4)
            zeroed[zeroed_count++] = o;
        else if (strncmp(name, "map's ", 6) == 0 && strstr(name, " deleted") && deleted_count < 4)
            deleted[deleted_count++] = o;
    }
    if (zeroed_count == 0 || deleted_count == 0 || failing == 0) return false;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        const double *got = s + row * f->output_count, *want = e + row * f->output_count;
        for (int i = 0; i < zeroed_count; i++)
            if (got[zeroed[i]] != 1 || want[zeroed[i]] != 1) return false;
        for (int i = 0; i < deleted_count; i++)
            if (got[deleted[i]] != 0 || want[deleted[i]] != 1) return false;
    }
    snprintf(out, n, "none of the map's objects is deleted, though its fields end 0: glDeleteFramebuffers and "
                     "glDeleteTextures never got their names — not called, or called after the fields were set to 0 "
                     "(deleting the name 0 does nothing). Delete first (glDeleteFramebuffers(1, &map->framebuffer), "
                     "...), then zero the fields");
    return true;
}

static bool _sl_row_relation(const sl_probe_function *f, const sl_check *k, const double *s, const double *e,
                             uint32_t failing, const uint32_t *differs, char *out, size_t n) {
    int outputs = f->output_count;
    if (_sl_is_matrix(f)) return false; /* a matrix: told as the camera it is */
    /* negated, or scaled by one factor, on every output that differs */
    bool negated = true, scaled = true, any = false;
    double factor = NAN, wanted = NAN;
    bool wanted_vary = false; /* two different expected values at least: one value has every ratio */
    int values = 0;
    char names[200] = "";
    int named = 0, example_row = -1, example_output = -1;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        for (int o = 0; o < outputs; o++) {
            if (!((differs[row] >> o) & 1u)) continue;
            char name[64];
            _sl_output_name(f, o, name, sizeof name);
            double a = s[row * outputs + o], b = e[row * outputs + o];
            bool usable = isfinite(a) && isfinite(b) && fabs(b) > 1e-9 && !_sl_output_is_enum(name);
            negated &= usable && fabs(a + b) <= 1e-4 * fabs(b) + 1e-7;
            double ratio = usable ? a / b : NAN;
            if (isnan(factor)) factor = ratio;
            if (isnan(wanted)) wanted = b;
            wanted_vary |= usable && fabs(fabs(b) - fabs(wanted)) > 1e-4 * fabs(wanted);
            scaled &= usable && fabs(ratio - factor) <= 1e-3 * fabs(factor);
            any = true;
            values++;
            _sl_name_once(f, o, names, sizeof names, &named);
            if (example_row < 0) example_row = row, example_output = o;
        }
    }
    /* "factor, units" as "factor and units" */
    char *last = strrchr(names, ',');
    if (last && named <= 4 && strlen(names) + 4 < sizeof names) {
        memmove(last + 4, last + 1, strlen(last + 1) + 1);
        memcpy(last, " and", 4);
    }
    if (any && wanted_vary && (negated || scaled) && !(scaled && (fabs(factor - 1) < 1e-3 || fabs(factor) < 1e-3))) {
        char a[48], b[48];
        _sl_value(s[example_row * outputs + example_output], a, sizeof a);
        _sl_value(e[example_row * outputs + example_output], b, sizeof b);
        if (negated)
            snprintf(out, n, "its %s come%s out negated on every row that differs (%s where %s is expected): a sign "
                     "flipped",
                     names, named == 1 && values == 1 ? "s" : "", a, b);
        else if (values >= 2)
            snprintf(out, n, "on every row that differs, its %s %s %.4g times the contract's (%s where %s is "
                     "expected): a factor of its own, or a wrong divisor",
                     names, named == 1 ? "is" : "are", factor, a, b);
        else
            return false; /* one value: any two numbers have a ratio */
        return true;
    }
    /* the contract's answers for another row, one parameter apart */
    int pairs = 0, first_row = -1, first_other = -1, param = -1;
    bool mutual = true, unique = true, consistent = true, hub_first = true, hub_other = true;
    for (int row = 0; row < k->rows; row++) {
        if (!((failing >> row) & 1u)) continue;
        /* the row whose answers these are; of several, one that answers as this row should (an exchange) */
        int found = -1, found_param = -1;
        for (int other = 0; other < k->rows; other++) {
            if (other == row) continue;
            int p = _sl_one_param_apart(f, k, row, other);
            if (p < 0 || (param >= 0 && p != param)) continue;
            bool as_other = true, other_differs = false, back = ((failing >> other) & 1u) != 0;
            for (int o = 0; o < outputs && as_other; o++) {
                if (!((differs[row] >> o) & 1u)) continue;
                double a = s[row * outputs + o], b = e[other * outputs + o], own = e[row * outputs + o];
                as_other = isfinite(a) && isfinite(b) && fabs(a - b) <= 1e-5 * (1 + fabs(b));
                other_differs |= fabs(b - own) > 1e-5 * (1 + fabs(own));
                back &= fabs(s[other * outputs + o] - own) <= 1e-5 * (1 + fabs(own));
            }
            if (!as_other || !other_differs) continue;
            if (found < 0 || back) found = other, found_param = p;
            if (back) break;
        }
        if (found >= 0) param = found_param;
        if (found < 0) return false;
        /* the answers of one row alone: values many rows share (a coverage of 0 or 0.25) tell nothing */
        int rows_alike = 0;
        for (int other = 0; other < k->rows; other++) {
            bool alike = other != row;
            for (int o = 0; o < outputs && alike; o++)
                alike = !((differs[row] >> o) & 1u) ||
                        fabs(s[row * outputs + o] - e[other * outputs + o]) <= 1e-5 * (1 + fabs(e[other * outputs + o]));
            rows_alike += alike;
        }
        unique &= rows_alike == 1;
        if (first_row < 0) first_row = row, first_other = found;
        /* one exchange of two values of the parameter, not a row found anywhere for each row */
        consistent &= (_sl_same_param(f, k, param, row, first_row) && _sl_same_param(f, k, param, found, first_other)) ||
                      (_sl_same_param(f, k, param, row, first_other) && _sl_same_param(f, k, param, found, first_row));
        /* or one value against all the others (a test inverted: mode 1's answers for every other mode) */
        hub_first &= _sl_same_param(f, k, param, row, first_row) || _sl_same_param(f, k, param, found, first_row);
        hub_other &= _sl_same_param(f, k, param, row, first_other) || _sl_same_param(f, k, param, found, first_other);
        mutual &= ((failing >> found) & 1u) != 0;
        pairs++;
    }
    bool hub = !consistent && (hub_first || hub_other) && mutual && pairs >= 3;
    if (pairs == 0 || param < 0 || !(consistent || hub) || (!unique && !(mutual && pairs >= 2))) return false;
    char a[600], b[600];
    const sl_probe_function *fp = f;
    _sl_inputs(fp, k->inputs[first_row], a, sizeof a);
    _sl_inputs(fp, k->inputs[first_other], b, sizeof b);
    /* the one parameter's value in each row, from its "name = value" in the inputs */
    char here[120] = "", there[120] = "";
    const char *name = f->params[param].name;
    for (int side = 0; side < 2; side++) {
        const char *text = side ? b : a, *at = text;
        size_t length = strlen(name);
        while ((at = strstr(at, name)) && !(at[length] == ' ' && at[length + 1] == '=' && (at == text || at[-1] == ' ')))
            at += length;
        if (!at) return false;
        size_t value = strcspn(at, ",)");
        if (at[length + 3] == '(') value = strcspn(at, ")") + 1; /* a vector: up to its parenthesis */
        snprintf(side ? there : here, 120, "%.*s", (int)value, at);
    }
    if (hub)
        snprintf(out, n, "with %s it answers as the contract does with the other values of %s, and with those as "
                 "the contract does with %s: the two sides' answers are exchanged", hub_first ? here : there, name,
                 hub_first ? here : there);
    else if (mutual && pairs >= 2)
        snprintf(out, n, "with %s it answers as the contract does with %s, and the other way round: the two cases' "
                 "answers are exchanged", here, there);
    else
        snprintf(out, n, "with %s it gives what the contract gives with %s", here, there);
    return true;
}

/* " (3 of 24 rows differ, 2 of them generic; TODO(...) in ...)": how many rows differ, and of those how many
 * were drawn from the seed rather than written (sl_probe_generic.h). */
static void _sl_rows_differ(sl_check_result *out, const sl_check *k, int failing, const char *todo, const char *file) {
    int generic = 0;
    for (int row = k->rows - k->generic_rows; row < k->rows; row++) generic += (out->failing_rows >> row) & 1u;
    if (k->generic_rows > 0)
        sl_diag_append(out, " (%d of %d rows differ, %d of them generic; %s in %s)", failing, k->rows, generic, todo,
                       file);
    else
        sl_diag_append(out, " (%d of %d rows differ; %s in %s)", failing, k->rows, todo, file);
}

static bool _sl_probe_contract(const sl_check *k, const double *student, const double *expected, uint32_t *broken,
                               char *text, size_t n, int *shown) {
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(sl_probe_at(k->function)->lab);
    return lab && lab->probe_contract && lab->probe_contract(k, student, expected, broken, text, n, shown);
}

void sl_diagnose_probe(const sl_case *c, const sl_check *k, const sl_case_result *r, const sl_reference *ref,
                       sl_check_result *out) {
    const sl_probe_function *f = sl_probe_at(k->function);
    char capture[32];
    snprintf(capture, sizeof capture, "%s", sl_check_capture_name(c, k));
    const char *todo = "", *file = "";
    sl_diag_stub_location(f->name, &todo, &file);
    for (int i = 0; i < r->not_implemented_count; i++)
        if (strcmp(r->not_implemented[i], f->name) == 0) {
            sl_diag_say(out, "not implemented: %s%s still returns SL_NOT_IMPLEMENTED (%s in %s)", f->name, sl_probe_parens(f->name), todo, file);
            sl_utf8_copy(out->summary, sizeof out->summary, out->message);
            out->settled = out->stub = true;
            return;
        }
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        /* its own error: every probe of a file that does not compile says so, not only the last one */
        int index = (int)(k - c->checks);
        const char *own = index >= 0 && index < SL_JOB_MAX_PROBES ? r->probe_errors[index] : "";
        size_t len = strlen(capture);
        if (own[0] && sl_diag_compile_error(out, own))
            return;
        else if (own[0])
            sl_diag_say(out, "%s%s could not be called: %s", f->name, sl_probe_parens(f->name), own);
        else if (strncmp(r->capture_error, capture, len) == 0 && r->capture_error[len] == ':')
            sl_diag_say(out, "%s%s could not be called:%s", f->name, sl_probe_parens(f->name), r->capture_error + len + 1);
        else
            sl_diag_say(out, "%s%s was not called: the case ended before its probe", f->name, sl_probe_parens(f->name));
        sl_utf8_copy(out->summary, sizeof out->summary, out->message);
        out->settled = true;
        return;
    }
    int failing = 0, first = -1;
    bool all_stub = true;
    for (int row = 0; row < k->rows; row++) {
        bool row_ok = true;
        for (int o = 0; o < f->output_count; o++) {
            double s = cap->numbers[row * f->output_count + o], e = ref->numbers[row * f->output_count + o];
            bool close = _sl_close_enough(k, row, o, s, e);
            row_ok &= close;
            if (!close) out->row_outputs[row] |= (uint16_t)(1u << o);
            /* "not implemented" only where the stub's own answer is measured on every row, not one
             * within the check's tolerance of it (a small wrong-signed result is implemented code) */
            double stub = _sl_stub_output(f, k->inputs[row], o);
            all_stub &= !isnan(s) && fabs(s - stub) <= 1e-6 * (1 + fabs(stub));
        }
        if (!row_ok) {
            failing++;
            out->failing_rows |= 1u << row;
            if (first < 0) first = row;
        }
    }
    /* A function whose contract allows more than one answer (lab 6's light camera, lab 7's face views) is
     * judged by that contract, not by the solution's numbers; the verdict says which promise a row breaks. */
    char verdict[600] = "";
    uint32_t broken = 0;
    int shown = -1;
    if (_sl_probe_contract(k, cap->numbers, ref->loaded ? ref->numbers : NULL, &broken, verdict, sizeof verdict, &shown)) {
        out->failing_rows = broken;
        failing = 0;
        first = -1;
        for (int row = 0; row < k->rows; row++)
            if ((broken >> row) & 1u) {
                failing++;
                if (first < 0) first = row;
            }
        if (failing == 0) {
            out->passed = true;
            return;
        }
        /* what each broken row predicts a picture shows (a matrix: anything) */
        sl_verdict_rows judged = {.f = f, .k = k, .student = cap->numbers, .expected = ref->numbers, .failing = broken};
        for (int row = 0; row < k->rows; row++)
            if ((broken >> row) & 1u) out->row_predicts[row] = sl_probe_row_predicts(&judged, row);
        if (shown < 0 || !((broken >> shown) & 1u)) shown = first;
        char inputs[600];
        _sl_inputs(f, k->inputs[shown], inputs, sizeof inputs);
        sl_diag_say(out, "%s%s: %s. For example %s(%s)%s%s", f->name, sl_probe_parens(f->name), verdict[0] ? verdict : "its contract is broken",
                    f->name, inputs, k->about[shown][0] ? " — " : "", k->about[shown]);
        sl_utf8_copy(out->summary, sizeof out->summary, verdict);
        _sl_rows_differ(out, k, failing, todo, file);
        return;
    }
    if (failing == 0) {
        out->passed = true;
        return;
    }
    /* What each failing row predicts a picture shows: the evidence image checks need before they blame f. */
    uint32_t verdict_predicts = 0;
    sl_verdict_rows rows = {.f = f, .k = k, .student = cap->numbers, .expected = ref->numbers,
                            .failing = out->failing_rows, .predicts = &verdict_predicts};
    for (int row = 0; row < k->rows; row++)
        if ((out->failing_rows >> row) & 1u) out->row_predicts[row] = sl_probe_row_predicts(&rows, row);
    /* The stub's answers on every row, from code that is not the stub's (as handed out, up to comments and
     * spaces): written, but answering as the stub does; never "not implemented". */
    bool measured_stub = f->glsl || f->stub_outputs; /* a C stub that returns no status: what it did */
    if (all_stub && measured_stub && sl_diag_still_the_stub(f->file, sl_probe_entry(f)) == 0) all_stub = false;
    if (all_stub && !f->glsl && measured_stub) {
        sl_diag_say(out, "not implemented: %s() still does what its stub does, nothing (%s in %s)", f->name, todo, file);
        sl_utf8_copy(out->summary, sizeof out->summary, out->message);
        out->settled = out->stub = true;
        return;
    }
    if (all_stub && f->glsl) {
        char stub[96];
        const char *writes = f->stage == SL_PROBE_VERTEX_MAIN     ? " gl_Position ="
                             : f->stage == SL_PROBE_FRAGMENT_MAIN ? " gl_FragDepth ="
                                                                  : "";
        if (f->stub_outputs) {
            size_t used = (size_t)snprintf(stub, sizeof stub, "the stub's%s (", writes);
            for (int o = 0; o < f->output_count && used < sizeof stub; o++)
                used += (size_t)snprintf(stub + used, sizeof stub - used, "%s%g", o ? ", " : "", f->stub_outputs[o]);
            if (used < sizeof stub) snprintf(stub + used, sizeof stub - used, ")");
        } else if (f->stub_param >= 0) {
            snprintf(stub, sizeof stub, "%s%s %s unchanged", *writes ? "the stub's" : "its parameter", writes,
                     f->params[f->stub_param].name);
        } else {
            snprintf(stub, sizeof stub, "the stub's%s %g", writes, f->stub_value);
        }
        if (f->stage == SL_PROBE_FUNCTION)
            sl_diag_say(out, "not implemented: %s() still returns %s (%s in %s)", f->name, stub, todo, file);
        else
            sl_diag_say(out, "not implemented: %s still writes %s (%s in %s)", f->name, stub, todo, file);
        sl_utf8_copy(out->summary, sizeof out->summary, out->message);
        out->settled = out->stub = true;
        return;
    }
    /* What the rows say together, then the row that shows it (or the first that differs). The verdicts
     * read the written rows, each there to tell mistakes apart; a generic row's failure (every term drawn
     * at once) is shown as it is, in the contract's terms its "about" gives. */
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(f->lab);
    int written = k->rows - k->generic_rows;
    uint32_t written_failing = written >= 32 ? out->failing_rows : out->failing_rows & ((1u << written) - 1u);
    sl_check *written_check = written_failing ? malloc(sizeof *written_check) : NULL; /* the check as written */
    if (written_check) {
        *written_check = *k;
        written_check->rows = written;
        written_check->generic_rows = 0;
    }
    sl_verdict_rows written_rows = rows;
    written_rows.k = written_check;
    written_rows.failing = written_failing;
    /* One edit of the contract's formula that every modelled row follows, and that no catalogue lists
     * (staff builds: the contracts' formulas), read from every row, written and generic, says what the
     * code computes where no verdict was written for it: it leads (a verdict would name the mistake it
     * was written for: "lambda is ignored" for splits divided as integers). A catalogued slip (most have
     * a verdict of their own, in the README's words), a slip of one input, or several that fit alike
     * come after the written rows' verdicts, each written to tell apart mistakes such slips confuse (a
     * bias left out and one negated fit the same rows). Code still the stub's is "not implemented",
     * never a slip. */
    bool stub_shader = f->glsl && sl_diag_still_the_stub(f->file, sl_probe_entry(f)) == 1;
    /* A C function that answers every output NaN did not return SL_OK: where it does so on the differing
     * rows alone, that refusal is the mistake, whatever a verdict would read into NaN numbers. */
    bool all_failed = !f->glsl && failing > 0;
    for (int row = 0; row < k->rows && all_failed; row++)
        for (int o = 0; (out->failing_rows >> row) & 1u && o < f->output_count; o++)
            all_failed &= isnan(cap->numbers[row * f->output_count + o]);
    /* The other way round: every differing row is one the contract refuses (its outputs all NaN: SL_FAILED)
     * and the function answered, as if the input were valid. */
    bool all_accepted = !f->glsl && failing > 0;
    int accepted_first = -1;
    for (int row = 0; row < k->rows && all_accepted; row++) {
        if (!((out->failing_rows >> row) & 1u)) continue;
        bool refused = true, answered = false;
        for (int o = 0; o < f->output_count; o++) {
            refused &= isnan(ref->numbers[row * f->output_count + o]);
            answered |= !isnan(cap->numbers[row * f->output_count + o]);
        }
        all_accepted = refused && answered;
        if (accepted_first < 0) accepted_first = row;
    }
    if (all_accepted) {
        snprintf(verdict, sizeof verdict, "it answers %s the contract refuses: there it must return SL_FAILED "
                 "(and leave its outputs alone), where it returned SL_OK — check for such inputs first",
                 failing > 1 ? "inputs" : "an input");
        shown = accepted_first;
        all_failed = true; /* no verdict reads its numbers: they answer a question the contract does not ask */
    }
    char slip[sizeof verdict];
    sl_probe_slip slip_kind = stub_shader || all_failed
                                  ? SL_PROBE_SLIP_NONE
                                  : sl_probe_generic_slip(k, cap->numbers, ref->numbers, slip, sizeof slip);
    if (slip_kind == SL_PROBE_SLIP_EDIT) {
        snprintf(verdict, sizeof verdict, "%s", slip);
        shown = first;
    } else if (!all_failed)
        shown = written_check && lab && lab->probe_verdict
                ? lab->probe_verdict(written_check, cap->numbers, ref->numbers, written_failing, verdict, sizeof verdict)
                : -1;
    if (!verdict[0] && written_check && !all_failed) shown = sl_probe_verdict(&written_rows, verdict, sizeof verdict);
    /* the written rows' verdict, and one slip of one input every row fits, generic rows too: the slip is the
     * sharper fact ("bias negated" where the written rows can say only "missing or too small"), said after it */
    bool answers_vary = false; /* a constant answer (every row lit, say) fits an input's slip by coincidence */
    for (int row = 1; row < k->rows && !answers_vary; row++)
        for (int o = 0; o < f->output_count; o++)
            answers_vary |= fabs(cap->numbers[row * f->output_count + o] - cap->numbers[o]) > 1e-6;
    if (verdict[0] && slip_kind == SL_PROBE_SLIP_OF_INPUT && answers_vary) {
        size_t used = strlen(verdict);
        snprintf(verdict + used, sizeof verdict - used, " (and %s)", slip);
    }
    free(written_check);
    if (!verdict[0] && slip_kind != SL_PROBE_SLIP_NONE) {
        snprintf(verdict, sizeof verdict, "%s", slip);
        shown = first;
    }
    if (!verdict[0] && all_failed) {
        const char *gl = sl_result_gl_error(r, f->name);
        char shared[200];
        _sl_failed_rows_share(f, k, out->failing_rows, shared, sizeof shared);
        snprintf(verdict, sizeof verdict, "it returned SL_FAILED on %s%s, where the contract makes %s and returns SL_OK%s%s%s",
                 failing == k->rows ? "every row" : "every row that differs", shared, k->rows > 1 ? "them" : "it",
                 gl ? "; GL reported, while it ran: \"" : "", gl ? gl : "", gl ? "\"" : "");
    }
    if (shown < 0 || !((out->failing_rows >> shown) & 1u)) shown = first;
    if (!verdict[0]) {
        uint32_t differs[SL_PROBE_MAX_ROWS] = {0};
        for (int row = 0; row < k->rows; row++)
            for (int o = 0; o < f->output_count; o++)
                if (((out->failing_rows >> row) & 1u) &&
                    !_sl_close_enough(k, row, o, cap->numbers[row * f->output_count + o],
                                      ref->numbers[row * f->output_count + o]))
                    differs[row] |= 1u << o;
        if (!_sl_viewport_only(f, k, cap->numbers, ref->numbers, out->failing_rows, differs, verdict, sizeof verdict) &&
            !_sl_zeroed_before_deleted(f, k, cap->numbers, ref->numbers, out->failing_rows, verdict, sizeof verdict) &&
            !_sl_row_relation(f, k, cap->numbers, ref->numbers, out->failing_rows, differs, verdict, sizeof verdict))
            _sl_single_output(f, k, cap->numbers, ref->numbers, out->failing_rows, differs, verdict, sizeof verdict);
    }
    /* the same answer on every row while the contract's vary: it does not follow its inputs at all */
    if (!verdict[0] && f->output_count <= 4 && k->rows > 2) {
        bool constant = true, expected_vary = false;
        const double *s0 = &cap->numbers[0], *e0 = &ref->numbers[0];
        for (int row = 1; row < k->rows; row++)
            for (int o = 0; o < f->output_count; o++) {
                double sv = cap->numbers[row * f->output_count + o], ev = ref->numbers[row * f->output_count + o];
                constant &= isfinite(sv) && fabs(sv - s0[o]) <= 1e-6 * (1 + fabs(s0[o]));
                expected_vary |= fabs(ev - e0[o]) > 1e-3 * (1 + fabs(e0[o]));
            }
        if (constant && expected_vary) {
            char value[48];
            _sl_value(s0[0], value, sizeof value);
            snprintf(verdict, sizeof verdict, "it gives %s%s on all %d rows, whatever its inputs: the answer does not "
                     "follow them", value, f->output_count > 1 ? " (first output)" : "", k->rows);
            shown = first;
        }
    }
    /* a depth written as 1.0, the most gl_FragDepth keeps, on most rows that differ where the contract's is
     * below it: what the shader computes is 1 or more before the clamp */
    if (!verdict[0] && f->output_count == 1 && strcmp(f->outputs, "gl_FragDepth") == 0) {
        int capped = 0, capped_first = -1;
        for (int row = 0; row < k->rows; row++)
            if (((out->failing_rows >> row) & 1u) && cap->numbers[row] >= 1 - 1e-6 && ref->numbers[row] < 0.98) {
                capped++;
                if (capped_first < 0) capped_first = row;
            }
        if (capped > 0 && 2 * capped >= failing) {
            snprintf(verdict, sizeof verdict, "the depth it writes is 1.0, the most gl_FragDepth keeps, on %d of the %d "
                     "rows that differ, where the contract's depth is below 1: what it computes is 1 or more before "
                     "the clamp — divide all of it by the far plane, after length(), not inside it", capped,
                     failing);
            shown = capped_first;
        }
    }
    /* a matrix no verdict names: told as the camera it is (where it looks, its field of view, its box) */
    if (!verdict[0] && _sl_is_matrix(f))
        sl_camera_differences(&cap->numbers[shown * 16], &ref->numbers[shown * 16], verdict, sizeof verdict);
    /* a verdict that named the mistake says what it shows, for every failing row */
    for (int row = 0; verdict[0] && verdict_predicts && row < k->rows; row++)
        if ((out->failing_rows >> row) & 1u) out->row_predicts[row] = verdict_predicts;
    char evidence[1500];
    _sl_row_evidence(f, k, shown, &cap->numbers[shown * f->output_count], &ref->numbers[shown * f->output_count],
                     evidence, sizeof evidence);
    if (verdict[0]) {
        sl_diag_say(out, "%s%s: %s. For example %s", f->name, sl_probe_parens(f->name), verdict, evidence);
        sl_utf8_copy(out->summary, sizeof out->summary, verdict);
    } else {
        sl_diag_say(out, "%s", evidence);
        /* for other checks to quote: what differs and what the row tests, without the inputs */
        const char *equals = strstr(evidence, ") = "), *gives = strstr(evidence, ") gives ");
        if (equals) snprintf(out->summary, sizeof out->summary, "gives %s", equals + 4);
        else sl_utf8_copy(out->summary, sizeof out->summary, gives ? gives + 2 : evidence);
    }
    _sl_rows_differ(out, k, failing, todo, file);
}

bool sl_probe_reference_write(const char *path, const sl_check *k, const double *outputs, char *err, size_t n) {
    const sl_probe_function *f = sl_probe_at(k->function);
    int inputs = sl_probe_input_count(f);
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    fprintf(file.f, "{\n  \"function\": \"%s\",\n  \"rows\": [\n", f->name);
    int written = k->rows - k->generic_rows; /* generic rows are judged by the contract's formula, not kept */
    for (int r = 0; r < written; r++) {
        fprintf(file.f, "    {\"inputs\": [");
        for (int i = 0; i < inputs; i++) fprintf(file.f, "%s%.9g", i ? ", " : "", (double)k->inputs[r][i]);
        fprintf(file.f, "], \"outputs\": [");
        for (int o = 0; o < f->output_count; o++) {
            double v = outputs[r * f->output_count + o];
            if (isnan(v)) fprintf(file.f, "%snull", o ? ", " : "");
            else fprintf(file.f, "%s%.9g", o ? ", " : "", v);
        }
        fprintf(file.f, "]}%s\n", r + 1 < written ? "," : "");
    }
    fprintf(file.f, "  ]\n}\n");
    return sl_atomic_commit(&file, err, n);
}

bool sl_probe_reference_read(const char *path, const sl_check *k, double *outputs, char *err, size_t n) {
    const sl_probe_function *f = sl_probe_at(k->function);
    char json_err[600];
    cJSON *json = sl_json_load_file(path, "reference", json_err, sizeof json_err);
    if (!json) {
        snprintf(err, n, "reference corrupt: %s", json_err);
        return false;
    }
    const char *function = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "function"));
    const cJSON *rows = cJSON_GetObjectItemCaseSensitive(json, "rows");
    bool ok = function && cJSON_IsArray(rows);
    if (!ok) snprintf(err, n, "reference corrupt: %s: expected \"function\" and \"rows\"", path);
    int written = k->rows - k->generic_rows;
    bool same = ok && strcmp(function, f->name) == 0 && cJSON_GetArraySize(rows) == written;
    int inputs = sl_probe_input_count(f);
    for (int r = 0; ok && same && r < written; r++) {
        const cJSON *row = cJSON_GetArrayItem(rows, r);
        const cJSON *in = cJSON_GetObjectItemCaseSensitive(row, "inputs");
        const cJSON *o = cJSON_GetObjectItemCaseSensitive(row, "outputs");
        same = cJSON_GetArraySize(in) == inputs;
        for (int i = 0; same && i < inputs; i++) {
            const cJSON *v = cJSON_GetArrayItem(in, i);
            same = cJSON_IsNumber(v) && (float)v->valuedouble == k->inputs[r][i];
        }
        ok = cJSON_GetArraySize(o) == f->output_count;
        for (int j = 0; ok && j < f->output_count; j++) {
            const cJSON *v = cJSON_GetArrayItem(o, j);
            ok = cJSON_IsNumber(v) || cJSON_IsNull(v);
            outputs[r * f->output_count + j] = cJSON_IsNumber(v) ? v->valuedouble : NAN;
        }
        if (!ok) snprintf(err, n, "reference corrupt: %s: row %d has not %d outputs", path, r, f->output_count);
    }
    if (ok && !same)
        snprintf(err, n, "reference does not fit its case: %s was made for other inputs than the case's rows for "
                         "%s() (staff: --update-references)", path, f->name);
    cJSON_Delete(json);
    return ok && same;
}
