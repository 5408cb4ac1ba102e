#define _POSIX_C_SOURCE 200809L
#include "sl_gradebook.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sl_files.h"
#include "sl_json.h"
#include "sl_params.h"
#include "sl_report.h"
#include "sl_roster.h"

#define _SL_MAX_SUBMISSIONS 20000
#define _SL_NOTE_MAX 400
/* A grade that stopped on the staff's side (staging, extraction, the compile
 * fence, no process, memory or disk for it, a bad reference, ...): no score of
 * the student's, whatever the report holds so far, so no partial total is
 * taken for a grade, and never "not implemented" or "no lab file". */
#define _SL_STAFF_PROBLEM "staff problem"

typedef struct _sl_row {
    char name[128];
    char student[160], student_id[64]; /* from a bulk download's names (student.json), else "" */
    bool late;                         /* the download marked the submission late (Canvas) */
    char seed[32], options[640];       /* what the grade was made with (results.json) */
    char status[32];
    bool have_lab[SL_LAB_MAX + 1];
    double lab[SL_LAB_MAX + 1];
    bool have_totals;
    double bonus, total, max;
    char content[72];                  /* the sha256 of what was graded (content.sha256) */
    char student_note[_SL_NOTE_MAX];   /* what the batch says of it (a renamed submission, an older upload left out) */
    char note[_SL_NOTE_MAX];
} _sl_row;

static int _sl_by_name(const void *a, const void *b) { return strcmp(((const _sl_row *)a)->name, ((const _sl_row *)b)->name); }

/* A submission's folder name as the batch makes it: letters, digits, '.', '_', '-'. */
static bool _sl_submission_name(const char *name) {
    if (!name[0] || name[0] == '.' || strlen(name) >= 128) return false;
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') || *p == '.' ||
              *p == '_' || *p == '-'))
            return false;
    return true;
}

static bool _sl_exists(const char *path) {
    struct stat st;
    return stat(path, &st) == 0;
}

/* The first line of a small file, or "". */
static void _sl_first_line(const char *path, char *out, size_t n) {
    out[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    if (fgets(out, (int)n, f)) out[strcspn(out, "\r\n")] = '\0';
    fclose(f);
}

/* Who handed the submission in, when grade-batch took it from a bulk
 * download: DIR/<submission>/student.json {"name", "id", "late"}. */
static void _sl_read_student(const char *dir, _sl_row *row) {
    char path[1400], err[1200];
    snprintf(path, sizeof path, "%s/%s/student.json", dir, row->name);
    if (!_sl_exists(path)) return;
    cJSON *json = sl_json_load_file(path, "student", err, sizeof err);
    if (!json) return;
    const char *name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "name"));
    const char *id = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "id"));
    snprintf(row->student, sizeof row->student, "%s", name ? name : "");
    snprintf(row->student_id, sizeof row->student_id, "%s", id ? id : "");
    row->late = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(json, "late"));
    const char *note = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "note"));
    snprintf(row->student_note, sizeof row->student_note, "%s", note ? note : "");
    cJSON_Delete(json);
}

/* A staff problem's note: the cause the batch found (DIR/<submission>/problem), else `otherwise`. */
static void _sl_row_staff_problem(const char *dir, _sl_row *row, const char *otherwise) {
    char path[1400];
    snprintf(row->status, sizeof row->status, "%s", _SL_STAFF_PROBLEM);
    snprintf(path, sizeof path, "%s/%s/problem", dir, row->name);
    _sl_first_line(path, row->note, sizeof row->note);
    if (!row->note[0]) snprintf(row->note, sizeof row->note, "%s", otherwise);
}

static void _sl_read_row(const char *dir, _sl_row *row) {
    char path[1400], status_text[32];
    _sl_read_student(dir, row);
    snprintf(path, sizeof path, "%s/%s/content.sha256", dir, row->name);
    _sl_first_line(path, row->content, sizeof row->content);
    snprintf(path, sizeof path, "%s/%s/status", dir, row->name);
    if (!_sl_exists(path)) {
        snprintf(row->status, sizeof row->status, "not finished");
        snprintf(row->note, sizeof row->note, "interrupted: the next batch run grades it again");
        return;
    }
    _sl_first_line(path, status_text, sizeof status_text);
    snprintf(path, sizeof path, "%s/%s/report/results.json", dir, row->name);
    char err[1200];
    cJSON *json = _sl_exists(path) ? sl_json_load_file(path, "results", err, sizeof err) : NULL;
    char otherwise[300];
    if (!json) {
        snprintf(otherwise, sizeof otherwise, "no report (grade exit status %s): see %s/grade.log",
                 status_text[0] ? status_text : "?", row->name);
        _sl_row_staff_problem(dir, row, otherwise);
        return;
    }
    /* 0 full marks, 1 checks failed, 3 no lab file: the student's grade; anything else the staff's */
    bool staff = strcmp(status_text, "0") != 0 && strcmp(status_text, "1") != 0 && strcmp(status_text, "3") != 0;
    const char *options = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "options"));
    const char *seed = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "seed"));
    snprintf(row->options, sizeof row->options, "%s", options ? options : "");
    snprintf(row->seed, sizeof row->seed, "%s", seed ? seed : "");
    const cJSON *labs = cJSON_GetObjectItemCaseSensitive(json, "lab_scores"), *lab;
    cJSON_ArrayForEach(lab, labs) {
        const cJSON *number = cJSON_GetObjectItemCaseSensitive(lab, "lab");
        const cJSON *score = cJSON_GetObjectItemCaseSensitive(lab, "score");
        if (cJSON_IsNumber(number) && cJSON_IsNumber(score) && number->valueint >= 1 && number->valueint <= SL_LAB_MAX) {
            row->have_lab[number->valueint] = true;
            row->lab[number->valueint] = score->valuedouble;
        }
    }
    const cJSON *score = cJSON_GetObjectItemCaseSensitive(json, "score");
    const cJSON *max = cJSON_GetObjectItemCaseSensitive(json, "max_score");
    const cJSON *bonus = cJSON_GetObjectItemCaseSensitive(json, "bonus");
    row->have_totals = cJSON_IsNumber(score) && cJSON_IsNumber(max);
    if (row->have_totals) {
        row->bonus = cJSON_IsNumber(bonus) ? bonus->valuedouble : 0;
        row->max = max->valuedouble;
        /* the grade's own total (its --bonus policy), so the gradebook says what the student was told */
        const cJSON *total = cJSON_GetObjectItemCaseSensitive(json, "total");
        sl_bonus_policy policy = SL_BONUS_APART;
        const char *policy_name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "bonus_policy"));
        if (policy_name) sl_bonus_policy_parse(policy_name, &policy);
        row->total = cJSON_IsNumber(total) ? total->valuedouble
                                           : sl_bonus_total(policy, score->valuedouble, row->max, row->bonus);
    }
    const cJSON *problems = cJSON_GetObjectItemCaseSensitive(json, "problems");
    const char *build_error = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "build_error"));
    if (staff || cJSON_GetArraySize(problems) > 0) {
        const char *first = cJSON_GetStringValue(cJSON_GetArrayItem(problems, 0));
        if (first) snprintf(otherwise, sizeof otherwise, "%s", first);
        else snprintf(otherwise, sizeof otherwise, "grade exit status %s: see %s/grade.log", status_text, row->name);
        _sl_row_staff_problem(dir, row, otherwise);
    } else if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "built"))) {
        snprintf(row->status, sizeof row->status, "did not build");
        snprintf(row->note, sizeof row->note, "%s", build_error ? build_error : "");
    } else if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "complete"))) {
        snprintf(row->status, sizeof row->status, "incomplete");
        snprintf(row->note, sizeof row->note, "the grader was stopped before it finished");
    } else if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(json, "no_lab_file")) || strcmp(status_text, "3") == 0) {
        /* an empty upload, a text entry, only links: graded as the stubs, and said so */
        const char *first = cJSON_GetStringValue(
            cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(json, "submission_notes"), 0));
        snprintf(row->status, sizeof row->status, "no lab file");
        snprintf(row->note, sizeof row->note, "%s", first ? first : "no lab file in the submission: see its report");
    } else {
        snprintf(row->status, sizeof row->status, "graded");
        /* graded per lab: a lab that did not build is named, the others have their grades */
        if (build_error) snprintf(row->note, sizeof row->note, "%s", build_error);
    }
    if (strcmp(row->status, _SL_STAFF_PROBLEM) == 0) {
        memset(row->have_lab, 0, sizeof row->have_lab);
        row->have_totals = false;
    }
    cJSON_Delete(json);
}

/* One CSV field, defused for spreadsheets (sl_csv_field). */
static void _sl_field(FILE *f, const char *text, bool first) { sl_csv_field(f, text, first); }

static void _sl_number(FILE *f, bool have, double v) {
    char text[32] = "";
    if (have) snprintf(text, sizeof text, "%g", v);
    _sl_field(f, text, false);
}

static bool _sl_roster_rows(const char *dir, _sl_row *rows, int *count, const sl_gradebook_roster *lms, char *err,
                            size_t n);
/* DIR/gradebook.json: the rows' count and the staff problems, each with its
 * cause, for a script to act on (grade again, or tell the staff); and each
 * row's submission, student and status. */
static bool _sl_write_json(const char *dir, const _sl_row *rows, int count, char *err, size_t n) {
    cJSON *root = cJSON_CreateObject(), *problems = cJSON_CreateArray();
    cJSON_AddNumberToObject(root, "rows", count);
    for (int i = 0; i < count; i++) {
        if (strcmp(rows[i].status, _SL_STAFF_PROBLEM) != 0) continue;
        cJSON *p = cJSON_CreateObject();
        cJSON_AddStringToObject(p, "submission", rows[i].name);
        cJSON_AddStringToObject(p, "student", rows[i].student);
        cJSON_AddStringToObject(p, "student_id", rows[i].student_id);
        cJSON_AddStringToObject(p, "cause", rows[i].note);
        cJSON_AddItemToArray(problems, p);
    }
    cJSON_AddItemToObject(root, "staff_problems", problems);
    /* every row's student and status by submission: the class report names students as the gradebook does */
    cJSON *students = cJSON_AddArrayToObject(root, "students");
    for (int i = 0; i < count; i++) {
        cJSON *s = cJSON_CreateObject();
        cJSON_AddStringToObject(s, "submission", rows[i].name);
        cJSON_AddStringToObject(s, "student", rows[i].student);
        cJSON_AddStringToObject(s, "student_id", rows[i].student_id);
        cJSON_AddStringToObject(s, "status", rows[i].status);
        cJSON_AddItemToArray(students, s);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    char path[1200];
    snprintf(path, sizeof path, "%s/gradebook.json", dir);
    sl_atomic_file file;
    bool ok = text && sl_atomic_open(&file, path, err, n);
    if (ok) {
        fputs(text, file.f);
        fputc('\n', file.f);
        ok = sl_atomic_commit(&file, err, n);
    } else if (!text) {
        snprintf(err, n, "out of memory");
    }
    free(text);
    return ok;
}

bool sl_gradebook_write(const char *dir, const char *csv_path, char *err, size_t n) {
    return sl_gradebook_write_roster(dir, csv_path, NULL, err, n);
}

bool sl_gradebook_write_roster(const char *dir, const char *csv_path, const sl_gradebook_roster *lms, char *err,
                               size_t n) {
    DIR *d = opendir(dir);
    if (!d) {
        snprintf(err, n, "%s: cannot open the batch folder", dir);
        return false;
    }
    _sl_row *rows = calloc(_SL_MAX_SUBMISSIONS, sizeof *rows);
    if (!rows) {
        closedir(d);
        snprintf(err, n, "out of memory");
        return false;
    }
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < _SL_MAX_SUBMISSIONS) {
        char path[1400];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (!_sl_submission_name(e->d_name) || stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) continue;
        snprintf(rows[count].name, sizeof rows[count].name, "%s", e->d_name);
        count++;
    }
    closedir(d);
    qsort(rows, (size_t)count, sizeof rows[0], _sl_by_name);
    bool labs[SL_LAB_MAX + 1] = {false}, any = false;
    for (int i = 0; i < count; i++) {
        _sl_read_row(dir, &rows[i]);
        for (int lab = 1; lab <= SL_LAB_MAX; lab++) {
            labs[lab] |= rows[i].have_lab[lab];
            any |= rows[i].have_lab[lab];
        }
    }
    if (lms && !_sl_roster_rows(dir, rows, &count, lms, err, n)) {
        free(rows);
        return false;
    }
    for (int lab = 1; !any && lab <= SL_LAB_COUNT; lab++) labs[lab] = sl_lab_folder(lab) != NULL;

    sl_atomic_file file;
    if (!sl_atomic_open(&file, csv_path, err, n)) {
        free(rows);
        return false;
    }
    FILE *f = file.f;
    _sl_field(f, "submission", true);
    _sl_field(f, "student", false);
    _sl_field(f, "student_id", false);
    _sl_field(f, "late", false);
    _sl_field(f, "status", false);
    for (int lab = 1; lab <= SL_LAB_MAX; lab++) {
        char column[16];
        snprintf(column, sizeof column, "lab%d", lab);
        if (labs[lab]) _sl_field(f, column, false);
    }
    _sl_field(f, "bonus", false);
    _sl_field(f, "total", false);
    _sl_field(f, "max", false);
    _sl_field(f, "seed", false);
    _sl_field(f, "options", false);
    _sl_field(f, "content", false);
    _sl_field(f, "note", false);
    fputc('\n', f);
    for (int i = 0; i < count; i++) {
        const _sl_row *r = &rows[i];
        _sl_field(f, r->name, true);
        _sl_field(f, r->student, false);
        _sl_field(f, r->student_id, false);
        _sl_field(f, r->late ? "late" : "", false);
        _sl_field(f, r->status, false);
        for (int lab = 1; lab <= SL_LAB_MAX; lab++)
            if (labs[lab]) _sl_number(f, r->have_lab[lab], r->lab[lab]);
        _sl_number(f, r->have_totals, r->bonus);
        _sl_number(f, r->have_totals, r->total);
        _sl_number(f, r->have_totals, r->max);
        _sl_field(f, r->seed, false);
        _sl_field(f, r->options, false);
        _sl_field(f, r->content, false);
        char note[2 * _SL_NOTE_MAX + 4];
        snprintf(note, sizeof note, "%s%s%s", r->student_note, r->student_note[0] && r->note[0] ? "; " : "", r->note);
        _sl_field(f, note, false);
        fputc('\n', f);
    }
    bool ok = sl_atomic_commit(&file, err, n);
    if (ok) ok = _sl_write_json(dir, rows, count, err, n);
    free(rows);
    return ok;
}

/* ---- with the LMS's roster (--roster): its names and ids, and a row for each student without a submission ---- */

/* The LMS a submission came from, as grade-batch wrote it in student.json ("Canvas (...)", "Moodle (...)"). */
static bool _sl_from_lms(const char *dir, const char *submission, const char *lms) {
    char path[1400], err[1200];
    snprintf(path, sizeof path, "%s/%s/student.json", dir, submission);
    if (!_sl_exists(path)) return false;
    cJSON *json = sl_json_load_file(path, "student", err, sizeof err);
    const char *from = json ? cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "from")) : NULL;
    bool same = from && strncmp(from, lms, strlen(lms)) == 0;
    cJSON_Delete(json);
    return same;
}

/* Matched by the LMS id a bulk download carried, never by a name; a submission whose
 * id is not on the roster keeps its row, with a note that says so. */
static bool _sl_roster_rows(const char *dir, _sl_row *rows, int *count, const sl_gradebook_roster *lms, char *err,
                            size_t n) {
    const sl_roster *roster = lms->roster;
    int students = sl_roster_count(roster), submissions = *count, strays = 0;
    bool *seen = calloc((size_t)students + 1, sizeof *seen);
    if (!seen) {
        snprintf(err, n, "out of memory");
        return false;
    }
    const char *kind = sl_roster_kind_name(sl_roster_kind_of(roster));
    for (int i = 0; i < submissions; i++) {
        _sl_row *r = &rows[i];
        bool same_lms = r->student_id[0] && _sl_from_lms(dir, r->name, kind);
        int s = same_lms ? sl_roster_find(roster, r->student_id) : -1;
        if (s < 0) {
            char note[_SL_NOTE_MAX], why[200];
            if (!r->student_id[0]) snprintf(why, sizeof why, "no LMS id: not from a bulk download");
            else if (!same_lms) snprintf(why, sizeof why, "id '%s', not from a %s download", r->student_id, kind);
            else snprintf(why, sizeof why, "%s id '%s'", kind, r->student_id);
            snprintf(note, sizeof note, "%s", r->note);
            snprintf(r->note, sizeof r->note, "%s (%s)%s%s", SL_ROSTER_NOT_ON_ROSTER, why, note[0] ? ": " : "", note);
            fprintf(stderr, "shadowlab-grade: %s is not on the roster (%s): its row is kept\n", r->name, why);
            strays++;
            continue;
        }
        seen[s] = true;
        snprintf(r->student, sizeof r->student, "%s", sl_roster_name(roster, s));
        if (lms->have_due) {
            int late = sl_roster_late(roster, s, lms->due, err, n);
            if (late < 0) {
                free(seen);
                return false;
            }
            r->late = late;
        }
    }
    for (int s = 0; s < students; s++) {
        if (seen[s]) continue;
        if (*count >= _SL_MAX_SUBMISSIONS) {
            snprintf(err, n, "more than %d rows", _SL_MAX_SUBMISSIONS);
            free(seen);
            return false;
        }
        _sl_row *r = &rows[(*count)++];
        memset(r, 0, sizeof *r);
        snprintf(r->student, sizeof r->student, "%s", sl_roster_name(roster, s));
        snprintf(r->student_id, sizeof r->student_id, "%s", sl_roster_id(roster, s));
        snprintf(r->status, sizeof r->status, "no submission");
    }
    if (strays)
        fprintf(stderr, "shadowlab-grade: %d submission(s) not on the roster: see the gradebook's notes\n", strays);
    free(seen);
    return true;
}
