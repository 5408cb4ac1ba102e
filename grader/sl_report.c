#define _POSIX_C_SOURCE 200809L
#include "sl_report.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "sl_build_failure.h"
#include "sl_data_url.h"
#include "sl_files.h"
#include "sl_html.h"
#include "sl_json.h"
#include "sl_params.h"
#include "sl_utf8.h"

bool sl_report_load_submission(sl_grade_report *rep, const char *path, char *err, size_t err_size) {
    cJSON *root = sl_json_load_file(path, "submission summary", err, err_size);
    if (!root) return false;
    const cJSON *found = cJSON_GetObjectItemCaseSensitive(root, "lab_files_found");
    const cJSON *notes = cJSON_GetObjectItemCaseSensitive(root, "notes"), *note;
    if (!cJSON_IsBool(found) || !cJSON_IsArray(notes)) {
        snprintf(err, err_size, "%s: not a submission summary (no lab_files_found, no notes)", path);
        cJSON_Delete(root);
        return false;
    }
    rep->no_lab_file = cJSON_IsFalse(found);
    rep->submission_note_count = 0;
    cJSON_ArrayForEach(note, notes) {
        if (!cJSON_IsString(note) || rep->submission_note_count >= SL_SUBMISSION_NOTES_MAX) continue;
        /* a note is one line of the text report: staged from what a submission named */
        sl_utf8_clean(rep->submission_notes[rep->submission_note_count++], sizeof rep->submission_notes[0],
                      note->valuestring, strlen(note->valuestring), SL_UTF8_KEEP_TAB);
    }
    cJSON_Delete(rep->submission_summary);
    rep->submission_summary = root;
    return true;
}

void sl_report_free_submission(sl_grade_report *rep) {
    cJSON_Delete(rep->submission_summary);
    rep->submission_summary = NULL;
}

void sl_report_totals(const sl_grade_report *rep, double *score, double *max_score, double *bonus) {
    *score = *max_score = *bonus = 0;
    for (int i = 0; i < rep->case_count; i++)
        for (int k = 0; k < rep->cases[i].c->check_count; k++) {
            const sl_check_result *cr = &rep->cases[i].checks[k];
            if (cr->bonus) {
                *bonus += cr->points;
            } else {
                *score += cr->points;
                *max_score += cr->max_points;
            }
        }
}

static const char *const _sl_bonus_names[] = {"apart", "fill", "add"};

const char *sl_bonus_policy_name(sl_bonus_policy policy) {
    return (unsigned)policy < sizeof _sl_bonus_names / sizeof _sl_bonus_names[0] ? _sl_bonus_names[policy] : "?";
}

bool sl_bonus_policy_parse(const char *name, sl_bonus_policy *policy) {
    for (size_t i = 0; i < sizeof _sl_bonus_names / sizeof _sl_bonus_names[0]; i++)
        if (strcmp(name, _sl_bonus_names[i]) == 0) {
            *policy = (sl_bonus_policy)i;
            return true;
        }
    return false;
}

double sl_bonus_total(sl_bonus_policy policy, double score, double max, double bonus) {
    switch (policy) {
    case SL_BONUS_FILL: return score + bonus > max ? (score > max ? score : max) : score + bonus;
    case SL_BONUS_ADD: return score + bonus;
    default: return score;
    }
}

double sl_report_total(const sl_grade_report *rep) {
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    return sl_bonus_total(rep->bonus_policy, score, max, bonus);
}

void sl_report_score_line(const sl_grade_report *rep, char *out, size_t n) {
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    double total = sl_bonus_total(rep->bonus_policy, score, max, bonus);
    int used;
    if (bonus > 0 && rep->bonus_policy != SL_BONUS_APART)
        used = snprintf(out, n, "Score: %g/%g (%g + %g bonus%s)", total, max, score, bonus,
                        total < score + bonus ? ", up to the maximum" : "");
    else if (bonus > 0)
        used = snprintf(out, n, "Score: %g/%g (+%g bonus)", score, max, bonus);
    else
        used = snprintf(out, n, "Score: %g/%g", score, max);
    if (rep->interrupted && used > 0 && (size_t)used < n)
        snprintf(out + used, n - (size_t)used, " (incomplete: the grader was stopped; %d of %d cases graded)",
                 rep->cases_finished, rep->case_count);
}

bool sl_report_full_marks(const sl_grade_report *rep) {
    for (int i = 0; i < rep->case_count; i++)
        for (int k = 0; k < rep->cases[i].c->check_count; k++)
            if (!rep->cases[i].checks[k].bonus && !rep->cases[i].checks[k].passed) return false;
    return true;
}

/* A message under its check, indented, and each line after its first marked
 * "| " as well, so that no line of it (a runner's error quotes what lab code
 * sent: "\nScore: 16/16") can pass for one of the report's own; the text is
 * cleaned here too, whatever its way in. */
static void _sl_print_message(FILE *out, const char *message) {
    int lines = 0;
    const char *p = message;
    while (*p && lines < 10) {
        const char *end = strchr(p, '\n');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len > 0) {
            fputs(lines ? "          | " : "          ", out);
            sl_utf8_write(out, p, len, SL_UTF8_KEEP_TAB);
            fputc('\n', out);
        }
        lines += len > 0;
        p = end ? end + 1 : p + len;
    }
    if (*p) fprintf(out, "          ...\n");
}

/* Lab 0 is the technique the runners' build adds (docs/adding-a-technique.md): every report lists it. */
static const char *_sl_report_lab_title(int lab) { return lab ? sl_lab_title(lab) : "the build's added technique"; }

void sl_report_print(const sl_grade_report *rep, FILE *out, bool color) {
    const char *red = color ? "\033[31m" : "", *green = color ? "\033[32m" : "", *bold = color ? "\033[1m" : "",
               *reset = color ? "\033[0m" : "";
    if (rep->self_check) fprintf(out, "%sSelf-check:%s %s\n", bold, reset, rep->self_check);
    for (int i = 0; i < rep->submission_note_count; i++) {
        fprintf(out, "%sSubmission:%s ", i == 0 && rep->no_lab_file ? red : bold, reset);
        sl_utf8_write(out, rep->submission_notes[i], strlen(rep->submission_notes[i]), SL_UTF8_KEEP_TAB);
        fputc('\n', out);
    }
    for (int lab = 0; lab <= SL_LAB_MAX; lab++) { /* 0: the technique the runners' build adds */
        double score = 0, max = 0, bonus = 0;
        bool any = false;
        for (int i = 0; i < rep->case_count; i++) {
            const sl_graded_case *g = &rep->cases[i];
            if (g->c->lab != lab) continue;
            if (!any)
                fprintf(out, "%sLab %d: %s%s\n", bold, lab, _sl_report_lab_title(lab), reset);
            any = true;
            for (int k = 0; k < g->c->check_count; k++) {
                const sl_check_result *cr = &g->checks[k];
                char label[200];
                snprintf(label, sizeof label, "%s / %s", g->c->name, g->c->checks[k].name);
                fprintf(out, "  %s%s%s %4.1f/%-4.1f %s%s\n", cr->passed ? green : red, cr->passed ? "PASS" : "FAIL", reset,
                        cr->points, cr->max_points, label, cr->bonus ? " (bonus)" : "");
                if (!cr->passed || cr->message[0]) _sl_print_message(out, cr->message); /* a probe's: on which inputs */
                if (cr->bonus) {
                    bonus += cr->points;
                } else {
                    score += cr->points;
                    max += cr->max_points;
                }
            }
        }
        if (any && bonus > 0) fprintf(out, "  Lab %d: %g/%g (+%g bonus)\n", lab, score, max, bonus);
        else if (any) fprintf(out, "  Lab %d: %g/%g\n", lab, score, max);
    }
    for (int i = 0; i < rep->problem_count; i++) {
        fprintf(out, "%sPROBLEM%s ", red, reset);
        sl_utf8_write(out, rep->problems[i], strlen(rep->problems[i]), SL_UTF8_KEEP_TAB);
        fputc('\n', out);
    }
    fprintf(out, "Time: %.2f s (%d cases, %d at a time)\n", rep->seconds, rep->case_count, rep->jobs);
    char line[256];
    sl_report_score_line(rep, line, sizeof line);
    fprintf(out, "%s%s%s\n", bold, line, reset);
}

static bool _sl_write_json(cJSON *json, const char *path, char *err, size_t err_size) {
    /* whatever a string holds, the file is JSON: a reader refuses the whole file for one byte that is not UTF-8 */
    char *text = sl_json_clean_strings(json) ? cJSON_Print(json) : NULL;
    if (!text) {
        snprintf(err, err_size, "%s: out of memory", path);
        return false;
    }
    sl_atomic_file f;
    bool ok = sl_atomic_open(&f, path, err, err_size);
    if (ok) {
        fputs(text, f.f);
        fputc('\n', f.f);
        ok = sl_atomic_commit(&f, err, err_size);
    }
    free(text);
    return ok;
}

/* A check's picture as people look at it: cascade numbers in the viewer's
 * cascade colours (a grey image would show cascade 0 as black as the
 * background), two channels (lab 5's moments) as red = depth and green =
 * depth² (a PNG would make them grey and alpha). Anything else as it is.
 * Returns an image to free, or one with no data when the picture is fine as it is. */
static sl_image _sl_for_people(sl_check_kind kind, const sl_image *img) {
    sl_image none = {0};
    bool cascades = kind == SL_CHECK_CASCADE_INDEX && img->channels == 1;
    if (!img->data || (!cascades && img->channels != 2)) return none;
    sl_image out = sl_image_alloc(img->width, img->height, 3);
    if (!out.data) return none;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            const float *p = sl_image_pixel(img, x, y);
            float *q = sl_image_pixel(&out, x, y);
            if (cascades) {
                sl_cascade_colour(p[0] >= -0.5f && p[0] < SL_MAX_CASCADES ? (int)floorf(p[0] + 0.5f) : -1, q);
            } else {
                q[0] = p[0], q[1] = p[1], q[2] = 0;
            }
        }
    return out;
}

/* The legend under a check's pictures, for the kinds drawn in false colour. */
static void _sl_html_legend(FILE *f, const char *kind) {
    if (strcmp(kind, "cascade_index") == 0) {
        fputs("<p class=\"legend\">", f);
        for (int i = 0; i <= SL_MAX_CASCADES; i++) {
            float rgb[3];
            sl_cascade_colour(i < SL_MAX_CASCADES ? i : -1, rgb);
            fprintf(f, "<span class=\"swatch\" style=\"background:rgb(%d,%d,%d)\"></span>", (int)(rgb[0] * 255 + 0.5f),
                    (int)(rgb[1] * 255 + 0.5f), (int)(rgb[2] * 255 + 0.5f));
            if (i < SL_MAX_CASCADES) fprintf(f, "cascade %d &nbsp; ", i);
            else fputs("no cascade", f);
        }
        fputs("</p>", f);
    } else if (strcmp(kind, "moments") == 0 || strcmp(kind, "moments_blurred") == 0) {
        fputs("<p class=\"legend\"><span class=\"swatch\" style=\"background:#f00\"></span>red: depth &nbsp; "
              "<span class=\"swatch\" style=\"background:#0f0\"></span>green: depth&sup2; &nbsp; "
              "<span class=\"swatch\" style=\"background:#ff0\"></span>both high (far) &nbsp; "
              "<span class=\"swatch\" style=\"background:#000\"></span>both 0 (near)</p>", f);
    }
}

/* A page a TA can open: the score per lab, every check, and the images of the failed ones. */
static bool _sl_write_html(const sl_grade_report *rep, const cJSON *root, const char *path, char *err, size_t err_size) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, err_size)) return false;
    FILE *f = file.f;
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    char line[256];
    sl_report_score_line(rep, line, sizeof line);
    double total = sl_bonus_total(rep->bonus_policy, score, max, bonus);
    fprintf(f, "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>shadowlab grade: %g/%g</title>\n"
               "<style>body{font-family:sans-serif;margin:2em}td,th{padding:.2em .6em;text-align:left;vertical-align:top}"
               ".pass{color:#070}.fail{color:#b00}img{width:256px;image-rendering:pixelated;border:1px solid #ccc}"
               "figure{display:inline-block;margin:.3em}.legend{margin:.2em .3em;font-size:90%%;color:#333}"
               ".swatch{display:inline-block;width:1em;height:1em;border:1px solid #888;vertical-align:middle;"
               "margin-right:.3em}</style></head><body>\n",
            total, max);
    fputs("<h1>", f);
    sl_html_text(f, line);
    fprintf(f, "</h1>\n<p>%s labs, %d cases, %.2f s; rendered with ", rep->labs_kind, rep->case_count, rep->seconds);
    sl_html_text(f, rep->backend[0] ? rep->backend : "?"); /* the runner's word, as the renderer's */
    fputs(" (", f);
    sl_html_text(f, rep->renderer);
    fputs("); sandbox: ", f);
    sl_html_text(f, rep->sandbox);
    if (rep->case_set[0]) {
        fputs("; cases: ", f);
        sl_html_text(f, rep->case_set);
    }
    if (rep->options[0]) {
        fputs("; options: ", f);
        sl_html_text(f, rep->options);
    }
    fputs("</p>\n", f);
    if (rep->self_check) {
        fputs("<p class=\"fail\"><strong>", f);
        sl_html_text(f, rep->self_check);
        fputs("</strong></p>\n", f);
    }
    if (rep->not_built) {
        fputs("<p class=\"fail\">The submission did not build: ", f);
        sl_html_text(f, rep->not_built);
        fputs("</p>\n", f);
    }
    for (int i = 0; i < rep->submission_note_count; i++) {
        fprintf(f, "<p%s>Submission: ", i == 0 && rep->no_lab_file ? " class=\"fail\"" : "");
        sl_html_text(f, rep->submission_notes[i]);
        fputs("</p>\n", f);
    }
    for (int i = 0; i < rep->problem_count; i++) {
        fputs("<p class=\"fail\">PROBLEM ", f);
        sl_html_text(f, rep->problems[i]);
        fputs("</p>\n", f);
    }
    const cJSON *cases = cJSON_GetObjectItemCaseSensitive(root, "cases"), *jc;
    fputs("<table>\n<tr><th>lab</th><th>case / check</th><th>points</th><th>result</th></tr>\n", f);
    cJSON_ArrayForEach(jc, cases) {
        const cJSON *jk;
        cJSON_ArrayForEach(jk, cJSON_GetObjectItemCaseSensitive(jc, "checks")) {
            bool passed = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(jk, "passed"));
            fprintf(f, "<tr><td>%d</td><td>", cJSON_GetObjectItemCaseSensitive(jc, "lab")->valueint);
            sl_html_text(f, cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jc, "name")));
            fputs(" / ", f);
            sl_html_text(f, cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "name")));
            fprintf(f, "%s</td><td>%g/%g</td><td class=\"%s\">%s", cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(jk, "bonus")) ? " (bonus)" : "",
                    cJSON_GetObjectItemCaseSensitive(jk, "points")->valuedouble,
                    cJSON_GetObjectItemCaseSensitive(jk, "max_points")->valuedouble, passed ? "pass" : "fail",
                    passed ? "PASS" : "FAIL ");
            if (!passed) sl_html_text(f, cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "message")));
            const cJSON *imgs = cJSON_GetObjectItemCaseSensitive(jk, "images"), *img;
            if (imgs) fputs("<br>", f);
            cJSON_ArrayForEach(img, imgs) {
                fputs("<figure><img src=\"", f);
                sl_html_text(f, img->valuestring);
                fprintf(f, "\"><figcaption>%s</figcaption></figure>", img->string);
            }
            if (imgs) _sl_html_legend(f, cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(jk, "kind")));
            fputs("</td></tr>\n", f);
        }
    }
    fputs("</table>\n</body></html>\n", f);
    return sl_atomic_commit(&file, err, err_size);
}

bool sl_report_write_junit(const sl_grade_report *rep, const char *path, char *err, size_t err_size) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, err_size)) return false;
    FILE *f = file.f;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadowlab\">\n", f);
    for (int lab = 0; lab <= SL_LAB_MAX; lab++) {
        int tests = 0, failures = 0, skipped = 0;
        double score = 0, max = 0, bonus = 0;
        for (int i = 0; i < rep->case_count; i++)
            if (rep->cases[i].c->lab == lab)
                for (int k = 0; k < rep->cases[i].c->check_count; k++) {
                    const sl_check_result *cr = &rep->cases[i].checks[k];
                    tests++;
                    /* a bonus not earned costs nothing: skipped, not failed */
                    failures += !cr->passed && !cr->bonus;
                    skipped += !cr->passed && cr->bonus;
                    if (cr->bonus) bonus += cr->points;
                    else score += cr->points, max += cr->max_points;
                }
        if (!tests) continue;
        fprintf(f, "  <testsuite name=\"lab%d ", lab);
        sl_html_text(f, _sl_report_lab_title(lab));
        fprintf(f, "\" tests=\"%d\" failures=\"%d\" skipped=\"%d\">\n", tests, failures, skipped);
        fprintf(f, "    <properties><property name=\"score\" value=\"%g\"/><property name=\"max_score\" value=\"%g\"/>"
                   "<property name=\"bonus\" value=\"%g\"/><property name=\"total\" value=\"%g\"/>"
                   "<property name=\"bonus_policy\" value=\"%s\"/></properties>\n",
                score, max, bonus, sl_bonus_total(rep->bonus_policy, score, max, bonus),
                sl_bonus_policy_name(rep->bonus_policy));
        for (int i = 0; i < rep->case_count; i++) {
            const sl_graded_case *g = &rep->cases[i];
            if (g->c->lab != lab) continue;
            for (int k = 0; k < g->c->check_count; k++) {
                const sl_check_result *cr = &g->checks[k];
                fputs("    <testcase classname=\"", f);
                sl_html_text(f, g->c->name);
                fputs("\" name=\"", f);
                sl_html_text(f, g->c->checks[k].name);
                fprintf(f, "\" time=\"%.3f\">", g->result->seconds);
                if (!cr->passed) {
                    const char *element = cr->bonus ? "skipped" : "failure";
                    fprintf(f, "<%s message=\"%g/%g points%s\">", element, cr->points, cr->max_points,
                            cr->bonus ? ", a bonus not earned" : "");
                    sl_html_text(f, cr->message);
                    fprintf(f, "</%s>", element);
                }
                fputs("</testcase>\n", f);
            }
        }
        fputs("  </testsuite>\n", f);
    }
    fputs("</testsuites>\n", f);
    return sl_atomic_commit(&file, err, err_size);
}

/* Labs graded on their own that did not build (the others were graded):
 * "labs_not_built" [{lab, error}], and the first as "build_error". */
static void _sl_add_labs_not_built(const sl_grade_report *rep, cJSON *root) {
    cJSON *list = NULL;
    for (int lab = 1; lab <= SL_LAB_MAX; lab++) {
        if (!rep->lab_not_built[lab]) continue;
        if (!list) {
            list = cJSON_AddArrayToObject(root, "labs_not_built");
            if (!rep->not_built) {
                char text[SL_BUILD_ERROR_MAX + 64];
                snprintf(text, sizeof text, "lab %d did not build: %s", lab, rep->lab_not_built[lab]);
                sl_utf8_trim(text);
                cJSON_AddStringToObject(root, "build_error", text);
            }
        }
        cJSON *l = cJSON_CreateObject();
        cJSON_AddNumberToObject(l, "lab", lab);
        cJSON_AddStringToObject(l, "error", rep->lab_not_built[lab]);
        cJSON_AddItemToArray(list, l);
    }
}

/* What the course platforms show above the tests: what did not build, what
 * stopped, and the bonus in words (their scores stop at the maximum). */
/* The stager's no-lab-file note ends by saying how every lab is graded; an upload
 * PrairieLearn is told is not gradable was not graded at all, so it says that instead. */
static void _sl_note_for_platform(const char *note, bool graded, char *out, size_t n) {
    static const char tail[] = " Every lab is graded as the handout's stub.";
    size_t len = strlen(note), tail_len = sizeof tail - 1;
    if (!graded && len >= tail_len && strcmp(note + len - tail_len, tail) == 0)
        snprintf(out, n, "%.*s Nothing was graded: upload the lab files (this upload costs no attempt).",
                 (int)(len - tail_len), note);
    else
        snprintf(out, n, "%s", note);
}

/* PrairieLearn's verdict: a submission that did not build or held no lab file is
 * "not gradable" (it costs the student no attempt), as is a grade the staff must look at. */
static bool _sl_prairielearn_gradable(const sl_grade_report *rep) {
    return rep->problem_count == 0 && !rep->interrupted && !rep->not_built && !rep->no_lab_file;
}

static void _sl_platform_text(const sl_grade_report *rep, bool prairielearn, char *text, size_t n) {
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    size_t used = 0;
    text[0] = '\0';
#define _SL_SAY(...) (used += used < n ? (size_t)snprintf(text + used, n - used, __VA_ARGS__) : 0)
    bool graded = !prairielearn || _sl_prairielearn_gradable(rep);
    for (int i = 0; i < rep->submission_note_count; i++) {
        char note[sizeof rep->submission_notes[0] + 100];
        _sl_note_for_platform(rep->submission_notes[i], graded, note, sizeof note);
        _SL_SAY("%s\n", note);
    }
    if (rep->not_built) _SL_SAY("The submission did not build: %s\n", rep->not_built);
    for (int lab = 1; lab <= SL_LAB_MAX && !rep->not_built; lab++)
        if (rep->lab_not_built[lab])
            _SL_SAY("Lab %d did not build: %s (the other labs were graded on their own)\n", lab,
                    rep->lab_not_built[lab]);
    if (rep->interrupted) _SL_SAY("The grader was stopped before it finished: incomplete.\n");
    for (int i = 0; i < rep->problem_count; i++) _SL_SAY("%s\n", rep->problems[i]);
    if (bonus > 0) {
        double total = sl_bonus_total(rep->bonus_policy, score, max, bonus);
        if (rep->bonus_policy == SL_BONUS_APART)
            _SL_SAY("Bonus: %g points earned on extension checks, kept apart from the score (%g/%g): the course "
                    "counts them on its own.\n", bonus, score, max);
        else if (total < score + bonus)
            _SL_SAY("Bonus: %g points earned on extension checks; %g of them counted, since the score stops at its "
                    "maximum (%g).\n", bonus, total - score, max);
        else if (prairielearn && total > max)
            _SL_SAY("Bonus: %g points earned on extension checks, counted in the score (%g/%g); PrairieLearn's "
                    "score stops at 100%%.\n", bonus, total, max);
        else
            _SL_SAY("Bonus: %g points earned on extension checks, counted in the score (%g/%g).\n", bonus, total,
                    max);
    }
#undef _SL_SAY
    sl_utf8_trim(text);
}

bool sl_report_write_dir(const sl_grade_report *rep, const char *dir, char *err, size_t err_size) {
    char images[1100];
    snprintf(images, sizeof images, "%s/images", dir);
    if (!sl_mkdirs(images)) {
        snprintf(err, err_size, "%s: cannot create the report folder", images);
        return false;
    }
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    cJSON *root = cJSON_CreateObject();
    cJSON_AddNumberToObject(root, "score", score);
    cJSON_AddNumberToObject(root, "max_score", max);
    cJSON_AddNumberToObject(root, "bonus", bonus);
    /* the one number every other report and the gradebook show */
    cJSON_AddStringToObject(root, "bonus_policy", sl_bonus_policy_name(rep->bonus_policy));
    cJSON_AddNumberToObject(root, "total", sl_bonus_total(rep->bonus_policy, score, max, bonus));
    cJSON_AddBoolToObject(root, "complete", !rep->interrupted);
    cJSON_AddNumberToObject(root, "seconds", rep->seconds);
    cJSON_AddStringToObject(root, "labs", rep->labs_kind);
    cJSON_AddStringToObject(root, "backend", rep->backend);
    cJSON_AddStringToObject(root, "renderer", rep->renderer);
    cJSON_AddStringToObject(root, "sandbox", rep->sandbox);
    if (rep->self_check) cJSON_AddStringToObject(root, "self_check", rep->self_check);
    if (rep->case_set[0]) cJSON_AddStringToObject(root, "case_set", rep->case_set);
    /* what made this grade: a gradebook row says it, and a pass with other options is told apart */
    cJSON_AddStringToObject(root, "options", rep->options);
    if (rep->seed) cJSON_AddStringToObject(root, "seed", rep->seed);
    cJSON_AddBoolToObject(root, "built", rep->not_built == NULL);
    if (rep->not_built) cJSON_AddStringToObject(root, "build_error", rep->not_built);
    _sl_add_labs_not_built(rep, root);
    if (rep->submission_summary) {
        cJSON_AddBoolToObject(root, "no_lab_file", rep->no_lab_file);
        cJSON *notes = cJSON_AddArrayToObject(root, "submission_notes");
        for (int i = 0; i < rep->submission_note_count; i++)
            cJSON_AddItemToArray(notes, cJSON_CreateString(rep->submission_notes[i]));
        cJSON_AddItemToObject(root, "submission", cJSON_Duplicate(rep->submission_summary, true));
    }
    cJSON *labs = cJSON_AddArrayToObject(root, "lab_scores");
    for (int lab = 0; lab <= SL_LAB_MAX; lab++) {
        double s = 0, m = 0, b = 0;
        bool any = false;
        for (int i = 0; i < rep->case_count; i++)
            if (rep->cases[i].c->lab == lab)
                for (int k = 0; k < rep->cases[i].c->check_count; k++) {
                    const sl_check_result *cr = &rep->cases[i].checks[k];
                    any = true;
                    if (cr->bonus) {
                        b += cr->points;
                    } else {
                        s += cr->points;
                        m += cr->max_points;
                    }
                }
        if (!any) continue;
        cJSON *l = cJSON_CreateObject();
        cJSON_AddNumberToObject(l, "lab", lab);
        cJSON_AddStringToObject(l, "title", _sl_report_lab_title(lab));
        cJSON_AddNumberToObject(l, "score", s);
        cJSON_AddNumberToObject(l, "max_score", m);
        cJSON_AddNumberToObject(l, "bonus", b);
        cJSON_AddItemToArray(labs, l);
    }
    cJSON *cases = cJSON_AddArrayToObject(root, "cases");
    bool ok = true;
    for (int i = 0; i < rep->case_count; i++) {
        const sl_graded_case *g = &rep->cases[i];
        cJSON *jc = cJSON_CreateObject();
        cJSON_AddStringToObject(jc, "name", g->c->name);
        cJSON_AddStringToObject(jc, "title", g->c->title);
        cJSON_AddNumberToObject(jc, "lab", g->c->lab);
        cJSON_AddNumberToObject(jc, "seconds", g->result->seconds);
        if (g->result->output_tail[0]) cJSON_AddStringToObject(jc, "output", g->result->output_tail);
        cJSON_AddNumberToObject(jc, "cpu_seconds", g->result->cpu_seconds);
        cJSON_AddNumberToObject(jc, "render_seconds", g->result->render_seconds);
        cJSON *checks = cJSON_AddArrayToObject(jc, "checks");
        for (int k = 0; k < g->c->check_count; k++) {
            const sl_check *ck = &g->c->checks[k];
            const sl_check_result *cr = &g->checks[k];
            cJSON *j = cJSON_CreateObject();
            cJSON_AddStringToObject(j, "name", ck->name);
            cJSON_AddStringToObject(j, "kind", sl_check_kind_name(ck->kind));
            cJSON_AddNumberToObject(j, "points", cr->points);
            cJSON_AddNumberToObject(j, "max_points", cr->max_points);
            cJSON_AddBoolToObject(j, "passed", cr->passed);
            cJSON_AddBoolToObject(j, "bonus", cr->bonus);
            cJSON_AddStringToObject(j, "message", cr->message);
            if (!cr->passed && cr->diagnosis[0]) {
                cJSON_AddStringToObject(j, "diagnosis", cr->diagnosis);
                cJSON_AddStringToObject(j, "diagnosis_text", cr->diagnosis_text);
            }
            if (!cr->passed && cr->cause_kind) { /* the function behind the mistake: the class report counts it once */
                cJSON *cause = cJSON_AddObjectToObject(j, "cause");
                cJSON_AddStringToObject(cause, "function", cr->cause_function);
                cJSON_AddStringToObject(cause, "kind", cr->cause_kind);
            }
            const sl_capture *cap = sl_result_capture(g->result, sl_check_capture_name(g->c, ck));
            if (!cr->passed && cap && cap->is_image) {
                const sl_image *shown[3] = {&cap->image, &g->references[k].image, &cr->diff};
                static const char *const roles[3] = {"student", "reference", "diff"};
                cJSON *imgs = cJSON_AddObjectToObject(j, "images");
                for (int m = 0; m < 3; m++) {
                    char path[1400], name[300];
                    if (!shown[m]->data) continue;
                    snprintf(name, sizeof name, "images/%s.%s.%s.png", g->c->name, ck->name, roles[m]);
                    snprintf(path, sizeof path, "%s/%s", dir, name);
                    sl_image coloured = m < 2 ? _sl_for_people(ck->kind, shown[m]) : (sl_image){0};
                    if (sl_atomic_write_image(path, coloured.data ? &coloured : shown[m], err, err_size))
                        cJSON_AddStringToObject(imgs, roles[m], name);
                    else ok = false;
                    sl_image_free(&coloured);
                }
            }
            cJSON_AddItemToArray(checks, j);
        }
        cJSON_AddItemToArray(cases, jc);
    }
    cJSON *problems = cJSON_AddArrayToObject(root, "problems");
    for (int i = 0; i < rep->problem_count; i++) cJSON_AddItemToArray(problems, cJSON_CreateString(rep->problems[i]));
    char path[1100];
    snprintf(path, sizeof path, "%s/results.json", dir);
    ok = _sl_write_json(root, path, err, err_size) && ok;
    snprintf(path, sizeof path, "%s/report.html", dir);
    ok = _sl_write_html(rep, root, path, err, err_size) && ok;
    cJSON_Delete(root);
    return ok;
}

/* One test per check, as Gradescope and PrairieLearn list them. A bonus
 * check is a test of its own points, named so; Gradescope shows the tests
 * of hidden cases after the due date; PrairieLearn gets the diff image of a
 * failed picture (its results stay under 1 MB: the images share 600 kB). */
static void _sl_add_tests(const sl_grade_report *rep, cJSON *tests, bool prairielearn) {
    size_t image_budget = 600 * 1024;
    for (int i = 0; i < rep->case_count; i++) {
        const sl_graded_case *g = &rep->cases[i];
        for (int k = 0; k < g->c->check_count; k++) {
            const sl_check_result *cr = &g->checks[k];
            char name[300];
            snprintf(name, sizeof name, "Lab %d (%s): %s / %s%s", g->c->lab, sl_lab_title(g->c->lab), g->c->name,
                     g->c->checks[k].name, cr->bonus ? " (bonus)" : "");
            cJSON *t = cJSON_CreateObject();
            cJSON_AddStringToObject(t, "name", name);
            cJSON_AddNumberToObject(t, prairielearn ? "points" : "score", cr->points);
            cJSON_AddNumberToObject(t, prairielearn ? "max_points" : "max_score", cr->max_points);
            cJSON_AddStringToObject(t, "output", cr->passed ? "passed" : cr->message);
            if (!prairielearn) cJSON_AddStringToObject(t, "status", cr->passed ? "passed" : "failed");
            if (!prairielearn && rep->hidden) cJSON_AddStringToObject(t, "visibility", "after_due_date");
            if (prairielearn && !cr->passed && cr->diff.data && image_budget > 0) {
                char *url = sl_image_data_url(&cr->diff, image_budget < 200 * 1024 ? image_budget : 200 * 1024);
                if (url) {
                    cJSON *image = cJSON_CreateObject();
                    cJSON_AddStringToObject(image, "label", "difference from the reference");
                    cJSON_AddStringToObject(image, "url", url);
                    cJSON_AddItemToArray(cJSON_AddArrayToObject(t, "images"), image);
                    image_budget -= strlen(url) < image_budget ? strlen(url) : image_budget;
                    free(url);
                }
            }
            cJSON_AddItemToArray(tests, t);
        }
    }
}

bool sl_report_write_gradescope(const sl_grade_report *rep, const char *path, char *err, size_t err_size) {
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    cJSON *root = cJSON_CreateObject();
    /* the total under the bonus policy (Gradescope shows one above the maximum as extra credit) */
    cJSON_AddNumberToObject(root, "score", sl_bonus_total(rep->bonus_policy, score, max, bonus));
    cJSON_AddNumberToObject(root, "execution_time", rep->seconds);
    char text[4096 + SL_SUBMISSION_NOTES_MAX * 1600];
    _sl_platform_text(rep, false, text, sizeof text);
    if (text[0]) cJSON_AddStringToObject(root, "output", text);
    _sl_add_tests(rep, cJSON_AddArrayToObject(root, "tests"), false);
    bool ok = _sl_write_json(root, path, err, err_size);
    cJSON_Delete(root);
    return ok;
}

bool sl_report_write_prairielearn(const sl_grade_report *rep, const char *path, char *err, size_t err_size) {
    double score, max, bonus;
    sl_report_totals(rep, &score, &max, &bonus);
    cJSON *root = cJSON_CreateObject();
    bool gradable = _sl_prairielearn_gradable(rep);
    cJSON_AddBoolToObject(root, "gradable", gradable);
    cJSON *format_errors = rep->not_built || rep->no_lab_file ? cJSON_AddArrayToObject(root, "format_errors") : NULL;
    if (rep->no_lab_file && rep->submission_note_count) {
        char note[sizeof rep->submission_notes[0] + 100];
        _sl_note_for_platform(rep->submission_notes[0], gradable, note, sizeof note);
        cJSON_AddItemToArray(format_errors, cJSON_CreateString(note));
    }
    if (rep->not_built) {
        char text[512];
        snprintf(text, sizeof text, "The submission did not build: %s", rep->not_built);
        sl_utf8_trim(text);
        cJSON_AddItemToArray(format_errors, cJSON_CreateString(text));
    }
    /* PrairieLearn takes a fraction in [0, 1]: the total under the bonus policy, said in words */
    double fraction = max > 0 ? sl_bonus_total(rep->bonus_policy, score, max, bonus) / max : 0;
    cJSON_AddNumberToObject(root, "score", fraction > 1 ? 1 : fraction < 0 ? 0 : fraction);
    char text[4096 + SL_SUBMISSION_NOTES_MAX * 1600];
    _sl_platform_text(rep, true, text, sizeof text);
    if (text[0]) cJSON_AddStringToObject(root, "message", text);
    _sl_add_tests(rep, cJSON_AddArrayToObject(root, "tests"), true);
    bool ok = _sl_write_json(root, path, err, err_size);
    cJSON_Delete(root);
    return ok;
}
