/* sl_glsl_functions: the function definitions of a GLSL source (or a lab's C
 * file), found by matching braces (comments, preprocessor lines and C's string
 * and character literals skipped), and a source
 * with one definition replaced by another's. Staff grading's experiments
 * (sl_experiment.h) put one solution function into a student's shader file
 * with it. Text only: nothing here compiles or runs GLSL. */
#ifndef SL_GLSL_FUNCTIONS_H
#define SL_GLSL_FUNCTIONS_H

#include <stdbool.h>
#include <stddef.h>

#define SL_GLSL_NAME_MAX 64

typedef struct sl_glsl_function {
    char name[SL_GLSL_NAME_MAX]; /* "pcf_grid", "main" */
    size_t start, end;           /* the definition: from its return type to its closing brace, included */
} sl_glsl_function;

/* The definitions in text[0..size), in order (declarations without a body are
 * not definitions); at most `max`. Returns how many, or -1 when the braces do
 * not match (a source the compiler would refuse anyway). */
int sl_glsl_functions(const char *text, size_t size, sl_glsl_function *out, int max);

/* The `occurrence`-th (0: first) definition of `name`, or NULL. */
const sl_glsl_function *sl_glsl_find(const sl_glsl_function *functions, int count, const char *name, int occurrence);

/* `into` with the definition `target` replaced by `from`'s text of `source`:
 * a new string (free it), or NULL when out of memory. */
char *sl_glsl_splice(const char *into, size_t into_size, const sl_glsl_function *target, const char *from,
                     const sl_glsl_function *source);

/* A source file's text (at most 1 MiB, NUL-terminated), or NULL; *size its length. Symbolic links are
 * not followed: a graded tree's file is read as the tree holds it. */
char *sl_glsl_read_source(const char *path, size_t *size);

/* Whether two definitions are the same text up to comments and white space. */
bool sl_glsl_same_code(const char *a_text, const sl_glsl_function *a, const char *b_text, const sl_glsl_function *b);

#endif
