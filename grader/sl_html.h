/* sl_html: text written into the grader's HTML pages (a student's report, the
 * class report) and its JUnit XML. Everything that comes from a grade — a
 * case's name, a message quoting lab output — is escaped, so no text can
 * become markup, and cleaned, so the page or file stays well-formed whatever
 * bytes the text holds. */
#ifndef SL_HTML_H
#define SL_HTML_H

#include <stdio.h>

/* Writes text with <, >, & and " as entities (safe in element content and in
 * double-quoted attribute values), bytes that are not UTF-8 as U+FFFD and
 * control characters other than newline and tab as '?': what XML 1.0 allows
 * (it forbids those controls even as character references) and HTML reads. */
void sl_html_text(FILE *f, const char *text);

#endif
