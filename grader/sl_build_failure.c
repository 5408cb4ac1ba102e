#define _XOPEN_SOURCE 700
#include "sl_build_failure.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_utf8.h"

#define _SL_LOG_MAX (8 << 20) /* a build log is read this far at most */
#define _SL_LINE_MAX 4096

/* Keeps printable characters; drops colour codes (ESC [ ... letter) and other
 * controls; bytes that are not UTF-8 (a lab file's, quoted by the compiler)
 * become U+FFFD (sl_utf8_clean), so every report can hold the line. */
static void _sl_clean(const char *in, char *out, size_t n) {
    char *plain = malloc(n);
    if (!plain) {
        if (n) out[0] = '\0';
        return;
    }
    size_t used = 0;
    for (const unsigned char *p = (const unsigned char *)in; *p && used + 1 < n; p++) {
        if (*p == 0x1b) {
            if (p[1] == '[') {
                p += 2;
                while (*p && !((*p >= '@' && *p <= '~'))) p++;
                if (!*p) break;
            }
            continue;
        }
        if (*p == '\t') plain[used++] = ' ';
        else if (*p >= 0x20 && *p != 0x7f) plain[used++] = (char)*p;
    }
    sl_utf8_clean(out, n, plain, used, 0);
    free(plain);
}

/* Removes every occurrence of `prefix` + '/' from `line`, in place. */
static void _sl_drop_prefix(char *line, const char *prefix) {
    size_t len = strlen(prefix);
    if (len == 0) return;
    char *at;
    while ((at = strstr(line, prefix)) && at[len] == '/') memmove(at, at + len + 1, strlen(at + len + 1) + 1);
}

/* How strongly a line looks like the error to show: 3 a compiler error, 2 the
 * linker's, 1 CMake's or make's, 0 none. */
static int _sl_error_rank(const char *line) {
    if (strstr(line, ": error:") || strstr(line, ": fatal error:")) return 3;
    if (strstr(line, "undefined reference to") || strstr(line, "multiple definition of") ||
        strstr(line, "ld returned"))
        return 2;
    if (strstr(line, "CMake Error") || strstr(line, "Error ") || strstr(line, "error:")) return 1;
    return 0;
}

bool sl_build_failure_first_error(const char *log_path, const char *labs_dir, char *out, size_t n, char *err,
                                  size_t err_size) {
    FILE *f = fopen(log_path, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot read the build log (%s)", log_path, strerror(errno));
        return false;
    }
    char *line = malloc(_SL_LINE_MAX), *clean = malloc(_SL_LINE_MAX);
    char best[_SL_LINE_MAX] = "";
    int best_rank = 0;
    long read_so_far = 0;
    while (line && clean && read_so_far < _SL_LOG_MAX && fgets(line, _SL_LINE_MAX, f)) {
        read_so_far += (long)strlen(line);
        /* a line longer than the buffer: keep its start, skip the rest */
        if (!strchr(line, '\n')) {
            int c;
            while ((c = fgetc(f)) != EOF && c != '\n') read_so_far++;
        }
        _sl_clean(line, clean, _SL_LINE_MAX);
        int rank = _sl_error_rank(clean);
        if (rank > best_rank) {
            best_rank = rank;
            snprintf(best, sizeof best, "%s", clean);
            if (rank == 3) break; /* the compiler's first error: the one to fix first */
        }
    }
    fclose(f);
    free(line);
    free(clean);
    if (!best_rank) snprintf(best, sizeof best, "the build failed without a compiler error (see the build log)");
    char resolved[4096];
    if (labs_dir && realpath(labs_dir, resolved)) _sl_drop_prefix(best, resolved);
    if (labs_dir) _sl_drop_prefix(best, labs_dir);
    size_t limit = n < SL_BUILD_ERROR_MAX + 1 ? n : SL_BUILD_ERROR_MAX + 1;
    if (strlen(best) >= limit && limit > 4) snprintf(out, n, "%.*s...", (int)sl_utf8_cut(best, limit - 4), best);
    else snprintf(out, n, "%s", best);
    return true;
}

void sl_build_failure_grade(const sl_check *k, const char *first_error, sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    out->bonus = k->bonus;
    snprintf(out->message, sizeof out->message, "the submission did not build: %s", first_error);
}

void sl_build_failure_grade_lab(const sl_check *k, int lab, const char *first_error, sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    out->bonus = k->bonus;
    snprintf(out->message, sizeof out->message, "lab %d did not build: %s", lab, first_error);
}
