/* Attack: stop or kill the grader, its process group, and every other
 * shadowlab process in sight, so that no grade is written, or an old one
 * stays. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <signal.h>
#include <sys/syscall.h>

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    pid_t parent = getppid();
    kill(parent, SIGSTOP);
    syscall(SYS_tgkill, parent, parent, SIGSTOP);
    kill(-getpgid(parent), SIGSTOP);
    DIR *d = opendir("/proc");
    struct dirent *e;
    while (d && (e = readdir(d))) {
        int pid = atoi(e->d_name);
        if (pid <= 1 || pid == getpid()) continue;
        char path[64], comm[64] = "";
        snprintf(path, sizeof path, "/proc/%d/comm", pid);
        FILE *f = fopen(path, "r");
        if (!f) continue;
        if (fgets(comm, sizeof comm, f) && strncmp(comm, "shadowlab", 9) == 0) kill(pid, SIGSTOP);
        fclose(f);
    }
    if (d) closedir(d);
    kill(parent, SIGKILL);
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
