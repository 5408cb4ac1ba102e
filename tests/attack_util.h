/* What the attack suite's lab files share (tests/attacks/README.md): the
 * stubs they keep, finding the project on disk as a student's code could,
 * and writing to the grader's channel. Test code, never part of a lab. */
#ifndef ATTACK_UTIL_H
#define ATTACK_UTIL_H

#define _GNU_SOURCE
#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shadowlab.h"
#include "sl_protocol.h"

/* Lab 1's functions as the stubs have them: the attack adds, never implements. */
#define ATTACK_LAB1_STUBS                                                   \
    sl_status lab1_begin_depth_pass(const sl_shadow_map *map) {             \
        (void)map;                                                          \
        return SL_NOT_IMPLEMENTED;                                          \
    }                                                                       \
    void lab1_destroy_shadow_map(sl_shadow_map *map) { (void)map; }

static inline bool attack_is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* The project's root (the folder with grader/cases), searched upwards from
 * this file's path and from the running executable's, as a student could. */
static inline bool attack_find_project(const char *start, char *out, size_t n) {
    const char *starts[2] = {start, "/proc/self/exe"};
    for (int s = 0; s < 2; s++) {
        char path[PATH_MAX];
        if (!realpath(starts[s], path)) snprintf(path, sizeof path, "%s", starts[s]);
        for (char *slash = strrchr(path, '/'); slash; slash = strrchr(path, '/')) {
            *slash = '\0';
            char probe[PATH_MAX + 32];
            snprintf(probe, sizeof probe, "%s/grader/cases", path);
            if (attack_is_dir(probe)) {
                snprintf(out, n, "%s", path);
                return true;
            }
            /* a build folder: its CMakeCache names the source */
            snprintf(probe, sizeof probe, "%s/CMakeCache.txt", path);
            FILE *f = fopen(probe, "r");
            if (f) {
                char line[PATH_MAX + 64];
                while (fgets(line, sizeof line, f))
                    if (strncmp(line, "CMAKE_HOME_DIRECTORY:INTERNAL=", 30) == 0) {
                        line[strcspn(line, "\n")] = '\0';
                        snprintf(out, n, "%s", line + 30);
                        fclose(f);
                        return true;
                    }
                fclose(f);
            }
        }
    }
    return false;
}

static inline void attack_write(int fd, const void *data, size_t n) {
    const char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w <= 0) return;
        p += w;
        n -= (size_t)w;
    }
}

/* One message on the grader's channel, framed as the runner frames them. */
static inline void attack_send(uint32_t type, const char *name, const void *payload, uint64_t length) {
    sl_message_header h = {type, name ? (uint32_t)strlen(name) : 0, length};
    attack_write(SL_CHANNEL_FD, &h, sizeof h);
    if (h.name_length) attack_write(SL_CHANNEL_FD, name, h.name_length);
    if (length) attack_write(SL_CHANNEL_FD, payload, (size_t)length);
}

/* Leaves a file where the test looks for leftovers: /tmp and the project. */
static inline void attack_leave_marker(const char *what) {
    char path[PATH_MAX + 64], project[PATH_MAX];
    snprintf(path, sizeof path, "/tmp/shadowlab-attack-marker-%s", what);
    close(open(path, O_WRONLY | O_CREAT, 0644));
    if (attack_find_project(__FILE__, project, sizeof project)) {
        snprintf(path, sizeof path, "%s/grader/cases/shadowlab-attack-marker-%s.json", project, what);
        close(open(path, O_WRONLY | O_CREAT, 0644));
    }
}

/* After a forged DONE: wait, as the runner does, until the grader lets go. */
static inline void attack_wait_for_grader(void) {
    char byte;
    while (read(0, &byte, 1) > 0) {}
    _exit(0);
}

#endif
