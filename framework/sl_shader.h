/* sl_shader: GLSL programs built from files at run time.
 *
 * - `#include "file.glsl"` is resolved against the including file's folder, then
 *   the search folders given in the desc; each file is included once per stage.
 * - Compile and link errors name the original file and line:
 *     labs/lab2_projective/shaders/shadow_lookup.glsl:14:5: error: ...
 * - Each file is read as editors write it (sl_text.h): a UTF-8 byte-order mark
 *   is dropped and CRLF or CR line ends become LF; a NUL byte, bytes that are
 *   not UTF-8 or a UTF-16 file fail with the file and the byte's offset.
 * - sl_program_reload_if_changed() rebuilds when any source file changed on disk,
 *   keeping the old program when the new one fails (the viewer's hot reload). */
#ifndef SL_SHADER_H
#define SL_SHADER_H

#include <stdbool.h>
#include <stddef.h>
#include <time.h>

#include "sl_gl.h"

#define SL_SHADER_MAX_FILES 32
#define SL_SHADER_MAX_DIRS 4
#define SL_PATH_MAX 1024

typedef struct sl_shader_desc {
    const char *vertex_path;
    const char *fragment_path;
    const char *geometry_path;                 /* optional */
    const char *search_dirs[SL_SHADER_MAX_DIRS]; /* for #include; NULL-terminated */
    const char *defines;                       /* optional lines inserted after #version */
    /* optional: a stage's text itself, instead of reading its path (which
     * then only names it and places its #includes) */
    const char *vertex_source;
    const char *fragment_source;
} sl_shader_desc;

typedef struct sl_program {
    GLuint id;
    char stage_paths[3][SL_PATH_MAX];
    char search_dirs[SL_SHADER_MAX_DIRS][SL_PATH_MAX];
    char defines[512];
    char *vertex_source;   /* owned copy of sl_shader_desc.vertex_source, or NULL */
    char *fragment_source; /* owned copy of sl_shader_desc.fragment_source, or NULL */
    /* every file read for the current program, with its time stamp */
    char files[SL_SHADER_MAX_FILES][SL_PATH_MAX];
    long long mtimes[SL_SHADER_MAX_FILES]; /* nanoseconds (sl_platform_file_time): polled, not watched */
    int file_count;
} sl_program;

/* On failure returns false and writes the compiler's log, with file names and
 * lines, into err; the program is left empty. */
bool sl_program_build(sl_program *program, const sl_shader_desc *desc, char *err, size_t err_size);
/* True when a file the program was built from changed on disk since. */
bool sl_program_files_changed(const sl_program *program);
/* Returns true if it rebuilt successfully; false if unchanged or on failure
 * (err non-empty then, and the old program stays in use). */
bool sl_program_reload_if_changed(sl_program *program, char *err, size_t err_size);
void sl_program_destroy(sl_program *program);
GLint sl_program_uniform(const sl_program *program, const char *name);

/* Preprocessing alone (no GL): expands includes and inserts #line markers.
 * Returns a malloc'ed string or NULL with err set. files/file_count receive the
 * source list (index = GLSL source-string number). Exposed for tests. */
char *sl_shader_preprocess(const char *path, const char *const *search_dirs, const char *defines,
                           char files[][SL_PATH_MAX], int *file_count, char *err, size_t err_size);
/* The same for a main file given as text (`path` names it and places its includes). */
char *sl_shader_preprocess_text(const char *path, const char *text, const char *const *search_dirs,
                                const char *defines, char files[][SL_PATH_MAX], int *file_count, char *err,
                                size_t err_size);
/* Rewrites a driver log "0:12(5): error: x" into "file:12:5: error: x". */
void sl_shader_map_log(const char *log, char files[][SL_PATH_MAX], int file_count, char *out, size_t out_size);

#endif
