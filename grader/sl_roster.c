#define _POSIX_C_SOURCE 200809L
#include "sl_roster.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "sl_files.h"

/* A roster is a small file; a larger one is not a roster. */
#define _SL_ROSTER_MAX_BYTES (64u << 20)
/* Canvas's name for its test student, as its export sorts it. */
#define _SL_CANVAS_TEST_STUDENT "Student, Test"

/* ---- a growing byte buffer ---- */

typedef struct _sl_buf {
    char *s;
    size_t len, cap;
    bool failed; /* out of memory: said once, by whoever finishes the buffer */
} _sl_buf;

static void _sl_buf_add(_sl_buf *b, const char *p, size_t n) {
    if (b->failed) return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 256;
        while (b->len + n + 1 > cap) cap *= 2;
        char *s = realloc(b->s, cap);
        if (!s) {
            b->failed = true;
            return;
        }
        b->s = s, b->cap = cap;
    }
    memcpy(b->s + b->len, p, n);
    b->len += n;
    b->s[b->len] = '\0';
}

static void _sl_buf_str(_sl_buf *b, const char *s) { _sl_buf_add(b, s, strlen(s)); }

/* ---- CSV as RFC 4180 reads it, with where each field and record lies in the file ---- */

typedef struct _sl_span {
    size_t start, end;
} _sl_span;

typedef struct _sl_record {
    int line;               /* where it starts, from 1 */
    size_t start, end, next; /* its bytes [start, end), its line end [end, next) */
    int count;
    _sl_span *raw;          /* each field's bytes, quotes included */
    char **cell;            /* each field's text */
} _sl_record;

typedef struct _sl_csv {
    char *data;
    size_t size, body; /* body: past a byte-order mark */
    _sl_record *records;
    int count;
} _sl_csv;

static void _sl_csv_free(_sl_csv *c) {
    for (int i = 0; i < c->count; i++) {
        for (int k = 0; k < c->records[i].count; k++) free(c->records[i].cell[k]);
        free(c->records[i].cell);
        free(c->records[i].raw);
    }
    free(c->records);
    free(c->data);
    memset(c, 0, sizeof *c);
}

/* The offset of the first byte that is not UTF-8 (or a NUL), or `size`. */
static size_t _sl_utf8_bad(const unsigned char *s, size_t size) {
    for (size_t i = 0; i < size;) {
        unsigned c = s[i];
        size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        if (c == 0 || n == 0 || (n == 2 && c < 0xC2) || (n == 4 && c > 0xF4) || i + n > size) return i;
        for (size_t k = 1; k < n; k++)
            if ((s[i + k] & 0xC0) != 0x80) return i;
        if (n == 3 && ((c == 0xE0 && s[i + 1] < 0xA0) || (c == 0xED && s[i + 1] >= 0xA0))) return i; /* overlong, surrogate */
        if (n == 4 && ((c == 0xF0 && s[i + 1] < 0x90) || (c == 0xF4 && s[i + 1] >= 0x90))) return i;
        i += n;
    }
    return size;
}

static int _sl_line_at(const char *data, size_t offset) {
    int line = 1;
    for (size_t i = 0; i < offset; i++)
        if (data[i] == '\n' || (data[i] == '\r' && data[i + 1] != '\n')) line++;
    return line;
}

static bool _sl_csv_push(void **array, int count, size_t size) {
    if ((count & (count - 1)) == 0 || count == 0) { /* grow at 0, 1, 2, 4, 8, ... */
        void *grown = realloc(*array, (size_t)(count ? count * 2 : 1) * size);
        if (!grown) return false;
        *array = grown;
    }
    return true;
}

/* Parses c->data into records; false with "NAME:LINE: reason". */
static bool _sl_csv_parse(const char *name, _sl_csv *c, char *err, size_t n) {
    const char *d = c->data;
    c->body = c->size >= 3 && memcmp(d, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    size_t bad = _sl_utf8_bad((const unsigned char *)d, c->size);
    if (bad < c->size) {
        snprintf(err, n, "%s:%d: %s (byte %zu): save it as UTF-8 CSV, as the LMS exported it", name,
                 _sl_line_at(d, bad), d[bad] ? "not UTF-8 text" : "a NUL byte", bad);
        return false;
    }
    size_t p = c->body;
    int line = _sl_line_at(d, p);
    while (p < c->size) {
        _sl_record r = {.line = line, .start = p};
        _sl_buf text = {0};
        for (;;) {
            _sl_span span = {p, p};
            text.len = 0;
            _sl_buf_add(&text, "", 0);
            if (p < c->size && d[p] == '"') {
                int opened = line;
                for (p++;; p++) {
                    if (p >= c->size) {
                        snprintf(err, n, "%s:%d: a quoted field is never closed", name, opened);
                        goto fail;
                    }
                    if (d[p] == '"') {
                        if (p + 1 < c->size && d[p + 1] == '"') p++;
                        else break;
                    } else if (d[p] == '\n' || (d[p] == '\r' && (p + 1 >= c->size || d[p + 1] != '\n')))
                        line++;
                    _sl_buf_add(&text, d + p, 1);
                }
                p++; /* the closing quote */
                if (p < c->size && d[p] != ',' && d[p] != '\r' && d[p] != '\n') {
                    snprintf(err, n, "%s:%d: text after the closing quote of a field", name, line);
                    goto fail;
                }
            } else {
                size_t from = p;
                while (p < c->size && d[p] != ',' && d[p] != '\r' && d[p] != '\n') p++;
                _sl_buf_add(&text, d + from, p - from);
            }
            span.end = p;
            if (text.failed || !_sl_csv_push((void **)&r.raw, r.count, sizeof *r.raw) ||
                !_sl_csv_push((void **)&r.cell, r.count, sizeof *r.cell)) {
                snprintf(err, n, "%s: out of memory", name);
                goto fail;
            }
            r.raw[r.count] = span;
            r.cell[r.count++] = text.s;
            text = (_sl_buf){0};
            if (p < c->size && d[p] == ',') {
                p++;
                continue;
            }
            break;
        }
        r.end = p;
        if (p < c->size && d[p] == '\r') p++;
        if (p < c->size && d[p] == '\n' && (p == r.end || d[p - 1] == '\r')) p++;
        r.next = p;
        line++;
        if (!_sl_csv_push((void **)&c->records, c->count, sizeof *c->records)) {
            snprintf(err, n, "%s: out of memory", name);
            goto fail;
        }
        c->records[c->count++] = r;
        continue;
    fail:
        free(text.s);
        for (int k = 0; k < r.count; k++) free(r.cell[k]);
        free(r.cell);
        free(r.raw);
        return false;
    }
    return true;
}

static bool _sl_csv_load(const char *path, _sl_csv *c, char *err, size_t n) {
    memset(c, 0, sizeof *c);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, n, "%s: cannot read it", path);
        return false;
    }
    _sl_buf b = {0};
    char chunk[65536];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0 && b.len <= _SL_ROSTER_MAX_BYTES) _sl_buf_add(&b, chunk, got);
    bool error = ferror(f);
    fclose(f);
    if (error || b.failed || b.len > _SL_ROSTER_MAX_BYTES) {
        snprintf(err, n, "%s: %s", path, error ? "cannot read it" : b.failed ? "out of memory" : "too large for a roster");
        free(b.s);
        return false;
    }
    c->data = b.s ? b.s : calloc(1, 1);
    c->size = b.len;
    if (!c->data || !_sl_csv_parse(path, c, err, n)) {
        _sl_csv_free(c);
        return false;
    }
    return true;
}

static bool _sl_blank(const _sl_record *r) { return r->count == 1 && r->cell[0][0] == '\0'; }

static int _sl_column(const _sl_record *header, const char *name) {
    for (int i = 0; i < header->count; i++)
        if (strcmp(header->cell[i], name) == 0) return i;
    return -1;
}

/* One field as RFC 4180 writes it: quoted when it holds a comma, a quote or a line break. */
static void _sl_put_field(_sl_buf *b, const char *text) {
    if (!strpbrk(text, ",\"\r\n")) {
        _sl_buf_str(b, text);
        return;
    }
    _sl_buf_add(b, "\"", 1);
    for (const char *p = text; *p; p++) {
        if (*p == '"') _sl_buf_add(b, "\"\"", 2);
        else _sl_buf_add(b, p, 1);
    }
    _sl_buf_add(b, "\"", 1);
}

static bool _sl_formula(const char *text) { return sl_csv_formula(text); }

/* A name that a spreadsheet would take for a formula gets a leading ' (as the gradebook's cells do). */
static char *_sl_defused(const char *text) {
    size_t n = strlen(text);
    char *out = malloc(n + 2);
    if (!out) return NULL;
    if (_sl_formula(text)) snprintf(out, n + 2, "'%s", text);
    else memcpy(out, text, n + 1);
    return out;
}

/* ---- the roster ---- */

typedef struct _sl_student {
    int record;
    char *id; /* Canvas: ID; Moodle: the number of "Participant N" */
} _sl_student;

struct sl_roster {
    char path[1024];
    sl_roster_kind kind;
    _sl_csv csv;
    int col_name, col_id;
    int identity;                    /* Canvas: the columns before the first assignment */
    int *assignments, assignment_count; /* Canvas: "Name (id)" columns */
    int col_grade, col_max, col_submitted, col_feedback; /* Moodle */
    _sl_student *students;
    int count;
};

/* Canvas names an assignment's column "Name (assignment id)". */
static bool _sl_canvas_assignment(const char *header) {
    size_t n = strlen(header);
    if (n < 4 || header[n - 1] != ')') return false;
    size_t i = n - 1;
    while (i > 0 && isdigit((unsigned char)header[i - 1])) i--;
    return i < n - 1 && i >= 3 && header[i - 1] == '(' && header[i - 2] == ' ';
}

/* Moodle's Identifier is "Participant N" in the language of whoever downloaded it: N is what counts. */
static char *_sl_moodle_id(const char *identifier) {
    size_t n = strlen(identifier), i = n;
    while (i > 0 && isdigit((unsigned char)identifier[i - 1])) i--;
    return i < n ? strdup(identifier + i) : NULL;
}

static bool _sl_roster_layout(sl_roster *r, char *err, size_t n) {
    const _sl_record *h = &r->csv.records[0];
    if (_sl_column(h, "Student") >= 0 && _sl_column(h, "ID") >= 0) {
        r->kind = SL_ROSTER_CANVAS;
        r->col_name = _sl_column(h, "Student"), r->col_id = _sl_column(h, "ID");
        r->assignments = calloc((size_t)h->count, sizeof *r->assignments);
        if (!r->assignments) return snprintf(err, n, "out of memory"), false;
        r->identity = -1;
        for (int i = 0; i < h->count; i++)
            if (_sl_canvas_assignment(h->cell[i])) {
                if (r->identity < 0) r->identity = i;
                r->assignments[r->assignment_count++] = i;
            }
        if (r->identity < 0) {
            int section = _sl_column(h, "Section");
            r->identity = section >= 0 ? section + 1 : h->count;
        }
        if (r->col_name >= r->identity || r->col_id >= r->identity) {
            snprintf(err, n, "%s:%d: Student and ID come after the assignments: not a Canvas gradebook export",
                     r->path, h->line);
            return false;
        }
        return true;
    }
    if (_sl_column(h, "Identifier") >= 0 && _sl_column(h, "Grade") >= 0) {
        r->kind = SL_ROSTER_MOODLE;
        r->col_id = _sl_column(h, "Identifier"), r->col_name = _sl_column(h, "Full name");
        r->col_grade = _sl_column(h, "Grade"), r->col_max = _sl_column(h, "Maximum Grade");
        r->col_submitted = _sl_column(h, "Last modified (submission)");
        r->col_feedback = _sl_column(h, "Feedback comments");
        if (r->col_name < 0 || _sl_column(h, "Last modified (grade)") < 0) {
            snprintf(err, n, "%s:%d: a Moodle grading worksheet has the columns Full name and Last modified (grade)",
                     r->path, h->line);
            return false;
        }
        return true;
    }
    snprintf(err, n,
             "%s:%d: neither a Canvas gradebook export (columns Student, ID, SIS User ID, SIS Login ID, Section, "
             "then the assignments) nor a Moodle grading worksheet (Identifier, Full name, ..., Grade); this "
             "program reads their English headers",
             r->path, h->line);
    return false;
}

static bool _sl_roster_students(sl_roster *r, char *err, size_t n) {
    const _sl_csv *c = &r->csv;
    r->students = calloc((size_t)c->count, sizeof *r->students);
    if (!r->students) return snprintf(err, n, "out of memory"), false;
    int columns = c->records[0].count;
    for (int i = 1; i < c->count; i++) {
        const _sl_record *rec = &c->records[i];
        if (_sl_blank(rec)) continue;
        if (rec->count != columns) {
            snprintf(err, n, "%s:%d: %d fields where the header has %d", r->path, rec->line, rec->count, columns);
            return false;
        }
        char *id = NULL;
        if (r->kind == SL_ROSTER_CANVAS) {
            /* the Points Possible and Manual Posting rows have no ID */
            if (!rec->cell[r->col_id][0] || strcmp(rec->cell[r->col_name], _SL_CANVAS_TEST_STUDENT) == 0) continue;
            id = strdup(rec->cell[r->col_id]);
        } else if (!(id = _sl_moodle_id(rec->cell[r->col_id]))) {
            snprintf(err, n, "%s:%d: Identifier '%s' does not end with the participant's number", r->path, rec->line,
                     rec->cell[r->col_id]);
            return false;
        }
        if (!id) return snprintf(err, n, "out of memory"), false;
        int other = sl_roster_find(r, id);
        if (other >= 0) {
            snprintf(err, n, "%s:%d: the id %s is on line %d too", r->path, rec->line, id,
                     c->records[r->students[other].record].line);
            free(id);
            return false;
        }
        r->students[r->count++] = (_sl_student){.record = i, .id = id};
    }
    return true;
}

sl_roster *sl_roster_read(const char *path, char *err, size_t n) {
    sl_roster *r = calloc(1, sizeof *r);
    if (!r) return snprintf(err, n, "out of memory"), NULL;
    snprintf(r->path, sizeof r->path, "%s", path);
    if (!_sl_csv_load(path, &r->csv, err, n)) {
        free(r);
        return NULL;
    }
    if (r->csv.count == 0) {
        snprintf(err, n, "%s:1: empty: export the roster again", path);
        sl_roster_free(r);
        return NULL;
    }
    if (!_sl_roster_layout(r, err, n) || !_sl_roster_students(r, err, n)) {
        sl_roster_free(r);
        return NULL;
    }
    return r;
}

void sl_roster_free(sl_roster *r) {
    if (!r) return;
    for (int i = 0; i < r->count; i++) free(r->students[i].id);
    free(r->students);
    free(r->assignments);
    _sl_csv_free(&r->csv);
    free(r);
}

sl_roster_kind sl_roster_kind_of(const sl_roster *r) { return r->kind; }
const char *sl_roster_kind_name(sl_roster_kind kind) { return kind == SL_ROSTER_CANVAS ? "Canvas" : "Moodle"; }
int sl_roster_count(const sl_roster *r) { return r->count; }
const char *sl_roster_id(const sl_roster *r, int i) { return r->students[i].id; }
const char *sl_roster_name(const sl_roster *r, int i) {
    return r->csv.records[r->students[i].record].cell[r->col_name];
}

int sl_roster_find(const sl_roster *r, const char *id) {
    for (int i = 0; i < r->count; i++)
        if (strcmp(r->students[i].id, id) == 0) return i;
    return -1;
}

/* ---- dates: wall-clock minutes, no time zone ---- */

static long long _sl_days(int y, int m, int d) { /* days since 1970-01-01 of the proleptic Gregorian calendar */
    y -= m <= 2;
    long long era = (y >= 0 ? y : y - 399) / 400;
    unsigned yoe = (unsigned)(y - era * 400);
    unsigned doy = (153u * (unsigned)(m + (m > 2 ? -3 : 9)) + 2) / 5 + (unsigned)d - 1;
    unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + (long long)doe - 719468;
}

static bool _sl_minutes(int y, int mo, int d, int h, int mi, long long *out) {
    static const int days[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (y < 1970 || y > 9999 || mo < 1 || mo > 12 || d < 1 || d > days[mo - 1] || h < 0 || h > 23 || mi < 0 || mi > 59)
        return false;
    *out = (_sl_days(y, mo, d) * 24 + h) * 60 + mi;
    return true;
}

bool sl_roster_parse_due(const char *text, long long *minutes) {
    int y, mo, d, h, mi, end = -1;
    char sep;
    if (sscanf(text, "%4d-%2d-%2d%c%2d:%2d%n", &y, &mo, &d, &sep, &h, &mi, &end) != 6 || end < 0 || text[end] ||
        (sep != ' ' && sep != 'T'))
        return false;
    return _sl_minutes(y, mo, d, h, mi, minutes);
}

/* Moodle's worksheet dates, as userdate() writes them in English: "Friday, 4 December 2026, 3:05 PM"
 * (the weekday optional); an ISO "2026-12-04 15:05" too. */
static bool _sl_moodle_date(const char *text, long long *minutes) {
    if (sl_roster_parse_due(text, minutes)) return true;
    static const char *const months[] = {"jan", "feb", "mar", "apr", "may", "jun",
                                         "jul", "aug", "sep", "oct", "nov", "dec"};
    const char *p = text;
    if (isalpha((unsigned char)*p)) { /* the weekday */
        const char *comma = strchr(p, ',');
        if (!comma) return false;
        p = comma + 1;
    }
    int d, y, h, mi, end = -1;
    char month[32], half[3] = "";
    int got = sscanf(p, " %2d %31[A-Za-z] %4d, %2d:%2d %2[AaPpMm]%n", &d, month, &y, &h, &mi, half, &end);
    if (got == 5) {
        end = -1;
        sscanf(p, " %*d %*[A-Za-z] %*d, %*d:%*d%n", &end);
    }
    if ((got != 5 && got != 6) || end < 0 || p[end] != '\0' || strlen(month) < 3) return false;
    int mo = 0;
    for (int i = 0; i < 12 && !mo; i++)
        if (strncasecmp(month, months[i], 3) == 0) mo = i + 1;
    if (!mo) return false;
    if (got == 6) {
        bool pm = tolower((unsigned char)half[0]) == 'p';
        if (h < 1 || h > 12 || tolower((unsigned char)half[1]) != 'm') return false;
        h = h % 12 + (pm ? 12 : 0);
    }
    return _sl_minutes(y, mo, d, h, mi, minutes);
}

int sl_roster_late(const sl_roster *r, int student, long long due, char *err, size_t n) {
    if (r->kind != SL_ROSTER_MOODLE) return 0;
    if (r->col_submitted < 0) {
        snprintf(err, n, "%s:1: --due: no column Last modified (submission)", r->path);
        return -1;
    }
    const _sl_record *rec = &r->csv.records[r->students[student].record];
    const char *when = rec->cell[r->col_submitted];
    long long at;
    if (!when[0] || strcmp(when, "-") == 0) return 0;
    if (!_sl_moodle_date(when, &at)) {
        snprintf(err, n,
                 "%s:%d: Last modified (submission) '%s' is not a date this program reads (\"Friday, 4 December "
                 "2026, 3:05 PM\", as an English Moodle writes it)",
                 r->path, rec->line, when);
        return -1;
    }
    return at > due;
}

/* ---- the export ---- */

typedef struct _sl_grade_row {
    const char *submission, *status, *total, *max, *note;
} _sl_grade_row;

/* The gradebook's row of each roster student (NULL: none); false when one has two. */
static bool _sl_join(const sl_roster *r, const _sl_csv *book, const char *book_path, _sl_grade_row *rows, char *err,
                     size_t n) {
    const _sl_record *h = &book->records[0];
    int col[6];
    static const char *const names[] = {"submission", "student_id", "status", "total", "max", "note"};
    for (int k = 0; k < 6; k++)
        if ((col[k] = _sl_column(h, names[k])) < 0) {
            snprintf(err, n, "%s: no column %s: not a gradebook of shadowlab-grade --gradebook", book_path, names[k]);
            return false;
        }
    for (int i = 1; i < book->count; i++) {
        const _sl_record *rec = &book->records[i];
        if (_sl_blank(rec)) continue;
        if (rec->count != h->count) {
            snprintf(err, n, "%s:%d: %d fields where the header has %d", book_path, rec->line, rec->count, h->count);
            return false;
        }
        /* a submission of another LMS whose id happens to be a roster's is not that student's */
        if (strncmp(rec->cell[col[5]], SL_ROSTER_NOT_ON_ROSTER, strlen(SL_ROSTER_NOT_ON_ROSTER)) == 0) continue;
        int s = sl_roster_find(r, rec->cell[col[1]]);
        if (s < 0) continue;
        _sl_grade_row row = {rec->cell[col[0]], rec->cell[col[2]], rec->cell[col[3]], rec->cell[col[4]], rec->cell[col[5]]};
        if (rows[s].status && rows[s].submission[0] && row.submission[0]) {
            snprintf(err, n,
                     "%s: %s (id %s) has two submissions, %s and %s: remove one from the batch folder and write "
                     "the gradebook again",
                     book_path, sl_roster_name(r, s), sl_roster_id(r, s), rows[s].submission, row.submission);
            return false;
        }
        if (!rows[s].status || row.submission[0]) rows[s] = row;
    }
    return true;
}

static bool _sl_number(const char *text, double *v) {
    char *end;
    if (!text[0]) return false;
    *v = strtod(text, &end);
    return *end == '\0' && isfinite(*v);
}

/* What goes out for one student: the grade (NULL: leave the cell as it was, or empty) and Moodle's feedback. */
typedef struct _sl_out {
    char grade[32];
    bool set;
    char feedback[600];
} _sl_out;

static bool _sl_grades(const sl_roster *r, const _sl_grade_row *rows, double points_possible, bool have_points,
                       const sl_roster_export_desc *desc, _sl_out *out, char *err, size_t n) {
    int empty = 0;
    for (int s = 0; s < r->count; s++) {
        const _sl_grade_row *row = &rows[s];
        _sl_out *o = &out[s];
        double points = points_possible, total, max;
        bool have = have_points;
        if (r->kind == SL_ROSTER_MOODLE && r->col_max >= 0) {
            const _sl_record *rec = &r->csv.records[r->students[s].record];
            if (!(have = _sl_number(rec->cell[r->col_max], &points))) {
                /* a scale's grades are words, which a score is not */
                snprintf(err, n, "%s:%d: Maximum Grade '%s' is not a number: the assignment is graded with a scale",
                         r->path, rec->line, rec->cell[r->col_max]);
                return false;
            }
        }
        if (!row->status || !row->submission[0]) { /* no submission */
            if (desc->missing_as_zero) {
                snprintf(o->grade, sizeof o->grade, "0");
                snprintf(o->feedback, sizeof o->feedback, "no submission");
                o->set = true;
            }
            continue;
        }
        if (!_sl_number(row->total, &total)) {
            if (row->total[0]) {
                snprintf(err, n, "the gradebook's total of %s is '%s', not a number", row->submission, row->total);
                return false;
            }
            fprintf(stderr, "shadowlab-grade: %s (%s): no grade exported: %s%s%s\n", sl_roster_name(r, s),
                    row->submission, row->status, row->note[0] ? ": " : "", row->note);
            empty++;
            continue;
        }
        if (have && _sl_number(row->max, &max) && fabs(max - points) > 1e-9) {
            snprintf(err, n,
                     "%s (%s): the gradebook's max is %g, the %s assignment's is %g: make them the same (the "
                     "assignment's points in the LMS, or the labs graded) and export again; no grade is scaled",
                     sl_roster_name(r, s), row->submission, max, sl_roster_kind_name(r->kind), points);
            return false;
        }
        snprintf(o->grade, sizeof o->grade, "%s", row->total);
        o->set = true;
        char capped[120] = "";
        if (have && total > points + 1e-9) {
            if (r->kind == SL_ROSTER_MOODLE) {
                /* Moodle's import skips a grade above the maximum without a word: send the maximum, say the rest */
                snprintf(o->grade, sizeof o->grade, "%g", points);
                snprintf(capped, sizeof capped, " (%s with the bonus; Moodle's maximum is %g)", row->total, points);
            }
            fprintf(stderr, "shadowlab-grade: %s (%s): %s points, above the assignment's %g (the bonus)%s\n",
                    sl_roster_name(r, s), row->submission, row->total, points,
                    r->kind == SL_ROSTER_MOODLE ? ": exported as the maximum" : ": Canvas takes it as extra credit");
        }
        snprintf(o->feedback, sizeof o->feedback, "%s: %s of %s points%s.%s%.300s Report: %s/report/report.html",
                 row->status, o->grade, row->max[0] ? row->max : "?", capped, row->note[0] ? " " : "", row->note,
                 row->submission);
    }
    if (empty)
        fprintf(stderr, "shadowlab-grade: %d graded submission(s) have no total (above): their grades are left empty\n",
                empty);
    return true;
}

/* Canvas: the identity columns and the one assignment's, every row but blank lines. */
static void _sl_canvas_rows(const sl_roster *r, int column, const _sl_out *out, _sl_buf *b, _sl_buf *expected) {
    const _sl_csv *c = &r->csv;
    /* the roster's own line end (Canvas writes CRLF) */
    const _sl_record *h = &c->records[0];
    const char *eol = h->next > h->end ? c->data + h->end : "\r\n";
    size_t eol_len = h->next > h->end ? h->next - h->end : 2;
    _sl_buf_add(b, c->data, c->body);
    int s = 0;
    for (int i = 0; i < c->count; i++) {
        const _sl_record *rec = &c->records[i];
        if (_sl_blank(rec)) continue;
        bool student = s < r->count && r->students[s].record == i;
        for (int k = 0; k <= r->identity; k++) {
            int col = k < r->identity ? k : column;
            char *value = NULL;
            const char *text = rec->cell[col];
            if (col == column && student) text = out[s].set ? out[s].grade : "";
            else if (col == r->col_name && i > 0 && _sl_formula(text)) {
                if (!(value = _sl_defused(text))) b->failed = true;
                text = value ? value : "";
            }
            if (k) _sl_buf_add(b, ",", 1);
            _sl_put_field(b, text);
            _sl_buf_add(expected, text, strlen(text) + 1);
            free(value);
        }
        _sl_buf_add(b, eol, eol_len);
        if (student) s++;
    }
}

/* Moodle: the worksheet as read, byte for byte, but each graded student's Grade and Feedback
 * comments (and a name a spreadsheet would take for a formula). */
static void _sl_moodle_rows(const sl_roster *r, const _sl_out *out, _sl_buf *b, _sl_buf *expected) {
    const _sl_csv *c = &r->csv;
    _sl_buf_add(b, c->data, c->body);
    int s = 0;
    for (int i = 0; i < c->count; i++) {
        const _sl_record *rec = &c->records[i];
        bool student = s < r->count && r->students[s].record == i;
        for (int k = 0; k < rec->count; k++) {
            const char *text = NULL; /* NULL: the field's own bytes */
            char *value = NULL;
            if (student && out[s].set && k == r->col_grade) text = out[s].grade;
            else if (student && out[s].set && k == r->col_feedback) text = out[s].feedback;
            else if (student && k == r->col_name && _sl_formula(rec->cell[k])) {
                if (!(value = _sl_defused(rec->cell[k]))) b->failed = true;
                text = value ? value : "";
            }
            if (k) _sl_buf_add(b, ",", 1);
            if (text) _sl_put_field(b, text);
            else _sl_buf_add(b, c->data + rec->raw[k].start, rec->raw[k].end - rec->raw[k].start);
            const char *said = text ? text : rec->cell[k];
            _sl_buf_add(expected, said, strlen(said) + 1);
            free(value);
        }
        _sl_buf_add(b, c->data + rec->end, rec->next - rec->end);
        if (student) s++;
    }
}

/* Reads the written file back: the same bytes, and a CSV whose cells are the ones meant. */
static bool _sl_check_written(const char *path, const _sl_buf *b, const _sl_buf *expected, char *err, size_t n) {
    _sl_csv back;
    if (!_sl_csv_load(path, &back, err, n)) return false;
    bool same = back.size == b->len && (b->len == 0 || memcmp(back.data, b->s, b->len) == 0);
    if (!same) snprintf(err, n, "%s: read back, its bytes are not the ones written", path);
    size_t at = 0;
    for (int i = 0; same && i < back.count; i++) {
        for (int k = 0; same && k < back.records[i].count; k++) {
            const char *cell = back.records[i].cell[k];
            same = at < expected->len && strcmp(cell, expected->s + at) == 0;
            if (!same)
                snprintf(err, n, "%s:%d: read back, field %d is '%s', not '%s'", path, back.records[i].line, k + 1,
                         cell, at < expected->len ? expected->s + at : "(nothing)");
            at += strlen(cell) + 1;
        }
    }
    if (same && at != expected->len) {
        snprintf(err, n, "%s: read back, it holds fewer fields than were written", path);
        same = false;
    }
    _sl_csv_free(&back);
    return same;
}

/* The Canvas column the export fills: --assignment's, or the only one. */
static int _sl_canvas_column(const sl_roster *r, const char *wanted, char *err, size_t n) {
    const _sl_record *h = &r->csv.records[0];
    for (int a = 0; wanted && a < r->assignment_count; a++)
        if (strcmp(h->cell[r->assignments[a]], wanted) == 0) return r->assignments[a];
    if (!wanted && r->assignment_count == 1) return r->assignments[0];
    size_t used = (size_t)snprintf(err, n, "%s: %s; its assignments:", r->path,
                                   r->assignment_count == 0 ? "no assignment column (\"Name (id)\")"
                                   : wanted                 ? "no assignment column is the --assignment given"
                                                            : "several assignments: say which with --assignment");
    for (int a = 0; a < r->assignment_count && used < n; a++)
        used += (size_t)snprintf(err + used, n - used, " \"%s\"", h->cell[r->assignments[a]]);
    return -1;
}

bool sl_roster_export(const sl_roster *r, const char *gradebook_csv, const sl_roster_export_desc *desc, char *err,
                      size_t n) {
    const char *kind = r->kind == SL_ROSTER_CANVAS ? "canvas" : "moodle";
    if (strcmp(desc->format, kind) != 0) {
        snprintf(err, n, "--export %s: the roster %s is %s's: export in its own format (--export %s)", desc->format,
                 r->path, sl_roster_kind_name(r->kind), kind);
        return false;
    }
    int column = -1;
    double points = 0;
    bool have_points = false;
    if (r->kind == SL_ROSTER_CANVAS) {
        if ((column = _sl_canvas_column(r, desc->assignment, err, n)) < 0) return false;
        for (int i = 1; i < r->csv.count && !have_points; i++) {
            const _sl_record *rec = &r->csv.records[i];
            const char *who = rec->cell[r->col_name];
            while (*who == ' ') who++;
            if (rec->count > column && strcmp(who, "Points Possible") == 0)
                have_points = _sl_number(rec->cell[column], &points);
        }
    } else if (desc->assignment) {
        snprintf(err, n, "--assignment picks a Canvas column; %s is a Moodle worksheet, of one assignment", r->path);
        return false;
    }
    _sl_csv book;
    if (!_sl_csv_load(gradebook_csv, &book, err, n)) return false;
    _sl_grade_row *rows = calloc((size_t)r->count + 1, sizeof *rows);
    _sl_out *out = calloc((size_t)r->count + 1, sizeof *out);
    _sl_buf b = {0}, expected = {0};
    bool ok = rows && out;
    if (!ok) snprintf(err, n, "out of memory");
    if (ok && book.count == 0) {
        snprintf(err, n, "%s: empty: write the gradebook first", gradebook_csv);
        ok = false;
    }
    ok = ok && _sl_join(r, &book, gradebook_csv, rows, err, n) &&
         _sl_grades(r, rows, points, have_points, desc, out, err, n);
    if (ok) {
        if (r->kind == SL_ROSTER_CANVAS) _sl_canvas_rows(r, column, out, &b, &expected);
        else _sl_moodle_rows(r, out, &b, &expected);
        if (b.failed || expected.failed) {
            snprintf(err, n, "out of memory");
            ok = false;
        }
    }
    sl_atomic_file file;
    if (ok && (ok = sl_atomic_open(&file, desc->path, err, n))) {
        fwrite(b.s ? b.s : "", 1, b.len, file.f);
        ok = sl_atomic_commit(&file, err, n);
    }
    if (ok && !_sl_check_written(desc->path, &b, &expected, err, n)) {
        unlink(desc->path);
        ok = false;
    }
    free(b.s);
    free(expected.s);
    free(rows);
    free(out);
    _sl_csv_free(&book);
    return ok;
}
