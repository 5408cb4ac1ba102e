#include "sl_text.h"

#include <stdio.h>
#include <string.h>

/* The length of the UTF-8 sequence at p (at most `left` bytes), or 0 when it
 * is not well-formed (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF). */
static size_t _sl_utf8_sequence(const unsigned char *p, size_t left) {
    unsigned char c = p[0];
    if (c < 0x80) return 1;
    size_t n;
    unsigned char lo = 0x80, hi = 0xbf; /* the range of the second byte */
    if (c >= 0xc2 && c <= 0xdf) n = 2;
    else if (c == 0xe0) n = 3, lo = 0xa0;
    else if (c == 0xed) n = 3, hi = 0x9f;
    else if (c >= 0xe1 && c <= 0xef) n = 3;
    else if (c == 0xf0) n = 4, lo = 0x90;
    else if (c == 0xf4) n = 4, hi = 0x8f;
    else if (c >= 0xf1 && c <= 0xf3) n = 4;
    else return 0;
    if (left < n || p[1] < lo || p[1] > hi) return 0;
    for (size_t i = 2; i < n; i++)
        if (p[i] < 0x80 || p[i] > 0xbf) return 0;
    return n;
}

sl_text_problem sl_text_normalize(char *data, size_t *length, sl_text_report *report) {
    sl_text_report local;
    sl_text_report *r = report ? report : &local;
    memset(r, 0, sizeof *r);
    const unsigned char *p = (const unsigned char *)data;
    size_t n = *length;
    if (n >= 2 && ((p[0] == 0xff && p[1] == 0xfe) || (p[0] == 0xfe && p[1] == 0xff))) {
        r->problem = SL_TEXT_UTF16;
        r->line = r->column = 1;
        r->byte = p[0];
        return r->problem;
    }
    size_t start = n >= 3 && p[0] == 0xef && p[1] == 0xbb && p[2] == 0xbf ? 3 : 0;
    int line = 1;
    size_t line_start = start;
    for (size_t i = start; i < n;) {
        size_t step = p[i] == 0 ? 0 : _sl_utf8_sequence(p + i, n - i);
        if (step == 0) {
            r->problem = p[i] == 0 ? SL_TEXT_NUL : SL_TEXT_INVALID_UTF8;
            r->offset = i;
            r->line = line;
            r->column = (int)(i - line_start) + 1;
            r->byte = p[i];
            return r->problem;
        }
        if (p[i] == '\n' || (p[i] == '\r' && !(i + 1 < n && p[i + 1] == '\n'))) {
            line++;
            line_start = i + 1;
        }
        i += step;
    }
    /* Text: drop the mark, and make every line end LF. */
    r->had_bom = start == 3;
    size_t out = 0;
    for (size_t i = start; i < n; i++) {
        if (data[i] == '\r') {
            if (i + 1 < n && data[i + 1] == '\n') {
                r->crlf_count++;
                continue; /* the LF follows */
            }
            r->cr_count++;
            data[out++] = '\n';
            continue;
        }
        data[out++] = data[i];
    }
    data[out] = '\0';
    *length = out;
    return SL_TEXT_OK;
}

bool sl_text_changed(const sl_text_report *r) {
    return r->problem == SL_TEXT_OK && (r->had_bom || r->crlf_count || r->cr_count);
}

void sl_text_describe(const sl_text_report *r, const char *path, char *out, size_t n) {
    if (n == 0) return;
    out[0] = '\0';
    switch (r->problem) {
    case SL_TEXT_NUL:
        snprintf(out, n, "%s: byte %zu (line %d, column %d): a NUL byte (0x00): this is not a text file, or it was "
                         "saved with an encoding other than UTF-8",
                 path, r->offset, r->line, r->column);
        return;
    case SL_TEXT_INVALID_UTF8:
        snprintf(out, n, "%s: byte %zu (line %d, column %d): 0x%02x is not UTF-8 (saved as Latin-1 or another "
                         "encoding?): save the file as UTF-8",
                 path, r->offset, r->line, r->column, r->byte);
        return;
    case SL_TEXT_UTF16:
        snprintf(out, n, "%s: byte 0: the file is UTF-16 (a byte-order mark 0x%02x 0x%02x): save it as UTF-8", path,
                 r->byte, r->byte == 0xff ? 0xfe : 0xff);
        return;
    case SL_TEXT_OK: break;
    }
    if (!sl_text_changed(r)) return;
    int used = snprintf(out, n, "%s:", path);
    const char *sep = " ";
    if (r->had_bom && used > 0 && (size_t)used < n) {
        used += snprintf(out + used, n - (size_t)used, "%sa UTF-8 byte-order mark removed", sep);
        sep = ", ";
    }
    if (r->crlf_count && used > 0 && (size_t)used < n) {
        used += snprintf(out + used, n - (size_t)used, "%s%zu CRLF line end%s made LF", sep, r->crlf_count,
                         r->crlf_count == 1 ? "" : "s");
        sep = ", ";
    }
    if (r->cr_count && used > 0 && (size_t)used < n)
        snprintf(out + used, n - (size_t)used, "%s%zu CR line end%s made LF", sep, r->cr_count,
                 r->cr_count == 1 ? "" : "s");
}
