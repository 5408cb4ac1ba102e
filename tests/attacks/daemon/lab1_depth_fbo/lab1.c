/* Attack: start a process that outlives the case and the grader, to rewrite
 * the reports once the grader has written them (every way there is to start
 * one: fork, vfork, clone, posix_spawn of a shell). */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <time.h>

extern char **environ;

/* What the daemon does: wait for the grade, then leave marks where it could. */
static void _daemon(void) {
    setsid();
    struct timespec t = {1, 0};
    nanosleep(&t, NULL);
    attack_leave_marker("daemon");
    nanosleep(&t, NULL);
    _exit(0);
}

__attribute__((constructor)) static void _at_start(void) {
    attack_leave_marker("tmp-state"); /* state for a later run, in /tmp */
    pid_t pid = fork();
    if (pid == 0) _daemon();
    pid = vfork();
    if (pid == 0) _exit(0);
    pid = (pid_t)syscall(SYS_clone, SIGCHLD, NULL, NULL, NULL, NULL);
    if (pid == 0) _daemon();
    char *const argv[] = {(char *)"sh", (char *)"-c",
                          (char *)"sleep 1; touch /tmp/shadowlab-attack-marker-spawn", NULL};
    posix_spawn(&pid, "/bin/sh", NULL, NULL, argv, environ);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
