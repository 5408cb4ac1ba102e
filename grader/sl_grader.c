#define _GNU_SOURCE
#include "sl_grader.h"
#include "sl_diag.h"

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
#include "sl_case.h"
#include "sl_class_report.h"
#include "sl_backend.h"
#include "sl_files.h"
#include "sl_grade.h"
#include "sl_experiment.h"
#include "sl_gradebook.h"
#include "sl_roster.h"
#include "sl_grader_options.h"
#include "sl_grader_steps.h"
#include "sl_hidden.h"
#include "sl_probe_generic.h"
#include "sl_manifest.h"
#include "sl_report.h"
#include "sl_run.h"
#include "sl_sandbox.h"
#include "sl_utf8.h"

/* What the grader was doing, for the message of a fault of its own. */
static const char *volatile _sl_phase = "starting";

/* --gradebook DIR: the gradebook and the class report from a batch's reports; with
 * --roster, the LMS's names and missing students, and --export its import file. */
static int _sl_gradebook(const _sl_options *o) {
    char csv[1200], gradebook_err[1500];
    snprintf(csv, sizeof csv, "%s/gradebook.csv", o->gradebook);
    sl_gradebook_roster lms = {0};
    if ((o->due || o->export_format || o->assignment || o->missing_as_zero) && !o->roster) {
        fprintf(stderr, "shadowlab-grade: --due, --export, --assignment and --missing-as-zero need --roster FILE\n");
        return SL_EXIT_ERROR;
    }
    if (o->due && !(lms.have_due = sl_roster_parse_due(o->due, &lms.due))) {
        fprintf(stderr, "shadowlab-grade: --due '%s': give \"YYYY-MM-DD HH:MM\"\n", o->due);
        return SL_EXIT_ERROR;
    }
    sl_roster *roster = o->roster ? sl_roster_read(o->roster, gradebook_err, sizeof gradebook_err) : NULL;
    bool ok = roster || !o->roster;
    if (ok && roster && lms.have_due && sl_roster_kind_of(roster) != SL_ROSTER_MOODLE) {
        snprintf(gradebook_err, sizeof gradebook_err,
                 "--due: %s is Canvas's, whose downloads mark late submissions themselves (LATE_)", o->roster);
        ok = false;
    }
    lms.roster = roster;
    ok = ok && sl_gradebook_write_roster(o->gradebook, csv, roster ? &lms : NULL, gradebook_err, sizeof gradebook_err) &&
         sl_class_report_write(o->gradebook, gradebook_err, sizeof gradebook_err);
    if (ok)
        printf("shadowlab-grade: wrote %s, and the class report %s/class-report.html (and .csv, and class-mistakes.csv)\n",
               csv, o->gradebook);
    if (ok && o->export_format) {
        sl_roster_export_desc desc = {o->export_format, o->export_path, o->assignment, o->missing_as_zero};
        ok = sl_roster_export(roster, csv, &desc, gradebook_err, sizeof gradebook_err);
        if (ok) printf("shadowlab-grade: wrote %s (%s import, read back and checked)\n", o->export_path, o->export_format);
    }
    sl_roster_free(roster);
    if (!ok) fprintf(stderr, "shadowlab-grade: %s\n", gradebook_err);
    return ok ? SL_EXIT_FULL : SL_EXIT_ERROR;
}

static int _sl_grade(int argc, char **argv, sl_sandbox *sandbox, char isolation_root[64], sl_hidden *hidden) {
    _sl_options o = {
        .jobs = (int)sysconf(_SC_NPROCESSORS_ONLN),
        .sandbox_level = SL_SANDBOX_NAMESPACES,
        .backend = SL_BACKEND_DEFAULT_HEADLESS,
    };
    int parsed = _sl_parse(argc, argv, &o);
    if (parsed) return parsed < 0 ? SL_EXIT_FULL : parsed;
    if (o.gradebook) return _sl_gradebook(&o);
    if (o.roster || o.due || o.export_format || o.assignment || o.missing_as_zero) {
        fprintf(stderr, "shadowlab-grade: --roster, --due, --export, --assignment and --missing-as-zero go with "
                        "--gradebook DIR\n");
        return SL_EXIT_ERROR;
    }
    static char default_cases[1100], default_refs[1100];
    snprintf(default_cases, sizeof default_cases, "%s/cases", sl_config_grader_dir);
    snprintf(default_refs, sizeof default_refs, "%s/references", sl_config_grader_dir);
    if (!o.cases_dir) o.cases_dir = default_cases;
    if (!o.refs_dir) o.refs_dir = default_refs;
    bool custom = o.labs_dir || o.runners_dir;
    /* The references of a technique a build adds (lab 0) come from its correct build's runners:
     * --update-references --runners DIR, every case of lab 0 (checked once the cases are read). */
    bool technique_update = o.update && o.runners_dir && !o.labs_dir;
    const char *labs_kind = custom ? "other" : sl_config_labs_kind;
    if (!o.labs_dir) o.labs_dir = sl_config_labs_dir;
    if (!o.runners_dir) o.runners_dir = sl_config_runners_dir;
    bool have_solutions = sl_config_solutions_runner[0] && _sl_is_dir(sl_config_solutions_dir);

    if (o.isolate && o.update) {
        fprintf(stderr, "shadowlab-grade: --isolate and --update-references do not go together\n");
        return SL_EXIT_ERROR;
    }
    uint64_t seed = 0;
    if (o.hidden != (o.seed != NULL) || (o.seed && !sl_hidden_parse_seed(o.seed, &seed))) {
        fprintf(stderr, "shadowlab-grade: --hidden and --seed S go together (S: a whole number, 0 to 2^64 - 1)\n");
        return SL_EXIT_ERROR;
    }
    if (o.not_built && o.update) {
        fprintf(stderr, "shadowlab-grade: --not-built and --update-references do not go together\n");
        return SL_EXIT_ERROR;
    }
    if (o.hidden && o.update) {
        fprintf(stderr, "shadowlab-grade: --hidden and --update-references do not go together\n");
        return SL_EXIT_ERROR;
    }
    if (o.hidden && !have_solutions) {
        fprintf(stderr, "shadowlab-grade: --hidden renders its references from the solutions, and this copy has no "
                        "solutions/ (a student handout)\n");
        return SL_EXIT_ERROR;
    }
    if ((o.isolate || o.update) && !have_solutions) {
        fprintf(stderr, "shadowlab-grade: %s renders references from the solutions, and this copy has no solutions/ "
                        "(a student handout): the references come with the handout.\n",
                o.update ? "--update-references"
                         : "--isolate (the solutions stand in for the labs each lab builds on)");
        return SL_EXIT_ERROR;
    }
    if (o.isolate && !_sl_is_dir(sl_config_stubs_dir)) {
        fprintf(stderr, "shadowlab-grade: --isolate: the handout's stubs (%s) are missing: the per-lab runners "
                        "take the labs a lab does not build on from there (build the project: cmake --build build)\n",
                sl_config_stubs_dir[0] ? sl_config_stubs_dir : "none in this build");
        return SL_EXIT_ERROR;
    }
    if (o.update && custom && !technique_update) {
        fprintf(stderr, "shadowlab-grade: --update-references renders references from the solutions' own runner; "
                        "drop --labs-dir and --runners\n");
        return SL_EXIT_ERROR;
    }
    char err[1500];
    const char *graded_tree = o.update && !technique_update ? sl_config_solutions_dir : o.labs_dir;
    sl_diag_set_sources(graded_tree, sl_config_stubs_dir[0] ? sl_config_stubs_dir : NULL);
    if (!_sl_check_labs_tree(graded_tree, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: --labs-dir: %s\n", err);
        return SL_EXIT_ERROR;
    }
    /* The runners this grade needs, before anything runs. */
    if (o.backend == SL_BACKEND_DEFAULT_HEADLESS) o.backend = sl_backend_default_headless();
    sl_run_options run = {
        .jobs = o.jobs,
        .timeout = o.timeout,
        .memory_bytes = (unsigned long long)(o.memory_mb * 1048576.0),
        .backend = o.backend,
        .sandbox = sandbox,
        .framework_dir = sl_config_framework_dir,
        .environment = _sl_runner_environment(o.backend == SL_BACKEND_WINDOW),
    };
    static char runner_paths[SL_LAB_COUNT + 1][1200];
    static char trees[SL_LAB_COUNT + 1][96];
    if (o.isolate) {
        if (!_sl_make_isolation_trees(isolation_root, o.labs_dir, trees)) return SL_EXIT_ERROR;
        for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
            if (!sl_lab_folder(lab)) continue;
            snprintf(runner_paths[lab], sizeof runner_paths[lab], "%s/shadowlab-runner-isolate-lab%d", o.runners_dir, lab);
            sl_runner_setup *s = &run.setups[lab];
            s->runner = runner_paths[lab];
            s->labs_tree = trees[lab];
            for (int other = 1; other <= SL_LAB_COUNT; other++)
                if (sl_lab_folder(other)) s->lab_dirs[other] = _sl_isolated_source(lab, other, o.labs_dir);
        }
    } else {
        if (o.update && !technique_update)
            snprintf(runner_paths[0], sizeof runner_paths[0], "%s", sl_config_solutions_runner);
        else snprintf(runner_paths[0], sizeof runner_paths[0], "%s/shadowlab-runner", o.runners_dir);
        run.setups[0].runner = runner_paths[0];
        run.setups[0].labs_tree = graded_tree;
        for (int lab = 1; lab <= SL_LAB_COUNT; lab++)
            if (sl_lab_folder(lab)) run.setups[0].lab_dirs[lab] = graded_tree;
        run.setups[0].lab_dirs[0] = o.technique_dir; /* lab 0's files: the technique's folder */
    }

    static sl_grade_report rep;
    rep = (sl_grade_report){.jobs = o.jobs, .labs_kind = o.update ? "solutions" : labs_kind, .labs_dir = graded_tree};
    if (o.submission_summary && !sl_report_load_submission(&rep, o.submission_summary, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: --submission-summary: %s\n", err);
        return SL_EXIT_ERROR;
    }
    static sl_case cases[_SL_MAX_CASES];
    int count = _sl_load_cases(&o, cases, &rep);
    if (count < 0) {
        fprintf(stderr, "shadowlab-grade: cannot open the cases folder %s\n", o.cases_dir);
        return SL_EXIT_ERROR;
    }
    static char hidden_notes[_SL_MAX_CASES][400];
    if (o.hidden)
        for (int i = 0; i < count; i++) sl_hidden_derive(&cases[i], seed, hidden_notes[i], sizeof hidden_notes[i]);
    /* every probe also runs on generic rows, drawn from the hidden seed when there is one (never when
     * writing references: those hold the written rows alone) */
    uint64_t probe_seed = o.hidden ? seed : SL_PROBE_GENERIC_DEFAULT_SEED;
    if (o.probe_seed && !sl_hidden_parse_seed(o.probe_seed, &probe_seed)) {
        fprintf(stderr, "shadowlab-grade: --probe-seed S takes a whole number, 0 to 2^64 - 1\n");
        return SL_EXIT_ERROR;
    }
    if (!o.update)
        for (int i = 0; i < count; i++) sl_probe_generic_add(&cases[i], probe_seed);
    if (o.list) {
        _sl_list_cases(cases, count, &rep, o.hidden ? (const char(*)[400])hidden_notes : NULL);
        return rep.problem_count ? SL_EXIT_ERROR : SL_EXIT_FULL;
    }
    if (count == 0) {
        for (int i = 0; i < rep.problem_count; i++) fprintf(stderr, "PROBLEM %s\n", rep.problems[i]);
        fprintf(stderr, "shadowlab-grade: no case matches in %s\n", o.cases_dir);
        return SL_EXIT_ERROR;
    }
    /* what decides this grade, for its reports and the gradebook */
    rep.seed = o.hidden ? o.seed : NULL;
    rep.bonus_policy = o.bonus_policy;
    _sl_describe_options(&o, default_cases, default_refs, rep.options, sizeof rep.options);
    if (o.not_built) return _sl_grade_not_built(&o, cases, count, &rep);
    /* --build-logs: a lab whose runner is missing did not build; the others are graded */
    static char lab_errors[SL_LAB_MAX + 1][SL_BUILD_ERROR_MAX + 8];
    int runnable = 0;
    for (int i = 0; i < count; i++) {
        int lab = cases[i].lab;
        const sl_runner_setup *s = run.setups[lab].runner ? &run.setups[lab] : &run.setups[0];
        if (technique_update && lab != 0) {
            fprintf(stderr, "shadowlab-grade: --update-references renders references from the solutions' own runner; "
                            "drop --labs-dir and --runners (%s grades lab %d; only lab 0's, a build's added "
                            "technique, come from --runners)\n", cases[i].path, lab);
            return SL_EXIT_ERROR;
        }
        if (lab == 0 && o.isolate) {
            fprintf(stderr, "shadowlab-grade: %s grades lab 0, the technique a build adds, which --isolate has no "
                            "runner for: grade it without --isolate\n", cases[i].path);
            return SL_EXIT_ERROR;
        }
        /* lab 0: the technique the runners' build adds; the runner says when its build adds none */
        if (lab > SL_LAB_COUNT || (lab > 0 && !sl_lab_folder(lab))) {
            fprintf(stderr, "shadowlab-grade: %s grades lab %d, which this build does not have\n", cases[i].path, lab);
            return SL_EXIT_ERROR;
        }
        if (_sl_stub_lab(&o, lab)) {
            continue; /* the handout's stubs: not built, not run */
        } else if (_sl_is_executable(s->runner)) {
            runnable++;
        } else if (o.isolate && o.build_logs) {
            if (!rep.lab_not_built[lab]) {
                char log[1300];
                snprintf(log, sizeof log, "%s/lab%d.log", o.build_logs, lab);
                if (!sl_build_failure_first_error(log, o.labs_dir, lab_errors[lab], sizeof lab_errors[lab], err,
                                                  sizeof err))
                    snprintf(lab_errors[lab], sizeof lab_errors[lab], "its runner was not built, and %s", err);
                rep.lab_not_built[lab] = lab_errors[lab];
            }
        } else {
            fprintf(stderr, "shadowlab-grade: the runner %s is missing (build it: cmake --build build)\n", s->runner);
            return SL_EXIT_ERROR;
        }
    }
    for (int lab = 1; lab <= SL_LAB_MAX; lab++)
        if (rep.lab_not_built[lab]) {
            printf("shadowlab-grade: lab %d did not build: ", lab);
            sl_utf8_write(stdout, rep.lab_not_built[lab], strlen(rep.lab_not_built[lab]), 0);
            fputc('\n', stdout);
        }
    if (runnable == 0) return _sl_grade_not_built(&o, cases, count, &rep);
    if (o.hidden && !_sl_is_executable(sl_config_solutions_runner)) {
        fprintf(stderr, "shadowlab-grade: the solutions' runner %s is missing (build it: cmake --build build)\n",
                sl_config_solutions_runner);
        return SL_EXIT_ERROR;
    }

    /* The sandbox, before any lab code runs. */
    const char *probe_runner = run.setups[0].runner;
    for (int i = 0; i < count && !probe_runner; i++)
        if (!rep.lab_not_built[cases[i].lab] && !_sl_stub_lab(&o, cases[i].lab)) probe_runner = run.setups[cases[i].lab].runner;
    if (!sl_sandbox_open(sandbox, o.sandbox_level, probe_runner, err, sizeof err)) {
        fprintf(stderr, "shadowlab-grade: %s\n", err);
        return SL_EXIT_ERROR;
    }
    sl_sandbox_describe(sandbox, rep.sandbox, sizeof rep.sandbox);
    if (sandbox->self_check) rep.self_check = SL_SANDBOX_SELF_CHECK_NOTE;
    /* Hidden cases: the references are this run's, in a folder of the grader's own. */
    if (o.hidden) {
        if (!sl_hidden_open(hidden, seed, err, sizeof err)) {
            fprintf(stderr, "shadowlab-grade: %s\n", err);
            return SL_EXIT_ERROR;
        }
        o.refs_dir = hidden->references_dir;
    }
    /* Below the namespaces level the runners see the real file system: say
     * plainly when the answers are within their reach. */
    const char *sensitive[3] = {o.refs_dir, o.cases_dir, sl_config_solutions_dir[0] ? sl_config_solutions_dir : NULL};
    const char *what[3] = {"the references", "the case files", "the solutions"};
    bool readable[3];
    int sensitive_count = sensitive[2] ? 3 : 2;
    if (!sandbox->self_check && sl_sandbox_readable(sandbox, sensitive, sensitive_count, readable) > 0) {
        char list[200] = "";
        for (int i = 0; i < sensitive_count; i++)
            if (readable[i])
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", list[0] ? ", " : "", what[i]);
        snprintf(rep.sandbox + strlen(rep.sandbox), sizeof rep.sandbox - strlen(rep.sandbox),
                 "; lab code can read %s: grade with --strict for a grade no submission can forge", list);
    }
    if (o.strict && sandbox->self_check) {
        fprintf(stderr, "shadowlab-grade: --strict: this build's runners have no sandbox (%s module): build with "
                        "-DSL_SANDBOX=linux on Linux to grade for a course\n", sl_sandbox_module());
        return SL_EXIT_ERROR;
    }
    if (o.strict && sandbox->level < SL_SANDBOX_NAMESPACES) {
        fprintf(stderr, "shadowlab-grade: --strict: the runners would get only the %s sandbox (%s). Grade as root, or "
                        "where unprivileged user namespaces are allowed (sysctl kernel.unprivileged_userns_clone=1; "
                        "in a container: CAP_SYS_ADMIN or a seccomp profile that allows unshare).\n",
                sl_sandbox_level_name(sandbox->level), sandbox->why_not_stronger);
        return SL_EXIT_ERROR;
    }
    /* The compiler is the other way in: what did it let lab code read? */
    char compiler[600];
    bool fenced = o.update || _sl_compile_fence(o.runners_dir, compiler, sizeof compiler);
    if (o.strict && !fenced) {
        fprintf(stderr, "shadowlab-grade: --strict: the runners' lab code was compiled without a fence: %s. Build "
                        "them where a mount namespace is allowed (root, or unprivileged user namespaces), or as root "
                        "with the answers unreadable to uid 65534 (scripts/grade-submission says which).\n",
                compiler);
        return SL_EXIT_ERROR;
    }
    if (!fenced)
        snprintf(rep.sandbox + strlen(rep.sandbox), sizeof rep.sandbox - strlen(rep.sandbox), "; compiler not fenced");

    if (o.hidden) {
        sl_run_options solutions_run = run;
        /* limits set for lab code never go below the cases' own for the solutions */
        for (int i = 0; i < count; i++) {
            if (solutions_run.timeout > 0 && solutions_run.timeout < cases[i].timeout_seconds) solutions_run.timeout = 0;
            if (solutions_run.memory_bytes > 0 && solutions_run.memory_bytes < cases[i].memory_mb * 1048576.0)
                solutions_run.memory_bytes = 0;
        }
        memset(solutions_run.setups, 0, sizeof solutions_run.setups);
        solutions_run.setups[0].runner = sl_config_solutions_runner;
        solutions_run.setups[0].labs_tree = sl_config_solutions_dir;
        for (int lab = 1; lab <= SL_LAB_COUNT; lab++)
            if (sl_lab_folder(lab)) solutions_run.setups[0].lab_dirs[lab] = sl_config_solutions_dir;
        if (!sl_hidden_render_references(hidden, cases, count, &solutions_run, &_sl_stop, err, sizeof err)) {
            fprintf(stderr, "shadowlab-grade: %s\n", err);
            return SL_EXIT_ERROR;
        }
    }

    /* Every reference is read and verified in this process, which runs no lab code. */
    static sl_reference refs[_SL_MAX_CASES * SL_CASE_MAX_CHECKS];
    sl_manifest *manifest = NULL;
    sl_reference_cache *reference_cache = NULL;
    char reference_cache_state[1400] = "not used";
    char reference_renderer[160] = "";
    if (!o.update) {
        char manifest_error[1500] = "";
        manifest = sl_manifest_load(o.refs_dir, false, manifest_error, sizeof manifest_error);
        reference_cache = _sl_reference_cache_open(&o, sandbox, reference_cache_state, sizeof reference_cache_state);
        for (int i = 0; i < count; i++) {
            if (manifest) cases[i].reference_cpu_seconds = sl_manifest_cpu_seconds(manifest, cases[i].name);
            if (manifest) snprintf(reference_renderer, sizeof reference_renderer, "%s", sl_manifest_renderer(manifest));
            for (int k = 0; k < cases[i].check_count; k++)
                sl_reference_load_cached(&refs[i * SL_CASE_MAX_CHECKS + k], o.refs_dir, manifest, manifest_error,
                                         reference_cache, &cases[i], &cases[i].checks[k]);
        }
        sl_manifest_free(manifest);
        if (reference_cache) {
            sl_reference_cache_counts counts = sl_reference_cache_counts_of(reference_cache);
            snprintf(reference_cache_state, sizeof reference_cache_state, "%s: %d read, %d stored, %d ignored",
                     sl_reference_cache_dir(reference_cache), counts.hits, counts.stored, counts.ignored);
        }
        sl_reference_cache_close(reference_cache);
    }

    _sl_progress progress = {.lines = o.progress, .terminal = !o.progress && isatty(2)};
    if (progress.lines || progress.terminal) {
        run.case_ended = _sl_case_ended;
        run.case_ended_context = &progress;
    }
    double start = _sl_monotonic_now();
    static sl_case_result results[_SL_MAX_CASES];
    /* the cases of labs that built, in runs of consecutive cases (the report keeps the cases' order) */
    bool complete = true;
    for (int first = 0; first < count && complete;) {
        int end = first;
        if (rep.lab_not_built[cases[first].lab] || _sl_stub_lab(&o, cases[first].lab)) {
            first++;
            continue;
        }
        while (end < count && !rep.lab_not_built[cases[end].lab] && !_sl_stub_lab(&o, cases[end].lab)) end++;
        complete = sl_run_cases(cases + first, end - first, &run, results + first, &_sl_stop);
        first = end;
        /* stopped: the cases not started are interrupted too */
        for (int i = end; !complete && i < count; i++)
            results[i].interrupted = !rep.lab_not_built[cases[i].lab] && !_sl_stub_lab(&o, cases[i].lab);
    }
    if (progress.terminal) fputs("\r\033[K", stderr); /* the report follows on stdout */
    /* CPU times compare on the references' renderer only. Which one the runners get, the grader learns
     * from staff code where the build has it, when a case is slow enough to ask; else from each runner's
     * first HELLO, sent before any lab function runs (lab C code that rewrites the channel could still
     * rename it there). */
    char runners_renderer[160] = "";
    bool any_slow = false;
    for (int i = 0; i < count && !o.update; i++) any_slow |= sl_grade_too_slow(&cases[i], &results[i]);
    if (any_slow && reference_renderer[0])
        _sl_probe_renderer(&run, &_sl_stop, runners_renderer, sizeof runners_renderer);
    /* A case the machine could not run grades nothing: the staff hear why (exit 2). */
    int staff_faults = 0;
    for (int i = 0; i < count; i++)
        if (results[i].staff_error[0] && staff_faults++ == 0 && rep.problem_count < 31)
            snprintf(rep.problems[rep.problem_count++], sizeof rep.problems[0], "could not grade %s: %s", cases[i].name,
                     results[i].staff_error);
    if (staff_faults > 1 && rep.problem_count < 32)
        snprintf(rep.problems[rep.problem_count++], sizeof rep.problems[0],
                 "could not grade %d more cases (each case's message says why)", staff_faults - 1);
    int status = SL_EXIT_FULL;
    if (o.update) {
        status = complete ? _sl_update_references(&o, cases, count, results) : SL_EXIT_ERROR;
        if (!complete) fprintf(stderr, "shadowlab-grade: stopped: no reference was written\n");
    } else {
        static sl_graded_case graded[_SL_MAX_CASES];
        rep.cases = graded;
        rep.case_count = count;
        rep.interrupted = !complete;
        bool reference_problem = false;
        /* Probes first: an image check whose case calls a function that
         * failed its probe leads with that function. */
        static sl_probe_failure probe_failures[_SL_MAX_CASES * SL_CASE_MAX_CHECKS];
        int probe_failure_count = 0;
        uint64_t probes_graded = 0, probes_failed = 0; /* by sl_probe index: what a message may rule out */
        uint64_t probes_written_only = 0;              /* a probe check of the function ran no generic row */
        for (int i = 0; i < count; i++)
            for (int k = 0; k < cases[i].check_count; k++) {
                if (cases[i].checks[k].kind != SL_CHECK_PROBE) continue;
                sl_check_result *cr = &graded[i].checks[k];
                if (_sl_stub_lab(&o, cases[i].lab)) {
                    _sl_grade_stub(&cases[i].checks[k], cases[i].lab, cr);
                    probes_failed |= cases[i].checks[k].function >= 0 && cases[i].checks[k].function < 64
                                         ? 1ull << cases[i].checks[k].function : 0;
                    continue;
                }
                if (rep.lab_not_built[cases[i].lab]) {
                    sl_build_failure_grade_lab(&cases[i].checks[k], cases[i].lab, rep.lab_not_built[cases[i].lab], cr);
                    continue;
                }
                sl_grade_check(&cases[i], &cases[i].checks[k], &results[i], &refs[i * SL_CASE_MAX_CHECKS + k], NULL, cr);
                int function = cases[i].checks[k].function;
                uint64_t bit = function >= 0 && function < 64 ? 1ull << function : 0;
                if (!cr->reference_problem && !results[i].interrupted) probes_graded |= bit;
                if (!cr->passed) probes_failed |= bit;
                if (cases[i].checks[k].generic_rows == 0) probes_written_only |= bit;
                if (sl_probe_failure_of(&cases[i], &cases[i].checks[k], cr, &probe_failures[probe_failure_count]))
                    probe_failure_count++;
            }
        for (int i = 0; i < count; i++) {
            graded[i].c = &cases[i];
            graded[i].result = &results[i];
            graded[i].references = &refs[i * SL_CASE_MAX_CHECKS];
            rep.cases_finished += !results[i].interrupted;
            /* CPU times compare only on the renderer the references were made with (above) */
            const char *renderer = runners_renderer[0] ? runners_renderer : results[i].renderer;
            if (!_sl_same_renderer(renderer, reference_renderer)) cases[i].reference_cpu_seconds = 0;
            if (!rep.backend[0] && results[i].backend[0]) {
                snprintf(rep.backend, sizeof rep.backend, "%s", results[i].backend);
                snprintf(rep.renderer, sizeof rep.renderer, "%s", results[i].renderer);
            }
        }
        /* Lab by lab, so that a later lab's check knows what failed in the labs it builds on. */
        static sl_lab_failure lab_failures[_SL_MAX_CASES * SL_CASE_MAX_CHECKS];
        int lab_failure_count = 0;
        memset(lab_failures, 0, sizeof lab_failures);
        for (int lab = 0; lab <= SL_LAB_MAX; lab++) { /* 0: a build's added technique */
            for (int i = 0; i < count; i++) {
                if (cases[i].lab != lab) continue;
                for (int k = 0; k < cases[i].check_count; k++) {
                    sl_check_result *cr = &graded[i].checks[k];
                    if (_sl_stub_lab(&o, lab)) {
                        _sl_grade_stub(&cases[i].checks[k], lab, cr);
                    } else if (rep.lab_not_built[lab]) {
                        sl_build_failure_grade_lab(&cases[i].checks[k], lab, rep.lab_not_built[lab], cr);
                    } else if (cases[i].checks[k].kind != SL_CHECK_PROBE) {
                        sl_grade_context context = {.earlier = graded[i].checks, .earlier_count = k,
                                                    .probe_failures = probe_failures,
                                                    .probe_failure_count = probe_failure_count,
                                                    .probes_passed = probes_graded & ~probes_failed,
                                                    .probes_generic = probes_graded & ~probes_failed & ~probes_written_only,
                                                    .lab_failures = lab_failures,
                                                    .lab_failure_count = lab_failure_count, .isolated = o.isolate};
                        sl_grade_check(&cases[i], &cases[i].checks[k], &results[i], &refs[i * SL_CASE_MAX_CHECKS + k],
                                       &context, cr);
                    }
                    reference_problem |= cr->reference_problem;
                }
                if (!_sl_stub_lab(&o, lab) && !rep.lab_not_built[lab]) sl_grade_require_evidence(&cases[i], graded[i].checks);
            }
            /* the lab's failures: pictures' before probes' (they say what a later lab will see) */
            for (int probe = 0; probe < 2; probe++)
                for (int i = 0; i < count; i++)
                    for (int k = 0; k < cases[i].check_count; k++) {
                        const sl_check *ck = &cases[i].checks[k];
                        const sl_check_result *cr = &graded[i].checks[k];
                        if (cases[i].lab != lab || (ck->kind == SL_CHECK_PROBE) != (probe == 1) || cr->passed ||
                            cr->bonus || cr->reference_problem)
                            continue;
                        sl_lab_failure *lf = &lab_failures[lab_failure_count++];
                        *lf = (sl_lab_failure){.failed = true, .lab = lab, .c = &cases[i], .k = ck,
                                               .symptoms = cr->symptoms};
                        snprintf(lf->where, sizeof lf->where, "%s / %s", cases[i].name, ck->name);
                        sl_utf8_copy(lf->summary, sizeof lf->summary, cr->summary[0] ? cr->summary : cr->message);
                    }
        }
        /* Staff grading: each failed check run again with one function of its lab replaced by the
         * solution's (sl_experiment.h); each run gives one bit, and the checks it answers for are
         * said again with it. Nothing runs where nothing failed. */
        sl_experiment_cost experiment_cost = {0};
        bool experiments = o.isolate && have_solutions && !o.no_experiments && complete;
        if (experiments) {
            static sl_experiment_verdict verdicts[_SL_MAX_CASES * SL_CASE_MAX_CHECKS];
            sl_experiment_grade eg = {.cases = cases, .count = count, .graded = graded, .refs = refs, .run = &run,
                                      .graded_tree = o.labs_dir, .solutions_tree = sl_config_solutions_dir,
                                      .stubs_tree = sl_config_stubs_dir[0] ? sl_config_stubs_dir : NULL,
                                      .builder = o.experiment_builder,
                                      .work_dir = isolation_root};
            sl_experiment_budget budget = {.seconds = o.experiment_budget > 0 ? o.experiment_budget : 120,
                                           .max_runs = 120};
            sl_experiments_run(&eg, &budget, verdicts, &experiment_cost, &_sl_stop);
            for (int i = 0; i < count; i++)
                for (int k = 0; k < cases[i].check_count; k++) {
                    const sl_experiment_verdict *v = &verdicts[i * SL_CASE_MAX_CHECKS + k];
                    char lead[1200];
                    sl_experiment_lead(v, lead, sizeof lead);
                    if (!lead[0]) continue;
                    sl_image_free(&graded[i].checks[k].diff);
                    /* the function the experiment found, when its own probe failed too */
                    const sl_probe_failure *experiment_probe = NULL;
                    if (v->outcome == SL_EXPERIMENT_SINGLE) {
                        char name[64];
                        snprintf(name, sizeof name, "%s", v->functions[0]);
                        name[strcspn(name, "(")] = '\0';
                        const sl_probe_function *pf = sl_probe_find(name);
                        for (int p = 0; pf && p < probe_failure_count && !experiment_probe; p++)
                            if (probe_failures[p].function == sl_probe_index(pf)) experiment_probe = &probe_failures[p];
                    }
                    sl_grade_context context = {.earlier = graded[i].checks, .earlier_count = k, .isolated = true,
                                                .experiment_lead = lead, .experiment_probe = experiment_probe,
                                                .experiment_function = v->outcome == SL_EXPERIMENT_SINGLE ||
                                                                               v->outcome == SL_EXPERIMENT_PAIR
                                                                           ? v->functions[0] : ""};
                    sl_grade_check(&cases[i], &cases[i].checks[k], &results[i], &refs[i * SL_CASE_MAX_CHECKS + k],
                                   &context, &graded[i].checks[k]);
                }
        }
        if (experiments)
            for (int i = 0; i < count; i++) sl_grade_quote_evidence(&cases[i], graded[i].checks);
        /* Each shader's compile error quoted once, at the first check it stopped, in the reports' order. */
        static sl_compile_errors_said said;
        said.count = 0;
        for (int i = 0; i < count; i++)
            for (int k = 0; k < cases[i].check_count; k++) sl_diag_compile_error_once(&graded[i].checks[k], &said);
        /* the grade's time without the experiments': how long they took is said to staff alone (below) */
        rep.seconds = _sl_monotonic_now() - start - experiment_cost.seconds;
        if (experiments)
            fprintf(stderr, "shadowlab-grade: experiments (staff only): %d runs for %d failed checks (%d functions "
                            "differing from the solutions'), %.0f s%s%s\n", experiment_cost.runs, experiment_cost.checks,
                    experiment_cost.functions, experiment_cost.seconds,
                    experiment_cost.budget_spent ? "; the budget ran out: the checks not answered keep the probes' "
                                                   "ranking" : "",
                    experiment_cost.unmade ? "; some experiments could not be made (a copy of the lab or a runner's "
                                             "link failed): their checks keep the probes' ranking" : "");
        printf("shadowlab-grade: %s labs (%s), %d cases%s\n", rep.labs_kind, rep.labs_dir, count,
               o.isolate ? ", each lab isolated (the solutions stand in for the labs it builds on, the handout's "
                              "stubs for the others)" : "");
        printf("shadowlab-grade: sandbox: %s\n", rep.sandbox);
        if (rep.self_check) printf("shadowlab-grade: %s\n", rep.self_check);
        if (!o.update) printf("shadowlab-grade: compiler: %s\n", compiler);
        if (o.hidden)
            snprintf(rep.case_set, sizeof rep.case_set, "hidden variants of the public cases, seed %s", o.seed);
        rep.hidden = o.hidden;
        if (o.hidden)
            printf("shadowlab-grade: hidden cases: variants of the public ones drawn from seed %s; references rendered "
                   "from the solutions for this run\n", o.seed);
        /* what a runner said it rendered with: its text, on this one line */
        const char *backend = rep.backend[0] ? rep.backend : "(no runner started)", *renderer = rep.renderer[0] ? rep.renderer : "-";
        fputs("shadowlab-grade: rendered with ", stdout);
        sl_utf8_write(stdout, backend, strlen(backend), 0);
        fputs(": ", stdout);
        sl_utf8_write(stdout, renderer, strlen(renderer), 0);
        fputc('\n', stdout);
        if (o.backend == SL_BACKEND_WINDOW)
            printf("shadowlab-grade: SELF-CHECK: rendered in hidden windows with this computer's OpenGL, not the "
                   "course's renderer. It tells you what to fix; your grade comes from the course's own grader.\n");
        fflush(stdout);
        _sl_phase = "writing the reports";
        bool reports_ok = _sl_write_reports(&o, &rep);
        sl_report_print(&rep, stdout, isatty(1));
        _sl_phase = "freeing the grade, after the reports were written";
        if (reference_problem || rep.problem_count || !reports_ok || rep.interrupted) status = SL_EXIT_ERROR;
        else if (!sl_report_full_marks(&rep)) status = rep.no_lab_file ? SL_EXIT_NO_LAB_FILE : SL_EXIT_FAILED;
        for (int i = 0; i < count; i++)
            for (int k = 0; k < cases[i].check_count; k++) sl_image_free(&graded[i].checks[k].diff);
    }
    for (int i = 0; i < count; i++) {
        sl_case_result_free(&results[i]);
        for (int k = 0; k < SL_CASE_MAX_CHECKS; k++) sl_reference_free(&refs[i * SL_CASE_MAX_CHECKS + k]);
    }
    const char *debug = getenv("SHADOWLAB_GRADE_DEBUG");
    if (debug && debug[0] && strcmp(debug, "0") != 0 && !o.update)
        fprintf(stderr, "shadowlab-grade: debug: reference cache %s; image module loaded: %s\n", reference_cache_state,
                _sl_image_module_mapped());
    return status;
}

static void _sl_say_fault(const char *text) {
    for (size_t n = strlen(text); n > 0;) {
        ssize_t w = write(STDERR_FILENO, text, n);
        if (w <= 0) return;
        text += w;
        n -= (size_t)w;
    }
}

/* A crash of the grader's own (its code, or a library it loads, as in
 * teardown) is the staff's problem: said with its cause, exit 2, never a
 * status a script does not know (128 + the signal). Only async-signal-safe
 * calls here. */
static void _sl_on_fault(int sig) {
    const char *name = sig == SIGSEGV ? "SIGSEGV (a bad memory access)" : sig == SIGBUS ? "SIGBUS (a bad memory access)"
                     : sig == SIGABRT ? "SIGABRT (an abort)" : sig == SIGFPE ? "SIGFPE (an arithmetic fault)"
                     : sig == SIGILL ? "SIGILL (an illegal instruction)" : sig == SIGSYS ? "SIGSYS (a bad system call)"
                     : "SIGTRAP (a trap)";
    _sl_say_fault("\nshadowlab-grade: internal error: ");
    _sl_say_fault(name);
    _sl_say_fault(" while ");
    _sl_say_fault(_sl_phase);
    _sl_say_fault(" (a problem on the staff's side, not the submission's: grade again; if it stays, report it with "
                  "this line)\n");
    _exit(SL_EXIT_ERROR);
}

int sl_grader_main(int argc, char **argv) {
    struct sigaction sa = {.sa_handler = _sl_on_signal};
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    struct sigaction fault = {.sa_handler = _sl_on_fault, .sa_flags = SA_RESETHAND};
    sigemptyset(&fault.sa_mask);
    static const int faults[] = {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGSYS, SIGTRAP};
    for (size_t i = 0; i < sizeof faults / sizeof faults[0]; i++) sigaction(faults[i], &fault, NULL);
    sl_sandbox sandbox = {0};
    char isolation_root[64] = "";
    sl_hidden hidden = {0};
    _sl_phase = "grading";
    int status = _sl_grade(argc, argv, &sandbox, isolation_root, &hidden);
    _sl_phase = "closing the sandbox and removing its folders";
    sl_sandbox_close(&sandbox);
    _sl_remove_isolation_trees(isolation_root);
    sl_hidden_close(&hidden);
    /* Out without the libraries' exit handlers (the image module's C++
     * destructors): what they would free goes with the process anyway, and a
     * fault of theirs must not turn a finished grade's status into another. */
    _sl_phase = "exiting, after the reports were written";
    fflush(NULL);
    _exit(status);
}
