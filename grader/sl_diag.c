#include "sl_diag.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_glsl_functions.h"
#include "sl_utf8.h"

/* The TODO tags a stub's message points to. */
static const struct { const char *function, *todo, *file; } _sl_stubs[] = {
    {"lab1_create_shadow_map", "TODO(lab1.1), TODO(lab1.2)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab1_begin_depth_pass", "TODO(lab1.3)", "labs/lab1_depth_fbo/lab1.c"},
    {"lab2_light_view", "TODO(lab2.1)", "labs/lab2_projective/lab2.c"},
    {"lab2_light_projection", "TODO(lab2.2)", "labs/lab2_projective/lab2.c"},
    {"lab2_shadow_matrix", "TODO(lab2.3)", "labs/lab2_projective/lab2.c"},
    {"lab3_depth_pass_state", "TODO(lab3.1)", "labs/lab3_bias/lab3.c"},
    {"lab3_second_depth_state", "TODO(lab3.4), the optional extension,", "labs/lab3_bias/lab3.c"},
    {"lab4_configure_shadow_texture", "TODO(lab4.1)", "labs/lab4_pcf/lab4.c"},
    {"lab5_create_moments_target", "TODO(lab5.1)", "labs/lab5_vsm/lab5.c"},
    {"lab5_begin_moments_pass", "TODO(lab5.2)", "labs/lab5_vsm/lab5.c"},
    {"lab5_begin_blur_pass", "TODO(lab5.4)", "labs/lab5_vsm/lab5.c"},
    {"lab5_filter_moments", "TODO(lab5.6)", "labs/lab5_vsm/lab5.c"},
    {"lab7_create_cube_map", "TODO(lab7.1)", "labs/lab7_cube/lab7.c"},
    {"lab7_begin_cube_pass", "TODO(lab7.2)", "labs/lab7_cube/lab7.c"},
    {"lab7_face_view", "TODO(lab7.3)", "labs/lab7_cube/lab7.c"},
    {"lab7_face_projection", "TODO(lab7.4)", "labs/lab7_cube/lab7.c"},
};

void sl_diag_say(sl_check_result *out, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->message, sizeof out->message, fmt, args);
    va_end(args);
    sl_utf8_trim(out->message); /* a long text cut between characters */
}

void sl_diag_append(sl_check_result *out, const char *fmt, ...) {
    size_t used = strlen(out->message);
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->message + used, sizeof out->message - used, fmt, args);
    va_end(args);
    sl_utf8_trim(out->message);
}

void sl_diag_cause(sl_check_result *out, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->cause, sizeof out->cause, fmt, args);
    va_end(args);
    sl_utf8_trim(out->cause);
}

void sl_diag_cause_in(sl_check_result *out, const char *function, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vsnprintf(out->cause, sizeof out->cause, fmt, args);
    va_end(args);
    sl_utf8_trim(out->cause);
    /* "pcf_grid()", "shadow_compare_manual() (lab 2)": the name alone */
    snprintf(out->blamed, sizeof out->blamed, "%.*s", (int)strcspn(function, "( "), function);
}

void sl_diag_set_cause(sl_check_result *out, const char *function, const char *kind) {
    snprintf(out->cause_function, sizeof out->cause_function, "%.*s", (int)strcspn(function, "( "), function);
    out->cause_kind = out->cause_function[0] ? kind : NULL;
}

/* Adds a case's hint after the message, unless the message already says it word for word (a diagnosis
 * whose cause is the hint's own advice): each piece of advice is said once. */
void sl_diag_hint(sl_check_result *out, const char *hint) {
    if (!hint[0] || strstr(out->message, hint)) return;
    size_t n = strlen(out->message);
    bool ends_sentence = n > 0 && strchr(".?!", out->message[n - 1]) != NULL;
    sl_diag_append(out, "%s Hint: %s", ends_sentence ? "" : ".", hint);
}

bool sl_diag_image_passes(const sl_check *k, const sl_compare_stats *st, const char *what, sl_check_result *out) {
    bool pixels_ok = st->failing_fraction <= k->fail_fraction && st->nan_pixels == 0;
    bool mean_ok = k->mean_tolerance <= 0 || st->mean_difference <= k->mean_tolerance;
    if (pixels_ok && !mean_ok)
        sl_diag_say(out, "the %s is off by %.4f on average (allowed %.4f), though hardly a pixel is far off: a small "
                         "error everywhere (%s %.4f on average, the reference %.4f)",
                    what, st->mean_difference, k->mean_tolerance, what, st->mean_student, st->mean_reference);
    return pixels_ok && mean_ok;
}

bool sl_diag_lit_lost(const sl_image *student, const sl_image *reference, const sl_image *mask, const char *what,
                      sl_check_result *out) {
    sl_lit_lost l = sl_visibility_lit_lost(student, reference, mask);
    if (!l.failed) return false;
    if (l.nan * 2 > l.dark + l.nan)
        sl_diag_say(out, "the visibility is NaN on %.0f%% of the surfaces the reference shows lit", 100.0 * l.nan / l.lit);
    else if (l.fraction > 0.9)
        sl_diag_say(out, "everything is in shadow: %.0f%% of the surfaces the reference shows lit are dark here", 100 * l.fraction);
    else
        sl_diag_say(out, "too much is in shadow: %.1f%% of the surfaces the reference shows lit are dark here (allowed %.0f%%)",
                    100 * l.fraction, 100 * SL_LIT_MAX_LOST);
    sl_diag_append(out, "; a picture without its light shows no %s either, so it earns nothing here", what);
    sl_diag_cause(out, "does the shadow lookup return a constant, or NaN? The lab's probes name the function");
    return true;
}

bool sl_diag_stub_location(const char *function, const char **todo, const char **file) {
    static char todos[64][48], files[64][160];
    for (size_t s = 0; s < sizeof _sl_stubs / sizeof _sl_stubs[0]; s++)
        if (strcmp(_sl_stubs[s].function, function) == 0) {
            *todo = _sl_stubs[s].todo;
            *file = _sl_stubs[s].file;
            return true;
        }
    const sl_probe_function *f = sl_probe_find(function);
    if (!f) return false;
    int i = sl_probe_index(f) % 64;
    snprintf(todos[i], sizeof todos[i], "TODO(%s)", f->todo);
    snprintf(files[i], sizeof files[i], "labs/%s", f->file);
    *todo = todos[i];
    *file = files[i];
    return true;
}

int sl_diag_function_lab(const char *function) {
    return strncmp(function, "lab", 3) == 0 ? atoi(function + 3) : 0;
}

void sl_diag_gl_error(sl_check_result *out, const sl_case_result *r, const char *function) {
    const char *said = sl_result_gl_error(r, function);
    if (!said || !said[0] || strstr(out->message, "GL reported")) return;
    /* GL's words, as its debug output gave them: they name the call and the value it refused */
    sl_diag_append(out, "%sGL reported, while %s%s ran: \"%s\"", out->message[0] ? ". " : "", function,
                   sl_probe_parens(function), said);
}

/* "not implemented" for this lab's stubs first, then "needs lab K". */
bool sl_diag_explain_missing(const sl_case *c, const sl_case_result *r, sl_check_result *out) {
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < r->not_implemented_count; i++) {
            const char *fn = r->not_implemented[i];
            int lab = sl_diag_function_lab(fn);
            if ((pass == 0) != (lab == c->lab)) continue;
            const char *todo = "", *file = "";
            sl_diag_stub_location(fn, &todo, &file);
            if (lab == c->lab)
                sl_diag_say(out, "not implemented: %s() still returns SL_NOT_IMPLEMENTED (%s in %s)", fn, todo, file);
            else
                sl_diag_say(out, "not implemented: needs lab %d first, and %s() still returns SL_NOT_IMPLEMENTED", lab, fn);
            sl_diag_set_cause(out, fn, SL_CAUSE_STUB);
            out->cause[0] = '\0';
            out->settled = true;
            return true;
        }
    }
    if (r->failed[0]) {
        sl_diag_say(out, "%s() returned SL_FAILED", r->failed);
        if (sl_result_gl_error(r, r->failed)) sl_diag_gl_error(out, r, r->failed);
        else if (strcmp(r->failed, "lab1_create_shadow_map") == 0)
            sl_diag_append(out, " (is the framebuffer complete? glCheckFramebufferStatus tells why not)");
        sl_diag_set_cause(out, r->failed, SL_CAUSE_WRONG);
        out->cause[0] = '\0';
        out->settled = true;
        return true;
    }
    return false;
}

/* A GL enum's name ("GL_CLAMP_TO_EDGE"), "unknown GL enum" for others. */
const char *sl_diag_enum_name(unsigned value) {
    /* the wrap modes a probe reads back, which the framework's table leaves out */
    switch (value) {
    case GL_CLAMP_TO_EDGE: return "GL_CLAMP_TO_EDGE";
    case GL_CLAMP_TO_BORDER: return "GL_CLAMP_TO_BORDER";
    case GL_REPEAT: return "GL_REPEAT";
    case GL_MIRRORED_REPEAT: return "GL_MIRRORED_REPEAT";
    /* and the cube map faces a pass attaches */
    case GL_TEXTURE_CUBE_MAP_POSITIVE_X: return "GL_TEXTURE_CUBE_MAP_POSITIVE_X";
    case GL_TEXTURE_CUBE_MAP_NEGATIVE_X: return "GL_TEXTURE_CUBE_MAP_NEGATIVE_X";
    case GL_TEXTURE_CUBE_MAP_POSITIVE_Y: return "GL_TEXTURE_CUBE_MAP_POSITIVE_Y";
    case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y: return "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y";
    case GL_TEXTURE_CUBE_MAP_POSITIVE_Z: return "GL_TEXTURE_CUBE_MAP_POSITIVE_Z";
    case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z: return "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z";
    default: return sl_gl_enum_name((GLenum)value);
    }
}

/* ---- GLSL compile errors ---- */

#define _SL_COMPILE_ERROR "GLSL compile error in "
/* A list (of candidate functions) shows this many items, then how many more: the first say what the
 * compiler wanted; twenty overloads of min() say nothing more. */
#define _SL_CONTINUED_MAX 4

/* The length of a compiler line's location and kind ("labs/x.glsl:9:9: error:"), 0 if it has none;
 * *file_len: the length of its file name. */
static size_t _sl_compiler_location(const char *line, size_t len, size_t *file_len, bool *error) {
    const char *end = line + len, *colon = memchr(line, ':', len);
    if (!colon || colon == line) return 0;
    const char *p = colon + 1;
    int numbers = 0;
    while (numbers < 2 && p < end && isdigit((unsigned char)*p)) {
        while (p < end && isdigit((unsigned char)*p)) p++;
        if (p >= end || *p != ':') return 0;
        p++;
        numbers++;
    }
    if (numbers == 0) return 0;
    while (p < end && *p == ' ') p++;
    static const char *const kinds[] = {"error:", "warning:"};
    for (int i = 0; i < 2; i++) {
        size_t n = strlen(kinds[i]);
        if ((size_t)(end - p) >= n && strncmp(p, kinds[i], n) == 0) {
            *file_len = (size_t)(colon - line);
            *error = i == 0;
            return (size_t)(p + n - line);
        }
    }
    return 0;
}

bool sl_diag_compile_error(sl_check_result *out, const char *error) {
    size_t prefix = strlen(_SL_COMPILE_ERROR);
    if (!error || strncmp(error, _SL_COMPILE_ERROR, prefix) != 0) return false;
    const char *main_file = error + prefix, *nl = strchr(main_file, '\n');
    size_t main_len = nl ? (size_t)(nl - main_file) : strlen(main_file);
    if (main_len > 0 && main_file[main_len - 1] == ':') main_len--;
    char file[sizeof out->not_compiled];
    snprintf(file, sizeof file, "%.*s", (int)main_len, main_file);
    /* The compiler's lines; a line that only continues the one before (Mesa's candidate list: the
     * same location, then the text indented) goes on that line, so a list is one line, not twenty.
     * Each line goes whole into the message, or is counted among those left out. */
    char lines[sizeof out->message] = "", pending[1024] = "", last[300] = "";
    size_t used = 0, last_len = 0, room = sizeof out->message - strlen(file) - 80;
    int continued = 0, more = 0, dropped = 0; /* a line's continuations said and left out; lines left out */
    bool file_found = false;
    for (const char *line = nl ? nl + 1 : NULL;;) {
        const char *end = line ? strchr(line, '\n') : NULL;
        size_t len = !line ? 0 : end ? (size_t)(end - line) : strlen(line), file_len = 0;
        bool is_error = false, whole = line && *line;
        size_t at = whole ? _sl_compiler_location(line, len, &file_len, &is_error) : 0;
        if (at && is_error && !file_found) {
            file_found = true;
            if (file_len > 5 && strncmp(line, "labs/", 5) == 0) snprintf(file, sizeof file, "%.*s", (int)file_len, line);
        }
        bool continues = whole && at && last_len == at && strncmp(line, last, at) == 0 && len > at + 2 &&
                         line[at] == ' ' && line[at + 1] == ' ';
        size_t p = strlen(pending);
        if (continues && ++continued > _SL_CONTINUED_MAX) {
            more++;
        } else if (continues) {
            const char *rest = line + at;
            while (*rest == ' ') rest++;
            snprintf(pending + p, sizeof pending - p, "%s%.*s", p > 0 && pending[p - 1] == ':' ? " " : ", ",
                     (int)(len - (size_t)(rest - line)), rest);
        } else if (len > 0 || !whole) {
            /* the line before is complete: into the message, whole, or left out */
            if (more > 0) snprintf(pending + p, sizeof pending - p, " and %d more", more);
            if (pending[0] && used + strlen(pending) + 1 < room)
                used += (size_t)snprintf(lines + used, sizeof lines - used, "%s%s", used ? "\n" : "", pending);
            else if (pending[0])
                dropped++;
            pending[0] = '\0';
            continued = more = 0;
            if (!whole) break;
            snprintf(pending, sizeof pending, "%.*s", (int)len, line);
            last_len = at < sizeof last ? at : 0;
            snprintf(last, sizeof last, "%.*s", (int)last_len, line);
        }
        line = end ? end + 1 : NULL;
    }
    if (dropped > 0) snprintf(lines + used, sizeof lines - used, "%s(and %d more lines)", used ? "\n" : "", dropped);
    sl_diag_say(out, "not reached: %s did not compile%s%s", file, lines[0] ? ":\n" : "", lines);
    snprintf(out->summary, sizeof out->summary, "not reached: %s did not compile", file);
    sl_utf8_trim(out->summary);
    sl_utf8_copy(out->not_compiled, sizeof out->not_compiled, file);
    out->settled = true;
    return true;
}

void sl_diag_compile_error_once(sl_check_result *out, sl_compile_errors_said *said) {
    if (!out->not_compiled[0] || out->passed) return;
    for (int i = 0; i < said->count; i++)
        if (strcmp(said->files[i], out->not_compiled) == 0) {
            sl_diag_say(out, "not reached: %s did not compile (see above)", out->not_compiled);
            return;
        }
    if (said->count < (int)(sizeof said->files / sizeof said->files[0]))
        snprintf(said->files[said->count++], sizeof said->files[0], "%s", out->not_compiled);
}

static char _sl_graded_tree[1024], _sl_stubs_tree[1024];

void sl_diag_set_sources(const char *graded_tree, const char *stubs_tree) {
    snprintf(_sl_graded_tree, sizeof _sl_graded_tree, "%s", graded_tree ? graded_tree : "");
    snprintf(_sl_stubs_tree, sizeof _sl_stubs_tree, "%s", stubs_tree ? stubs_tree : "");
}

int sl_diag_still_the_stub(const char *file, const char *function) {
    if (!_sl_graded_tree[0] || !_sl_stubs_tree[0] || !file || strstr(file, "..")) return -1;
    char path[2200];
    size_t graded_size = 0, stub_size = 0;
    snprintf(path, sizeof path, "%s/%s", _sl_graded_tree, file);
    char *graded = sl_glsl_read_source(path, &graded_size);
    snprintf(path, sizeof path, "%s/%s", _sl_stubs_tree, file);
    char *stub = sl_glsl_read_source(path, &stub_size);
    int answer = -1;
    sl_glsl_function *ours = malloc(2 * 128 * sizeof *ours);
    if (graded && stub && ours) {
        sl_glsl_function *theirs = ours + 128;
        int n = sl_glsl_functions(graded, graded_size, ours, 128), m = sl_glsl_functions(stub, stub_size, theirs, 128);
        const sl_glsl_function *mine = n > 0 ? sl_glsl_find(ours, n, function, 0) : NULL;
        const sl_glsl_function *handout = m > 0 ? sl_glsl_find(theirs, m, function, 0) : NULL;
        if (mine && handout) answer = sl_glsl_same_code(graded, mine, stub, handout) ? 1 : 0;
    }
    free(ours);
    free(graded);
    free(stub);
    return answer;
}
