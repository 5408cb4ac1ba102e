#define _XOPEN_SOURCE 700
#include "sl_shader.h"

#include <ctype.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_platform.h"

#include "sl_text.h"

#define _SL_INCLUDE_DEPTH_MAX 16
/* Every file's lines are numbered from (its source number * this): some
 * drivers report a wrong source number for some errors (Mesa, for
 * initializers in an included file) but always the right line, so the line
 * alone says which file it was. */
#define _SL_LINE_BASE 100000

typedef struct _sl_strbuf {
    char *data;
    size_t len, cap;
    bool failed;
} _sl_strbuf;

static void _sl_append(_sl_strbuf *b, const char *s, size_t n) {
    if (b->failed) return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n + 1) cap *= 2;
        char *data = realloc(b->data, cap);
        if (!data) {
            b->failed = true;
            return;
        }
        b->data = data;
        b->cap = cap;
    }
    memcpy(b->data + b->len, s, n);
    b->len += n;
    b->data[b->len] = '\0';
}

static void _sl_appendf(_sl_strbuf *b, const char *fmt, ...) {
    char tmp[SL_PATH_MAX + 64];
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(tmp, sizeof tmp, fmt, args);
    va_end(args);
    if (n > 0) _sl_append(b, tmp, (size_t)n < sizeof tmp ? (size_t)n : sizeof tmp - 1);
}

/* The file's bytes, NUL-terminated, and their count (a file may hold NULs). */
static char *_sl_read_file(const char *path, size_t *length) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    _sl_strbuf b = {0};
    char chunk[4096];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) _sl_append(&b, chunk, n);
    fclose(f);
    if (!b.data) _sl_append(&b, "", 0);
    if (b.failed) {
        free(b.data);
        return NULL;
    }
    *length = b.len;
    return b.data;
}

static bool _sl_file_exists(const char *path) { return sl_platform_is_file(path); }

static void _sl_dirname(const char *path, char *out, size_t n) {
    const char *slash = strrchr(path, '/');
    if (!slash) {
        snprintf(out, n, ".");
        return;
    }
    snprintf(out, n, "%.*s", (int)(slash - path), path);
}

typedef struct _sl_pp {
    const char *const *search_dirs;
    /* Included files must lie in one of these (real paths): the search
     * folders and the main file's folder, so lab code cannot pull in files
     * from elsewhere on the machine (other labs' solutions, references). */
    char roots[SL_SHADER_MAX_DIRS + 1][SL_PATH_MAX];
    int root_count;
    char (*files)[SL_PATH_MAX];
    int file_count;
    char *err;
    size_t err_size;
    bool version_seen;
    const char *defines;
    const char *main_text; /* the main file's text, when it is not a file */
} _sl_pp;

static int _sl_register_file(_sl_pp *pp, const char *path, bool *already) {
    for (int i = 0; i < pp->file_count; i++) {
        if (strcmp(pp->files[i], path) == 0) {
            *already = true;
            return i;
        }
    }
    *already = false;
    if (pp->file_count >= SL_SHADER_MAX_FILES) return -1;
    snprintf(pp->files[pp->file_count], SL_PATH_MAX, "%s", path);
    return pp->file_count++;
}

static bool _sl_expand(_sl_pp *pp, _sl_strbuf *out, const char *path, int depth);

static void _sl_add_root(_sl_pp *pp, const char *dir) {
    char real[PATH_MAX];
    if (pp->root_count <= SL_SHADER_MAX_DIRS && sl_platform_real_path(dir, real, sizeof real))
        snprintf(pp->roots[pp->root_count++], SL_PATH_MAX, "%s", real);
}

static bool _sl_inside_roots(const _sl_pp *pp, const char *path) {
    char real[PATH_MAX];
    if (!sl_platform_real_path(path, real, sizeof real)) return false;
    for (int i = 0; i < pp->root_count; i++) {
        size_t n = strlen(pp->roots[i]);
        if (strncmp(real, pp->roots[i], n) == 0 && (real[n] == '/' || (n == 1 && pp->roots[i][0] == '/'))) return true;
    }
    return false;
}

/* Resolves an #include name: the including file's folder first, then the
 * search folders. 0: found; 1: not found; 2: found, but outside the roots. */
static int _sl_resolve_include(_sl_pp *pp, const char *from, const char *name, char *out, size_t n) {
    char dir[SL_PATH_MAX];
    bool outside = false;
    _sl_dirname(from, dir, sizeof dir);
    snprintf(out, n, "%s/%s", dir, name);
    if (_sl_file_exists(out)) {
        if (_sl_inside_roots(pp, out)) return 0;
        outside = true;
    }
    for (int i = 0; pp->search_dirs && i < SL_SHADER_MAX_DIRS && pp->search_dirs[i]; i++) {
        snprintf(out, n, "%s/%s", pp->search_dirs[i], name);
        if (_sl_file_exists(out)) {
            if (_sl_inside_roots(pp, out)) return 0;
            outside = true;
        }
    }
    return outside ? 2 : 1;
}

static bool _sl_expand(_sl_pp *pp, _sl_strbuf *out, const char *path, int depth) {
    /* Messages name the real file, also when a labs tree is assembled from links (--isolate). */
    char real[4096];
    bool given = depth == 0 && pp->main_text;
    if (!given && sl_platform_real_path(path, real, sizeof real)) path = real;
    bool already;
    int id = _sl_register_file(pp, path, &already);
    if (already) return true; /* included once */
    if (id < 0) {
        snprintf(pp->err, pp->err_size, "%s: too many included files (at most %d)", path, SL_SHADER_MAX_FILES);
        return false;
    }
    size_t length = 0;
    char *text = given ? strdup(pp->main_text) : _sl_read_file(path, &length);
    if (!text) {
        snprintf(pp->err, pp->err_size, "%s: cannot read shader file", path);
        return false;
    }
    if (given) length = strlen(text);
    /* Bytes that are not text are named with their offset (the compiler would
     * only say "syntax error"); a BOM and CRLF or CR line ends (Windows and old
     * Mac editors) are made plain. */
    sl_text_problems problems;
    if (!sl_text_check(text, length, &problems)) {
        sl_text_problems_describe(&problems, path, pp->err, pp->err_size);
        free(text);
        return false;
    }
    text[sl_text_normalize(text, length, NULL)] = '\0';
    int line_no = 1;
    bool need_marker = id != 0; /* the main file starts at line 1 by itself */
    const char *line = text;
    bool ok = true;
    while (ok && *line) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        const char *p = line;
        while (p < line + len && isspace((unsigned char)*p)) p++;
        if (need_marker && !(strncmp(p, "#version", 8) == 0)) {
            _sl_appendf(out, "#line %d %d\n", id * _SL_LINE_BASE + line_no, id);
            need_marker = false;
        }
        if (strncmp(p, "#version", 8) == 0) {
            if (depth > 0 || pp->version_seen) {
                _sl_append(out, "\n", 1); /* only the main file's #version counts */
            } else {
                _sl_append(out, line, len);
                _sl_append(out, "\n", 1);
                if (pp->defines && *pp->defines) {
                    _sl_append(out, pp->defines, strlen(pp->defines));
                    _sl_append(out, "\n", 1);
                }
                _sl_appendf(out, "#line %d %d\n", id * _SL_LINE_BASE + line_no + 1, id);
            }
            pp->version_seen = true;
        } else if (strncmp(p, "#include", 8) == 0) {
            const char *q1 = strchr(p, '"');
            const char *q2 = q1 ? strchr(q1 + 1, '"') : NULL;
            if (!q1 || !q2 || q2 > line + len) {
                snprintf(pp->err, pp->err_size, "%s:%d: error: #include expects \"file\"", path, line_no);
                ok = false;
                break;
            }
            char name[SL_PATH_MAX], resolved[SL_PATH_MAX];
            snprintf(name, sizeof name, "%.*s", (int)(q2 - q1 - 1), q1 + 1);
            if (depth >= _SL_INCLUDE_DEPTH_MAX) {
                snprintf(pp->err, pp->err_size, "%s:%d: error: #include nested too deeply", path, line_no);
                ok = false;
                break;
            }
            int found = name[0] == '/' ? 2 : _sl_resolve_include(pp, path, name, resolved, sizeof resolved);
            if (found == 2) {
                snprintf(pp->err, pp->err_size,
                         "%s:%d: error: #include \"%s\" reaches outside the shader folders (the labs folder and "
                         "framework/shaders): include files from there only",
                         path, line_no, name);
                ok = false;
                break;
            }
            if (found == 1) {
                snprintf(pp->err, pp->err_size, "%s:%d: error: cannot find included file \"%s\"", path, line_no, name);
                ok = false;
                break;
            }
            ok = _sl_expand(pp, out, resolved, depth + 1);
            _sl_appendf(out, "#line %d %d\n", id * _SL_LINE_BASE + line_no + 1, id);
        } else {
            _sl_append(out, line, len);
            _sl_append(out, "\n", 1);
        }
        line_no++;
        line = end ? end + 1 : line + len;
    }
    free(text);
    if (out->failed) {
        snprintf(pp->err, pp->err_size, "%s: out of memory", path);
        return false;
    }
    return ok;
}

char *sl_shader_preprocess(const char *path, const char *const *search_dirs, const char *defines,
                           char files[][SL_PATH_MAX], int *file_count, char *err, size_t err_size) {
    return sl_shader_preprocess_text(path, NULL, search_dirs, defines, files, file_count, err, err_size);
}

char *sl_shader_preprocess_text(const char *path, const char *text, const char *const *search_dirs,
                                const char *defines, char files[][SL_PATH_MAX], int *file_count, char *err,
                                size_t err_size) {
    char dummy_err[8];
    _sl_pp pp = {
        .search_dirs = search_dirs,
        .files = files,
        .err = err ? err : dummy_err,
        .err_size = err ? err_size : sizeof dummy_err,
        .defines = defines,
        .main_text = text,
    };
    char main_dir[SL_PATH_MAX];
    _sl_dirname(path, main_dir, sizeof main_dir);
    _sl_add_root(&pp, main_dir);
    for (int i = 0; search_dirs && i < SL_SHADER_MAX_DIRS && search_dirs[i]; i++) _sl_add_root(&pp, search_dirs[i]);
    _sl_strbuf out = {0};
    bool ok = _sl_expand(&pp, &out, path, 0);
    if (file_count) *file_count = pp.file_count;
    if (!ok) {
        free(out.data);
        return NULL;
    }
    return out.data;
}

/* Driver logs name sources by number: Mesa "3:12(5): error: x", NVIDIA "3(12) : error x",
 * AMD/others "ERROR: 3:12: x". Map the number to its file. */
void sl_shader_map_log(const char *log, char files[][SL_PATH_MAX], int file_count, char *out, size_t out_size) {
    _sl_strbuf b = {0};
    const char *line = log;
    while (line && *line) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        int src = -1, ln = 0, col = 0, consumed = 0;
        const char *p = line;
        bool mapped = false;
        if (strncmp(p, "ERROR: ", 7) == 0 || strncmp(p, "WARNING: ", 9) == 0) p = strchr(p, ' ') + 1;
        if (sscanf(p, "%d:%d(%d): %n", &src, &ln, &col, &consumed) == 3 && consumed > 0) {
            mapped = true;
        } else if (sscanf(p, "%d(%d) : %n", &src, &ln, &consumed) == 2 && consumed > 0) {
            col = 0;
            mapped = true;
        } else if (sscanf(p, "%d:%d: %n", &src, &ln, &consumed) == 2 && consumed > 0) {
            col = 0;
            mapped = true;
        }
        if (mapped && ln >= _SL_LINE_BASE) { /* the line names the file (see _SL_LINE_BASE) */
            src = ln / _SL_LINE_BASE;
            ln %= _SL_LINE_BASE;
        }
        if (mapped && src >= 0 && src < file_count) {
            if (col > 0)
                _sl_appendf(&b, "%s:%d:%d: ", files[src], ln, col);
            else
                _sl_appendf(&b, "%s:%d: ", files[src], ln);
            size_t rest = len - (size_t)(p + consumed - line);
            _sl_append(&b, p + consumed, rest);
        } else {
            _sl_append(&b, line, len);
        }
        _sl_append(&b, "\n", 1);
        line = end ? end + 1 : NULL;
    }
    snprintf(out, out_size, "%s", b.data ? b.data : "");
    free(b.data);
}

static GLuint _sl_compile(GLenum stage, const char *path, const sl_program *program, int *total_files,
                          char all_files[][SL_PATH_MAX], char *err, size_t err_size) {
    const char *dirs[SL_SHADER_MAX_DIRS + 1] = {0};
    for (int i = 0; i < SL_SHADER_MAX_DIRS && program->search_dirs[i][0]; i++) dirs[i] = program->search_dirs[i];
    char files[SL_SHADER_MAX_FILES][SL_PATH_MAX];
    int count = 0;
    const char *text = stage == GL_FRAGMENT_SHADER ? program->fragment_source
                       : stage == GL_VERTEX_SHADER ? program->vertex_source
                                                   : NULL;
    char *source = sl_shader_preprocess_text(path, text, dirs, program->defines, files, &count, err, err_size);
    if (!source) return 0;
    for (int i = 0; i < count && *total_files < SL_SHADER_MAX_FILES; i++)
        snprintf(all_files[(*total_files)++], SL_PATH_MAX, "%s", files[i]);
    GLuint shader = glCreateShader(stage);
    const GLchar *src = source;
    glShaderSource(shader, 1, &src, NULL);
    glCompileShader(shader);
    free(source);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192] = {0};
        glGetShaderInfoLog(shader, sizeof log, NULL, log);
        char mapped[8192];
        sl_shader_map_log(log, files, count, mapped, sizeof mapped);
        snprintf(err, err_size, "GLSL compile error in %s:\n%s", path, mapped);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

static bool _sl_build_from_paths(sl_program *program, char *err, size_t err_size) {
    static const GLenum stages[3] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_GEOMETRY_SHADER};
    char files[SL_SHADER_MAX_FILES][SL_PATH_MAX];
    int file_count = 0;
    GLuint shaders[3] = {0};
    GLuint id = 0;
    bool ok = true;
    for (int s = 0; s < 3 && ok; s++) {
        if (!program->stage_paths[s][0]) continue;
        shaders[s] = _sl_compile(stages[s], program->stage_paths[s], program, &file_count, files, err, err_size);
        ok = shaders[s] != 0;
    }
    if (ok) {
        id = glCreateProgram();
        for (int s = 0; s < 3; s++)
            if (shaders[s]) glAttachShader(id, shaders[s]);
        glBindAttribLocation(id, 0, "a_position");
        glBindAttribLocation(id, 1, "a_normal");
        glLinkProgram(id);
        GLint linked = 0;
        glGetProgramiv(id, GL_LINK_STATUS, &linked);
        if (!linked) {
            char log[4096] = {0};
            glGetProgramInfoLog(id, sizeof log, NULL, log);
            snprintf(err, err_size, "GLSL link error (%s + %s):\n%s", program->stage_paths[0], program->stage_paths[1], log);
            glDeleteProgram(id);
            id = 0;
            ok = false;
        }
    }
    for (int s = 0; s < 3; s++)
        if (shaders[s]) glDeleteShader(shaders[s]);
    /* Every file read is watched, even on failure, so a fix triggers a reload. */
    program->file_count = 0;
    for (int i = 0; i < file_count; i++) {
        bool dup = false;
        for (int j = 0; j < program->file_count; j++) dup |= strcmp(program->files[j], files[i]) == 0;
        if (dup) continue;
        int k = program->file_count++;
        snprintf(program->files[k], SL_PATH_MAX, "%s", files[i]);
        if (!sl_platform_file_time(files[i], &program->mtimes[k])) program->mtimes[k] = 0;
    }
    for (int s = 0; s < 3 && !ok; s++) /* a file that failed to preprocess is watched too */
        if (program->stage_paths[s][0] && program->file_count < SL_SHADER_MAX_FILES) {
            bool dup = false;
            for (int j = 0; j < program->file_count; j++) dup |= strcmp(program->files[j], program->stage_paths[s]) == 0;
            if (!dup) {
                int k = program->file_count++;
                snprintf(program->files[k], SL_PATH_MAX, "%s", program->stage_paths[s]);
                if (!sl_platform_file_time(program->stage_paths[s], &program->mtimes[k])) program->mtimes[k] = 0;
            }
        }
    if (ok) {
        if (program->id) glDeleteProgram(program->id);
        program->id = id;
        if (err && err_size) err[0] = '\0';
    }
    return ok;
}

bool sl_program_build(sl_program *program, const sl_shader_desc *desc, char *err, size_t err_size) {
    memset(program, 0, sizeof *program);
    const char *paths[3] = {desc->vertex_path, desc->fragment_path, desc->geometry_path};
    for (int s = 0; s < 3; s++)
        if (paths[s]) snprintf(program->stage_paths[s], SL_PATH_MAX, "%s", paths[s]);
    for (int i = 0; i < SL_SHADER_MAX_DIRS && desc->search_dirs[i]; i++)
        snprintf(program->search_dirs[i], SL_PATH_MAX, "%s", desc->search_dirs[i]);
    if (desc->defines) snprintf(program->defines, sizeof program->defines, "%s", desc->defines);
    if (desc->vertex_source) program->vertex_source = strdup(desc->vertex_source);
    if (desc->fragment_source) program->fragment_source = strdup(desc->fragment_source);
    return _sl_build_from_paths(program, err, err_size);
}

bool sl_program_files_changed(const sl_program *program) {
    /* Polled (the viewer asks four times a second), not watched: the same on
     * every system and on file systems that send no change events. */
    for (int i = 0; i < program->file_count; i++) {
        long long time = 0;
        if (!sl_platform_file_time(program->files[i], &time)) continue; /* mid-save: try again later */
        if (time != program->mtimes[i]) return true;
    }
    return false;
}

bool sl_program_reload_if_changed(sl_program *program, char *err, size_t err_size) {
    if (err && err_size) err[0] = '\0';
    if (!sl_program_files_changed(program)) return false;
    return _sl_build_from_paths(program, err, err_size);
}

void sl_program_destroy(sl_program *program) {
    if (program->id) glDeleteProgram(program->id);
    program->id = 0;
    free(program->vertex_source);
    program->vertex_source = NULL;
    free(program->fragment_source);
    program->fragment_source = NULL;
}

GLint sl_program_uniform(const sl_program *program, const char *name) {
    return glGetUniformLocation(program->id, name);
}
