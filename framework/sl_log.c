#include "sl_log.h"

#include <stdio.h>

static sl_log_level _sl_min_level = SL_LOG_INFO;

void sl_log_set_min_level(sl_log_level level) { _sl_min_level = level; }

void sl_log(sl_log_level level, const char *fmt, ...) {
    static const char *const prefix[] = {"debug: ", "", "warning: ", "error: "};
    if (level < _sl_min_level) return;
    va_list args;
    va_start(args, fmt);
    fputs("shadowlab: ", stderr);
    fputs(prefix[level], stderr);
    vfprintf(stderr, fmt, args);
    fputc('\n', stderr);
    va_end(args);
}
