#define _GNU_SOURCE
#include "sl_stage_channel.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef SYS_openat2
#include <linux/openat2.h>
#endif

#include "sl_stage_desc.h"

/* ---- the channel: child -> parent ---- */

static void _sl_write_all(int fd, const void *data, size_t n) {
    const char *p = data;
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) _exit(SL_STAGE_PROBLEM); /* the parent is gone */
        p += w;
        n -= (size_t)w;
    }
}

int _sl_channel_fd = -1;

void _sl_send_record3(int kind, const char *a, size_t la, const char *b, size_t lb, const char *c, size_t lc) {
    _sl_record_header h = {.kind = (uint8_t)kind, .len = {(uint32_t)la, (uint32_t)lb, (uint32_t)lc}};
    _sl_write_all(_sl_channel_fd, &h, sizeof h);
    if (la) _sl_write_all(_sl_channel_fd, a, la);
    if (lb) _sl_write_all(_sl_channel_fd, b, lb);
    if (lc) _sl_write_all(_sl_channel_fd, c, lc);
}

void _sl_send_record(int kind, const char *a, const char *b) {
    size_t la = a ? strlen(a) : 0, lb = b ? strlen(b) : 0;
    if (la > _SL_TEXT_MAX) la = _SL_TEXT_MAX;
    if (lb > _SL_TEXT_MAX) lb = _SL_TEXT_MAX;
    _sl_send_record3(kind, a, la, b, lb, NULL, 0);
}
