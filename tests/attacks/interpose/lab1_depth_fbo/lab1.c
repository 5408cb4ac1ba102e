/* Attack: define functions of the grader and of libc in lab code, so the
 * link takes them instead of the real ones: the grader's scoring (if it were
 * linked with lab code), and write(), through which the runner reports, to
 * drop every "not implemented" and claim success. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <stdarg.h>
#include <sys/syscall.h>

/* the grader's own functions, as they were named when it linked lab code */
bool sl_report_full_marks(const void *report) {
    (void)report;
    return true;
}
void sl_report_totals(const void *report, double *score, double *max_score, double *bonus) {
    (void)report;
    *score = *max_score = 57;
    *bonus = 0;
}
void sl_grade_check(void) {}

ssize_t write(int fd, const void *buf, size_t n) {
    if (fd == SL_CHANNEL_FD && n >= sizeof(sl_message_header)) {
        sl_message_header h;
        memcpy(&h, buf, sizeof h);
        if (h.type == SL_MSG_NOT_IMPLEMENTED) h.type = SL_MSG_STAGE; /* hide the stub */
        char copy[65536];
        if (n <= sizeof copy) {
            memcpy(copy, buf, n);
            memcpy(copy, &h, sizeof h);
            return syscall(SYS_write, fd, copy, n);
        }
    }
    return syscall(SYS_write, fd, buf, n);
}

int fprintf(FILE *stream, const char *format, ...) {
    va_list args;
    va_start(args, format);
    int n = vfprintf(stream, format, args);
    va_end(args);
    fputs("\nScore: 57/57\n", stream);
    return n;
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    fprintf(stdout, "interposed\n");
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
