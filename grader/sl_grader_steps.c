#define _GNU_SOURCE
#include "sl_grader_steps.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <fnmatch.h>
#include <ftw.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sl_build_failure.h"
#include "sl_backend.h"
#include "sl_diagnose.h"
#include "sl_files.h"
#include "sl_grade.h"
#include "sl_gradebook.h"
#include "sl_hidden.h"
#include "sl_manifest.h"
#include "sl_utf8.h"

volatile int _sl_stop;
void _sl_on_signal(int sig) {
    (void)sig;
    _sl_stop = 1;
}

static int _sl_compare_names(const void *a, const void *b) {
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

double _sl_monotonic_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static bool _sl_matches(const char *name, const char *pattern) {
    return fnmatch(pattern, name, 0) == 0 || strstr(name, pattern) != NULL;
}

static bool _sl_matches_any(const char *name, const char *const *patterns, int count) {
    for (int i = 0; i < count; i++)
        if (_sl_matches(name, patterns[i])) return true;
    return false;
}

bool _sl_is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

bool _sl_is_executable(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, X_OK) == 0;
}

bool _sl_check_labs_tree(const char *dir, char *err, size_t n) {
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        if (!sl_lab_folder(lab)) continue; /* a lab number this course tree does not have */
        char path[1200];
        snprintf(path, sizeof path, "%s/%s/shaders", dir, sl_lab_folder(lab));
        if (!_sl_is_dir(path)) {
            snprintf(err, n, "%s is not a labs tree: %s is missing", dir, path);
            return false;
        }
    }
    return true;
}

const char *const *_sl_runner_environment(bool window) {
    static char *env[64];
    static const char *const prefixes[] = {"LP_", "GALLIUM_", "MESA_", "LIBGL_", "EGL_", "__EGL_", "DRI_PRIME"};
    extern char **environ;
    int n = 0;
    env[n++] = "PATH=/usr/bin:/bin";
    env[n++] = "HOME=/tmp";
    env[n++] = "TMPDIR=/tmp";
    env[n++] = "LANG=C";
    /* --backend window: the display the hidden window opens, and its cookie */
    if (window) {
        static char display[300], cookie[1100];
        const char *d = getenv("DISPLAY"), *x = getenv("XAUTHORITY"), *home = getenv("HOME");
        if (d && strlen(d) < 256) {
            snprintf(display, sizeof display, "DISPLAY=%s", d);
            env[n++] = display;
        }
        if (x && x[0] == '/') snprintf(cookie, sizeof cookie, "XAUTHORITY=%s", x);
        else if (home && home[0] == '/') snprintf(cookie, sizeof cookie, "XAUTHORITY=%s/.Xauthority", home);
        if (cookie[0]) env[n++] = cookie;
    }
    /* no shader cache: nothing a case writes may reach a later case */
    env[n++] = "MESA_SHADER_CACHE_DISABLE=true";
    env[n++] = "MESA_GLSL_CACHE_DISABLE=true";
    /* One thread per runner, unless staff say otherwise: llvmpipe makes its
     * drawing threads with the context, and one that cannot (the machine or
     * the user out of processes: a neighbour's doing) hangs at its first
     * draw. Single-threaded, an honest runner needs no new thread, and the
     * pictures are the same (runners run side by side instead, -j). */
    if (!getenv("LP_NUM_THREADS")) env[n++] = "LP_NUM_THREADS=0";
    for (char **e = environ; *e && n < 62; e++) {
        if (strncmp(*e, "MESA_SHADER_CACHE", 17) == 0 || strncmp(*e, "MESA_GLSL_CACHE", 15) == 0) continue;
        for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++)
            if (strncmp(*e, prefixes[i], strlen(prefixes[i])) == 0) {
                env[n++] = *e;
                break;
            }
    }
    env[n] = NULL;
    return (const char *const *)env;
}

const char *_sl_isolated_source(int lab, int other, const char *graded) {
    if (other == lab) return graded;
    return sl_lab_builds_on(lab, other) ? sl_config_solutions_dir : sl_config_stubs_dir;
}

/* Copies the regular files and folders of `from` into `to` (made), readable to
 * all: the runners of the uid and basic sandboxes read the stand-ins' shaders
 * as a user who may not read the solutions or the build (the Gradescope image
 * closes them to uid 65534). Links are not followed. */
static bool _sl_copy_readable(const char *from, const char *to, int depth) {
    if (depth > 4 || mkdir(to, 0755) != 0) return false;
    chmod(to, 0755);
    DIR *dir = opendir(from);
    if (!dir) return false;
    bool ok = true;
    struct dirent *e;
    while (ok && (e = readdir(dir))) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        char src[2048], dst[2048];
        struct stat st;
        snprintf(src, sizeof src, "%s/%s", from, e->d_name);
        snprintf(dst, sizeof dst, "%s/%s", to, e->d_name);
        if (lstat(src, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            ok = _sl_copy_readable(src, dst, depth + 1);
        } else if (S_ISREG(st.st_mode)) {
            int in = open(src, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
            int out = in >= 0 ? open(dst, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644) : -1;
            char buf[16384];
            ssize_t n = 0;
            while (out >= 0 && (n = read(in, buf, sizeof buf)) > 0)
                if (write(out, buf, (size_t)n) != n) n = -1, ok = false;
            if (in < 0 || out < 0 || n < 0) ok = false;
            if (out >= 0) fchmod(out, 0644), close(out);
            if (in >= 0) close(in);
        }
    }
    closedir(dir);
    return ok;
}

static int _sl_remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw) {
    (void)st, (void)ftw;
    return type == FTW_DP ? rmdir(path) : unlink(path);
}

bool _sl_make_isolation_trees(char root[64], const char *graded, char trees[][96]) {
    snprintf(root, 64, "/tmp/shadowlab-isolate-XXXXXX");
    if (!mkdtemp(root)) {
        fprintf(stderr, "shadowlab-grade: cannot create a folder under /tmp for --isolate: %s\n", strerror(errno));
        root[0] = '\0';
        return false;
    }
    chmod(root, 0755);
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        if (!sl_lab_folder(lab)) continue;
        snprintf(trees[lab], 96, "%s/lab%d", root, lab);
        if (mkdir(trees[lab], 0755) != 0) return false;
        for (int other = 1; other <= SL_LAB_COUNT; other++) {
            if (!sl_lab_folder(other)) continue;
            char target[2048], link_path[256];
            snprintf(target, sizeof target, "%s/%s", _sl_isolated_source(lab, other, graded), sl_lab_folder(other));
            snprintf(link_path, sizeof link_path, "%s/%s", trees[lab], sl_lab_folder(other));
            if (!_sl_copy_readable(target, link_path, 0)) {
                fprintf(stderr, "shadowlab-grade: cannot copy %s for --isolate\n", target);
                return false;
            }
        }
    }
    return true;
}

void _sl_remove_isolation_trees(const char *root) {
    if (!root[0]) return;
    nftw(root, _sl_remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

bool _sl_compile_fence(const char *runners_dir, char *out, size_t n) {
    char path[1300], line[400] = "";
    snprintf(path, sizeof path, "%s/compile-fence.txt", runners_dir);
    FILE *f = fopen(path, "r");
    if (!f || !fgets(line, sizeof line, f)) {
        if (f) fclose(f);
        snprintf(out, n, "not fenced (the runners' build says nothing of a fence: %s is missing; rebuild them)", path);
        return false;
    }
    fclose(f);
    line[strcspn(line, "\r\n")] = '\0';
    for (char *c = line; *c; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = ' ';
    if (strcmp(line, "namespaces") == 0 || strcmp(line, "uid") == 0) {
        snprintf(out, n, "fenced (%s): it saw the framework's headers, the system and the lab's own files only", line);
        return true;
    }
    if (strncmp(line, "trusted:", 8) == 0) {
        snprintf(out, n, "no fence needed:%s", line + 8);
        return true;
    }
    snprintf(out, n, "NOT fenced (%s): lab code could read at build time what the builder could", line);
    return false;
}

void _sl_case_ended(const sl_case *c, const sl_case_result *r, int ended, int total, void *context) {
    const _sl_progress *p = context;
    if (p->lines)
        fprintf(stderr, "shadowlab-grade: [%d/%d] %s (%.1f s)\n", ended, total, c->name, r->seconds);
    else
        fprintf(stderr, "\r\033[Kshadowlab-grade: [%d/%d] %s", ended, total, c->name);
    fflush(stderr);
}

/* Where a case stands in the order a student works a lab: its probes first (each step's function on its
 * own, the first thing to fix: a picture's message leads with a failed probe, and quotes a compile
 * error there), then the pictures by the last step they need, then the cases only a bonus has. */
typedef struct _sl_case_rank {
    int lab, kind, step, index;
} _sl_case_rank;

static _sl_case_rank _sl_rank_of(const sl_case *c, int index) {
    bool probes_only = true, bonus_only = true;
    for (int k = 0; k < c->check_count; k++) {
        probes_only &= c->checks[k].kind == SL_CHECK_PROBE;
        bonus_only &= c->checks[k].bonus;
    }
    return (_sl_case_rank){c->lab, bonus_only ? 2 : probes_only ? 0 : 1, sl_case_step(c), index};
}

static int _sl_compare_ranks(const void *a, const void *b) {
    const _sl_case_rank *x = a, *y = b;
    if (x->lab != y->lab) return x->lab < y->lab ? -1 : 1;
    if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
    if (x->step != y->step) return x->step < y->step ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index; /* then by name, as read */
}

/* Sorts the cases into the order a student works (_sl_case_rank): every report prints them so. */
static void _sl_order_cases(sl_case *cases, int count) {
    _sl_case_rank *ranks = malloc(sizeof *ranks * (size_t)(count > 0 ? count : 1));
    sl_case *sorted = malloc(sizeof *sorted * (size_t)(count > 0 ? count : 1));
    if (!ranks || !sorted) { /* no memory: the name order stands */
        free(ranks);
        free(sorted);
        return;
    }
    for (int i = 0; i < count; i++) ranks[i] = _sl_rank_of(&cases[i], i);
    qsort(ranks, (size_t)count, sizeof *ranks, _sl_compare_ranks);
    for (int i = 0; i < count; i++) sorted[i] = cases[ranks[i].index];
    memcpy(cases, sorted, sizeof *sorted * (size_t)count);
    free(ranks);
    free(sorted);
}

int _sl_load_cases(const _sl_options *o, sl_case *cases, sl_grade_report *rep) {
    DIR *d = opendir(o->cases_dir);
    if (!d) return -1;
    char *names[_SL_MAX_CASES];
    int name_count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && name_count < _SL_MAX_CASES) {
        size_t len = strlen(e->d_name);
        if (len > 5 && strcmp(e->d_name + len - 5, ".json") == 0) names[name_count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)name_count, sizeof names[0], _sl_compare_names);
    int count = 0;
    for (int i = 0; i < name_count; i++) {
        char path[1400], err[1200];
        snprintf(path, sizeof path, "%s/%s", o->cases_dir, names[i]);
        free(names[i]);
        sl_case *c = &cases[count];
        bool ok = sl_case_load(c, path, err, sizeof err);
        for (int j = 0; ok && j < count; j++)
            if (strcmp(cases[j].name, c->name) == 0) {
                snprintf(err, sizeof err, "%s: the name \"%s\" is taken by %s", path, c->name, cases[j].path);
                ok = false;
            }
        if (!ok) {
            if (rep->problem_count < 32) sl_utf8_copy(rep->problems[rep->problem_count++], sizeof rep->problems[0], err);
            continue;
        }
        if (o->only_labs && !((o->only_labs >> c->lab) & 1u)) continue;
        if (o->pattern_count && !_sl_matches_any(c->name, o->patterns, o->pattern_count)) continue;
        if (_sl_matches_any(c->name, o->excludes, o->exclude_count)) continue;
        count++;
    }
    _sl_order_cases(cases, count);
    return count;
}

bool _sl_probe_renderer(const sl_run_options *run, volatile int *stop, char *out, size_t out_size) {
    if (!_sl_is_executable(sl_config_solutions_runner) || !sl_config_solutions_dir[0]) return false;
    static sl_case probe; /* no frame, no check: the runner makes its context, says HELLO and DONE */
    memset(&probe, 0, sizeof probe);
    snprintf(probe.name, sizeof probe.name, "renderer_probe");
    snprintf(probe.title, sizeof probe.title, "the renderer the runners get");
    probe.lab = 1;
    probe.width = probe.height = 16;
    probe.timeout_seconds = 60;
    probe.memory_mb = 4096;
    sl_run_options solutions = *run;
    memset(solutions.setups, 0, sizeof solutions.setups);
    solutions.setups[0].runner = sl_config_solutions_runner;
    solutions.setups[0].labs_tree = sl_config_solutions_dir;
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++)
        if (sl_lab_folder(lab)) solutions.setups[0].lab_dirs[lab] = sl_config_solutions_dir;
    solutions.case_ended = NULL;
    solutions.jobs = 1;
    static sl_case_result r;
    bool ok = sl_run_cases(&probe, 1, &solutions, &r, stop) && r.finished && r.renderer[0];
    if (ok) snprintf(out, out_size, "%s", r.renderer);
    sl_case_result_free(&r);
    return ok;
}

bool _sl_same_renderer(const char *a, const char *b) {
    size_t n = strcspn(a, " ");
    if (n == 0 || n != strcspn(b, " ") || strncmp(a, b, n) != 0) return false;
    const char *wa = strstr(a, " bits"), *wb = strstr(b, " bits");
    if (!wa || !wb) return !wa && !wb;
    while (wa > a && wa[-1] >= '0' && wa[-1] <= '9') wa--;
    while (wb > b && wb[-1] >= '0' && wb[-1] <= '9') wb--;
    return atoi(wa) == atoi(wb);
}

void _sl_list_cases(const sl_case *cases, int count, const sl_grade_report *rep, const char (*hidden_notes)[400]) {
    for (int i = 0; i < count; i++) {
        printf("lab %d  %-36s %s (", cases[i].lab, cases[i].name, cases[i].title);
        for (int k = 0; k < cases[i].check_count; k++)
            printf("%s%s %gp%s", k ? ", " : "", cases[i].checks[k].name, cases[i].checks[k].points,
                   cases[i].checks[k].bonus ? " bonus" : "");
        printf(")\n");
        if (hidden_notes) printf("       hidden: %s\n", hidden_notes[i]);
    }
    for (int i = 0; i < rep->problem_count; i++) printf("PROBLEM %s\n", rep->problems[i]);
}

int _sl_update_references(const _sl_options *o, sl_case *cases, int count, sl_case_result *results) {
    int status = SL_EXIT_FULL, written = 0;
    char err[1500];
    if (!sl_mkdirs(o->refs_dir)) {
        fprintf(stderr, "shadowlab-grade: cannot create %s\n", o->refs_dir);
        return SL_EXIT_ERROR;
    }
    sl_manifest *manifest = sl_manifest_load(o->refs_dir, true, err, sizeof err);
    if (!manifest) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        return SL_EXIT_ERROR;
    }
    for (int i = 0; i < count; i++) {
        if (results[i].renderer[0]) sl_manifest_set_renderer(manifest, results[i].renderer);
        if (results[i].finished) sl_manifest_forget_case(manifest, cases[i].name);
        for (int k = 0; k < cases[i].check_count; k++) {
            char file[200];
            if (!sl_check_reference_file(&cases[i].checks[k], file, sizeof file)) continue;
            if (!results[i].finished) {
                fprintf(stderr, "shadowlab-grade: %s did not finish: %s%s%s\n", cases[i].name,
                        results[i].staff_error[0] ? results[i].staff_error : results[i].error[0] ? results[i].error
                        : results[i].protocol_error[0] ? results[i].protocol_error : "crashed or timed out in ",
                        results[i].staff_error[0] || results[i].error[0] || results[i].protocol_error[0] ? "" : results[i].crashed_in,
                        results[i].interrupted ? " (interrupted)" : "");
                status = SL_EXIT_ERROR;
                break;
            }
            if (sl_reference_write(o->refs_dir, manifest, &cases[i], &cases[i].checks[k], &results[i], err, sizeof err)) {
                written++;
            } else {
                fprintf(stderr, "shadowlab-grade: %s\n", err);
                status = SL_EXIT_ERROR;
            }
        }
    }
    if (!sl_manifest_save(manifest, o->refs_dir, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        status = SL_EXIT_ERROR;
    }
    sl_manifest_free(manifest);
    printf("shadowlab-grade: wrote %d reference files and %s under %s\n", written, SL_MANIFEST_FILE, o->refs_dir);
    return status;
}

bool _sl_write_reports(const _sl_options *o, const sl_grade_report *rep) {
    char err[1500];
    bool ok = true;
    if (o->report_dir && !sl_report_write_dir(rep, o->report_dir, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        ok = false;
    }
    if (o->junit && !sl_report_write_junit(rep, o->junit, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        ok = false;
    }
    if (o->gradescope && !sl_report_write_gradescope(rep, o->gradescope, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        ok = false;
    }
    if (o->prairielearn && !sl_report_write_prairielearn(rep, o->prairielearn, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        ok = false;
    }
    return ok;
}

void _sl_grade_stub(const sl_check *k, int lab, sl_check_result *out) {
    memset(out, 0, sizeof *out);
    out->max_points = k->points;
    out->bonus = k->bonus;
    out->stub = true;
    out->settled = true;
    snprintf(out->message, sizeof out->message,
             "not implemented: lab %d's files are the handout's stubs, unchanged (so it was neither built nor run)",
             lab);
    snprintf(out->summary, sizeof out->summary, "lab %d: the handout's stubs, not implemented", lab);
    /* one diagnosis per lab for every student who left it as handed out */
    snprintf(out->diagnosis, sizeof out->diagnosis, "not-implemented-lab%d-stubs", lab);
    snprintf(out->diagnosis_text, sizeof out->diagnosis_text, "lab %d: the handout's stubs, not implemented", lab);
}

int _sl_grade_not_built(const _sl_options *o, const sl_case *cases, int count, sl_grade_report *rep) {
    static char first_error[SL_BUILD_ERROR_MAX + 8];
    char err[1500];
    if (!o->not_built) { /* per-lab builds, none of which built: the first lab's error stands for the whole */
        for (int lab = 1; lab <= SL_LAB_MAX && !first_error[0]; lab++)
            if (rep->lab_not_built[lab]) snprintf(first_error, sizeof first_error, "%s", rep->lab_not_built[lab]);
    } else if (!sl_build_failure_first_error(o->not_built, o->labs_dir, first_error, sizeof first_error, err,
                                             sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        return SL_EXIT_ERROR;
    }
    static const sl_case_result nothing_ran;
    static const sl_reference no_references[SL_CASE_MAX_CHECKS];
    static sl_graded_case graded[_SL_MAX_CASES];
    rep->cases = graded;
    rep->case_count = rep->cases_finished = count;
    /* every lab the stubs as handed out: nothing failed to build */
    bool built = !o->not_built && !first_error[0];
    rep->not_built = built ? NULL : first_error;
    snprintf(rep->sandbox, sizeof rep->sandbox, "none (no lab code ran)");
    for (int i = 0; i < count; i++) {
        graded[i].c = &cases[i];
        graded[i].result = &nothing_ran;
        graded[i].references = no_references;
        const char *lab_error = rep->lab_not_built[cases[i].lab];
        for (int k = 0; k < cases[i].check_count; k++) {
            if (_sl_stub_lab(o, cases[i].lab))
                _sl_grade_stub(&cases[i].checks[k], cases[i].lab, &graded[i].checks[k]);
            else if (lab_error)
                sl_build_failure_grade_lab(&cases[i].checks[k], cases[i].lab, lab_error, &graded[i].checks[k]);
            else sl_build_failure_grade(&cases[i].checks[k], first_error, &graded[i].checks[k]);
        }
    }
    printf("shadowlab-grade: %s labs (%s), %d cases\n", rep->labs_kind, rep->labs_dir, count);
    if (built) {
        printf("shadowlab-grade: every lab graded is the handout's stubs: not built, not run\n");
    } else {
        fputs("shadowlab-grade: the submission did not build: ", stdout);
        sl_utf8_write(stdout, first_error, strlen(first_error), 0); /* the compiler's words, on this one line */
        fputc('\n', stdout);
    }
    fflush(stdout);
    bool reports_ok = _sl_write_reports(o, rep);
    sl_report_print(rep, stdout, isatty(1));
    return reports_ok && !rep->problem_count ? (rep->no_lab_file ? SL_EXIT_NO_LAB_FILE : SL_EXIT_FAILED) : SL_EXIT_ERROR;
}

sl_reference_cache *_sl_reference_cache_open(const _sl_options *o, const sl_sandbox *sandbox, char *state,
                                             size_t n) {
    char dir[1100];
    if (o->no_reference_cache) snprintf(state, n, "off (--no-reference-cache)");
    else if (o->hidden) snprintf(state, n, "off (--hidden: this run's own references)");
    else if (sandbox->self_check || sandbox->level < SL_SANDBOX_UID)
        snprintf(state, n, "off (the %s sandbox: runners run as this user)", sl_sandbox_level_name(sandbox->level));
    else if (!sl_reference_cache_default_dir(dir, sizeof dir)) snprintf(state, n, "off (no folder of the program)");
    else {
        char why[1300];
        sl_reference_cache *cache = sl_reference_cache_open(dir, why, sizeof why);
        if (!cache) snprintf(state, n, "off (%s)", why);
        return cache;
    }
    return NULL;
}

const char *_sl_image_module_mapped(void) {
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f) return "unknown";
    char line[1400];
    bool mapped = false;
    while (!mapped && fgets(line, sizeof line, f)) mapped = strstr(line, "OpenImageIO") || strstr(line, "shadowlab_image");
    fclose(f);
    return mapped ? "yes" : "no";
}
