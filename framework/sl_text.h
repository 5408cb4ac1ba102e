/* sl_text: lab files as editors write them. Windows editors save CRLF line
 * ends and often a UTF-8 byte-order mark; old Mac editors a lone CR. GLSL
 * compilers reject the mark ("syntax error, unexpected HASH_TOKEN" on line 1)
 * and some choke on CR, so every lab file is normalised before it is compiled
 * (the grader's staging of a submission, the viewer's shader loader), and
 * bytes no editor should write (NUL, invalid UTF-8) are named with their
 * offset, so a student is told more than the compiler's error that follows. */
#ifndef SL_TEXT_H
#define SL_TEXT_H

#include <stdbool.h>
#include <stddef.h>

/* What sl_text_normalize changed. */
typedef struct sl_text_fix {
    bool bom_removed; /* a UTF-8 byte-order mark at the start */
    long crlf;        /* CRLF line ends made LF */
    long lone_cr;     /* lone CR line ends made LF */
} sl_text_fix;

/* In place: removes a UTF-8 byte-order mark at the start and turns CRLF and
 * a lone CR into LF. Returns the new length (never more than len); the text
 * is not NUL-terminated by this function. fix may be NULL. */
size_t sl_text_normalize(char *text, size_t len, sl_text_fix *fix);

/* Whether sl_text_normalize changed anything. */
bool sl_text_fix_any(const sl_text_fix *fix);

/* "a UTF-8 byte-order mark removed, 120 CRLF line ends made LF" (empty if nothing changed). */
void sl_text_fix_describe(const sl_text_fix *fix, char *out, size_t out_size);

/* Bytes that are not text: the first NUL and the first byte that is not
 * valid UTF-8 (overlong forms, surrogates, code points past U+10FFFF and cut
 * sequences included), as offsets from the start of the file as written
 * (-1: none) with their 1-based line. A file that starts with a UTF-16
 * byte-order mark is said to be UTF-16. */
typedef struct sl_text_problems {
    long long nul_offset, invalid_offset;
    long nul_line, invalid_line;
    bool utf16;
} sl_text_problems;

/* Checks the text; true when it is clean (no NUL, valid UTF-8, not UTF-16). */
bool sl_text_check(const char *text, size_t len, sl_text_problems *out);

/* One sentence per problem found, prefixed with `name`: "NAME: a NUL byte at
 * byte offset 12 (line 1): ..." (empty if the text is clean). */
void sl_text_problems_describe(const sl_text_problems *p, const char *name, char *out, size_t out_size);

#endif
