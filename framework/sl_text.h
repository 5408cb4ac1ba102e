/* sl_text: source files as editors write them, made plain before a compiler
 * reads them. Windows editors save a UTF-8 byte-order mark and CRLF line
 * ends, old Mac ones a lone CR; GLSL compilers take neither (Mesa says
 * "preprocessor error: syntax error, unexpected HASH_TOKEN" for a BOM before
 * #version). The viewer's shader loader and the grader's staging of a
 * submission both pass each lab file through sl_text_normalize.
 *
 * What is not text is refused with where it is: a NUL byte, bytes that are not
 * UTF-8 (a file saved as Latin-1), a UTF-16 file (Notepad's "Unicode"). */
#ifndef SL_TEXT_H
#define SL_TEXT_H

#include <stdbool.h>
#include <stddef.h>

typedef enum sl_text_problem {
    SL_TEXT_OK = 0,
    SL_TEXT_NUL,          /* a NUL byte */
    SL_TEXT_INVALID_UTF8, /* a byte sequence that is not UTF-8 */
    SL_TEXT_UTF16,        /* a UTF-16 byte-order mark at the start */
} sl_text_problem;

typedef struct sl_text_report {
    sl_text_problem problem;
    size_t offset;      /* of the first bad byte, in the file as it was read */
    int line, column;   /* where that byte is (1-based; a column counts bytes) */
    unsigned char byte; /* the bad byte */
    /* what was changed (when there was no problem) */
    bool had_bom;
    size_t crlf_count, cr_count;
} sl_text_report;

/* Checks data[0..*length) and, when it is text, normalises it in place: the
 * UTF-8 byte-order mark dropped, CRLF and lone CR turned into LF. *length is
 * the new length, and data[*length] is set to '\0' (the buffer must hold
 * *length + 1 bytes). On a problem nothing is changed. report may be NULL. */
sl_text_problem sl_text_normalize(char *data, size_t *length, sl_text_report *report);
/* Whether sl_text_normalize changed anything (a BOM, CRLF or CR). */
bool sl_text_changed(const sl_text_report *report);
/* "FILE: byte 1234 (line 5, column 3): a NUL byte (0x00): ..." — the problem
 * in words, or what was normalised ("a UTF-8 byte-order mark removed, 12 CRLF
 * line ends made LF"), or "" when the text was plain. */
void sl_text_describe(const sl_text_report *report, const char *path, char *out, size_t out_size);

#endif
