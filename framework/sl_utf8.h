/* sl_utf8: text the grader did not write itself (what lab code prints or
 * sends, a compiler's log, a submission's notes) made into valid UTF-8 that
 * prints as one plain line or block wherever it goes (a terminal, a log, JSON,
 * XML, HTML), and cuts of text that never split a character. Every report
 * format needs valid UTF-8 (a JSON or XML reader refuses the whole file
 * otherwise), and a control character or a newline where a line is expected
 * would let the text draw lines that look like the grader's own. */
#ifndef SL_UTF8_H
#define SL_UTF8_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* The length of the valid UTF-8 sequence at s (at most `left` bytes), or 0
 * where there is none (RFC 3629: no overlong forms, surrogates, code points
 * past U+10FFFF or cut sequences). *code_point (may be NULL) gets its value. */
size_t sl_utf8_sequence(const char *s, size_t left, uint32_t *code_point);

/* What sl_utf8_printable and the cleaning below keep besides printable characters. */
enum { SL_UTF8_KEEP_NEWLINE = 1, SL_UTF8_KEEP_TAB = 2 };

/* Whether a character prints as itself: not a C0 control (newline and tab if
 * kept), DEL, a C1 control (U+0080-U+009F: some terminals obey them) nor
 * U+FFFE or U+FFFF (not characters; XML 1.0 forbids them, as it does C0 controls). */
bool sl_utf8_printable(uint32_t code_point, unsigned keep);

/* Copies n bytes of `in` to `out` (out_size bytes, NUL included), cleaned:
 * each run of bytes that are not UTF-8 becomes U+FFFD, each character that
 * is not printable '?'. A NUL in `in` is a control like any other. When out
 * is full the copy stops between characters. Returns the length written. */
size_t sl_utf8_clean(char *out, size_t out_size, const char *in, size_t n, unsigned keep);

/* Whether n bytes of s are valid UTF-8 of printable characters (as sl_utf8_clean would leave them). */
bool sl_utf8_is_clean(const char *s, size_t n, unsigned keep);

/* The length of the longest start of the NUL-terminated s no longer than max
 * bytes that ends between two characters. */
size_t sl_utf8_cut(const char *s, size_t max);

/* Where the longest end of s (len bytes) no longer than max bytes starts, at
 * the start of a character: the tail of a text that was kept from its end. */
size_t sl_utf8_tail(const char *s, size_t len, size_t max);

/* snprintf(out, n, "%s", s), but a cut falls between characters. */
void sl_utf8_copy(char *out, size_t n, const char *s);

/* Drops a character split at the end of the NUL-terminated s (where snprintf cut it). */
void sl_utf8_trim(char *s);

/* Writes n bytes of text to f, cleaned as sl_utf8_clean cleans them. */
void sl_utf8_write(FILE *f, const char *text, size_t n, unsigned keep);

#endif
