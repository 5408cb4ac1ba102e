/* sl_experiment: blame by experiment (see the header). */
#define _GNU_SOURCE
#include "sl_experiment.h"

#include <dirent.h>
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "sl_diagnose.h"
#include "sl_glsl_functions.h"
#include "sl_grade.h"
#include "sl_params.h"

#define _SL_PAIR_CANDIDATES 6 /* pairs among at most this many functions: 15 pairs */

typedef struct _sl_candidate {
    bool c_function;   /* a function of the lab's C file: a runner of its own (the builder links it) */
    char file[128];    /* under the lab's shaders/: "pcf.glsl" */
    char name[SL_GLSL_NAME_MAX];
    int occurrence;    /* of its name in the file (overloads) */
    char said[80];     /* "pcf_grid()", "cube_depth.geom" */
    bool bonus;
} _sl_candidate;

static double _sl_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}


static bool _sl_write(const char *path, const char *text) {
    unlink(path);
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) return false;
    size_t size = strlen(text), done = 0;
    while (done < size) {
        ssize_t n = write(fd, text + done, size - done);
        if (n <= 0) break;
        done += (size_t)n;
    }
    fchmod(fd, 0644);
    close(fd);
    return done == size;
}

/* A copy of a labs tree, readable to all (the runners of the lower sandboxes read it as another user). */
static bool _sl_copy_tree(const char *from, const char *to, int depth) {
    if (depth > 5 || mkdir(to, 0755) != 0) return false;
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
            ok = _sl_copy_tree(src, dst, depth + 1);
        } else if (S_ISREG(st.st_mode)) {
            size_t size = 0;
            char *text = sl_glsl_read_source(src, &size);
            ok = text && strlen(text) == size && _sl_write(dst, text);
            free(text);
        }
    }
    closedir(dir);
    return ok;
}

static bool _sl_function_is_bonus(const char *said) {
    char name[80];
    snprintf(name, sizeof name, "%s", said);
    char *paren = strstr(name, "()");
    if (paren) *paren = '\0';
    for (int i = 0; i < sl_lab_function_count(); i++) {
        sl_lab_function fn = sl_lab_function_at(i);
        if (strcmp(fn.name, name) == 0) return fn.bonus;
    }
    return false;
}

static bool _sl_same_text(const char *a_text, const sl_glsl_function *a, const char *b_text, const sl_glsl_function *b) {
    size_t n = a->end - a->start;
    return n == b->end - b->start && memcmp(a_text + a->start, b_text + b->start, n) == 0;
}

/* The lab's functions whose text differs from the solution's: only those can change a picture
 * when replaced (the shaders' own, by name and order in each file). */
static int _sl_candidates(const char *graded_tree, const char *solutions_tree, const char *stubs_tree, int lab,
                          _sl_candidate *out, int max) {
    const char *folder = sl_lab_folder(lab);
    char dir_path[1400];
    snprintf(dir_path, sizeof dir_path, "%s/%s/shaders", solutions_tree, folder);
    DIR *dir = opendir(dir_path);
    if (!dir) return 0;
    char names[32][128];
    int files = 0;
    struct dirent *e;
    while ((e = readdir(dir)) && files < 32)
        if (e->d_name[0] != '.' && strlen(e->d_name) < sizeof names[0]) snprintf(names[files++], sizeof names[0], "%s", e->d_name);
    closedir(dir);
    qsort(names, (size_t)files, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    int count = 0;
    static sl_glsl_function theirs[128], ours[128], stubs[128];
    for (int f = 0; f < files; f++) {
        char path[1600];
        size_t solution_size = 0, student_size = 0, stub_size = 0;
        snprintf(path, sizeof path, "%s/%s/shaders/%s", solutions_tree, folder, names[f]);
        char *solution = sl_glsl_read_source(path, &solution_size);
        snprintf(path, sizeof path, "%s/%s/shaders/%s", graded_tree, folder, names[f]);
        char *student = sl_glsl_read_source(path, &student_size);
        snprintf(path, sizeof path, "%s/%s/shaders/%s", stubs_tree, folder, names[f]);
        char *stub = stubs_tree ? sl_glsl_read_source(path, &stub_size) : NULL;
        int n = solution ? sl_glsl_functions(solution, solution_size, theirs, 128) : -1;
        int m = student ? sl_glsl_functions(student, student_size, ours, 128) : -1;
        int o = stub ? sl_glsl_functions(stub, stub_size, stubs, 128) : -1;
        for (int i = 0; i < n && m >= 0 && count < max; i++) {
            int occurrence = 0;
            for (int j = 0; j < i; j++) occurrence += strcmp(theirs[j].name, theirs[i].name) == 0;
            const sl_glsl_function *mine = sl_glsl_find(ours, m, theirs[i].name, occurrence);
            if (!mine || _sl_same_text(solution, &theirs[i], student, mine)) continue;
            /* a stub left as the handout has it says "not implemented" by itself: nothing to find out */
            const sl_glsl_function *handout = o >= 0 ? sl_glsl_find(stubs, o, theirs[i].name, occurrence) : NULL;
            if (handout && _sl_same_text(stub, handout, student, mine)) continue;
            _sl_candidate *c = &out[count++];
            snprintf(c->file, sizeof c->file, "%s", names[f]);
            snprintf(c->name, sizeof c->name, "%s", theirs[i].name);
            c->occurrence = occurrence;
            if (strcmp(c->name, "main") == 0) snprintf(c->said, sizeof c->said, "%s", names[f]);
            else snprintf(c->said, sizeof c->said, "%s()", c->name);
            c->bonus = _sl_function_is_bonus(c->said);
        }
        free(solution);
        free(student);
        free(stub);
    }
    return count;
}

static bool _sl_starts_with_word(const char *text, const sl_glsl_function *f, const char *word) {
    size_t n = strlen(word);
    return f->end - f->start > n && strncmp(text + f->start, word, n) == 0 && !isalnum((unsigned char)text[f->start + n]);
}

/* The lab's C functions with external linkage whose text differs from the solution's and from
 * the stub's: each can be swapped in the linked runner (a static one cannot). */
static int _sl_c_candidates(const char *graded_tree, const char *solutions_tree, const char *stubs_tree, int lab,
                            _sl_candidate *out, int max) {
    const char *folder = sl_lab_folder(lab);
    char path[1600], file[32];
    snprintf(file, sizeof file, "lab%d.c", lab);
    size_t solution_size = 0, student_size = 0, stub_size = 0;
    snprintf(path, sizeof path, "%s/%s/%s", solutions_tree, folder, file);
    char *solution = sl_glsl_read_source(path, &solution_size);
    snprintf(path, sizeof path, "%s/%s/%s", graded_tree, folder, file);
    char *student = sl_glsl_read_source(path, &student_size);
    snprintf(path, sizeof path, "%s/%s/%s", stubs_tree, folder, file);
    char *stub = stubs_tree ? sl_glsl_read_source(path, &stub_size) : NULL;
    static sl_glsl_function theirs[128], ours[128], stubs[128];
    int n = solution ? sl_glsl_functions(solution, solution_size, theirs, 128) : -1;
    int m = student ? sl_glsl_functions(student, student_size, ours, 128) : -1;
    int o = stub ? sl_glsl_functions(stub, stub_size, stubs, 128) : -1;
    int count = 0;
    for (int i = 0; i < n && m >= 0 && count < max; i++) {
        const sl_glsl_function *mine = sl_glsl_find(ours, m, theirs[i].name, 0);
        if (!mine || sl_glsl_find(theirs, n, theirs[i].name, 1) || _sl_same_text(solution, &theirs[i], student, mine))
            continue;
        if (_sl_starts_with_word(solution, &theirs[i], "static") || _sl_starts_with_word(student, mine, "static")) continue;
        const sl_glsl_function *handout = o >= 0 ? sl_glsl_find(stubs, o, theirs[i].name, 0) : NULL;
        if (handout && _sl_same_text(stub, handout, student, mine)) continue;
        _sl_candidate *c = &out[count++];
        *c = (_sl_candidate){.c_function = true};
        snprintf(c->file, sizeof c->file, "%s", file);
        snprintf(c->name, sizeof c->name, "%s", theirs[i].name);
        snprintf(c->said, sizeof c->said, "%s()", c->name);
        c->bonus = _sl_function_is_bonus(c->said);
    }
    free(solution);
    free(student);
    free(stub);
    return count;
}

/* A runner with the set's C functions the solution's: the builder links it (the student's lab
 * object with those symbols weak, the solution's with only them global) and prints its path. */
static bool _sl_build_runner(const char *builder, int lab, const _sl_candidate *const *set, int n, char *out,
                             size_t out_size) {
    char lab_text[16], functions[200] = "";
    snprintf(lab_text, sizeof lab_text, "%d", lab);
    for (int i = 0; i < n; i++)
        if (set[i]->c_function)
            snprintf(functions + strlen(functions), sizeof functions - strlen(functions), "%s%s",
                     functions[0] ? "," : "", set[i]->name);
    int pipe_fds[2];
    if (pipe2(pipe_fds, O_CLOEXEC) != 0) return false;
    pid_t pid = fork();
    if (pid < 0) {
        close(pipe_fds[0]), close(pipe_fds[1]);
        return false;
    }
    if (pid == 0) {
        dup2(pipe_fds[1], 1);
        int null_fd = open("/dev/null", O_WRONLY);
        if (null_fd >= 0) dup2(null_fd, 2);
        char *const argv[] = {(char *)builder, lab_text, functions, NULL};
        execv(builder, argv);
        _exit(127);
    }
    close(pipe_fds[1]);
    char text[2048];
    size_t used = 0;
    ssize_t got;
    while ((got = read(pipe_fds[0], text + used, sizeof text - 1 - used)) > 0) used += (size_t)got;
    close(pipe_fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    text[used] = '\0';
    while (used > 0 && text[used - 1] == '\n') text[--used] = '\0';
    const char *last = strrchr(text, '\n');
    last = last ? last + 1 : text;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || last[0] != '/' || access(last, X_OK) != 0) return false;
    snprintf(out, out_size, "%s", last);
    return true;
}

/* Puts the solution's definition of `c` into the tree's copy of the student's file. */
static bool _sl_splice_into(const char *tree, const char *solutions_tree, int lab, const _sl_candidate *c) {
    const char *folder = sl_lab_folder(lab);
    char path[1600], target[1600];
    size_t solution_size = 0, student_size = 0;
    snprintf(path, sizeof path, "%s/%s/shaders/%s", solutions_tree, folder, c->file);
    snprintf(target, sizeof target, "%s/%s/shaders/%s", tree, folder, c->file);
    char *solution = sl_glsl_read_source(path, &solution_size), *student = sl_glsl_read_source(target, &student_size);
    static sl_glsl_function theirs[128], ours[128];
    int n = solution ? sl_glsl_functions(solution, solution_size, theirs, 128) : -1;
    int m = student ? sl_glsl_functions(student, student_size, ours, 128) : -1;
    const sl_glsl_function *from = n >= 0 ? sl_glsl_find(theirs, n, c->name, c->occurrence) : NULL;
    const sl_glsl_function *into = m >= 0 ? sl_glsl_find(ours, m, c->name, c->occurrence) : NULL;
    char *spliced = from && into ? sl_glsl_splice(student, student_size, into, solution, from) : NULL;
    bool ok = spliced && _sl_write(target, spliced);
    free(spliced);
    free(solution);
    free(student);
    return ok;
}

typedef struct _sl_lab_run {
    const sl_experiment_grade *g;
    const sl_experiment_budget *budget;
    sl_experiment_verdict *verdicts;
    sl_experiment_cost *cost;
    volatile int *stop;
    double start;
    int lab;
    int tree_count;
    bool incomplete; /* an experiment could not be made: no claim rests on "none fixes it" */
    char trees[1100]; /* the experiments' copies of the labs tree: a folder others cannot list */
} _sl_lab_run;

static bool _sl_within_budget(_sl_lab_run *L, int runs) {
    if (L->stop && *L->stop) return false;
    if (L->cost->runs + runs > L->budget->max_runs || _sl_now() - L->start > L->budget->seconds) {
        L->cost->budget_spent = true;
        return false;
    }
    return true;
}

/* Whether a candidate set may answer for check k: a bonus function only for a bonus check. */
static bool _sl_accepts(const sl_check *k, const _sl_candidate *const *set, int n) {
    for (int i = 0; i < n; i++)
        if (set[i]->bonus && !k->bonus) return false;
    return true;
}

static bool _sl_open(const sl_experiment_verdict *v) { return v->outcome == SL_EXPERIMENT_UNFINISHED; }

/* One experiment: the lab's cases with an open check this set may answer for, run with the set
 * replaced; each such check that now passes is fixed by it. False when the budget stops it. */
static bool _sl_try(_sl_lab_run *L, const _sl_candidate *const *set, int n) {
    const sl_experiment_grade *g = L->g;
    int lab = L->lab;
    static int picked[512];
    int cases = 0;
    for (int i = 0; i < g->count && cases < 512; i++) {
        if (g->cases[i].lab != lab) continue;
        bool wanted = false;
        for (int k = 0; k < g->cases[i].check_count; k++)
            wanted |= _sl_open(&L->verdicts[i * SL_CASE_MAX_CHECKS + k]) && _sl_accepts(&g->cases[i].checks[k], set, n);
        if (wanted) picked[cases++] = i;
    }
    if (cases == 0) return true;
    if (!_sl_within_budget(L, cases)) return false;
    char tree[1200];
    snprintf(tree, sizeof tree, "%s/lab%d-%d", L->trees, lab, L->tree_count++);
    const sl_runner_setup *base = &g->run->setups[lab];
    bool made = _sl_copy_tree(base->labs_tree, tree, 0);
    bool any_c = false;
    for (int i = 0; made && i < n; i++) {
        any_c |= set[i]->c_function;
        if (!set[i]->c_function) made = _sl_splice_into(tree, g->solutions_tree, lab, set[i]);
    }
    char runner[1200];
    if (made && any_c) made = g->builder && _sl_build_runner(g->builder, lab, set, n, runner, sizeof runner);
    if (!made) { /* an experiment that could not be made answers nothing */
        L->incomplete = true;
        L->cost->unmade++;
        return true;
    }
    sl_run_options run = *g->run;
    if (any_c) run.setups[lab].runner = runner;
    run.case_ended = NULL; /* no progress line names an experiment */
    run.case_ended_context = NULL;
    run.setups[lab].labs_tree = tree;
    run.setups[lab].lab_dirs[lab] = tree;
    sl_case *subset = calloc((size_t)cases, sizeof *subset);
    sl_case_result *results = calloc((size_t)cases, sizeof *results);
    sl_check_result *check = calloc(1, sizeof *check);
    if (!subset || !results || !check) {
        free(subset), free(results), free(check);
        return false;
    }
    for (int j = 0; j < cases; j++) subset[j] = g->cases[picked[j]];
    bool complete = sl_run_cases(subset, cases, &run, results, L->stop);
    L->cost->runs += cases;
    /* The one bit each run may give: whether the open checks pass now, by the grader's own comparison.
     * Its captures, output, exit status and time are dropped here, unread by anything else. */
    for (int j = 0; j < cases; j++) {
        int i = picked[j];
        for (int k = 0; complete && k < subset[j].check_count; k++) {
            sl_experiment_verdict *v = &L->verdicts[i * SL_CASE_MAX_CHECKS + k];
            const sl_check *ck = &subset[j].checks[k];
            if (!_sl_open(v) || !_sl_accepts(ck, set, n)) continue;
            sl_grade_check(&subset[j], ck, &results[j], &g->refs[i * SL_CASE_MAX_CHECKS + k], NULL, check);
            bool fixed = check->passed && !check->reference_problem;
            sl_image_free(&check->diff);
            if (!fixed) continue;
            v->outcome = n == 1 ? SL_EXPERIMENT_SINGLE : SL_EXPERIMENT_PAIR;
            for (int s = 0; s < n && s < 2; s++) snprintf(v->functions[s], sizeof v->functions[s], "%s", set[s]->said);
        }
        sl_case_result_free(&results[j]);
    }
    free(subset), free(results), free(check);
    return complete;
}

bool sl_experiment_eligible(const sl_check *k, const sl_check_result *result, const sl_case_result *run) {
    if (result->passed || result->reference_problem || result->not_compiled[0]) return false;
    if (k->kind == SL_CHECK_PROBE || sl_check_is_state(k)) return false; /* a probe names its own function */
    if (result->cause_kind && strcmp(result->cause_kind, SL_CAUSE_STUB) == 0) return false; /* "not implemented" says it */
    return run && !run->interrupted && !run->staff_error[0];
}

void sl_experiments_run(const sl_experiment_grade *g, const sl_experiment_budget *budget,
                        sl_experiment_verdict *verdicts, sl_experiment_cost *cost, volatile int *stop) {
    memset(cost, 0, sizeof *cost);
    _sl_lab_run L = {.g = g, .budget = budget, .verdicts = verdicts, .cost = cost, .stop = stop, .start = _sl_now()};
    /* Runners below the namespaces sandbox see the file system: a copy that holds a solution function
     * is reached by its own runner's path alone, in a folder no one else can list. */
    snprintf(L.trees, sizeof L.trees, "%s/experiments-XXXXXX", g->work_dir);
    if (!mkdtemp(L.trees) || chmod(L.trees, 0711) != 0) L.trees[0] = '\0';
    for (int i = 0; i < g->count; i++)
        for (int k = 0; k < SL_CASE_MAX_CHECKS; k++) verdicts[i * SL_CASE_MAX_CHECKS + k] = (sl_experiment_verdict){0};
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        if (!sl_lab_folder(lab) || !g->run->setups[lab].runner || !g->run->setups[lab].labs_tree) continue;
        int open = 0;
        for (int i = 0; i < g->count; i++) {
            if (g->cases[i].lab != lab) continue;
            for (int k = 0; k < g->cases[i].check_count; k++)
                if (sl_experiment_eligible(&g->cases[i].checks[k], &g->graded[i].checks[k], g->graded[i].result)) {
                    verdicts[i * SL_CASE_MAX_CHECKS + k].outcome = SL_EXPERIMENT_UNFINISHED;
                    open++;
                }
        }
        if (open == 0) continue; /* a lab without failures runs no experiment */
        if (!L.trees[0]) { /* nowhere to make an experiment: the probes' ranking */
            cost->unmade++;
            continue;
        }
        cost->checks += open;
        static _sl_candidate candidates[SL_EXPERIMENT_MAX_FUNCTIONS];
        int n = _sl_candidates(g->graded_tree, g->solutions_tree, g->stubs_tree, lab, candidates,
                               SL_EXPERIMENT_MAX_FUNCTIONS);
        if (g->builder) /* the lab's C functions, where a runner can be linked with one of the solution's */
            n += _sl_c_candidates(g->graded_tree, g->solutions_tree, g->stubs_tree, lab, candidates + n,
                                  SL_EXPERIMENT_MAX_FUNCTIONS - n);
        cost->functions += n;
        L.lab = lab;
        L.incomplete = false;
        bool going = true;
        for (int a = 0; a < n && going; a++) {
            const _sl_candidate *set[1] = {&candidates[a]};
            going = _sl_try(&L, set, 1);
        }
        int tried_alone = going ? n : 0;
        for (int a = 0; going && a < n && n <= _SL_PAIR_CANDIDATES; a++)
            for (int b = a + 1; going && b < n; b++) {
                const _sl_candidate *set[2] = {&candidates[a], &candidates[b]};
                going = _sl_try(&L, set, 2);
            }
        /* every single and every pair tried without a fix: the cause is outside what was replaced.
         * Where no function differs, nothing was tried: the probes' ranking stands. */
        bool exhausted = going && !L.incomplete && n > 0 && n <= _SL_PAIR_CANDIDATES;
        for (int i = 0; i < g->count; i++)
            for (int k = 0; g->cases[i].lab == lab && k < g->cases[i].check_count; k++) {
                sl_experiment_verdict *v = &verdicts[i * SL_CASE_MAX_CHECKS + k];
                v->tried = tried_alone;
                v->with_c = g->builder != NULL;
                if (v->outcome == SL_EXPERIMENT_UNFINISHED && n == 0) v->outcome = SL_EXPERIMENT_NONE;
                if (v->outcome == SL_EXPERIMENT_UNFINISHED && exhausted) v->outcome = SL_EXPERIMENT_OUTSIDE;
            }
    }
    cost->seconds = _sl_now() - L.start;
}

void sl_experiment_lead(const sl_experiment_verdict *v, char *out, size_t n) {
    out[0] = '\0';
    switch (v->outcome) {
    case SL_EXPERIMENT_SINGLE:
        snprintf(out, n, "Replacing %s with a correct one fixes this check (an experiment: the case was run again with "
                         "the solution's %s in place of yours, everything else yours): look for the mistake in %s "
                         "first",
                 v->functions[0], v->functions[0], v->functions[0]);
        break;
    case SL_EXPERIMENT_PAIR:
        snprintf(out, n, "Replacing %s and %s together with correct ones fixes this check, and neither alone does (an "
                         "experiment: the case was run again with the solution's versions in place of yours): both "
                         "are wrong", v->functions[0], v->functions[1]);
        break;
    case SL_EXPERIMENT_OUTSIDE:
        if (v->with_c)
            snprintf(out, n, "Replacing this lab's functions that differ from the solution's (%d, C and GLSL) with "
                             "correct ones, one or two at a time, does not fix this check (an experiment): the cause "
                             "lies outside them: in what the lab's files share (their constants, uniforms, #defines, "
                             "static helpers) or in a call the compiler folded into its caller",
                     v->tried);
        else
            snprintf(out, n, "Replacing this lab's shader functions that differ from the solution's (%d) with correct "
                             "ones, one or two at a time, does not fix this check (an experiment): the cause lies "
                             "outside them: in the lab's C code or in what the shader files share (their uniforms, "
                             "constants, #defines)",
                     v->tried);
        break;
    default: break;
    }
}
