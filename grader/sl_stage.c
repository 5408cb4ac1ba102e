#define _GNU_SOURCE
#include "sl_stage.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef SYS_openat2
#include <linux/openat2.h>
#endif

#include <cjson/cJSON.h>

#include "sl_files.h"
#include "sl_stage_channel.h"
#include "sl_stage_child.h"
#include "sl_stage_handout.h"
#include "sl_text.h"

#define _SL_LIST_MAX 400       /* entries kept per list in the summary */

/* ---- the parent: checks what it is sent, writes the stage and the summary ---- */

typedef struct _sl_item {
    char *a, *b;
} _sl_item;

typedef struct _sl_items {
    _sl_item *items;
    int count, dropped;
} _sl_items;

/* Text for people: control characters and bytes that are not UTF-8 as \xNN. */
static char *_sl_printable(const char *s, size_t len) {
    char *out = malloc(len * 4 + 1), *o = out;
    for (size_t i = 0; i < len;) {
        unsigned char ch = (unsigned char)s[i];
        sl_text_problems p;
        size_t seq = 1;
        if (ch >= 0x80) {
            seq = 0;
            for (size_t k = 2; k <= 4 && i + k <= len && !seq; k++)
                if (sl_text_check(s + i, k, &p)) seq = k;
        }
        if (ch < 0x20 || ch == 0x7f || seq == 0) {
            o += sprintf(o, "\\x%02X", ch);
            i++;
        } else {
            memcpy(o, s + i, seq);
            o += seq;
            i += seq;
        }
    }
    *o = '\0';
    return out;
}

static void _sl_list_add(_sl_items *l, const char *a, size_t la, const char *b, size_t lb) {
    if (l->count >= _SL_LIST_MAX) {
        l->dropped++;
        return;
    }
    if (!l->items) l->items = calloc(_SL_LIST_MAX, sizeof *l->items);
    l->items[l->count].a = _sl_printable(a, la);
    l->items[l->count].b = _sl_printable(b ? b : "", b ? lb : 0);
    l->count++;
}

typedef struct _sl_result {
    char fence[_SL_TEXT_MAX], source[16], from[_SL_TEXT_MAX], layout[64];
    bool layout_said, ended;
    _sl_items taken, ignored, refused, found, errors, staff, normalised, text_problems;
    long long taken_bytes;
    bool mismatch; /* a staff problem of its own: the stager read a file wrong */
} _sl_result;

/* A target the stage may receive: LAB/labN.c or LAB/shaders/NAME[/NAME...] (three folders at most). */
static bool _sl_valid_target(const _sl_labs *labs, const char *target) {
    char folder[64];
    const char *slash = strchr(target, '/');
    if (!slash || (size_t)(slash - target) >= sizeof folder) return false;
    snprintf(folder, sizeof folder, "%.*s", (int)(slash - target), target);
    int lab = _sl_lab_index(labs, folder);
    if (lab < 0) return false;
    char c_file[32];
    snprintf(c_file, sizeof c_file, "lab%d.c", labs->number[lab]);
    if (strcmp(slash + 1, c_file) == 0) return true;
    if (strncmp(slash + 1, "shaders/", 8) != 0) return false;
    const char *p = slash + 9;
    int parts = 0;
    while (*p) {
        size_t len = strcspn(p, "/");
        char part[256];
        if (len == 0 || len >= sizeof part) return false;
        snprintf(part, sizeof part, "%.*s", (int)len, p);
        if (!_sl_stageable_name(part) || ++parts > _SL_SHADERS_DEPTH + 1) return false;
        p += len;
        if (*p) p++;
    }
    return parts > 0;
}

/* Writes content at target under the stage, making its folders; never through a link. */
static bool _sl_stage_write(int stage_fd, const char *target, const char *content, size_t len, char *err, size_t n) {
    int dir = dup(stage_fd);
    const char *p = target;
    for (;;) {
        size_t part_len = strcspn(p, "/");
        char part[256];
        snprintf(part, sizeof part, "%.*s", (int)part_len, p);
        if (!p[part_len]) {
            int fd = openat(dir, part, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
            close(dir);
            if (fd < 0) {
                snprintf(err, n, "cannot write %s in the stage (%s)", target, strerror(errno));
                return false;
            }
            bool ok = write(fd, content, len) == (ssize_t)len;
            fchmod(fd, 0644);
            ok = close(fd) == 0 && ok;
            if (!ok) snprintf(err, n, "cannot write %s in the stage", target);
            return ok;
        }
        if (mkdirat(dir, part, 0755) != 0 && errno != EEXIST) {
            snprintf(err, n, "cannot make the folder of %s in the stage (%s)", target, strerror(errno));
            close(dir);
            return false;
        }
        int next = openat(dir, part, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        close(dir);
        if (next < 0) {
            snprintf(err, n, "cannot open the folder of %s in the stage", target);
            return false;
        }
        dir = next;
        p += part_len + 1;
    }
}

static bool _sl_read_exact(int fd, void *buf, size_t n, double deadline) {
    char *p = buf;
    while (n) {
        struct timespec now;
        clock_gettime(CLOCK_MONOTONIC, &now);
        double left = deadline - ((double)now.tv_sec + (double)now.tv_nsec * 1e-9);
        if (left <= 0) return false;
        struct pollfd pfd = {.fd = fd, .events = POLLIN};
        int r = poll(&pfd, 1, (int)(left * 1000) + 1);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        ssize_t got = read(fd, p, n);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        p += got;
        n -= (size_t)got;
    }
    return true;
}

static void _sl_take_file(const sl_stage_desc *d, const _sl_labs *labs, int stage_fd, _sl_result *res, char *target,
                          char *content, size_t len, const char *source, size_t source_len) {
    char *shown_target = _sl_printable(target, strlen(target));
    char err[1400];
    if (!_sl_valid_target(labs, target)) {
        snprintf(err, sizeof err, "the reader sent a file for %s, which is no lab file's place: refused", shown_target);
        _sl_list_add(&res->errors, err, strlen(err), NULL, 0);
    } else if ((long long)len > d->max_file_bytes || res->taken.count >= d->max_files ||
               res->taken_bytes + (long long)len > d->max_total_bytes) {
        _sl_list_add(&res->ignored, source, source_len, "past the limits", 15);
    } else {
        for (int i = 0; i < res->taken.count; i++)
            if (strcmp(res->taken.items[i].b, shown_target) == 0) {
                free(shown_target);
                return; /* one file per place */
            }
        char *shown_source = _sl_printable(source, source_len);
        sl_text_problems problems;
        if (!sl_text_check(content, len, &problems)) {
            char text[1400];
            sl_text_problems_describe(&problems, shown_source, text, sizeof text);
            _sl_list_add(&res->text_problems, text, strlen(text), NULL, 0);
        }
        sl_text_fix fix;
        size_t new_len = problems.utf16 ? len : sl_text_normalize(content, len, &fix);
        if (!problems.utf16 && sl_text_fix_any(&fix)) {
            char what[200];
            sl_text_fix_describe(&fix, what, sizeof what);
            _sl_list_add(&res->normalised, shown_target, strlen(shown_target), what, strlen(what));
        }
        if (_sl_stage_write(stage_fd, target, content, new_len, err, sizeof err)) {
            _sl_list_add(&res->taken, source, source_len, target, strlen(target));
            res->taken_bytes += (long long)len;
        } else {
            _sl_list_add(&res->staff, err, strlen(err), NULL, 0);
        }
        free(shown_source);
    }
    free(shown_target);
}

/* Reads the child's records until its end; false if it stopped without one. */
static bool _sl_receive(const sl_stage_desc *d, const _sl_labs *labs, int stage_fd, int channel, _sl_result *res) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    double deadline = (double)now.tv_sec + (double)now.tv_nsec * 1e-9 + d->timeout;
    size_t content_max = (size_t)d->max_file_bytes;
    char *buf[3] = {malloc(_SL_TEXT_MAX + 1), malloc((content_max > _SL_TEXT_MAX ? content_max : _SL_TEXT_MAX) + 1),
                    malloc(_SL_TEXT_MAX + 1)};
    bool ok = false;
    for (long records = 0; records < 200000; records++) {
        _sl_record_header h;
        if (!_sl_read_exact(channel, &h, sizeof h, deadline)) break;
        bool file = h.kind == _SL_R_FILE;
        if (h.len[0] > _SL_TEXT_MAX || h.len[2] > _SL_TEXT_MAX || h.len[1] > (file ? content_max : _SL_TEXT_MAX)) break;
        bool complete = true;
        for (int k = 0; k < 3 && complete; k++) {
            complete = _sl_read_exact(channel, buf[k], h.len[k], deadline);
            buf[k][h.len[k]] = '\0';
        }
        if (!complete) break;
        const char *a = buf[0], *b = buf[1];
        size_t la = h.len[0], lb = h.len[1];
        switch (h.kind) {
        case _SL_R_FENCE: snprintf(res->fence, sizeof res->fence, "%s", a); break;
        case _SL_R_SOURCE: {
            snprintf(res->source, sizeof res->source, "%s", strcmp(a, "archive") == 0 ? "archive" : "folder");
            char *p = _sl_printable(b, lb);
            snprintf(res->from, sizeof res->from, "%s", p);
            free(p);
            break;
        }
        case _SL_R_LAYOUT: {
            static const char *const layouts[] = {"a labs/ folder", "the lab folders", "loose files"};
            res->layout_said = true;
            for (size_t i = 0; i < 3; i++)
                if (strcmp(a, layouts[i]) == 0) snprintf(res->layout, sizeof res->layout, "%s", layouts[i]);
            break;
        }
        case _SL_R_FOUND: _sl_list_add(&res->found, a, la, b, lb); break;
        case _SL_R_IGNORED: _sl_list_add(&res->ignored, a, la, b, lb); break;
        case _SL_R_REFUSED: _sl_list_add(&res->refused, a, la, b, lb); break;
        case _SL_R_ERROR: _sl_list_add(&res->errors, a, la, NULL, 0); break;
        case _SL_R_STAFF: _sl_list_add(&res->staff, a, la, NULL, 0); break;
        case _SL_R_MISMATCH:
            res->mismatch = true;
            _sl_list_add(&res->staff, a, la, NULL, 0);
            break;
        case _SL_R_FILE: _sl_take_file(d, labs, stage_fd, res, buf[0], buf[1], lb, buf[2], h.len[2]); break;
        case _SL_R_END: ok = true; break;
        default: break;
        }
        if (ok) break;
    }
    for (int k = 0; k < 3; k++) free(buf[k]);
    return ok;
}

/* "a, b, c and 4 more" from a list's first fields (with its second in brackets when with_reason). */
static bool _sl_items_hold(const _sl_items *l, const char *a) {
    for (int i = 0; l && i < l->count; i++)
        if (strcmp(l->items[i].a, a) == 0) return true;
    return false;
}

/* l's items, joined with ", "; those also in `except` left out (a refused file was found too, but
 * is no file the submission gave). */
static void _sl_join_list_except(const _sl_items *l, const _sl_items *except, bool with_reason, int max,
                                 bool skip_clutter, char *out, size_t n) {
    out[0] = '\0';
    int shown = 0, left = 0;
    for (int i = 0; i < l->count; i++) {
        if (skip_clutter && strcmp(l->items[i].b, "clutter") == 0) continue;
        if (_sl_items_hold(except, l->items[i].a)) continue;
        if (shown >= max) {
            left++;
            continue;
        }
        size_t used = strlen(out);
        if (with_reason && l->items[i].b[0])
            snprintf(out + used, n - used, "%s%s (%s)", shown ? ", " : "", l->items[i].a, l->items[i].b);
        else
            snprintf(out + used, n - used, "%s%s", shown ? ", " : "", l->items[i].a);
        shown++;
    }
    left += l->dropped;
    if (left) snprintf(out + strlen(out), n - strlen(out), " and %d more", left);
}

static void _sl_join_list(const _sl_items *l, bool with_reason, int max, bool skip_clutter, char *out, size_t n) {
    _sl_join_list_except(l, NULL, with_reason, max, skip_clutter, out, n);
}

static cJSON *_sl_json_list(const _sl_items *l, const char *first, const char *second) {
    cJSON *array = cJSON_CreateArray();
    for (int i = 0; i < l->count; i++) {
        if (!second) {
            cJSON_AddItemToArray(array, cJSON_CreateString(l->items[i].a));
            continue;
        }
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, first, l->items[i].a);
        cJSON_AddStringToObject(o, second, l->items[i].b);
        cJSON_AddItemToArray(array, o);
    }
    return array;
}

static void _sl_accepted_layouts(const _sl_labs *labs, char *out, size_t n) {
    const char *shader = NULL;
    for (int i = 0; i < labs->file_count && !shader; i++)
        if (strstr(labs->files[i], "/shaders/")) shader = strrchr(labs->files[i], '/') + 1;
    snprintf(out, n,
             "a labs/ folder (labs/%s/lab%d.c, ...), the lab folders (%s/lab%d.c, %s/shaders/%s, ...), or the lab "
             "files loose (lab%d.c, %s, ...); as a folder, a .zip or a .tar.gz, possibly inside one top folder",
             labs->folder[0], labs->number[0], labs->folder[0], labs->number[0], labs->folder[0],
             shader ? shader : "...", labs->number[0], shader ? shader : "...");
}

/* Sentences for the reports, the most important first. */
static cJSON *_sl_notes(const _sl_labs *labs, const _sl_result *res, bool no_lab_file) {
    cJSON *notes = cJSON_CreateArray();
    char text[8192], list[6000];
    if (no_lab_file) {
        char accepted[1000];
        _sl_accepted_layouts(labs, accepted, sizeof accepted);
        _sl_join_list_except(&res->found, &res->refused, false, 12, true, list, sizeof list);
        char clutter[1000];
        _sl_join_list_except(&res->found, &res->refused, false, 6, false, clutter, sizeof clutter);
        if (!list[0] && (res->errors.count || res->refused.count)) {
            snprintf(text, sizeof text, "No lab file found: %s. Accepted layouts: %s. Every lab is graded as the "
                     "handout's stub.", res->errors.count ? res->errors.items[0].a : "nothing but what was refused (below)",
                     accepted);
        } else if (!list[0] && clutter[0]) {
            snprintf(text, sizeof text, "No lab file found: the submission holds only what macOS or Windows add (%s). "
                     "Accepted layouts: %s. Every lab is graded as the handout's stub.", clutter, accepted);
        } else if (!list[0]) {
            snprintf(text, sizeof text, "No lab file found: the submission is empty. Accepted layouts: %s. Every lab "
                     "is graded as the handout's stub.", accepted);
        } else {
            snprintf(text, sizeof text, "No lab file found: found %s. Accepted layouts: %s. Every lab is graded as the "
                     "handout's stub.", list, accepted);
        }
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    for (int i = 0; i < res->errors.count; i++) cJSON_AddItemToArray(notes, cJSON_CreateString(res->errors.items[i].a));
    if (res->refused.count) {
        _sl_join_list(&res->refused, true, 12, false, list, sizeof list);
        snprintf(text, sizeof text, "Refused, never read (the handout's stub stays in its place): %s.", list);
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    for (int i = 0; i < res->text_problems.count; i++)
        cJSON_AddItemToArray(notes, cJSON_CreateString(res->text_problems.items[i].a));
    for (int i = 0; i < res->ignored.count; i++)
        if (strncmp(res->ignored.items[i].b, "more than", 9) == 0 || strncmp(res->ignored.items[i].b, "past the", 8) == 0 ||
            strncmp(res->ignored.items[i].b, "deeper", 6) == 0) {
            snprintf(text, sizeof text, "Left out: %s (%s).", res->ignored.items[i].a, res->ignored.items[i].b);
            cJSON_AddItemToArray(notes, cJSON_CreateString(text));
        }
    if (res->normalised.count) {
        _sl_join_list(&res->normalised, false, 40, false, list, sizeof list);
        snprintf(text, sizeof text, "Line ends and byte-order marks made plain before compiling (as Windows and "
                 "old macOS editors write them): %s.", list);
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    return notes;
}

static void _sl_say(const sl_stage_desc *d, const char *format, const char *text) {
    fprintf(d->log, "%s", d->log_prefix);
    fprintf(d->log, format, text);
    fputc('\n', d->log);
}

static int _sl_finish(const sl_stage_desc *d, const _sl_labs *labs, _sl_result *res) {
    bool no_lab_file = res->taken.count == 0;
    bool staff = res->staff.count > 0;
    char list[8192];
    if (res->fence[0]) _sl_say(d, "read the submission as %s", res->fence);
    if (!no_lab_file) {
        char line[9000];
        _sl_join_list(&res->taken, false, 400, false, list, sizeof list);
        /* the places in the stage, as before: "took lab1_depth_fbo/lab1.c ..." */
        list[0] = '\0';
        for (int i = 0; i < res->taken.count; i++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", i ? " " : "", res->taken.items[i].b);
        snprintf(line, sizeof line, "layout: %s%s%s%s; took %s", res->layout, res->from[0] ? " (in " : "", res->from,
                 res->from[0] ? "/)" : "", list);
        _sl_say(d, "%s", line);
    }
    if (res->ignored.count) {
        _sl_join_list(&res->ignored, true, 40, false, list, sizeof list);
        _sl_say(d, "ignored: %s", list);
    }
    if (res->refused.count) {
        _sl_join_list(&res->refused, true, 40, false, list, sizeof list);
        _sl_say(d, "refused (never read): %s", list);
    }
    if (res->normalised.count) {
        _sl_join_list(&res->normalised, true, 40, false, list, sizeof list);
        _sl_say(d, "normalised: %s", list);
    }
    for (int i = 0; i < res->text_problems.count; i++) _sl_say(d, "%s", res->text_problems.items[i].a);
    for (int i = 0; i < res->errors.count; i++) _sl_say(d, "%s", res->errors.items[i].a);
    for (int i = 0; i < res->staff.count; i++) _sl_say(d, "PROBLEM (not the submission's fault) %s", res->staff.items[i].a);
    cJSON *notes = _sl_notes(labs, res, no_lab_file);
    if (no_lab_file) _sl_say(d, "%s", cJSON_GetArrayItem(notes, 0)->valuestring);

    int status = res->mismatch ? SL_STAGE_MISMATCH
                 : staff       ? SL_STAGE_PROBLEM
                 : no_lab_file ? SL_STAGE_NO_LAB_FILE
                               : SL_STAGE_TAKEN;
    if (d->summary) {
        cJSON *root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "submission", d->submission);
        cJSON_AddStringToObject(root, "source", res->source[0] ? res->source : "folder");
        cJSON_AddStringToObject(root, "looked_into", res->from);
        if (no_lab_file) cJSON_AddNullToObject(root, "layout");
        else cJSON_AddStringToObject(root, "layout", res->layout);
        cJSON_AddBoolToObject(root, "lab_files_found", !no_lab_file);
        cJSON_AddStringToObject(root, "read_as", res->fence);
        cJSON_AddItemToObject(root, "taken", _sl_json_list(&res->taken, "path", "as"));
        cJSON_AddItemToObject(root, "ignored", _sl_json_list(&res->ignored, "path", "reason"));
        cJSON_AddItemToObject(root, "refused", _sl_json_list(&res->refused, "path", "reason"));
        cJSON_AddItemToObject(root, "normalised", _sl_json_list(&res->normalised, "file", "what"));
        cJSON_AddItemToObject(root, "text_errors", _sl_json_list(&res->text_problems, NULL, NULL));
        cJSON_AddItemToObject(root, "errors", _sl_json_list(&res->errors, NULL, NULL));
        cJSON_AddItemToObject(root, "staff_problems", _sl_json_list(&res->staff, NULL, NULL));
        if (no_lab_file) {
            cJSON *found = cJSON_AddArrayToObject(root, "found");
            for (int i = 0; i < res->found.count; i++)
                cJSON_AddItemToArray(found, cJSON_CreateString(res->found.items[i].a));
            char accepted[1000];
            _sl_accepted_layouts(labs, accepted, sizeof accepted);
            cJSON_AddStringToObject(root, "accepted_layouts", accepted);
        }
        cJSON_AddItemToObject(root, "notes", notes);
        notes = NULL;
        char *text = cJSON_Print(root);
        cJSON_Delete(root);
        sl_atomic_file f;
        char err[1500];
        bool ok = text && sl_atomic_open(&f, d->summary, err, sizeof err);
        if (ok) {
            fputs(text, f.f);
            fputc('\n', f.f);
            ok = sl_atomic_commit(&f, err, sizeof err);
        }
        free(text);
        if (!ok) {
            _sl_say(d, "PROBLEM %s", err);
            status = SL_STAGE_PROBLEM;
        }
    }
    cJSON_Delete(notes);
    return status;
}

int sl_stage_run(const sl_stage_desc *given) {
    sl_stage_desc d = *given;
    if (!d.max_files) d.max_files = 256;
    if (!d.max_file_bytes) d.max_file_bytes = 1 << 20;
    if (!d.max_total_bytes) d.max_total_bytes = 16 << 20;
    if (!d.max_entries) d.max_entries = 20000;
    if (!d.max_depth) d.max_depth = 16;
    if (!d.max_unpacked_bytes) d.max_unpacked_bytes = 512ull << 20;
    if (d.timeout <= 0) d.timeout = 120;
    if (!d.log) d.log = stdout;
    if (!d.log_prefix) d.log_prefix = "shadowlab-stage: ";
    int stage_fd = open(d.stage, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (stage_fd < 0) {
        fprintf(stderr, "%sthe stage %s cannot be opened (%s)\n", d.log_prefix, d.stage, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    _sl_labs labs = {0};
    char err[600];
    if (!_sl_read_labs(stage_fd, &labs, err, sizeof err)) {
        fprintf(stderr, "%s%s: %s\n", d.log_prefix, d.stage, err);
        close(stage_fd);
        return SL_STAGE_PROBLEM;
    }
    int channel[2];
    if (pipe2(channel, O_CLOEXEC) != 0) {
        fprintf(stderr, "%scannot make a pipe (%s)\n", d.log_prefix, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    fflush(NULL);
    pid_t child = fork();
    if (child < 0) {
        fprintf(stderr, "%scannot start the process that reads the submission (%s)\n", d.log_prefix, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    if (child == 0) {
        close(channel[0]);
        close(stage_fd);
        signal(SIGPIPE, SIG_DFL);
        _sl_child_main(&d, &labs, channel[1]);
        _exit(SL_STAGE_PROBLEM);
    }
    close(channel[1]);
    _sl_result res = {0};
    bool ended = _sl_receive(&d, &labs, stage_fd, channel[0], &res);
    close(channel[0]);
    if (!ended) kill(child, SIGKILL);
    int wstatus = 0;
    while (waitpid(child, &wstatus, 0) < 0 && errno == EINTR) {
    }
    close(stage_fd);
    if (!ended) {
        char text[300];
        if (WIFSIGNALED(wstatus))
            snprintf(text, sizeof text, "the submission could not be read to its end: its reader was stopped (signal "
                     "%d%s)", WTERMSIG(wstatus), WTERMSIG(wstatus) == SIGXCPU || WTERMSIG(wstatus) == SIGKILL ?
                     ": too slow, a damaged or huge archive?" : "");
        else
            snprintf(text, sizeof text, "the submission could not be read to its end (its reader exited with %d)",
                     WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
        if (!res.fence[0] || (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == SL_STAGE_PROBLEM))
            _sl_list_add(&res.staff, text, strlen(text), NULL, 0);
        else
            _sl_list_add(&res.errors, text, strlen(text), NULL, 0);
    }
    return _sl_finish(&d, &labs, &res);
}
