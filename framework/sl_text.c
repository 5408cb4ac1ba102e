#include "sl_text.h"

#include <stdio.h>
#include <string.h>

#include "sl_utf8.h"

size_t sl_text_normalize(char *text, size_t len, sl_text_fix *fix) {
    sl_text_fix local = {0};
    size_t in = 0, out = 0;
    if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF) {
        local.bom_removed = true;
        in = 3;
    }
    while (in < len) {
        char c = text[in++];
        if (c == '\r') {
            if (in < len && text[in] == '\n') {
                in++;
                local.crlf++;
            } else {
                local.lone_cr++;
            }
            c = '\n';
        }
        text[out++] = c;
    }
    if (fix) *fix = local;
    return out;
}

bool sl_text_fix_any(const sl_text_fix *fix) { return fix->bom_removed || fix->crlf || fix->lone_cr; }

void sl_text_fix_describe(const sl_text_fix *fix, char *out, size_t n) {
    if (!n) return;
    out[0] = '\0';
    size_t used = 0;
    if (fix->bom_removed) used += (size_t)snprintf(out + used, n - used, "a UTF-8 byte-order mark removed");
    if (fix->crlf && used < n)
        used += (size_t)snprintf(out + used, n - used, "%s%ld CRLF line end%s made LF", used ? ", " : "", fix->crlf,
                                 fix->crlf == 1 ? "" : "s");
    if (fix->lone_cr && used < n)
        snprintf(out + used, n - used, "%s%ld CR line end%s made LF", used ? ", " : "", fix->lone_cr,
                 fix->lone_cr == 1 ? "" : "s");
}

bool sl_text_check(const char *text, size_t len, sl_text_problems *p) {
    *p = (sl_text_problems){.nul_offset = -1, .invalid_offset = -1};
    const unsigned char *s = (const unsigned char *)text;
    if (len >= 2 && ((s[0] == 0xFF && s[1] == 0xFE) || (s[0] == 0xFE && s[1] == 0xFF))) {
        p->utf16 = true;
        return false;
    }
    long line = 1;
    for (size_t i = 0; i < len && (p->nul_offset < 0 || p->invalid_offset < 0);) {
        if (s[i] == '\n' || (s[i] == '\r' && (i + 1 == len || s[i + 1] != '\n'))) line++;
        if (s[i] == 0 && p->nul_offset < 0) {
            p->nul_offset = (long long)i;
            p->nul_line = line;
        }
        size_t n = sl_utf8_sequence(text + i, len - i, NULL);
        if (n == 0) {
            if (p->invalid_offset < 0) {
                p->invalid_offset = (long long)i;
                p->invalid_line = line;
            }
            n = 1;
        }
        i += n;
    }
    return p->nul_offset < 0 && p->invalid_offset < 0;
}

void sl_text_problems_describe(const sl_text_problems *p, const char *name, char *out, size_t n) {
    if (!n) return;
    out[0] = '\0';
    if (p->utf16) {
        snprintf(out, n, "%s: saved as UTF-16, which the compilers do not read: save it as UTF-8", name);
        return;
    }
    size_t used = 0;
    if (p->nul_offset >= 0)
        used += (size_t)snprintf(out, n, "%s: a NUL byte at byte offset %lld (line %ld): not text; the compiler stops there "
                                         "or rejects the file",
                                 name, p->nul_offset, p->nul_line);
    if (p->invalid_offset >= 0 && used < n)
        snprintf(out + used, n - used, "%s%s: invalid UTF-8 at byte offset %lld (line %ld): save the file as UTF-8 (GLSL "
                                       "allows only ASCII outside comments)",
                 used ? "; " : "", name, p->invalid_offset, p->invalid_line);
}
