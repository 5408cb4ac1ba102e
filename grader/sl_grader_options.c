#define _GNU_SOURCE
#include "sl_grader_options.h"

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

#include "sl_case.h"
#include "sl_run.h"

static void _sl_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab-grade [options]\n"
            "Grades a build's labs headless against the reference renders. The lab code runs in a\n"
            "separate process per case (shadowlab-runner), in a sandbox; this program runs none of it.\n"
            "  --lab LABS           grade these labs only: a number, a range or a list (--lab 2,\n"
            "                       --lab 1-3, --lab 1,3-4); give it several times for more\n"
            "  --case PATTERN       cases whose name matches PATTERN (shell glob, or a substring);\n"
            "                       give it several times for several patterns\n"
            "  --exclude PATTERN    leave out the cases whose name matches PATTERN (several times too)\n"
            "  -j N, --jobs N       cases run at once (default: the number of CPUs)\n"
            "  --report DIR         write DIR/report.html, DIR/results.json, and student, reference and\n"
            "                       diff images of failed image checks\n"
            "  --junit FILE         write JUnit XML (one suite per lab, one test per check)\n"
            "  --gradescope FILE    write Gradescope's results.json\n"
            "  --prairielearn FILE  write PrairieLearn's results.json\n"
            "  --bonus POLICY       how extension checks' bonus points count, the same in every report and\n"
            "                       the gradebook: apart (default: the score counts the regular checks only,\n"
            "                       the bonus is shown as its own number and never fills a lost point),\n"
            "                       fill (it fills lost points, up to the maximum) or add (it is added,\n"
            "                       past the maximum too: extra credit)\n"
            "  --timeout SECONDS    time limit per case (default: each case's own, 20 s)\n"
            "  --memory MB          address space per case (default: each case's own, 4096 MB)\n"
            "  --cases DIR          case files (default: this source tree's grader/cases)\n"
            "  --references DIR     reference files (default: grader/references)\n"
            "  --labs-dir DIR       the labs tree whose shaders are graded (default: this build's)\n"
            "  --runners DIR        the folder with shadowlab-runner built from those labs' C files\n"
            "                       (default: this build's)\n"
            "  --technique-dir DIR  the folder of the technique those runners' build adds (lab 0 cases,\n"
            "                       docs/adding-a-technique.md): the sandbox shows its shaders/ to the runner\n"
            "                       as technique/shaders in its labs tree. With --update-references and\n"
            "                       --runners, lab 0's references are rendered by those runners (the\n"
            "                       technique's correct build)\n"
            "  --backend NAME       GL: osmesa or egl (default: OSMesa where this build has it, else\n"
            "                       EGL; both render with llvmpipe, as the references were), or window:\n"
            "                       a hidden window on this machine's GL (macOS, Windows, a build\n"
            "                       with no headless GL, where it is the default): a self-check only\n"
            "  --sandbox LEVEL      the strongest sandbox to try: namespaces, uid or basic\n"
            "                       (default namespaces; the report says which one was used)\n"
            "  --progress           a line on stderr as each case ends ([k/N] case, seconds); on a\n"
            "                       terminal, one line that updates\n"
            "  --strict             refuse to grade unless the runners get the namespaces sandbox and\n"
            "                       their lab code was compiled behind a fence (for grading servers: a\n"
            "                       weaker sandbox lets lab code read the files the grader's user can\n"
            "                       read, an unfenced compiler the files the builder could)\n"
            "  --isolate            grade each lab on its own runner: the solutions stand in for the labs\n"
            "                       it builds on, the handout's stubs for the others, so one lab's mistake\n"
            "                       costs that lab only (needs a copy with solutions/)\n"
            "  --build-logs DIR     with --isolate: a lab whose runner is missing did not build; its checks\n"
            "                       fail with the compiler's first error in DIR/labN.log\n"
            "                       (scripts/grade-submission)\n"
            "  --hidden --seed S    grade on hidden variants of the cases, drawn from the seed S (light,\n"
            "                       camera, objects, map size), with references rendered from the\n"
            "                       solutions for this run (needs a copy with solutions/)\n"
            "  --probe-seed S       draw the function probes' generic rows from S (default: the --seed of\n"
            "                       --hidden, else a fixed one); their expected outputs are the contracts'\n"
            "  --list               list the cases and exit (with --hidden: what each variant changes)\n"
            "  --not-built LOG      the labs did not compile: report every check as failed with the\n"
            "                       compiler's first error in the build log LOG (scripts/grade-submission)\n"
            "  --stub-labs LABS     these labs are the handout's stubs, unchanged (2, 1-3, 1,3-4): their checks\n"
            "                       fail as not implemented, scoring what the stubs score, and they are\n"
            "                       neither built nor run (scripts/grade-submission)\n"
            "  --submission-summary FILE  what staging the submission found (shadowlab-stage --summary): its\n"
            "                       notes lead every report (no lab file found, refused links, normalised\n"
            "                       line ends, bytes that are not text), and a submission without a lab file\n"
            "                       exits 3 (scripts/grade-submission)\n"
            "  --gradebook DIR      write DIR/gradebook.csv from the reports of a batch (scripts/grade-batch)\n"
            "                       and the class report: DIR/class-report.html and .csv, DIR/class-mistakes.csv\n"
            "  --roster FILE        with --gradebook: the LMS's roster as it exports it (Canvas: Grades >\n"
            "                       Export CSV; Moodle: the grading worksheet): each row's name from it,\n"
            "                       matched by the download's LMS id, a 'no submission' row for each\n"
            "                       student without one, submissions not on it named\n"
            "  --due \"YYYY-MM-DD HH:MM\"  with a Moodle worksheet: late is Last modified (submission)\n"
            "                       after it, both in the worksheet's time zone\n"
            "  --export canvas|moodle FILE  with --roster: the grades (each row's total, under its --bonus) in\n"
            "                       the roster's format, ready to import; read back and checked\n"
            "  --assignment \"NAME (ID)\"  the Canvas column --export fills (default: the only one)\n"
            "  --missing-as-zero    --export gives a student without a submission 0, not an empty grade\n"
            "  --update-references  render the references, and their MANIFEST.json, from the solutions\n"
            "  --no-reference-cache decode every reference image from its file: no use of the build's\n"
            "                       cache of decoded references (cache/references beside bin/)\n"
            "  --no-experiments     with --isolate in a staff build: do not run a failed check again with\n"
            "                       one function replaced by the solution's; messages rank by the probes\n"
            "  --experiment-budget SECONDS  the wall time all experiments of a grade may take (default\n"
            "                       120, and 120 runs); past it, the probes' ranking stands (the log says so)\n"
            "  --experiment-builder PROGRAM  experiments on the lab's C functions too: PROGRAM LAB F1[,F2]\n"
            "                       links a runner with those of the solution's and prints its path\n"
            "                       (scripts/grade-submission gives scripts/build-experiment-runner)\n"
            "Exit status: 0 full marks, 1 some checks failed, 2 grading could not run properly\n"
            "(a staff-side problem: missing or changed references, bad case files, unwritable reports),\n"
            "3 graded, but the --submission-summary says the submission held no lab file.\n");
}

/* --lab's value: lab numbers, ranges and lists ("2", "1-3", "1,3-4") into a
 * mask of 1 << N; false with the reason on anything else. */
static bool _sl_parse_labs(const char *text, uint32_t *mask, char *err, size_t n) {
    const char *p = text;
    uint32_t found = 0;
    for (;;) {
        char *end;
        while (*p == ' ') p++;
        long first = strtol(p, &end, 10), last = first;
        bool number = end != p && *p >= '0' && *p <= '9';
        p = end;
        while (*p == ' ') p++;
        if (number && *p == '-') {
            p++;
            while (*p == ' ') p++;
            number = *p >= '0' && *p <= '9';
            last = strtol(p, &end, 10);
            p = end;
            while (*p == ' ') p++;
        }
        if (!number || (*p && *p != ',')) {
            snprintf(err, n, "--lab '%s': give lab numbers, ranges or lists (--lab 2, --lab 1-3, --lab 1,3-4)", text);
            return false;
        }
        if (first < 1 || last > SL_LAB_MAX || first > last) {
            snprintf(err, n, "--lab '%s': labs are numbered 1 to %d, a range goes up (1-3)", text, SL_LAB_MAX);
            return false;
        }
        for (long lab = first; lab <= last; lab++) found |= 1u << lab;
        if (!*p) break;
        p++; /* the comma */
    }
    *mask |= found;
    return true;
}

/* The gradebook's LMS options (--roster, --due, --export FORMAT FILE, --assignment,
 * --missing-as-zero): 1 when argv[*i] was one (and *i is past its values), 0 when
 * not, -1 on an error, said. */
static int _sl_parse_lms(int argc, char **argv, int *i, _sl_options *o) {
    const char *a = argv[*i];
    int values = strcmp(a, "--export") == 0 ? 2
                 : strcmp(a, "--roster") == 0 || strcmp(a, "--due") == 0 || strcmp(a, "--assignment") == 0 ? 1
                 : strcmp(a, "--missing-as-zero") == 0 ? 0
                                                        : -1;
    if (values < 0) return 0;
    if (*i + values >= argc) {
        fprintf(stderr, "shadowlab-grade: %s needs %s\n", a, values == 2 ? "a format and a file" : "a value");
        return -1;
    }
    const char *v = argv[*i + 1];
    if (strcmp(a, "--roster") == 0) o->roster = v;
    else if (strcmp(a, "--due") == 0) o->due = v;
    else if (strcmp(a, "--assignment") == 0) o->assignment = v;
    else if (strcmp(a, "--missing-as-zero") == 0) o->missing_as_zero = true;
    else {
        if (strcmp(v, "canvas") != 0 && strcmp(v, "moodle") != 0) {
            fprintf(stderr, "shadowlab-grade: --export canvas FILE or --export moodle FILE, not '%s'\n", v);
            return -1;
        }
        o->export_format = v;
        o->export_path = argv[*i + 2];
    }
    *i += values;
    return 1;
}

int _sl_parse(int argc, char **argv, _sl_options *o) {
    for (int i = 1; i < argc; i++) {
        int lms = _sl_parse_lms(argc, argv, &i, o);
        if (lms < 0) return SL_EXIT_ERROR;
        if (lms) continue;
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        static const char *const with_value[] = {"--lab", "--case", "--exclude", "-j", "--jobs", "--report",
                                                 "--gradescope", "--prairielearn", "--junit", "--timeout",
                                                 "--cases", "--references", "--labs-dir", "--runners", "--backend",
                                                 "--sandbox", "--memory", "--seed", "--probe-seed", "--not-built", "--gradebook",
                                                 "--build-logs", "--submission-summary", "--technique-dir",
                                                 "--stub-labs", "--bonus", "--experiment-budget",
                                                 "--experiment-builder"};
        bool value = false;
        for (size_t k = 0; k < sizeof with_value / sizeof with_value[0]; k++) value |= strcmp(a, with_value[k]) == 0;
        if (value && !v) {
            fprintf(stderr, "shadowlab-grade: %s needs a value\n", a);
            return SL_EXIT_ERROR;
        }
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            _sl_usage(stdout);
            return -1;
        } else if (strcmp(a, "--lab") == 0) {
            char lab_err[200];
            if (!_sl_parse_labs(v, &o->only_labs, lab_err, sizeof lab_err)) {
                fprintf(stderr, "shadowlab-grade: %s\n", lab_err);
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--stub-labs") == 0) {
            char lab_err[200];
            if (!_sl_parse_labs(v, &o->stub_labs, lab_err, sizeof lab_err)) {
                fprintf(stderr, "shadowlab-grade: --stub-labs: %s\n", lab_err);
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--case") == 0 || strcmp(a, "--exclude") == 0) {
            bool exclude = a[2] == 'e';
            int *count = exclude ? &o->exclude_count : &o->pattern_count;
            if (*count >= _SL_MAX_PATTERNS) {
                fprintf(stderr, "shadowlab-grade: at most %d %s patterns\n", _SL_MAX_PATTERNS, a);
                return SL_EXIT_ERROR;
            }
            (exclude ? o->excludes : o->patterns)[(*count)++] = v;
        } else if (strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0) o->jobs = atoi(v);
        else if (strncmp(a, "-j", 2) == 0 && a[2] >= '0' && a[2] <= '9') o->jobs = atoi(a + 2); /* make's -j4 */
        else if (strcmp(a, "--report") == 0) o->report_dir = v;
        else if (strcmp(a, "--gradescope") == 0) o->gradescope = v;
        else if (strcmp(a, "--prairielearn") == 0) o->prairielearn = v;
        else if (strcmp(a, "--junit") == 0) o->junit = v;
        else if (strcmp(a, "--timeout") == 0) o->timeout = atof(v);
        else if (strcmp(a, "--memory") == 0) {
            o->memory_mb = atof(v);
            if (o->memory_mb < 64) {
                fprintf(stderr, "shadowlab-grade: --memory takes megabytes, at least 64\n");
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--cases") == 0) o->cases_dir = v;
        else if (strcmp(a, "--references") == 0) o->refs_dir = v;
        else if (strcmp(a, "--labs-dir") == 0) o->labs_dir = v;
        else if (strcmp(a, "--runners") == 0) o->runners_dir = v;
        else if (strcmp(a, "--technique-dir") == 0) o->technique_dir = v;
        else if (strcmp(a, "--backend") == 0) {
            if (!sl_backend_parse(v, &o->backend) || !sl_backend_available(o->backend)) {
                fprintf(stderr, "shadowlab-grade: --backend: '%s' is not a backend of this build (it has %s)\n", v,
                        sl_backend_choices());
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--sandbox") == 0) {
            if (!sl_sandbox_level_parse(v, &o->sandbox_level)) {
                fprintf(stderr, "shadowlab-grade: --sandbox is namespaces, uid or basic\n");
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--bonus") == 0) {
            if (!sl_bonus_policy_parse(v, &o->bonus_policy)) {
                fprintf(stderr, "shadowlab-grade: --bonus is apart, fill or add (shadowlab-grade --help)\n");
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--strict") == 0) o->strict = true;
        else if (strcmp(a, "--progress") == 0) o->progress = true;
        else if (strcmp(a, "--update-references") == 0) o->update = true;
        else if (strcmp(a, "--no-reference-cache") == 0) o->no_reference_cache = true;
        else if (strcmp(a, "--no-experiments") == 0) o->no_experiments = true;
        else if (strcmp(a, "--experiment-builder") == 0) o->experiment_builder = v;
        else if (strcmp(a, "--experiment-budget") == 0) {
            o->experiment_budget = atof(v);
            if (!(o->experiment_budget > 0)) {
                fprintf(stderr, "shadowlab-grade: --experiment-budget takes seconds, more than 0\n");
                return SL_EXIT_ERROR;
            }
        }
        else if (strcmp(a, "--isolate") == 0) o->isolate = true;
        else if (strcmp(a, "--hidden") == 0) o->hidden = true;
        else if (strcmp(a, "--seed") == 0) o->seed = v;
        else if (strcmp(a, "--probe-seed") == 0) o->probe_seed = v;
        else if (strcmp(a, "--not-built") == 0) o->not_built = v;
        else if (strcmp(a, "--gradebook") == 0) o->gradebook = v;
        else if (strcmp(a, "--build-logs") == 0) o->build_logs = v;
        else if (strcmp(a, "--submission-summary") == 0) o->submission_summary = v;
        else if (strcmp(a, "--list") == 0) o->list = true;
        else {
            fprintf(stderr, "shadowlab-grade: unknown option %s\n", a);
            _sl_usage(stderr);
            return SL_EXIT_ERROR;
        }
        if (value) i++;
    }
    if (o->jobs < 1) o->jobs = 1;
    if (o->timeout < 0) o->timeout = 0;
    return 0;
}

void _sl_describe_options(const _sl_options *o, const char *default_cases, const char *default_refs, char *out,
                          size_t n) {
    size_t used = 0;
    out[0] = '\0';
#define _SL_ADD(...)                                                                          \
    do {                                                                                      \
        int added = snprintf(out + used, n - used, "%s", used ? " " : "");                   \
        if (added > 0 && (size_t)added < n - used) used += (size_t)added;                     \
        added = snprintf(out + used, n - used, __VA_ARGS__);                                  \
        if (added > 0) used = (size_t)added < n - used ? used + (size_t)added : n - 1;        \
    } while (0)
    if (o->only_labs) {
        char labs[64] = "";
        size_t l = 0;
        for (int lab = 1; lab <= SL_LAB_MAX; lab++) {
            if (!((o->only_labs >> lab) & 1u)) continue;
            int last = lab;
            while (last < SL_LAB_MAX && ((o->only_labs >> (last + 1)) & 1u)) last++;
            int added = last > lab ? snprintf(labs + l, sizeof labs - l, "%s%d-%d", l ? "," : "", lab, last)
                                   : snprintf(labs + l, sizeof labs - l, "%s%d", l ? "," : "", lab);
            if (added > 0 && (size_t)added < sizeof labs - l) l += (size_t)added;
            lab = last;
        }
        _SL_ADD("--lab %s", labs);
    }
    for (int i = 0; i < o->pattern_count; i++) _SL_ADD("--case %s", o->patterns[i]);
    for (int i = 0; i < o->exclude_count; i++) _SL_ADD("--exclude %s", o->excludes[i]);
    if (o->isolate) _SL_ADD("--isolate");
    if (o->hidden) _SL_ADD("--hidden --seed %s", o->seed ? o->seed : "?");
    if (o->probe_seed) _SL_ADD("--probe-seed %s", o->probe_seed);
    if (o->bonus_policy != SL_BONUS_APART) _SL_ADD("--bonus %s", sl_bonus_policy_name(o->bonus_policy));
    if (o->timeout > 0) _SL_ADD("--timeout %g", o->timeout);
    if (o->memory_mb > 0) _SL_ADD("--memory %g", o->memory_mb);
    if (o->cases_dir && strcmp(o->cases_dir, default_cases) != 0) _SL_ADD("--cases %s", o->cases_dir);
    if (o->refs_dir && strcmp(o->refs_dir, default_refs) != 0) _SL_ADD("--references %s", o->refs_dir);
#undef _SL_ADD
}
