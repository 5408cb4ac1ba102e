/* sl_html: escaped text for the grader's HTML pages. */
#include "sl_html.h"

void sl_html_text(FILE *f, const char *text) {
    for (const char *p = text; *p; p++) {
        switch (*p) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*p, f);
        }
    }
}
