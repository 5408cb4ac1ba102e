#include "sl_utf8.h"

#include <string.h>

static const char _sl_replacement[] = "\xef\xbf\xbd"; /* U+FFFD */

size_t sl_utf8_sequence(const char *text, size_t left, uint32_t *code_point) {
    if (left == 0) return 0;
    const unsigned char *s = (const unsigned char *)text;
    unsigned char c = s[0];
    if (c < 0x80) {
        if (code_point) *code_point = c;
        return 1;
    }
    size_t n;
    unsigned char lo = 0x80, hi = 0xBF; /* the allowed range of the second byte */
    if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c == 0xE0) n = 3, lo = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC) n = 3;
    else if (c == 0xED) n = 3, hi = 0x9F; /* no surrogates */
    else if (c >= 0xEE && c <= 0xEF) n = 3;
    else if (c == 0xF0) n = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3) n = 4;
    else if (c == 0xF4) n = 4, hi = 0x8F; /* nothing past U+10FFFF */
    else return 0;
    if (left < n || s[1] < lo || s[1] > hi) return 0;
    uint32_t value = c & (0x7Fu >> n);
    for (size_t i = 1; i < n; i++) {
        if (s[i] < 0x80 || s[i] > 0xBF) return 0;
        value = value << 6 | (s[i] & 0x3Fu);
    }
    if (code_point) *code_point = value;
    return n;
}

bool sl_utf8_printable(uint32_t cp, unsigned keep) {
    if (cp == '\n') return keep & SL_UTF8_KEEP_NEWLINE;
    if (cp == '\t') return keep & SL_UTF8_KEEP_TAB;
    return !(cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0xFFFE || cp == 0xFFFF);
}

/* The next piece of cleaned text at in[*i]: the bytes to write (a character
 * as it is, '?', or U+FFFD for a run of bytes that are not UTF-8) and their length. */
static const char *_sl_next(const char *in, size_t n, size_t *i, unsigned keep, size_t *len) {
    uint32_t cp;
    size_t seq = sl_utf8_sequence(in + *i, n - *i, &cp);
    if (seq == 0) {
        while (*i < n && sl_utf8_sequence(in + *i, n - *i, NULL) == 0) (*i)++;
        *len = 3;
        return _sl_replacement;
    }
    const char *at = in + *i;
    *i += seq;
    if (!sl_utf8_printable(cp, keep)) {
        *len = 1;
        return "?";
    }
    *len = seq;
    return at;
}

size_t sl_utf8_clean(char *out, size_t out_size, const char *in, size_t n, unsigned keep) {
    if (out_size == 0) return 0;
    size_t used = 0;
    for (size_t i = 0; i < n;) {
        size_t len;
        const char *piece = _sl_next(in, n, &i, keep, &len);
        if (used + len + 1 > out_size) break;
        memcpy(out + used, piece, len);
        used += len;
    }
    out[used] = '\0';
    return used;
}

bool sl_utf8_is_clean(const char *s, size_t n, unsigned keep) {
    for (size_t i = 0; i < n;) {
        uint32_t cp;
        size_t seq = sl_utf8_sequence(s + i, n - i, &cp);
        if (seq == 0 || !sl_utf8_printable(cp, keep)) return false;
        i += seq;
    }
    return true;
}

/* A continuation byte: never the first of a character. */
static bool _sl_continuation(char c) { return ((unsigned char)c & 0xC0) == 0x80; }

size_t sl_utf8_cut(const char *s, size_t max) {
    size_t len = 0;
    while (len <= max && s[len]) len++;
    if (len <= max) return len;
    size_t cut = max;
    /* a character is at most 4 bytes: step back over at most 3 continuation bytes */
    for (int back = 0; back < 3 && cut > 0 && _sl_continuation(s[cut]); back++) cut--;
    return _sl_continuation(s[cut]) ? max : cut;
}

size_t sl_utf8_tail(const char *s, size_t len, size_t max) {
    if (len <= max) return 0;
    size_t start = len - max;
    for (int ahead = 0; ahead < 3 && start < len && _sl_continuation(s[start]); ahead++) start++;
    return start;
}

void sl_utf8_copy(char *out, size_t n, const char *s) {
    if (n == 0) return;
    size_t len = sl_utf8_cut(s, n - 1);
    memmove(out, s, len);
    out[len] = '\0';
}

void sl_utf8_trim(char *s) {
    size_t len = strlen(s), start = len;
    for (int back = 0; back < 3 && start > 0 && _sl_continuation(s[start - 1]); back++) start--;
    if (start == 0) return;
    start--; /* the byte that may lead the last character */
    if ((unsigned char)s[start] < 0xC0) return; /* ASCII, or continuation bytes with no lead: not a cut */
    if (sl_utf8_sequence(s + start, len - start, NULL) == 0 && len - start < 4) s[start] = '\0';
}

void sl_utf8_write(FILE *f, const char *text, size_t n, unsigned keep) {
    for (size_t i = 0; i < n;) {
        size_t len;
        const char *piece = _sl_next(text, n, &i, keep, &len);
        fwrite(piece, 1, len, f);
    }
}
