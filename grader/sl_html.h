/* sl_html: text written into the grader's HTML pages (a student's report, the
 * class report). Everything that comes from a grade — a case's name, a
 * message quoting lab output — is escaped, so no text can become markup. */
#ifndef SL_HTML_H
#define SL_HTML_H

#include <stdio.h>

/* Writes text with <, >, & and " as entities: safe in element content and in
 * double-quoted attribute values. */
void sl_html_text(FILE *f, const char *text);

#endif
