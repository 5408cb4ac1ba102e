/* sl_html: escaped text for the grader's HTML pages and XML files. */
#include "sl_html.h"

#include <string.h>

#include "sl_utf8.h"

void sl_html_text(FILE *f, const char *text) {
    const unsigned keep = SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB;
    for (const char *p = text; *p;) {
        size_t plain = strcspn(p, "<>&\"");
        sl_utf8_write(f, p, plain, keep);
        p += plain;
        switch (*p) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: return;
        }
        p++;
    }
}
