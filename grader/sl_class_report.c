#define _POSIX_C_SOURCE 200809L
#include "sl_class_report.h"

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sl_files.h"
#include "sl_html.h"
#include "sl_json.h"
#include "sl_params.h"

#define _SL_BINS 11 /* 0-9%, 10-19%, ..., 90-99%, and full marks */

typedef struct _sl_diagnosis {
    char id[72], text[320];
    int students, last_student;
    int lab;              /* the first lab it was seen in */
    char where[4][200];   /* checks it was seen in, the first few */
    int where_count, where_more;
} _sl_diagnosis;

typedef struct _sl_check {
    char name[200];       /* "case / check" */
    int lab;
    double points;
    bool bonus;
    int graded, failed;   /* students graded on it, and failing it */
    /* its diagnoses: index into the table and students, the top few kept by count */
    int diagnosis[8], diagnosis_students[8], diagnosis_count;
} _sl_check;

typedef struct _sl_class {
    _sl_diagnosis *diagnoses;
    int diagnosis_count, diagnosis_cap;
    int *diagnosis_slots;  /* open addressing on the id: index + 1, 0 free */
    int slot_count;
    _sl_check *checks;
    int check_count, check_cap;
    int students;          /* counted */
    int did_not_build, no_lab_file, problems, unfinished;
    /* the staff problems, named (the first _SL_NAMED of them): not the students' mistakes */
    char problem_names[32][128], problem_causes[32][240];
    int bins[SL_LAB_MAX + 1][_SL_BINS], total_bins[_SL_BINS];
    bool lab_seen[SL_LAB_MAX + 1];
    double lab_max[SL_LAB_MAX + 1], lab_sum[SL_LAB_MAX + 1], total_sum, total_max;
    char options[640];
    int option_sets;       /* different options among the counted reports */
} _sl_class;

static uint32_t _sl_hash(const char *s) {
    uint32_t h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

static _sl_diagnosis *_sl_diagnosis_of(_sl_class *k, const char *id, const char *text, int lab) {
    if (k->diagnosis_count * 2 >= k->slot_count) { /* grow the slots, and place every id again */
        int slots = k->slot_count ? k->slot_count * 2 : 1024;
        int *table = calloc((size_t)slots, sizeof *table);
        if (!table) return NULL;
        for (int i = 0; i < k->diagnosis_count; i++) {
            uint32_t h = _sl_hash(k->diagnoses[i].id) % (uint32_t)slots;
            while (table[h]) h = (h + 1) % (uint32_t)slots;
            table[h] = i + 1;
        }
        free(k->diagnosis_slots);
        k->diagnosis_slots = table;
        k->slot_count = slots;
    }
    uint32_t h = _sl_hash(id) % (uint32_t)k->slot_count;
    while (k->diagnosis_slots[h]) {
        _sl_diagnosis *d = &k->diagnoses[k->diagnosis_slots[h] - 1];
        if (strcmp(d->id, id) == 0) return d;
        h = (h + 1) % (uint32_t)k->slot_count;
    }
    if (k->diagnosis_count == k->diagnosis_cap) {
        int cap = k->diagnosis_cap ? k->diagnosis_cap * 2 : 256;
        _sl_diagnosis *more = realloc(k->diagnoses, sizeof *more * (size_t)cap);
        if (!more) return NULL;
        k->diagnoses = more;
        k->diagnosis_cap = cap;
    }
    _sl_diagnosis *d = &k->diagnoses[k->diagnosis_count];
    memset(d, 0, sizeof *d);
    snprintf(d->id, sizeof d->id, "%s", id);
    snprintf(d->text, sizeof d->text, "%s", text);
    d->last_student = -1;
    d->lab = lab;
    k->diagnosis_slots[h] = ++k->diagnosis_count;
    return d;
}

/* Checks come in the same order in every report: a short linear look from the last one found. */
static _sl_check *_sl_check_of(_sl_class *k, const char *name, int lab, double points, bool bonus, int *hint) {
    for (int n = 0; n < k->check_count; n++) {
        int i = (*hint + n) % k->check_count;
        if (strcmp(k->checks[i].name, name) == 0) {
            *hint = i + 1;
            return &k->checks[i];
        }
    }
    if (k->check_count == k->check_cap) {
        int cap = k->check_cap ? k->check_cap * 2 : 256;
        _sl_check *more = realloc(k->checks, sizeof *more * (size_t)cap);
        if (!more) return NULL;
        k->checks = more;
        k->check_cap = cap;
    }
    _sl_check *c = &k->checks[k->check_count++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->lab = lab;
    c->points = points;
    c->bonus = bonus;
    *hint = k->check_count;
    return c;
}

static int _sl_bin(double score, double max) {
    if (max <= 0) return 0;
    double share = score / max;
    if (share >= 1 - 1e-9) return _SL_BINS - 1;
    int bin = (int)(share * 10);
    return bin < 0 ? 0 : bin > _SL_BINS - 2 ? _SL_BINS - 2 : bin;
}

static void _sl_count_check(_sl_class *k, _sl_check *c, int student, const cJSON *jk) {
    c->graded++;
    if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(jk, "passed"))) return;
    c->failed++;
    const char *id = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "diagnosis"));
    const char *text = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "diagnosis_text"));
    if (!id || !id[0]) return; /* a report from before diagnoses had ids */
    _sl_diagnosis *d = _sl_diagnosis_of(k, id, text ? text : id, c->lab);
    if (!d) return;
    if (d->last_student != student) {
        d->last_student = student;
        d->students++;
    }
    bool seen = false;
    for (int i = 0; i < d->where_count; i++) seen |= strcmp(d->where[i], c->name) == 0;
    if (!seen && d->where_count < 4) snprintf(d->where[d->where_count++], sizeof d->where[0], "%s", c->name);
    else if (!seen) d->where_more++;
    int index = (int)(d - k->diagnoses);
    for (int i = 0; i < c->diagnosis_count; i++)
        if (c->diagnosis[i] == index) {
            c->diagnosis_students[i]++;
            return;
        }
    if (c->diagnosis_count < 8) {
        c->diagnosis[c->diagnosis_count] = index;
        c->diagnosis_students[c->diagnosis_count++] = 1;
    }
}

static void _sl_count_report(_sl_class *k, int student, const cJSON *json) {
    const char *options = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "options"));
    if (k->students == 0) snprintf(k->options, sizeof k->options, "%s", options ? options : "");
    else if (strcmp(k->options, options ? options : "") != 0 && k->option_sets < 2) k->option_sets = 2;
    if (k->option_sets == 0) k->option_sets = 1;
    k->students++;
    const cJSON *lab;
    double total = 0, total_max = 0;
    cJSON_ArrayForEach(lab, cJSON_GetObjectItemCaseSensitive(json, "lab_scores")) {
        const cJSON *number = cJSON_GetObjectItemCaseSensitive(lab, "lab");
        const cJSON *score = cJSON_GetObjectItemCaseSensitive(lab, "score");
        const cJSON *max = cJSON_GetObjectItemCaseSensitive(lab, "max_score");
        if (!cJSON_IsNumber(number) || !cJSON_IsNumber(score) || !cJSON_IsNumber(max)) continue;
        int n = number->valueint;
        if (n < 1 || n > SL_LAB_MAX) continue;
        k->lab_seen[n] = true;
        if (max->valuedouble > k->lab_max[n]) k->lab_max[n] = max->valuedouble;
        k->lab_sum[n] += score->valuedouble;
        k->bins[n][_sl_bin(score->valuedouble, max->valuedouble)]++;
        total += score->valuedouble;
        total_max += max->valuedouble;
    }
    k->total_sum += total;
    if (total_max > k->total_max) k->total_max = total_max;
    k->total_bins[_sl_bin(total, total_max)]++;
    int hint = 0;
    const cJSON *jc, *jk;
    cJSON_ArrayForEach(jc, cJSON_GetObjectItemCaseSensitive(json, "cases")) {
        const char *case_name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jc, "name"));
        const cJSON *lab_number = cJSON_GetObjectItemCaseSensitive(jc, "lab");
        if (!case_name || !cJSON_IsNumber(lab_number)) continue;
        cJSON_ArrayForEach(jk, cJSON_GetObjectItemCaseSensitive(jc, "checks")) {
            const char *check_name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "name"));
            const cJSON *points = cJSON_GetObjectItemCaseSensitive(jk, "max_points");
            if (!check_name) continue;
            char name[200];
            snprintf(name, sizeof name, "%s / %s", case_name, check_name);
            _sl_check *c = _sl_check_of(k, name, lab_number->valueint, cJSON_IsNumber(points) ? points->valuedouble : 0,
                                        cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(jk, "bonus")), &hint);
            if (c) _sl_count_check(k, c, student, jk);
        }
    }
}

static bool _sl_submission_name(const char *name) {
    if (!name[0] || name[0] == '.' || strlen(name) >= 128) return false;
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') || *p == '.' ||
              *p == '_' || *p == '-'))
            return false;
    return true;
}

/* A grade that stopped on the staff's side: named with its cause (the batch's
 * DIR/<submission>/problem, else the report's first problem), never counted
 * among the class's mistakes. */
static void _sl_class_staff_problem(_sl_class *k, const char *dir, const char *name, const cJSON *json) {
    int i = k->problems++;
    if (i >= 32) return;
    snprintf(k->problem_names[i], sizeof k->problem_names[i], "%s", name);
    char path[1400];
    snprintf(path, sizeof path, "%s/%s/problem", dir, name);
    k->problem_causes[i][0] = '\0';
    FILE *f = fopen(path, "r");
    if (f) {
        if (fgets(k->problem_causes[i], sizeof k->problem_causes[i], f))
            k->problem_causes[i][strcspn(k->problem_causes[i], "\r\n")] = '\0';
        fclose(f);
    }
    const char *first = cJSON_GetStringValue(cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(json, "problems"), 0));
    if (!k->problem_causes[i][0] && first) snprintf(k->problem_causes[i], sizeof k->problem_causes[i], "%s", first);
    else if (!k->problem_causes[i][0])
        snprintf(k->problem_causes[i], sizeof k->problem_causes[i], "%s: see %.100s/grade.log",
                 json ? "the grade stopped" : "no report", name);
}

/* Reads every finished submission of the batch. */
static bool _sl_gather(const char *dir, _sl_class *k, char *err, size_t n) {
    DIR *d = opendir(dir);
    if (!d) {
        snprintf(err, n, "%s: cannot open the batch folder", dir);
        return false;
    }
    struct dirent *e;
    int student = 0;
    while ((e = readdir(d))) {
        char path[1400];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (!_sl_submission_name(e->d_name) || stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) continue;
        snprintf(path, sizeof path, "%s/%s/status", dir, e->d_name);
        if (stat(path, &st) != 0) {
            k->unfinished++;
            continue;
        }
        char status[16] = "";
        FILE *sf = fopen(path, "r");
        if (sf) {
            if (!fgets(status, sizeof status, sf)) status[0] = '\0';
            status[strcspn(status, "\r\n")] = '\0';
            fclose(sf);
        }
        /* 0, 1, 3: the student's grade; any other status the staff's */
        bool staff = strcmp(status, "0") != 0 && strcmp(status, "1") != 0 && strcmp(status, "3") != 0;
        snprintf(path, sizeof path, "%s/%s/report/results.json", dir, e->d_name);
        char json_err[1200];
        cJSON *json = stat(path, &st) == 0 ? sl_json_load_file(path, "results", json_err, sizeof json_err) : NULL;
        if (!json || staff || cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(json, "problems")) > 0) {
            _sl_class_staff_problem(k, dir, e->d_name, json);
            cJSON_Delete(json);
            continue;
        }
        if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "built"))) k->did_not_build++;
        else if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(json, "no_lab_file"))) k->no_lab_file++;
        else if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "complete")))
            _sl_class_staff_problem(k, dir, e->d_name, json);
        else
            _sl_count_report(k, student++, json);
        cJSON_Delete(json);
    }
    closedir(d);
    return true;
}

static int _sl_by_students(const void *a, const void *b) {
    const _sl_diagnosis *x = a, *y = b;
    if (x->students != y->students) return y->students - x->students;
    if (x->lab != y->lab) return x->lab - y->lab;
    return strcmp(x->id, y->id);
}

/* One CSV field (RFC 4180), defused for spreadsheets as the gradebook's are. */
static void _sl_csv(FILE *f, const char *text, bool first) {
    if (!first) fputc(',', f);
    bool formula = text[0] && strchr("=+-@", text[0]);
    bool quote = formula || strpbrk(text, ",\"\n\r") != NULL;
    if (quote) fputc('"', f);
    if (formula) fputc('\'', f);
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        if (*p < 0x20 || *p == 0x7f) fputc(' ', f);
        else if (*p == '"') fputs("\"\"", f);
        else fputc(*p, f);
    }
    if (quote) fputc('"', f);
}

static const char *_sl_bin_name(int bin, char *out, size_t n) {
    if (bin == _SL_BINS - 1) snprintf(out, n, "100%%");
    else snprintf(out, n, "%d-%d%%", bin * 10, bin * 10 + 9);
    return out;
}

/* A histogram as an inline SVG: one bar per range, its count above it. */
static void _sl_histogram(FILE *f, const char *title, const int *bins, int students, double mean, double max) {
    int top = 1;
    for (int b = 0; b < _SL_BINS; b++) top = bins[b] > top ? bins[b] : top;
    const int bar = 34, height = 110, base = height + 18;
    fprintf(f, "<figure class=\"hist\"><figcaption>");
    sl_html_text(f, title);
    fprintf(f, " <span class=\"dim\">mean %.1f of %g</span></figcaption>\n", students ? mean / students : 0, max);
    fprintf(f, "<svg width=\"%d\" height=\"%d\" role=\"img\">", _SL_BINS * bar + 2, base + 16);
    for (int b = 0; b < _SL_BINS; b++) {
        int h = (int)((double)bins[b] / top * height + 0.5);
        char name[16];
        fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" class=\"%s\"><title>%s: %d</title></rect>",
                b * bar + 2, base - h, bar - 4, h, b == _SL_BINS - 1 ? "full" : "bar",
                _sl_bin_name(b, name, sizeof name), bins[b]);
        if (bins[b]) fprintf(f, "<text x=\"%d\" y=\"%d\" class=\"count\">%d</text>", b * bar + bar / 2, base - h - 3, bins[b]);
        fprintf(f, "<text x=\"%d\" y=\"%d\" class=\"axis\">%s</text>", b * bar + bar / 2, base + 12,
                b == _SL_BINS - 1 ? "100" : (const char *[]){"0", "10", "20", "30", "40", "50", "60", "70", "80", "90"}[b]);
    }
    fputs("</svg></figure>\n", f);
}

static void _sl_share_bar(FILE *f, int count, int of) {
    int width = of ? (int)(120.0 * count / of + 0.5) : 0;
    fprintf(f, "<td class=\"num\"><span class=\"share\"><span style=\"width:%dpx\"></span></span> %d of %d</td>", width,
            count, of);
}

static bool _sl_write_html(const _sl_class *k, const _sl_diagnosis *sorted, const char *path, char *err, size_t n) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    FILE *f = file.f;
    fputs("<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>shadowlab class report</title>\n<style>"
          "body{font-family:sans-serif;margin:2em;max-width:72em}td,th{padding:.2em .6em;text-align:left;"
          "vertical-align:top}th{border-bottom:1px solid #999}.num{white-space:nowrap}.dim{color:#666;font-weight:normal}"
          ".share{display:inline-block;width:120px;height:.8em;background:#eee;vertical-align:middle}"
          ".share span{display:block;height:100%;background:#c33}.id{color:#666;font-size:85%}"
          ".hist{display:inline-block;margin:.5em 1.5em .5em 0}.hist figcaption{font-weight:bold}"
          "rect.bar{fill:#5b7fb5}rect.full{fill:#3a9a4a}text{font-size:10px;text-anchor:middle}.axis{fill:#555}"
          "h2{margin-top:1.6em}</style></head><body>\n",
          f);
    fprintf(f, "<h1>Class report: %d submission%s graded</h1>\n<p>", k->students, k->students == 1 ? "" : "s");
    int others = k->did_not_build + k->no_lab_file + k->problems + k->unfinished;
    if (others) {
        fputs("Not counted below: ", f);
        const char *sep = "";
        if (k->did_not_build) fprintf(f, "%s%d did not build", sep, k->did_not_build), sep = ", ";
        if (k->no_lab_file) fprintf(f, "%s%d held no lab file", sep, k->no_lab_file), sep = ", ";
        if (k->problems) fprintf(f, "%s%d staff problem%s", sep, k->problems, k->problems == 1 ? "" : "s"), sep = ", ";
        if (k->unfinished) fprintf(f, "%s%d not graded yet", sep, k->unfinished);
        fputs(" (see the gradebook). ", f);
    }
    if (k->problems) {
        fputs("</p>\n<h2>Staff problems</h2>\n<p>Not the students' doing, and not counted in what they got wrong: "
              "fix each and grade it again.</p>\n<table>\n<tr><th>submission</th><th>cause</th></tr>\n",
              f);
        for (int i = 0; i < k->problems && i < 32; i++) {
            fputs("<tr><td>", f);
            sl_html_text(f, k->problem_names[i]);
            fputs("</td><td>", f);
            sl_html_text(f, k->problem_causes[i]);
            fputs("</td></tr>\n", f);
        }
        if (k->problems > 32) fprintf(f, "<tr><td colspan=\"2\">and %d more (see the gradebook)</td></tr>\n", k->problems - 32);
        fputs("</table>\n<p>", f);
    }
    if (k->option_sets > 1) fputs("<b>The reports were made with different grader options</b>: see the gradebook's options column. ", f);
    else if (k->options[0]) {
        fputs("Grader options: <code>", f);
        sl_html_text(f, k->options);
        fputs("</code>. ", f);
    }
    fputs("Each student counts once per diagnosis, however many checks it failed.</p>\n", f);

    fputs("<h2>Scores</h2>\n", f);
    for (int lab = 1; lab <= SL_LAB_MAX; lab++) {
        if (!k->lab_seen[lab]) continue;
        char title[96];
        snprintf(title, sizeof title, "Lab %d: %s", lab, sl_lab_title(lab));
        _sl_histogram(f, title, k->bins[lab], k->students, k->lab_sum[lab], k->lab_max[lab]);
    }
    _sl_histogram(f, "Total", k->total_bins, k->students, k->total_sum, k->total_max);
    fputs("<p class=\"dim\">Bars: students per range of the score, in % of the maximum; green: full marks.</p>\n", f);

    for (int pass = 0; pass < 2; pass++) {
        bool any = false;
        for (int i = 0; i < k->diagnosis_count; i++) {
            const _sl_diagnosis *d = &sorted[i];
            bool follows = strncmp(d->id, "follows-", 8) == 0;
            if (follows != (pass == 1)) continue;
            if (!any) {
                fputs(pass == 0 ? "<h2>What students got wrong</h2>\n<table>\n<tr><th>students</th><th>lab</th>"
                                  "<th>diagnosis</th><th>seen in</th></tr>\n"
                                : "<h2>Failures that follow from an earlier lab's</h2>\n<p class=\"dim\">A later lab "
                                  "built on a lab that failed: these go when that one is fixed.</p>\n<table>\n"
                                  "<tr><th>students</th><th>lab</th><th>diagnosis</th><th>seen in</th></tr>\n",
                      f);
                any = true;
            }
            fputs("<tr>", f);
            _sl_share_bar(f, d->students, k->students);
            fprintf(f, "<td>%d</td><td>", d->lab);
            sl_html_text(f, d->text);
            fputs(" <span class=\"id\">", f);
            sl_html_text(f, d->id);
            fputs("</span></td><td>", f);
            for (int w = 0; w < d->where_count; w++) {
                fputs(w ? "<br>" : "", f);
                sl_html_text(f, d->where[w]);
            }
            if (d->where_more) fprintf(f, "<br>and %d more", d->where_more);
            fputs("</td></tr>\n", f);
        }
        if (any) fputs("</table>\n", f);
        else if (pass == 0) fputs("<h2>What students got wrong</h2>\n<p>Nothing: every check passed.</p>\n", f);
    }

    fputs("<h2>Checks</h2>\n<table>\n<tr><th>failed</th><th>lab</th><th>case / check</th><th>most got</th></tr>\n", f);
    for (int lab = 1; lab <= SL_LAB_MAX; lab++)
        for (int i = 0; i < k->check_count; i++) {
            const _sl_check *c = &k->checks[i];
            if (c->lab != lab) continue;
            fputs("<tr>", f);
            _sl_share_bar(f, c->failed, c->graded);
            fprintf(f, "<td>%d</td><td>", c->lab);
            sl_html_text(f, c->name);
            fprintf(f, "%s</td><td>", c->bonus ? " (bonus)" : "");
            int top = -1;
            for (int j = 0; j < c->diagnosis_count; j++)
                if (top < 0 || c->diagnosis_students[j] > c->diagnosis_students[top]) top = j;
            if (top >= 0) {
                sl_html_text(f, k->diagnoses[c->diagnosis[top]].text);
                fprintf(f, " <span class=\"dim\">(%d)</span>", c->diagnosis_students[top]);
            }
            fputs("</td></tr>\n", f);
        }
    fputs("</table>\n</body></html>\n", f);
    return sl_atomic_commit(&file, err, n);
}

static bool _sl_write_csv(const _sl_class *k, const _sl_diagnosis *sorted, const char *path, char *err, size_t n) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    FILE *f = file.f;
    fputs("kind,lab,name,text,students,of\n", f);
    char lab[16], count[16], of[16];
    snprintf(of, sizeof of, "%d", k->students);
    for (int i = 0; i < k->diagnosis_count; i++) {
        const _sl_diagnosis *d = &sorted[i];
        snprintf(lab, sizeof lab, "%d", d->lab);
        snprintf(count, sizeof count, "%d", d->students);
        _sl_csv(f, "diagnosis", true), _sl_csv(f, lab, false), _sl_csv(f, d->id, false), _sl_csv(f, d->text, false);
        _sl_csv(f, count, false), _sl_csv(f, of, false);
        fputc('\n', f);
    }
    for (int i = 0; i < k->check_count; i++) {
        const _sl_check *c = &k->checks[i];
        int top = -1;
        for (int j = 0; j < c->diagnosis_count; j++)
            if (top < 0 || c->diagnosis_students[j] > c->diagnosis_students[top]) top = j;
        char graded[16];
        snprintf(lab, sizeof lab, "%d", c->lab);
        snprintf(count, sizeof count, "%d", c->failed);
        snprintf(graded, sizeof graded, "%d", c->graded);
        _sl_csv(f, "check", true), _sl_csv(f, lab, false), _sl_csv(f, c->name, false);
        _sl_csv(f, top >= 0 ? k->diagnoses[c->diagnosis[top]].text : "", false);
        _sl_csv(f, count, false), _sl_csv(f, graded, false);
        fputc('\n', f);
    }
    for (int i = 0; i < k->problems && i < 32; i++) {
        _sl_csv(f, "staff problem", true), _sl_csv(f, "", false), _sl_csv(f, k->problem_names[i], false);
        _sl_csv(f, k->problem_causes[i], false), _sl_csv(f, "", false), _sl_csv(f, "", false);
        fputc('\n', f);
    }
    for (int l = 1; l <= SL_LAB_MAX + 1; l++) {
        if (l <= SL_LAB_MAX && !k->lab_seen[l]) continue;
        const int *bins = l <= SL_LAB_MAX ? k->bins[l] : k->total_bins;
        if (l <= SL_LAB_MAX) snprintf(lab, sizeof lab, "%d", l);
        else snprintf(lab, sizeof lab, "total");
        for (int b = 0; b < _SL_BINS; b++) {
            char name[16];
            snprintf(count, sizeof count, "%d", bins[b]);
            _sl_csv(f, "score", true), _sl_csv(f, lab, false), _sl_csv(f, _sl_bin_name(b, name, sizeof name), false);
            _sl_csv(f, "", false), _sl_csv(f, count, false), _sl_csv(f, of, false);
            fputc('\n', f);
        }
    }
    return sl_atomic_commit(&file, err, n);
}

bool sl_class_report_write(const char *dir, char *err, size_t n) {
    _sl_class k = {0};
    bool ok = _sl_gather(dir, &k, err, n);
    _sl_diagnosis *sorted = NULL;
    if (ok && k.diagnosis_count) {
        sorted = malloc(sizeof *sorted * (size_t)k.diagnosis_count);
        if (!sorted) {
            snprintf(err, n, "out of memory");
            ok = false;
        } else {
            memcpy(sorted, k.diagnoses, sizeof *sorted * (size_t)k.diagnosis_count);
            qsort(sorted, (size_t)k.diagnosis_count, sizeof *sorted, _sl_by_students);
        }
    }
    char path[1200];
    if (ok) {
        snprintf(path, sizeof path, "%s/class-report.html", dir);
        ok = _sl_write_html(&k, sorted ? sorted : k.diagnoses, path, err, n);
    }
    if (ok) {
        snprintf(path, sizeof path, "%s/class-report.csv", dir);
        ok = _sl_write_csv(&k, sorted ? sorted : k.diagnoses, path, err, n);
    }
    free(sorted);
    free(k.diagnoses);
    free(k.diagnosis_slots);
    free(k.checks);
    return ok;
}
