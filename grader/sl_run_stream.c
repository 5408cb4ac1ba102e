#define _GNU_SOURCE
#include "sl_run_stream.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "sl_protocol.h"
#include "sl_utf8.h"

/* ---- the stream from a runner, taken apart as it arrives ---- */

void _sl_protocol_error(_sl_stream *s, const char *fmt, ...) {
    if (s->r->protocol_error[0]) return;
    va_list args;
    va_start(args, fmt);
    vsnprintf(s->r->protocol_error, sizeof s->r->protocol_error, fmt, args);
    va_end(args);
}

static bool _sl_valid_name(const char *name, size_t n) {
    for (size_t i = 0; i < n; i++) {
        char ch = name[i];
        /* a '.' for a shader stage probed whole ("depth.vert") */
        if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '.')) return false;
    }
    return true;
}

uint32_t _sl_wanted_captures(const sl_case *c) {
    uint32_t wanted = 0;
    for (int i = 0; i < c->check_count; i++) wanted |= sl_check_captures(c, &c->checks[i]);
    return wanted;
}

/* The largest payload a message of this type and name may have; 0 when none is allowed. */
static uint64_t _sl_payload_limit(const _sl_stream *s, uint32_t type, int capture) {
    switch (type) {
    case SL_MSG_HELLO:
    case SL_MSG_ERROR:
    case SL_MSG_CAPTURE_ERROR: return SL_MSG_TEXT_MAX;
    case SL_MSG_GL_ERROR: return SL_MSG_GL_ERROR_MAX;
    case SL_MSG_NUMBERS: return SL_MSG_NUMBERS_MAX * sizeof(double);
    case SL_MSG_RENDER_TIME: return sizeof(double);
    case SL_MSG_IMAGE:
        if (capture == SL_CAPTURE_DEPTH_MAP || capture == SL_CAPTURE_MOMENTS || capture == SL_CAPTURE_MOMENTS_BLURRED ||
            capture == SL_CAPTURE_MOMENTS_PASSES)
            return SL_IMAGE_HEADER_BYTES + 2 * (uint64_t)SL_IMAGE_SIDE_MAX * SL_IMAGE_SIDE_MAX * sizeof(float);
        if (capture == SL_CAPTURE_FLICKER)
            return SL_IMAGE_HEADER_BYTES + (uint64_t)s->c->width * (uint64_t)s->c->height *
                                               (uint64_t)(s->c->frame_count > 0 ? s->c->frame_count : 1) * sizeof(float);
        if (capture >= SL_CAPTURE_CUBE_FACE && capture <= SL_CAPTURE_CUBE_FACE_LAST)
            return SL_IMAGE_HEADER_BYTES + (uint64_t)SL_IMAGE_SIDE_MAX * SL_IMAGE_SIDE_MAX * sizeof(float);
        return SL_IMAGE_HEADER_BYTES + (uint64_t)s->c->width * (uint64_t)s->c->height * 3 * sizeof(float);
    default: return 0;
    }
}

/* Checks a header before its payload is read: a lie about lengths is caught
 * here, before anything is allocated for it. */
static bool _sl_header_ok(_sl_stream *s, const sl_message_header *h, const char *name) {
    if (s->done) {
        _sl_protocol_error(s, "a message after DONE");
        return false;
    }
    if (h->type < SL_MSG_HELLO || h->type >= SL_MSG_TYPE_END) {
        _sl_protocol_error(s, "unknown message type %u", h->type);
        return false;
    }
    /* The runner says what it renders with once, before anything else: lab code, which may write to
     * fd 3 later, must not be able to rename the renderer (frame times compare on the references' one). */
    if (h->type == SL_MSG_HELLO && s->messages > 0) {
        _sl_protocol_error(s, s->r->backend[0] ? "a second HELLO" : "a HELLO after other messages");
        return false;
    }
    if (h->name_length > SL_MSG_NAME_MAX || !_sl_valid_name(name, h->name_length)) {
        _sl_protocol_error(s, "a message with a malformed name");
        return false;
    }
    int capture = -1;
    if (h->type == SL_MSG_IMAGE || h->type == SL_MSG_NUMBERS || h->type == SL_MSG_CAPTURE_ERROR) {
        char n[SL_MSG_NAME_MAX + 1];
        snprintf(n, sizeof n, "%.*s", (int)h->name_length, name);
        capture = sl_capture_parse(n);
        if (capture < 0 || !((s->wanted >> capture) & 1u)) {
            _sl_protocol_error(s, "a capture the case did not ask for (\"%s\")", n);
            return false;
        }
        if ((s->received >> capture) & 1u) {
            _sl_protocol_error(s, "the capture \"%s\" twice", n);
            return false;
        }
    }
    uint64_t limit = _sl_payload_limit(s, h->type, capture);
    if (h->payload_length > limit) {
        _sl_protocol_error(s, "a message of %llu bytes where at most %llu are allowed",
                           (unsigned long long)h->payload_length, (unsigned long long)limit);
        return false;
    }
    return true;
}

/* A compiler's message that filled its buffer was cut: it ends at its last whole line, so the report
 * quotes the compiler's lines as it wrote them, never half of one (other text keeps its every
 * character up to the cut). */
static void _sl_whole_lines(char *text, size_t size) {
    size_t len = strlen(text);
    char *nl = len + 4 >= size && strncmp(text, "GLSL compile error in ", 22) == 0 ? strrchr(text, '\n') : NULL;
    if (nl) nl[1] = '\0';
}

static void _sl_take_image(_sl_stream *s, int capture, const char *payload, uint64_t n) {
    sl_case_result *r = s->r;
    int32_t dims[3];
    if (n < SL_IMAGE_HEADER_BYTES) {
        _sl_protocol_error(s, "an image without its size");
        return;
    }
    memcpy(dims, payload, sizeof dims);
    bool moments = capture == SL_CAPTURE_MOMENTS || capture == SL_CAPTURE_MOMENTS_BLURRED ||
                   capture == SL_CAPTURE_MOMENTS_PASSES;
    bool cube_face = capture >= SL_CAPTURE_CUBE_FACE && capture <= SL_CAPTURE_CUBE_FACE_LAST;
    bool camera = capture != SL_CAPTURE_DEPTH_MAP && !moments && !cube_face;
    int channels = capture == SL_CAPTURE_IMAGE ? 3 : moments ? 2 : 1;
    int rows = capture == SL_CAPTURE_FLICKER ? s->c->height * s->c->frame_count : s->c->height; /* frames stacked */
    bool ok = dims[0] > 0 && dims[1] > 0 && dims[0] <= SL_IMAGE_SIDE_MAX && dims[1] <= SL_IMAGE_SIDE_MAX &&
              dims[2] == channels && (!camera || (dims[0] == s->c->width && dims[1] == rows));
    if (!ok || n != SL_IMAGE_HEADER_BYTES + (uint64_t)dims[0] * (uint64_t)dims[1] * (uint64_t)dims[2] * sizeof(float)) {
        _sl_protocol_error(s, "an image whose size does not add up");
        return;
    }
    if (r->capture_count >= SL_RUN_MAX_CAPTURES) return;
    sl_capture *cap = &r->captures[r->capture_count];
    *cap = (sl_capture){.is_image = true};
    snprintf(cap->name, sizeof cap->name, "%s", sl_capture_name(capture));
    cap->image = sl_image_alloc(dims[0], dims[1], dims[2]);
    if (!cap->image.data) {
        snprintf(r->staff_error, sizeof r->staff_error, "the grader ran out of memory for a capture");
        return;
    }
    memcpy(cap->image.data, payload + SL_IMAGE_HEADER_BYTES, (size_t)(n - SL_IMAGE_HEADER_BYTES));
    r->capture_count++;
}

static void _sl_take_message(_sl_stream *s, const sl_message_header *h, const char *name_raw, const char *payload) {
    sl_case_result *r = s->r;
    char name[SL_MSG_NAME_MAX + 1];
    snprintf(name, sizeof name, "%.*s", (int)h->name_length, name_raw);
    int capture = sl_capture_parse(name);
    switch ((sl_message_type)h->type) {
    case SL_MSG_HELLO: { /* "backend\nrenderer": each printed on the report's header line, so one line each */
        size_t n = (size_t)h->payload_length;
        const char *nl = memchr(payload, '\n', n);
        size_t first = nl ? (size_t)(nl - payload) : n;
        sl_utf8_clean(r->backend, sizeof r->backend, payload, first, 0);
        sl_utf8_clean(r->renderer, sizeof r->renderer, nl ? nl + 1 : "", nl ? n - first - 1 : 0, 0);
        break;
    }
    case SL_MSG_STAGE: snprintf(s->stage, sizeof s->stage, "%s", name); break;
    case SL_MSG_NOT_IMPLEMENTED:
        for (int i = 0; i < r->not_implemented_count; i++)
            if (strcmp(r->not_implemented[i], name) == 0) {
                _sl_protocol_error(s, "\"%s\" reported twice", name);
                return;
            }
        if (r->not_implemented_count < 16 && name[0])
            snprintf(r->not_implemented[r->not_implemented_count++], sizeof r->not_implemented[0], "%s", name);
        break;
    case SL_MSG_FAILED: snprintf(r->failed, sizeof r->failed, "%s", name); break;
    case SL_MSG_GL_ERROR: /* GL's words about a lab function's call: shown in a message, never graded */
        if (!name[0] || r->gl_error_count == SL_MSG_GL_ERRORS || sl_result_gl_error(r, name)) break;
        snprintf(r->gl_error_function[r->gl_error_count], sizeof r->gl_error_function[0], "%s", name);
        sl_utf8_clean(r->gl_error[r->gl_error_count], sizeof r->gl_error[0], payload, (size_t)h->payload_length, 0);
        r->gl_error_count++;
        break;
    /* text lab code may have written: made valid UTF-8 without controls here, where it comes in */
    case SL_MSG_ERROR:
        sl_utf8_clean(r->error, sizeof r->error, payload, (size_t)h->payload_length,
                      SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB);
        _sl_whole_lines(r->error, sizeof r->error);
        /* Before its hello the runner has no GL context yet: it could not make
         * one (no display, no headless GL, out of memory), a fault of this
         * machine, never the submission's: the staff's to solve, as a missing
         * reference, and the case is graded again when it is fixed. */
        if (!r->backend[0]) {
            snprintf(r->staff_error, sizeof r->staff_error,
                     "the runner could not make its OpenGL context on this machine: %.*s",
                     (int)sl_utf8_cut(r->error, 400), r->error);
        }
        break;
    case SL_MSG_CAPTURE_ERROR: {
        char text[sizeof r->probe_errors[0]];
        sl_utf8_clean(text, sizeof text, payload, (size_t)h->payload_length, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB);
        _sl_whole_lines(text, sizeof text);
        snprintf(r->capture_error, sizeof r->capture_error, "%s: %s", name, text);
        sl_utf8_trim(r->capture_error);
        if (capture >= SL_CAPTURE_PROBE && capture < SL_CAPTURE_END) {
            char *own = r->probe_errors[capture - SL_CAPTURE_PROBE];
            snprintf(own, sizeof r->probe_errors[0], "%s", text);
            sl_utf8_trim(own);
        }
        s->received |= 1u << capture;
        break;
    }
    case SL_MSG_IMAGE:
        s->received |= 1u << capture;
        _sl_take_image(s, capture, payload, h->payload_length);
        break;
    case SL_MSG_NUMBERS: {
        s->received |= 1u << capture;
        int expected = capture == SL_CAPTURE_FBO ? SL_FBO_NUMBERS : capture == SL_CAPTURE_MATRICES ? SL_MATRICES_NUMBERS : -1;
        if (capture == SL_CAPTURE_MOMENTS_TARGET) expected = SL_MOMENTS_TARGET_NUMBERS;
        if (capture == SL_CAPTURE_PATH) expected = SL_PATH_NUMBERS;
        if (capture >= SL_CAPTURE_PROBE) {
            const sl_check *k = &s->c->checks[capture - SL_CAPTURE_PROBE];
            const sl_probe_function *f = sl_probe_at(k->function);
            expected = f ? k->rows * f->output_count : -1;
        }
        if ((uint64_t)expected * sizeof(double) != h->payload_length) {
            _sl_protocol_error(s, "the capture \"%s\" has the wrong count of numbers", name);
            return;
        }
        if (r->capture_count >= SL_RUN_MAX_CAPTURES) return;
        sl_capture *cap = &r->captures[r->capture_count++];
        *cap = (sl_capture){.number_count = expected};
        snprintf(cap->name, sizeof cap->name, "%s", name);
        memcpy(cap->numbers, payload, (size_t)h->payload_length);
        break;
    }
    case SL_MSG_RENDER_TIME: {
        double t;
        if (h->payload_length != sizeof t) {
            _sl_protocol_error(s, "a render time of the wrong size");
            return;
        }
        memcpy(&t, payload, sizeof t);
        r->render_seconds = t >= 0 && t < 1e6 ? t : 0;
        break;
    }
    case SL_MSG_DONE: s->done = true; break;
    default: break;
    }
}

/* Takes every complete message from the front of the buffer. */
static void _sl_parse_available(_sl_stream *s) {
    size_t pos = 0;
    while (!s->r->protocol_error[0] && s->len - pos >= sizeof(sl_message_header)) {
        sl_message_header h;
        memcpy(&h, s->buf + pos, sizeof h);
        size_t name_have = s->len - pos - sizeof h;
        const char *name = s->buf + pos + sizeof h;
        if (h.name_length > SL_MSG_NAME_MAX) {
            _sl_protocol_error(s, "a message with a malformed name");
            break;
        }
        if (name_have < h.name_length) break;
        if (!_sl_header_ok(s, &h, name)) break;
        /* both lengths are bounded now: the sum cannot overflow */
        uint64_t size = sizeof h + (uint64_t)h.name_length + h.payload_length;
        if (s->len - pos < size) break;
        _sl_take_message(s, &h, name, name + h.name_length);
        s->messages++;
        pos += (size_t)size;
    }
    memmove(s->buf, s->buf + pos, s->len - pos);
    s->len -= pos;
}

bool _sl_stream_feed(_sl_stream *s, const char *data, size_t n) {
    s->total += n;
    if (s->total > _SL_CASE_BYTES_MAX) {
        _sl_protocol_error(s, "more than %llu MiB of results", (unsigned long long)(_SL_CASE_BYTES_MAX >> 20));
        return false;
    }
    if (s->len + n > s->cap) {
        size_t cap = s->cap ? s->cap : 65536;
        while (cap < s->len + n) cap *= 2;
        char *buf = realloc(s->buf, cap);
        if (!buf) {
            snprintf(s->r->staff_error, sizeof s->r->staff_error, "the grader ran out of memory for the results");
            _sl_protocol_error(s, "out of memory for the results");
            return false;
        }
        s->buf = buf;
        s->cap = cap;
    }
    memcpy(s->buf + s->len, data, n);
    s->len += n;
    _sl_parse_available(s);
    return !s->r->protocol_error[0];
}

void _sl_stream_end(_sl_stream *s) {
    if (s->len > 0 && !s->r->protocol_error[0] && s->done) _sl_protocol_error(s, "a message after DONE");
    if (!s->done && s->stage[0]) snprintf(s->r->crashed_in, sizeof s->r->crashed_in, "%s", s->stage);
    free(s->buf);
    s->buf = NULL;
    s->len = s->cap = 0;
}
