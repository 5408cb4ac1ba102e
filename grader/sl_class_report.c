#define _POSIX_C_SOURCE 200809L
#include "sl_class_report.h"

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sl_diag.h"
#include "sl_files.h"
#include "sl_html.h"
#include "sl_json.h"
#include "sl_params.h"

#define _SL_BINS 11 /* 0-9%, 10-19%, ..., 90-99%, and full marks */

/* One diagnosis id seen under a mistake: the wording one check gave it. */
typedef struct _sl_wording {
    char id[72], text[320];
    int students, last_student;
    bool own;             /* the probe of the mistake's function said it: its own verdict, shown first */
    bool other_probe;     /* a probe of another function said it (its name leads the wording) */
} _sl_wording;

/* One mistake: the function the evidence names plus the kind of cause
 * (results.json's "cause"), or, where nothing names a function, one
 * diagnosis id. Every check that failed through it counts here once per student. */
typedef struct _sl_mistake {
    char key[96];         /* "slope_scaled_bias: wrong", or the diagnosis id */
    char function[64], kind[16];
    int lab;              /* the function's lab, else the first lab it was seen in */
    _sl_wording wordings[4];
    int wording_count, wording_more;
    int students, last_student;
    int *who, who_cap;    /* the students (index into the class's), in name order */
    char where[4][200];   /* checks it was seen in, the first few */
    int where_count, where_more;
    bool follows;         /* only ever a lead from an earlier lab's failure, naming no function */
} _sl_mistake;

typedef struct _sl_check {
    char name[200];       /* "case / check" */
    int lab;
    double points;
    bool bonus;
    int graded, failed;   /* students graded on it, and failing it */
    /* its mistakes: index into the table and students, the top few kept by count */
    int mistake[8], mistake_students[8], mistake_count;
} _sl_check;

/* A submission as the gradebook names it. */
typedef struct _sl_student {
    char submission[128];
    char name[200];       /* the gradebook's student, else the submission's name */
    const char *status;   /* its gradebook status: "graded" when counted */
    char cause[240];      /* a staff problem's */
} _sl_student;

/* The submissions not counted among the mistakes, by status. */
enum { _SL_NOT_BUILT, _SL_NO_LAB_FILE, _SL_INCOMPLETE, _SL_STAFF, _SL_UNFINISHED, _SL_APART };
static const char *const _sl_apart_status[_SL_APART] = {"did not build", "no lab file", "incomplete", "staff problem",
                                                        "not finished"};

typedef struct _sl_class {
    _sl_mistake *mistakes;
    int mistake_count, mistake_cap;
    int *mistake_slots;   /* open addressing on the key: index + 1, 0 free */
    int slot_count;
    _sl_check *checks;
    int check_count, check_cap;
    _sl_student *all;     /* every submission, in name order */
    int all_count;
    int *counted;         /* index into all, per counted student */
    int students;         /* counted */
    int apart[_SL_APART];
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

static _sl_mistake *_sl_mistake_of(_sl_class *k, const char *key, int lab) {
    if (k->mistake_count * 2 >= k->slot_count) { /* grow the slots, and place every key again */
        int slots = k->slot_count ? k->slot_count * 2 : 1024;
        int *table = calloc((size_t)slots, sizeof *table);
        if (!table) return NULL;
        for (int i = 0; i < k->mistake_count; i++) {
            uint32_t h = _sl_hash(k->mistakes[i].key) % (uint32_t)slots;
            while (table[h]) h = (h + 1) % (uint32_t)slots;
            table[h] = i + 1;
        }
        free(k->mistake_slots);
        k->mistake_slots = table;
        k->slot_count = slots;
    }
    uint32_t h = _sl_hash(key) % (uint32_t)k->slot_count;
    while (k->mistake_slots[h]) {
        _sl_mistake *m = &k->mistakes[k->mistake_slots[h] - 1];
        if (strcmp(m->key, key) == 0) return m;
        h = (h + 1) % (uint32_t)k->slot_count;
    }
    if (k->mistake_count == k->mistake_cap) {
        int cap = k->mistake_cap ? k->mistake_cap * 2 : 256;
        _sl_mistake *more = realloc(k->mistakes, sizeof *more * (size_t)cap);
        if (!more) return NULL;
        k->mistakes = more;
        k->mistake_cap = cap;
    }
    _sl_mistake *m = &k->mistakes[k->mistake_count];
    memset(m, 0, sizeof *m);
    snprintf(m->key, sizeof m->key, "%s", key);
    m->last_student = -1;
    m->lab = lab;
    m->follows = true;
    k->mistake_slots[h] = ++k->mistake_count;
    return m;
}

/* How well a wording says its mistake: the function's own probe's verdict, then
 * one not led by an earlier failure, then one no other function's probe named. */
static int _sl_wording_rank(const _sl_wording *w) {
    return (w->own ? 4 : 0) + (strncmp(w->id, "follows-", 8) != 0 ? 2 : 0) + (w->other_probe ? 0 : 1);
}

/* The wording a mistake is shown with: the best ranked, then the one most students got. */
static const _sl_wording *_sl_wording_of(const _sl_mistake *m) {
    const _sl_wording *best = NULL;
    for (int i = 0; i < m->wording_count; i++) {
        const _sl_wording *w = &m->wordings[i];
        int rank = _sl_wording_rank(w), best_rank = best ? _sl_wording_rank(best) : -1;
        if (rank > best_rank || (rank == best_rank && w->students > best->students)) best = w;
    }
    return best;
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

/* The words for a kind of cause. */
static const char *_sl_kind_words(const char *kind) {
    if (strcmp(kind, "wrong") == 0) return "wrong results";
    if (strcmp(kind, "stub") == 0) return "not implemented";
    if (strcmp(kind, "crash") == 0) return "crashed in it";
    if (strcmp(kind, "timeout") == 0) return "timed out in it";
    return kind;
}

static void _sl_count_check(_sl_class *k, _sl_check *c, int student, const cJSON *jk, bool probe,
                            uint32_t labs_not_built) {
    c->graded++;
    if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(jk, "passed"))) return;
    c->failed++;
    const char *id = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "diagnosis"));
    const char *text = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "diagnosis_text"));
    char built_id[32], built_text[64];
    if ((!id || !id[0]) && c->lab >= 1 && c->lab <= SL_LAB_MAX && ((labs_not_built >> c->lab) & 1u)) {
        /* a lab that did not compile in a submission graded per lab: its checks carry the compiler's error */
        snprintf(built_id, sizeof built_id, "lab%d-did-not-compile", c->lab);
        snprintf(built_text, sizeof built_text, "lab %d did not compile", c->lab);
        id = built_id, text = built_text;
    }
    if (!id || !id[0]) return; /* a report from before diagnoses had ids */
    /* the mistake: the function the evidence named and the kind of cause, else the diagnosis */
    const cJSON *cause = cJSON_GetObjectItemCaseSensitive(jk, "cause");
    const char *function = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(cause, "function"));
    const char *kind = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(cause, "kind"));
    char key[sizeof k->mistakes[0].key];
    bool named = function && function[0] && kind && kind[0] && strlen(function) < 64 && strlen(kind) < 16;
    if (named) snprintf(key, sizeof key, "%s: %s", function, kind);
    else snprintf(key, sizeof key, "%s", id);
    int lab = c->lab;
    const sl_probe_function *f = named ? sl_probe_find(function) : NULL;
    if (f) lab = f->lab;
    else if (named && sl_diag_function_lab(function) > 0) lab = sl_diag_function_lab(function);
    _sl_mistake *m = _sl_mistake_of(k, key, lab);
    if (!m) return;
    if (named && !m->function[0]) {
        snprintf(m->function, sizeof m->function, "%s", function);
        snprintf(m->kind, sizeof m->kind, "%s", kind);
    }
    m->follows &= !named && strncmp(id, "follows-", 8) == 0;
    if (m->last_student != student) {
        if (m->students == m->who_cap) {
            int cap = m->who_cap ? m->who_cap * 2 : 8;
            int *more = realloc(m->who, sizeof *more * (size_t)cap);
            if (!more) return;
            m->who = more;
            m->who_cap = cap;
        }
        m->who[m->students++] = student;
        m->last_student = student;
    }
    _sl_wording *w = NULL;
    for (int i = 0; i < m->wording_count && !w; i++)
        if (strcmp(m->wordings[i].id, id) == 0) w = &m->wordings[i];
    if (!w && m->wording_count < 4) {
        w = &m->wordings[m->wording_count++];
        snprintf(w->id, sizeof w->id, "%s", id);
        snprintf(w->text, sizeof w->text, "%s", text ? text : id);
        w->last_student = -1;
    } else if (!w) {
        m->wording_more++;
    }
    if (w && w->last_student != student) {
        w->last_student = student;
        w->students++;
    }
    /* a probe's wording leads with its function's name ("pcf_grid(): ...") */
    size_t len = named ? strlen(function) : 0;
    bool own = probe && named && text && strncmp(text, function, len) == 0 && text[len] == '(';
    if (w) w->own |= own, w->other_probe |= probe && !own;
    bool seen = false;
    for (int i = 0; i < m->where_count; i++) seen |= strcmp(m->where[i], c->name) == 0;
    if (!seen && m->where_count < 4) snprintf(m->where[m->where_count++], sizeof m->where[0], "%s", c->name);
    else if (!seen) m->where_more++;
    int index = (int)(m - k->mistakes);
    for (int i = 0; i < c->mistake_count; i++)
        if (c->mistake[i] == index) {
            c->mistake_students[i]++;
            return;
        }
    if (c->mistake_count < 8) {
        c->mistake[c->mistake_count] = index;
        c->mistake_students[c->mistake_count++] = 1;
    }
}

static void _sl_count_report(_sl_class *k, int student, const cJSON *json) {
    const char *options = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "options"));
    if (k->students == 0) snprintf(k->options, sizeof k->options, "%s", options ? options : "");
    else if (strcmp(k->options, options ? options : "") != 0 && k->option_sets < 2) k->option_sets = 2;
    if (k->option_sets == 0) k->option_sets = 1;
    k->students++;
    const cJSON *lab;
    uint32_t labs_not_built = 0;
    cJSON_ArrayForEach(lab, cJSON_GetObjectItemCaseSensitive(json, "labs_not_built")) {
        const cJSON *number = cJSON_GetObjectItemCaseSensitive(lab, "lab");
        if (cJSON_IsNumber(number) && number->valueint >= 1 && number->valueint <= SL_LAB_MAX)
            labs_not_built |= 1u << number->valueint;
    }
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
            const char *kind = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "kind"));
            if (c) _sl_count_check(k, c, student, jk, kind && strcmp(kind, "probe") == 0, labs_not_built);
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

/* A grade that stopped on the staff's side: its cause (the batch's
 * DIR/<submission>/problem, else the report's first problem), never counted
 * among the class's mistakes. */
static void _sl_staff_cause(const char *dir, _sl_student *s, const cJSON *json) {
    char path[1400];
    snprintf(path, sizeof path, "%s/%s/problem", dir, s->submission);
    s->cause[0] = '\0';
    FILE *f = fopen(path, "r");
    if (f) {
        if (fgets(s->cause, sizeof s->cause, f)) s->cause[strcspn(s->cause, "\r\n")] = '\0';
        fclose(f);
    }
    const char *first = cJSON_GetStringValue(cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(json, "problems"), 0));
    if (!s->cause[0] && first) snprintf(s->cause, sizeof s->cause, "%s", first);
    else if (!s->cause[0])
        snprintf(s->cause, sizeof s->cause, "%s: see %.100s/grade.log", json ? "the grade stopped" : "no report",
                 s->submission);
}

static int _sl_by_submission(const void *a, const void *b) {
    return strcmp(((const _sl_student *)a)->submission, ((const _sl_student *)b)->submission);
}

/* Each submission's student as the gradebook has them (DIR/gradebook.json, written
 * just before: a bulk download's name, or the roster's); else the submission's name. */
static void _sl_names(const char *dir, _sl_class *k) {
    for (int i = 0; i < k->all_count; i++)
        snprintf(k->all[i].name, sizeof k->all[i].name, "%s", k->all[i].submission);
    char path[1200], err[1200];
    struct stat st;
    snprintf(path, sizeof path, "%s/gradebook.json", dir);
    cJSON *json = stat(path, &st) == 0 ? sl_json_load_file(path, "gradebook", err, sizeof err) : NULL;
    const cJSON *row;
    cJSON_ArrayForEach(row, cJSON_GetObjectItemCaseSensitive(json, "students")) {
        const char *submission = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(row, "submission"));
        const char *student = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(row, "student"));
        if (!submission || !submission[0] || !student || !student[0]) continue;
        _sl_student key = {0};
        snprintf(key.submission, sizeof key.submission, "%s", submission);
        _sl_student *s = bsearch(&key, k->all, (size_t)k->all_count, sizeof *k->all, _sl_by_submission);
        if (s) snprintf(s->name, sizeof s->name, "%s", student);
    }
    cJSON_Delete(json);
}

/* Reads every submission of the batch, in name order: the finished ones
 * graded are counted, the others set apart by status as the gradebook's. */
static bool _sl_gather(const char *dir, _sl_class *k, char *err, size_t n) {
    DIR *d = opendir(dir);
    if (!d) {
        snprintf(err, n, "%s: cannot open the batch folder", dir);
        return false;
    }
    struct dirent *e;
    int cap = 0;
    while ((e = readdir(d))) {
        char path[1400];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (!_sl_submission_name(e->d_name) || stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) continue;
        if (k->all_count == cap) {
            cap = cap ? cap * 2 : 64;
            _sl_student *more = realloc(k->all, sizeof *more * (size_t)cap);
            if (!more) {
                closedir(d);
                snprintf(err, n, "out of memory");
                return false;
            }
            k->all = more;
        }
        _sl_student *s = &k->all[k->all_count++];
        memset(s, 0, sizeof *s);
        snprintf(s->submission, sizeof s->submission, "%s", e->d_name);
    }
    closedir(d);
    if (k->all_count) qsort(k->all, (size_t)k->all_count, sizeof *k->all, _sl_by_submission);
    _sl_names(dir, k);
    k->counted = calloc((size_t)k->all_count + 1, sizeof *k->counted);
    if (!k->counted) {
        snprintf(err, n, "out of memory");
        return false;
    }
    for (int i = 0; i < k->all_count; i++) {
        _sl_student *s = &k->all[i];
        char path[1400];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s/status", dir, s->submission);
        if (stat(path, &st) != 0) {
            s->status = _sl_apart_status[_SL_UNFINISHED];
            k->apart[_SL_UNFINISHED]++;
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
        snprintf(path, sizeof path, "%s/%s/report/results.json", dir, s->submission);
        char json_err[1200];
        cJSON *json = stat(path, &st) == 0 ? sl_json_load_file(path, "results", json_err, sizeof json_err) : NULL;
        int apart = -1; /* the gradebook's order of statuses (sl_gradebook.c) */
        if (!json || staff || cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(json, "problems")) > 0) {
            apart = _SL_STAFF;
            _sl_staff_cause(dir, s, json);
        } else if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "built"))) {
            apart = _SL_NOT_BUILT;
        } else if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(json, "complete"))) {
            apart = _SL_INCOMPLETE;
        } else if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(json, "no_lab_file")) || strcmp(status, "3") == 0) {
            apart = _SL_NO_LAB_FILE;
        }
        if (apart >= 0) {
            s->status = _sl_apart_status[apart];
            k->apart[apart]++;
        } else {
            s->status = "graded";
            k->counted[k->students] = i;
            _sl_count_report(k, k->students, json);
        }
        cJSON_Delete(json);
    }
    return true;
}

static int _sl_by_students(const void *a, const void *b) {
    const _sl_mistake *x = a, *y = b;
    if (x->students != y->students) return y->students - x->students;
    if (x->lab != y->lab) return x->lab - y->lab;
    return strcmp(x->key, y->key);
}

static void _sl_csv(FILE *f, const char *text, bool first) { sl_csv_field(f, text, first); }

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

/* Names, comma-separated, the first `most` of them. */
static void _sl_html_names(FILE *f, const _sl_class *k, const int *who, int count, bool counted, int most) {
    for (int i = 0; i < count && i < most; i++) {
        const _sl_student *s = &k->all[counted ? k->counted[who[i]] : who[i]];
        fputs(i ? ", " : "", f);
        fputs("<span title=\"", f);
        sl_html_text(f, s->submission);
        fputs("\">", f);
        sl_html_text(f, s->name);
        fputs("</span>", f);
    }
    if (count > most) fprintf(f, " and %d more (class-mistakes.csv)", count - most);
}

static bool _sl_write_html(const _sl_class *k, const _sl_mistake *sorted, const char *path, char *err, size_t n) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    FILE *f = file.f;
    fputs("<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>shadowlab class report</title>\n<style>"
          "body{font-family:sans-serif;margin:2em;max-width:80em}td,th{padding:.2em .6em;text-align:left;"
          "vertical-align:top}th{border-bottom:1px solid #999}.num{white-space:nowrap}.dim{color:#666;font-weight:normal}"
          ".share{display:inline-block;width:120px;height:.8em;background:#eee;vertical-align:middle}"
          ".share span{display:block;height:100%;background:#c33}.id{color:#666;font-size:85%}"
          ".who{font-size:90%;max-width:22em}"
          ".hist{display:inline-block;margin:.5em 1.5em .5em 0}.hist figcaption{font-weight:bold}"
          "rect.bar{fill:#5b7fb5}rect.full{fill:#3a9a4a}text{font-size:10px;text-anchor:middle}.axis{fill:#555}"
          "h2{margin-top:1.6em}</style></head><body>\n",
          f);
    fprintf(f, "<h1>Class report: %d submission%s graded</h1>\n", k->students, k->students == 1 ? "" : "s");
    int others = 0;
    for (int a = 0; a < _SL_APART; a++) others += k->apart[a];
    int *who = malloc(sizeof *who * ((size_t)k->all_count + 1));
    if (!who) {
        sl_atomic_abort(&file);
        snprintf(err, n, "out of memory");
        return false;
    }
    if (others) {
        fputs("<p>Not counted in what the class got wrong (the gradebook's notes say why):</p>\n<ul>\n", f);
        static const char *const said[_SL_APART][2] = {{"did not build", "did not build"},
                                                       {"held no lab file", "held no lab file"},
                                                       {"incomplete (the grader was stopped)", "incomplete (the grader was stopped)"},
                                                       {"staff problem (below)", "staff problems (below)"},
                                                       {"not graded yet", "not graded yet"}};
        for (int a = 0; a < _SL_APART; a++) {
            if (!k->apart[a]) continue;
            int count = 0;
            for (int i = 0; i < k->all_count; i++)
                if (k->all[i].status == _sl_apart_status[a]) who[count++] = i;
            fprintf(f, "<li><b>%d %s</b>: ", k->apart[a], said[a][k->apart[a] != 1]);
            _sl_html_names(f, k, who, count, false, 200);
            fputs("</li>\n", f);
        }
        fputs("</ul>\n", f);
    }
    if (k->apart[_SL_STAFF]) {
        fputs("<h2>Staff problems</h2>\n<p>Not the students' doing, and not counted in what they got wrong: "
              "fix each and grade it again.</p>\n<table>\n<tr><th>submission</th><th>student</th><th>cause</th></tr>\n",
              f);
        for (int i = 0; i < k->all_count; i++) {
            const _sl_student *s = &k->all[i];
            if (s->status != _sl_apart_status[_SL_STAFF]) continue;
            fputs("<tr><td>", f);
            sl_html_text(f, s->submission);
            fputs("</td><td>", f);
            sl_html_text(f, s->name);
            fputs("</td><td>", f);
            sl_html_text(f, s->cause);
            fputs("</td></tr>\n", f);
        }
        fputs("</table>\n", f);
    }
    fputs("<p>", f);
    if (k->option_sets > 1) fputs("<b>The reports were made with different grader options</b>: see the gradebook's options column. ", f);
    else if (k->options[0]) {
        fputs("Grader options: <code>", f);
        sl_html_text(f, k->options);
        fputs("</code>. ", f);
    }
    fputs("One row per mistake: the checks that failed through the same function and the same kind of cause (its "
          "probe's verdict, a lead from it, a stub, a crash or a time cut in it) are one row, each student counted "
          "once. Who made each: class-mistakes.csv (a row per student, a column per mistake).</p>\n",
          f);
    free(who);

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
        for (int i = 0; i < k->mistake_count; i++) {
            const _sl_mistake *m = &sorted[i];
            if (m->follows != (pass == 1)) continue;
            if (!any) {
                fputs(pass == 0 ? "<h2>What students got wrong</h2>\n<table>\n<tr><th>students</th><th>lab</th>"
                                  "<th>mistake</th><th>seen in</th><th>who</th></tr>\n"
                                : "<h2>Failures that follow from an earlier lab's</h2>\n<p class=\"dim\">A later lab "
                                  "built on a lab that failed: these go when that one is fixed.</p>\n<table>\n"
                                  "<tr><th>students</th><th>lab</th><th>mistake</th><th>seen in</th><th>who</th></tr>\n",
                      f);
                any = true;
            }
            const _sl_wording *shown = _sl_wording_of(m);
            fputs("<tr>", f);
            _sl_share_bar(f, m->students, k->students);
            fprintf(f, "<td>%d</td><td>", m->lab);
            sl_html_text(f, shown ? shown->text : m->key);
            if (shown && m->wording_count > 1) fprintf(f, " <span class=\"dim\">(%d)</span>", shown->students);
            if (m->function[0]) {
                fputs("<br><span class=\"id\">cause: <code>", f);
                sl_html_text(f, m->function);
                fputs("</code>, ", f);
                sl_html_text(f, _sl_kind_words(m->kind));
                fputs("</span>", f);
            } else {
                fputs(" <span class=\"id\">", f);
                sl_html_text(f, m->key);
                fputs("</span>", f);
            }
            /* the other wordings, each with its students: two verdicts on one function show apart here */
            for (int w = 0, other = 0; w < m->wording_count; w++) {
                if (&m->wordings[w] == shown) continue;
                fputs(other++ ? "; " : "<br><span class=\"dim\">also reported as: ", f);
                sl_html_text(f, m->wordings[w].text);
                fprintf(f, " (%d)", m->wordings[w].students);
                if (other == m->wording_count - 1) fputs("</span>", f);
            }
            if (m->wording_more) fprintf(f, " <span class=\"dim\">and %d more wordings</span>", m->wording_more);
            fputs("</td><td>", f);
            for (int w = 0; w < m->where_count; w++) {
                fputs(w ? "<br>" : "", f);
                sl_html_text(f, m->where[w]);
            }
            if (m->where_more) fprintf(f, "<br>and %d more", m->where_more);
            fputs("</td><td class=\"who\">", f);
            _sl_html_names(f, k, m->who, m->students, true, 60);
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
            for (int j = 0; j < c->mistake_count; j++)
                if (top < 0 || c->mistake_students[j] > c->mistake_students[top]) top = j;
            if (top >= 0) {
                const _sl_mistake *m = &k->mistakes[c->mistake[top]];
                const _sl_wording *shown = _sl_wording_of(m);
                sl_html_text(f, shown ? shown->text : m->key);
                fprintf(f, " <span class=\"dim\">(%d)</span>", c->mistake_students[top]);
            }
            fputs("</td></tr>\n", f);
        }
    fputs("</table>\n</body></html>\n", f);
    return sl_atomic_commit(&file, err, n);
}

/* Names for a CSV cell: "; " between them. */
static void _sl_csv_names(FILE *f, const _sl_class *k, const int *who, int count) {
    size_t size = 1;
    for (int i = 0; i < count; i++) size += strlen(k->all[k->counted[who[i]]].name) + 2;
    char *text = malloc(size);
    if (!text) {
        _sl_csv(f, "", false);
        return;
    }
    size_t used = 0;
    text[0] = '\0';
    for (int i = 0; i < count; i++)
        used += (size_t)snprintf(text + used, size - used, "%s%s", i ? "; " : "", k->all[k->counted[who[i]]].name);
    _sl_csv(f, text, false);
    free(text);
}

static bool _sl_write_csv(const _sl_class *k, const _sl_mistake *sorted, const char *path, char *err, size_t n) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    FILE *f = file.f;
    fputs("kind,lab,name,text,who,students,of\n", f);
    char lab[16], count[16], of[16];
    snprintf(of, sizeof of, "%d", k->students);
    for (int i = 0; i < k->mistake_count; i++) {
        const _sl_mistake *m = &sorted[i];
        const _sl_wording *shown = _sl_wording_of(m);
        snprintf(lab, sizeof lab, "%d", m->lab);
        snprintf(count, sizeof count, "%d", m->students);
        _sl_csv(f, m->follows ? "follows" : "mistake", true), _sl_csv(f, lab, false), _sl_csv(f, m->key, false);
        _sl_csv(f, shown ? shown->text : m->key, false);
        _sl_csv_names(f, k, m->who, m->students);
        _sl_csv(f, count, false), _sl_csv(f, of, false);
        fputc('\n', f);
    }
    for (int i = 0; i < k->check_count; i++) {
        const _sl_check *c = &k->checks[i];
        int top = -1;
        for (int j = 0; j < c->mistake_count; j++)
            if (top < 0 || c->mistake_students[j] > c->mistake_students[top]) top = j;
        const _sl_wording *shown = top >= 0 ? _sl_wording_of(&k->mistakes[c->mistake[top]]) : NULL;
        char graded[16];
        snprintf(lab, sizeof lab, "%d", c->lab);
        snprintf(count, sizeof count, "%d", c->failed);
        snprintf(graded, sizeof graded, "%d", c->graded);
        _sl_csv(f, "check", true), _sl_csv(f, lab, false), _sl_csv(f, c->name, false);
        _sl_csv(f, shown ? shown->text : "", false), _sl_csv(f, "", false);
        _sl_csv(f, count, false), _sl_csv(f, graded, false);
        fputc('\n', f);
    }
    /* the submissions not counted, each by name: the staff problems with their cause */
    for (int i = 0; i < k->all_count; i++) {
        const _sl_student *s = &k->all[i];
        if (strcmp(s->status, "graded") == 0) continue;
        _sl_csv(f, s->status, true), _sl_csv(f, "", false), _sl_csv(f, s->submission, false);
        _sl_csv(f, s->cause, false), _sl_csv(f, s->name, false), _sl_csv(f, "", false), _sl_csv(f, "", false);
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
            _sl_csv(f, "", false), _sl_csv(f, "", false), _sl_csv(f, count, false), _sl_csv(f, of, false);
            fputc('\n', f);
        }
    }
    return sl_atomic_commit(&file, err, n);
}

/* DIR/class-mistakes.csv: a row per submission, a column per mistake (its name in
 * class-report.csv): 1 made it, 0 did not, empty when the submission was not counted. */
static bool _sl_write_matrix(const _sl_class *k, const _sl_mistake *sorted, const char *path, char *err, size_t n) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, n)) return false;
    FILE *f = file.f;
    unsigned char *made = calloc((size_t)k->students * (size_t)k->mistake_count + 1, 1);
    int *row_of = malloc(sizeof *row_of * ((size_t)k->all_count + 1));
    if (!made || !row_of) {
        free(made);
        free(row_of);
        sl_atomic_abort(&file);
        snprintf(err, n, "out of memory");
        return false;
    }
    for (int i = 0; i < k->all_count; i++) row_of[i] = -1;
    for (int s = 0; s < k->students; s++) row_of[k->counted[s]] = s;
    for (int j = 0; j < k->mistake_count; j++)
        for (int w = 0; w < sorted[j].students; w++) made[(size_t)sorted[j].who[w] * (size_t)k->mistake_count + (size_t)j] = 1;
    _sl_csv(f, "submission", true), _sl_csv(f, "student", false), _sl_csv(f, "status", false);
    for (int j = 0; j < k->mistake_count; j++) _sl_csv(f, sorted[j].key, false);
    fputc('\n', f);
    for (int i = 0; i < k->all_count; i++) {
        const _sl_student *s = &k->all[i];
        _sl_csv(f, s->submission, true), _sl_csv(f, s->name, false), _sl_csv(f, s->status, false);
        for (int j = 0; j < k->mistake_count; j++)
            _sl_csv(f, row_of[i] < 0 ? "" : made[(size_t)row_of[i] * (size_t)k->mistake_count + (size_t)j] ? "1" : "0", false);
        fputc('\n', f);
    }
    free(made);
    free(row_of);
    return sl_atomic_commit(&file, err, n);
}

bool sl_class_report_write(const char *dir, char *err, size_t n) {
    _sl_class k = {0};
    bool ok = _sl_gather(dir, &k, err, n);
    _sl_mistake *sorted = NULL;
    if (ok && k.mistake_count) {
        sorted = malloc(sizeof *sorted * (size_t)k.mistake_count);
        if (!sorted) {
            snprintf(err, n, "out of memory");
            ok = false;
        } else {
            memcpy(sorted, k.mistakes, sizeof *sorted * (size_t)k.mistake_count);
            qsort(sorted, (size_t)k.mistake_count, sizeof *sorted, _sl_by_students);
        }
    }
    char path[1200];
    if (ok) {
        snprintf(path, sizeof path, "%s/class-report.html", dir);
        ok = _sl_write_html(&k, sorted ? sorted : k.mistakes, path, err, n);
    }
    if (ok) {
        snprintf(path, sizeof path, "%s/class-report.csv", dir);
        ok = _sl_write_csv(&k, sorted ? sorted : k.mistakes, path, err, n);
    }
    if (ok) {
        snprintf(path, sizeof path, "%s/class-mistakes.csv", dir);
        ok = _sl_write_matrix(&k, sorted ? sorted : k.mistakes, path, err, n);
    }
    free(sorted);
    for (int i = 0; i < k.mistake_count; i++) free(k.mistakes[i].who);
    free(k.mistakes);
    free(k.mistake_slots);
    free(k.checks);
    free(k.all);
    free(k.counted);
    return ok;
}
