#define _XOPEN_SOURCE 700
#include "sl_grader.h"

#include <dirent.h>
#include <fnmatch.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sl_case.h"
#include "sl_grade.h"
#include "sl_renderer.h"
#include "sl_report.h"
#include "sl_run.h"

#ifndef SL_GRADER_DIR
#define SL_GRADER_DIR "grader"
#endif

enum { SL_EXIT_FULL = 0, SL_EXIT_FAILED = 1, SL_EXIT_ERROR = 2 };

static void _sl_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab-grade [options]\n"
            "Grades this build's labs headless (OSMesa) against the reference renders.\n"
            "  --lab N              grade lab N only\n"
            "  --case PATTERN       cases whose name matches PATTERN (shell glob, or a substring)\n"
            "  --exclude PATTERN    leave out the cases whose name matches PATTERN\n"
            "  -j N, --jobs N       cases run at once (default: the number of CPUs)\n"
            "  --report DIR         write DIR/report.html, DIR/results.json, and student, reference and\n"
            "                       diff images of failed image checks\n"
            "  --junit FILE         write JUnit XML (one suite per lab, one test per check)\n"
            "  --gradescope FILE    write Gradescope's results.json\n"
            "  --prairielearn FILE  write PrairieLearn's results.json\n"
            "  --timeout SECONDS    time limit per case (default: each case's own, 20 s)\n"
            "  --cases DIR          case files (default: this source tree's grader/cases)\n"
            "  --references DIR     reference files (default: grader/references)\n"
            "  --labs-dir DIR       lab sources whose shaders are loaded (default: this build's)\n"
            "  --isolate            grade each lab with the solutions standing in for the others, so one\n"
            "                       lab's mistake costs that lab only (needs a copy with solutions/)\n"
            "  --list               list the cases and exit\n"
            "  --update-references  render the references from this build (solutions builds only)\n"
            "Exit status: 0 full marks, 1 some checks failed, 2 grading could not run properly.\n");
}

static int _sl_compare_names(const void *a, const void *b) {
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static double _sl_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static bool _sl_matches(const char *name, const char *pattern) {
    return !pattern || fnmatch(pattern, name, 0) == 0 || strstr(name, pattern) != NULL;
}

/* For --isolate: ROOT/labN/ holds, for every lab, a link to its folder: lab N's
 * from the graded tree, the others' from the solutions. */
static bool _sl_make_isolation_dirs(sl_run_options *o, const char *graded, char *root, size_t root_size) {
    static char dirs[SL_LAB_COUNT + 1][96];
    snprintf(root, root_size, "/tmp/shadowlab-isolate-XXXXXX");
    if (!mkdtemp(root)) {
        fprintf(stderr, "shadowlab-grade: cannot create a folder under /tmp for --isolate\n");
        return false;
    }
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        snprintf(dirs[lab], sizeof dirs[lab], "%s/lab%d", root, lab);
        if (mkdir(dirs[lab], 0755) != 0) return false;
        for (int other = 1; other <= SL_LAB_COUNT; other++) {
            char target[2048], link_path[256];
            snprintf(target, sizeof target, "%s/%s", other == lab ? graded : sl_isolation_labs_dir, sl_lab_folder(other));
            snprintf(link_path, sizeof link_path, "%s/%s", dirs[lab], sl_lab_folder(other));
            if (symlink(target, link_path) != 0) {
                fprintf(stderr, "shadowlab-grade: cannot link %s for --isolate\n", target);
                return false;
            }
        }
        o->isolation_dirs[lab] = dirs[lab];
    }
    return true;
}

static void _sl_remove_isolation_dirs(const char *root) {
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        char path[256];
        for (int other = 1; other <= SL_LAB_COUNT; other++) {
            snprintf(path, sizeof path, "%s/lab%d/%s", root, lab, sl_lab_folder(other));
            unlink(path);
        }
        snprintf(path, sizeof path, "%s/lab%d", root, lab);
        rmdir(path);
    }
    rmdir(root);
}

int sl_grader_main(int argc, char **argv) {
    const char *cases_dir = SL_GRADER_DIR "/cases", *refs_dir = SL_GRADER_DIR "/references";
    const char *pattern = NULL, *exclude = NULL, *report_dir = NULL, *gradescope = NULL, *prairielearn = NULL;
    const char *junit = NULL;
    sl_run_options opts = {.jobs = (int)sysconf(_SC_NPROCESSORS_ONLN)};
    int only_lab = 0;
    bool update = false, list = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        bool value = strcmp(a, "--lab") == 0 || strcmp(a, "--case") == 0 || strcmp(a, "--exclude") == 0 || strcmp(a, "-j") == 0 ||
                     strcmp(a, "--jobs") == 0 || strcmp(a, "--report") == 0 || strcmp(a, "--gradescope") == 0 ||
                     strcmp(a, "--prairielearn") == 0 || strcmp(a, "--junit") == 0 || strcmp(a, "--timeout") == 0 ||
                     strcmp(a, "--cases") == 0 || strcmp(a, "--references") == 0 || strcmp(a, "--labs-dir") == 0;
        if (value && !v) {
            fprintf(stderr, "shadowlab-grade: %s needs a value\n", a);
            return SL_EXIT_ERROR;
        }
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            _sl_usage(stdout);
            return 0;
        } else if (strcmp(a, "--lab") == 0) {
            only_lab = atoi(v);
            if (only_lab < 1 || only_lab > 7) {
                fprintf(stderr, "shadowlab-grade: --lab takes 1..7\n");
                return SL_EXIT_ERROR;
            }
        } else if (strcmp(a, "--case") == 0) pattern = v;
        else if (strcmp(a, "--exclude") == 0) exclude = v;
        else if (strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0) opts.jobs = atoi(v);
        else if (strncmp(a, "-j", 2) == 0 && a[2] >= '0' && a[2] <= '9') opts.jobs = atoi(a + 2); /* make's -j4 */
        else if (strcmp(a, "--report") == 0) report_dir = v;
        else if (strcmp(a, "--gradescope") == 0) gradescope = v;
        else if (strcmp(a, "--prairielearn") == 0) prairielearn = v;
        else if (strcmp(a, "--junit") == 0) junit = v;
        else if (strcmp(a, "--timeout") == 0) opts.timeout = atof(v);
        else if (strcmp(a, "--cases") == 0) cases_dir = v;
        else if (strcmp(a, "--references") == 0) refs_dir = v;
        else if (strcmp(a, "--labs-dir") == 0) opts.labs_dir = v;
        else if (strcmp(a, "--update-references") == 0) update = true;
        else if (strcmp(a, "--isolate") == 0) opts.isolate = true;
        else if (strcmp(a, "--list") == 0) list = true;
        else {
            fprintf(stderr, "shadowlab-grade: unknown option %s\n", a);
            _sl_usage(stderr);
            return SL_EXIT_ERROR;
        }
        if (value) i++;
    }
    if (opts.jobs < 1) opts.jobs = 1;
    if (opts.isolate && !sl_isolation_lab_functions) {
        fprintf(stderr, "shadowlab-grade: --isolate needs the solutions, and this copy was built without solutions/\n");
        return SL_EXIT_ERROR;
    }
    if (opts.isolate && update) {
        fprintf(stderr, "shadowlab-grade: --isolate and --update-references do not go together\n");
        return SL_EXIT_ERROR;
    }
    char isolation_root[64] = "";
    if (opts.isolate && !_sl_make_isolation_dirs(&opts, opts.labs_dir ? opts.labs_dir : sl_build_labs_dir,
                                                 isolation_root, sizeof isolation_root))
        return SL_EXIT_ERROR;
    if (update && (strcmp(sl_build_labs_kind, "solutions") != 0 || opts.labs_dir)) {
        fprintf(stderr, "shadowlab-grade: --update-references renders references from the solutions, but this build "
                        "uses the %s labs%s. Configure with -DSL_LABS=solutions.\n",
                sl_build_labs_kind, opts.labs_dir ? " (and --labs-dir)" : "");
        return SL_EXIT_ERROR;
    }
    double start = _sl_now();

    /* Everything is read before any lab code runs: cases, then references. */
    DIR *d = opendir(cases_dir);
    if (!d) {
        fprintf(stderr, "shadowlab-grade: cannot open the cases folder %s\n", cases_dir);
        return SL_EXIT_ERROR;
    }
    char *names[512];
    int name_count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && name_count < 512) {
        size_t len = strlen(e->d_name);
        if (len > 5 && strcmp(e->d_name + len - 5, ".json") == 0) names[name_count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)name_count, sizeof names[0], _sl_compare_names);

    sl_grade_report rep = {.jobs = opts.jobs, .labs_kind = sl_build_labs_kind};
    sl_case *cases = calloc((size_t)name_count + 1, sizeof *cases);
    int count = 0;
    for (int i = 0; i < name_count; i++) {
        char path[1400], err[1200];
        snprintf(path, sizeof path, "%s/%s", cases_dir, names[i]);
        free(names[i]);
        sl_case *c = &cases[count];
        if (!sl_case_load(c, path, err, sizeof err)) {
            if (rep.problem_count < 32) snprintf(rep.problems[rep.problem_count++], sizeof rep.problems[0], "%s", err);
            continue;
        }
        if (only_lab && c->lab != only_lab) continue;
        if (!_sl_matches(c->name, pattern)) continue;
        if (exclude && _sl_matches(c->name, exclude)) continue;
        count++;
    }
    if (list) {
        for (int i = 0; i < count; i++) {
            printf("lab %d  %-36s %s (", cases[i].lab, cases[i].name, cases[i].title);
            for (int k = 0; k < cases[i].check_count; k++)
                printf("%s%s %gp%s", k ? ", " : "", cases[i].checks[k].name, cases[i].checks[k].points,
                       cases[i].checks[k].bonus ? " bonus" : "");
            printf(")\n");
        }
        for (int i = 0; i < rep.problem_count; i++) printf("PROBLEM %s\n", rep.problems[i]);
        free(cases);
        return rep.problem_count ? SL_EXIT_ERROR : 0;
    }
    if (count == 0) {
        for (int i = 0; i < rep.problem_count; i++) fprintf(stderr, "PROBLEM %s\n", rep.problems[i]);
        fprintf(stderr, "shadowlab-grade: no case matches%s%s in %s\n", pattern ? " " : "", pattern ? pattern : "",
                cases_dir);
        free(cases);
        return SL_EXIT_ERROR;
    }
    sl_reference *refs = calloc((size_t)count * SL_CASE_MAX_CHECKS, sizeof *refs);
    if (!update)
        for (int i = 0; i < count; i++)
            for (int k = 0; k < cases[i].check_count; k++)
                sl_reference_load(&refs[i * SL_CASE_MAX_CHECKS + k], refs_dir, &cases[i], &cases[i].checks[k]);

    sl_case_result *results = calloc((size_t)count, sizeof *results);
    sl_run_cases(cases, count, &opts, results);

    int status = SL_EXIT_FULL;
    if (update) {
        int written = 0;
        for (int i = 0; i < count; i++) {
            for (int k = 0; k < cases[i].check_count; k++) {
                char err[1200];
                if (!sl_check_reference_file(cases[i].checks[k].kind)) continue;
                if (!results[i].finished) {
                    fprintf(stderr, "shadowlab-grade: %s did not finish: %s%s\n", cases[i].name,
                            results[i].error[0] ? results[i].error : "crashed or timed out in ",
                            results[i].error[0] ? "" : results[i].crashed_in);
                    status = SL_EXIT_ERROR;
                    break;
                }
                if (sl_reference_write(refs_dir, &cases[i], &cases[i].checks[k], &results[i], err, sizeof err)) {
                    written++;
                } else {
                    fprintf(stderr, "shadowlab-grade: %s\n", err);
                    status = SL_EXIT_ERROR;
                }
            }
        }
        printf("shadowlab-grade: wrote %d reference files under %s\n", written, refs_dir);
    } else {
        rep.cases = calloc((size_t)count, sizeof *rep.cases);
        rep.case_count = count;
        bool reference_problem = false;
        for (int i = 0; i < count; i++) {
            rep.cases[i].c = &cases[i];
            rep.cases[i].result = &results[i];
            rep.cases[i].references = &refs[i * SL_CASE_MAX_CHECKS];
            for (int k = 0; k < cases[i].check_count; k++) {
                sl_check_result *cr = &rep.cases[i].checks[k];
                sl_grade_check(&cases[i], &cases[i].checks[k], &results[i], &refs[i * SL_CASE_MAX_CHECKS + k], cr);
                reference_problem |= cr->reference_problem;
            }
        }
        rep.seconds = _sl_now() - start;
        printf("shadowlab-grade: %s labs, %d cases%s\n", sl_build_labs_kind, count,
               opts.isolate ? ", each lab isolated (the solutions stand in for the other labs)" : "");
        sl_report_print(&rep, stdout, isatty(1));
        char err[1200];
        if (report_dir && !sl_report_write_dir(&rep, report_dir, err, sizeof err))
            fprintf(stderr, "shadowlab-grade: %s\n", err);
        if (junit && !sl_report_write_junit(&rep, junit, err, sizeof err))
            fprintf(stderr, "shadowlab-grade: %s\n", err);
        if (gradescope && !sl_report_write_gradescope(&rep, gradescope, err, sizeof err))
            fprintf(stderr, "shadowlab-grade: %s\n", err);
        if (prairielearn && !sl_report_write_prairielearn(&rep, prairielearn, err, sizeof err))
            fprintf(stderr, "shadowlab-grade: %s\n", err);
        double score, max;
        sl_report_totals(&rep, &score, &max);
        if (reference_problem || rep.problem_count) status = SL_EXIT_ERROR;
        else if (!sl_report_full_marks(&rep)) status = SL_EXIT_FAILED;
        for (int i = 0; i < count; i++)
            for (int k = 0; k < cases[i].check_count; k++) sl_image_free(&rep.cases[i].checks[k].diff);
        free(rep.cases);
    }
    for (int i = 0; i < count; i++) {
        sl_case_result_free(&results[i]);
        for (int k = 0; k < SL_CASE_MAX_CHECKS; k++) sl_reference_free(&refs[i * SL_CASE_MAX_CHECKS + k]);
    }
    free(results);
    free(refs);
    free(cases);
    if (isolation_root[0]) _sl_remove_isolation_dirs(isolation_root);
    return status;
}
