/* sl_glsl_functions: a GLSL function splitter by braces (see the header). */
#define _POSIX_C_SOURCE 200809L
#include "sl_glsl_functions.h"

#include <ctype.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define _SL_MAX_SOURCE (1u << 20)

/* Skips a comment, a preprocessor line or a C string or character literal at text[i], if one starts there;
 * returns where scanning goes on. `line_start`: i begins a line (after spaces). */
static size_t _sl_skip_comment(const char *text, size_t size, size_t i, bool line_start) {
    if (i + 1 < size && text[i] == '/' && text[i + 1] == '/') {
        while (i < size && text[i] != '\n') i++;
        return i;
    }
    if (i + 1 < size && text[i] == '/' && text[i + 1] == '*') {
        i += 2;
        while (i + 1 < size && !(text[i] == '*' && text[i + 1] == '/')) i++;
        return i + 1 < size ? i + 2 : size;
    }
    if (text[i] == '"' || text[i] == '\'') { /* C's literals (the splitter reads a lab's C file too) */
        char quote = text[i++];
        while (i < size && text[i] != quote && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
        return i < size ? i + 1 : size;
    }
    if (line_start && text[i] == '#') { /* a directive, continued by a backslash at a line's end */
        while (i < size && text[i] != '\n') {
            if (text[i] == '\\' && i + 1 < size && text[i + 1] == '\n') i++;
            i++;
        }
        return i;
    }
    return i;
}

static bool _sl_ident_char(char ch) { return isalnum((unsigned char)ch) || ch == '_'; }

int sl_glsl_functions(const char *text, size_t size, sl_glsl_function *out, int max) {
    int count = 0, depth = 0;
    size_t item_start = (size_t)-1; /* where the current top-level declaration began */
    size_t open_paren = (size_t)-1, close_paren = (size_t)-1, body_start = 0;
    bool line_start = true;
    for (size_t i = 0; i < size;) {
        size_t next = _sl_skip_comment(text, size, i, line_start);
        if (next != i) {
            i = next;
            continue;
        }
        char ch = text[i];
        if (ch == '\n') line_start = true;
        else if (!isspace((unsigned char)ch)) line_start = false;
        if (depth == 0 && !isspace((unsigned char)ch) && item_start == (size_t)-1) item_start = i;
        if (ch == '{') {
            if (depth == 0) body_start = i;
            depth++;
        } else if (ch == '}') {
            if (--depth < 0) return -1;
            if (depth == 0) {
                /* a body after a parameter list is a function; after anything else (a struct, a block) not */
                bool function = close_paren != (size_t)-1 && open_paren < close_paren && close_paren < body_start;
                for (size_t j = close_paren + 1; function && j < body_start; j++)
                    if (!isspace((unsigned char)text[j])) function = false;
                if (function && count < max) {
                    size_t name_end = open_paren;
                    while (name_end > item_start && isspace((unsigned char)text[name_end - 1])) name_end--;
                    size_t name_start = name_end;
                    while (name_start > item_start && _sl_ident_char(text[name_start - 1])) name_start--;
                    size_t length = name_end - name_start;
                    if (length > 0 && length < SL_GLSL_NAME_MAX) {
                        memcpy(out[count].name, text + name_start, length);
                        out[count].name[length] = '\0';
                        out[count].start = item_start;
                        out[count].end = i + 1;
                        count++;
                    }
                }
                if (function) { /* a function's body ends its definition; a struct's needs its ';' */
                    item_start = (size_t)-1;
                    open_paren = close_paren = (size_t)-1;
                }
            }
        } else if (depth == 0 && ch == '(' && open_paren == (size_t)-1) {
            open_paren = i;
        } else if (depth == 0 && ch == ')') {
            close_paren = i;
        } else if (depth == 0 && ch == ';') {
            item_start = (size_t)-1;
            open_paren = close_paren = (size_t)-1;
        }
        i++;
    }
    return depth == 0 ? count : -1;
}

const sl_glsl_function *sl_glsl_find(const sl_glsl_function *functions, int count, const char *name, int occurrence) {
    for (int i = 0; i < count; i++)
        if (strcmp(functions[i].name, name) == 0 && occurrence-- == 0) return &functions[i];
    return NULL;
}

char *sl_glsl_splice(const char *into, size_t into_size, const sl_glsl_function *target, const char *from,
                     const sl_glsl_function *source) {
    size_t piece = source->end - source->start;
    size_t size = into_size - (target->end - target->start) + piece;
    char *text = malloc(size + 1);
    if (!text) return NULL;
    memcpy(text, into, target->start);
    memcpy(text + target->start, from + source->start, piece);
    memcpy(text + target->start + piece, into + target->end, into_size - target->end);
    text[size] = '\0';
    return text;
}

char *sl_glsl_read_source(const char *path, size_t *size) {
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) return NULL;
    char *text = malloc(_SL_MAX_SOURCE + 1);
    size_t used = 0;
    ssize_t got = 0;
    while (text && used < _SL_MAX_SOURCE && (got = read(fd, text + used, _SL_MAX_SOURCE - used)) > 0)
        used += (size_t)got;
    close(fd);
    if (!text || got < 0 || used >= _SL_MAX_SOURCE) {
        free(text);
        return NULL;
    }
    text[used] = '\0';
    *size = used;
    return text;
}

/* The next character of a definition that is code (comments and white space skipped), or -1 at its end. */
static int _sl_next_code(const char *text, size_t end, size_t *i) {
    while (*i < end) {
        char ch = text[*i];
        if (isspace((unsigned char)ch)) {
            (*i)++;
        } else if (ch == '/' && *i + 1 < end && (text[*i + 1] == '/' || text[*i + 1] == '*')) {
            *i = _sl_skip_comment(text, end, *i, false);
        } else {
            (*i)++;
            return (unsigned char)ch;
        }
    }
    return -1;
}

bool sl_glsl_same_code(const char *a_text, const sl_glsl_function *a, const char *b_text, const sl_glsl_function *b) {
    size_t i = a->start, j = b->start;
    for (;;) {
        int x = _sl_next_code(a_text, a->end, &i), y = _sl_next_code(b_text, b->end, &j);
        if (x != y) return false;
        if (x < 0) return true;
    }
}
