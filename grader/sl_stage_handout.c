#define _GNU_SOURCE
#include "sl_stage_handout.h"

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

#include "sl_text.h"

/* ---- the handout's lab files, from the stage's stubs (trusted) ---- */

static int _sl_compare_strings(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void _sl_add_stub_files(_sl_labs *labs, int dir_fd, const char *rel, int depth) {
    int fd = openat(dir_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        if (fd >= 0) close(fd);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        struct stat st;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
        char path[256];
        if ((size_t)snprintf(path, sizeof path, "%s/%s", rel, e->d_name) >= sizeof path) continue;
        if (S_ISDIR(st.st_mode) && depth < _SL_SHADERS_DEPTH) {
            int sub = openat(dirfd(d), e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub >= 0) {
                _sl_add_stub_files(labs, sub, path, depth + 1);
                close(sub);
            }
        } else if (S_ISREG(st.st_mode) && labs->file_count < 512) {
            snprintf(labs->files[labs->file_count++], 256, "%s", path);
        }
    }
    closedir(d);
}

bool _sl_read_labs(int stage_fd, _sl_labs *labs, char *err, size_t n) {
    int fd = openat(stage_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        snprintf(err, n, "cannot list the stage (%s)", strerror(errno));
        if (fd >= 0) close(fd);
        return false;
    }
    char *names[_SL_MAX_LABS];
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < _SL_MAX_LABS) {
        int number = 0, used = 0;
        if (sscanf(e->d_name, "lab%d_%n", &number, &used) != 1 || used == 0 || number < 1 ||
            strlen(e->d_name) >= sizeof labs->folder[0])
            continue;
        struct stat st;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode))
            names[count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], _sl_compare_strings);
    labs->files = calloc(512, sizeof *labs->files);
    for (int i = 0; i < count; i++) {
        snprintf(labs->folder[i], sizeof labs->folder[i], "%s", names[i]);
        sscanf(names[i], "lab%d_", &labs->number[i]);
        free(names[i]);
        char c_file[96];
        snprintf(c_file, sizeof c_file, "%s/lab%d.c", labs->folder[i], labs->number[i]);
        struct stat st;
        if (fstatat(stage_fd, c_file, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode) && labs->file_count < 512)
            snprintf(labs->files[labs->file_count++], 256, "%s", c_file);
        char shaders[96];
        snprintf(shaders, sizeof shaders, "%s/shaders", labs->folder[i]);
        int sub = openat(stage_fd, shaders, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (sub >= 0) {
            _sl_add_stub_files(labs, sub, shaders, 1);
            close(sub);
        }
    }
    labs->count = count;
    if (!count) {
        snprintf(err, n, "the stage holds no lab folder (lab1_..., lab2_...): not a labs tree");
        return false;
    }
    return true;
}

int _sl_lab_index(const _sl_labs *labs, const char *name) {
    for (int i = 0; i < labs->count; i++)
        if (strcmp(labs->folder[i], name) == 0) return i;
    return -1;
}

bool _sl_stageable_name(const char *name) {
    size_t len = strlen(name);
    if (len == 0 || len > 255 || strcmp(name, ".") == 0 || strcmp(name, "..") == 0) return false;
    for (size_t i = 0; i < len; i++)
        if ((unsigned char)name[i] < 0x20 || name[i] == 0x7f || name[i] == '/' || name[i] == '\\') return false;
    sl_text_problems p;
    return sl_text_check(name, len, &p);
}
