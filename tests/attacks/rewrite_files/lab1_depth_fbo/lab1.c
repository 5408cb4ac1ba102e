/* Attack: find the project on disk and change what grades the next
 * submission: touch every case, reference and binary (a real attacker would
 * rewrite them; touching shows the same access without harm), add a case
 * file, and leave files in /tmp for a later run to find. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <sys/time.h>

static void _touch_all(const char *dir, int depth) {
    DIR *d = opendir(dir);
    if (!d || depth > 4) {
        if (d) closedir(d);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        char path[PATH_MAX + 256];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (attack_is_dir(path)) {
            _touch_all(path, depth + 1);
        } else {
            int fd = open(path, O_WRONLY | O_APPEND);
            if (fd >= 0) {
                futimes(fd, NULL);
                close(fd);
            }
        }
    }
    closedir(d);
}

__attribute__((constructor)) static void _at_start(void) {
    char project[PATH_MAX], path[PATH_MAX + 64];
    attack_leave_marker("rewrite_files");
    if (!attack_find_project(__FILE__, project, sizeof project)) return;
    static const char *const targets[] = {"grader", "solutions", "framework", "build/bin", "build/tests/bin"};
    for (size_t i = 0; i < sizeof targets / sizeof targets[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", project, targets[i]);
        _touch_all(path, 0);
    }
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        *strrchr(exe, '/') = '\0';
        _touch_all(exe, 0); /* the runners */
    }
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
