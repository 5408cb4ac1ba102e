/* sl_sandbox where Linux's sandbox does not exist (macOS, the BSDs), or where
 * a build asks for it (SL_SANDBOX=fallback): each runner is a plain child
 * process of the grader's user, in a session of its own, with a cleared
 * environment, only fds 0-3 open, and the limits the system has (CPU time,
 * memory, file size, no core files). The grader's wall-clock deadline kills
 * a runner that hangs (sl_run.c). Lab code can read whatever the user can:
 * a grade here is a student's self-check (sl_sandbox.self_check), and the
 * report says so. Only POSIX calls: no /proc, no prctl. */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE   /* RLIMIT_AS, RLIMIT_CORE on glibc */
#define _DARWIN_C_SOURCE  /* the same on macOS */
#include "sl_sandbox.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *const _sl_level_names[] = {"basic", "uid", "namespaces"};

const char *sl_sandbox_module(void) { return "fallback"; }

const char *sl_sandbox_level_name(sl_sandbox_level level) {
    if (level == SL_SANDBOX_NONE) return "none";
    return (unsigned)level <= SL_SANDBOX_NAMESPACES ? _sl_level_names[level] : "?";
}

bool sl_sandbox_level_parse(const char *name, sl_sandbox_level *level) {
    for (int i = 0; i <= SL_SANDBOX_NAMESPACES; i++)
        if (strcmp(name, _sl_level_names[i]) == 0) {
            *level = (sl_sandbox_level)i;
            return true;
        }
    return false;
}

/* ---- the child's side, between fork and exec ---- */

/* Set-up failures go to the parent over a close-on-exec pipe: an exec that
 * succeeds closes it empty. */
static void _sl_fail(int report_fd, const char *what, int error) {
    char text[400];
    int n = snprintf(text, sizeof text, "%s: %s", what, strerror(error));
    if (n > 0 && write(report_fd, text, (size_t)n < sizeof text ? (size_t)n : sizeof text - 1) < 0) {}
    _exit(127);
}

static void _sl_limit(int resource, rlim_t value) {
    struct rlimit l;
    if (getrlimit(resource, &l) != 0) return;
    /* never above a hard limit the system set already */
    if (l.rlim_max != RLIM_INFINITY && value > l.rlim_max) value = l.rlim_max;
    l.rlim_cur = l.rlim_max = value;
    /* a limit the system does not enforce (RLIMIT_AS on macOS) is no failure: the wall clock still holds */
    (void)setrlimit(resource, &l);
}

static void _sl_child(const sl_sandbox_spawn_desc *d, int report_fd) {
    /* its own session and process group: the grader kills the whole group */
    if (setsid() < 0) _sl_fail(report_fd, "setsid", errno);
    rlim_t cpu = (rlim_t)(d->cpu_seconds > 0 ? d->cpu_seconds : 60) + 1;
    _sl_limit(RLIMIT_CPU, cpu);
    _sl_limit(RLIMIT_FSIZE, 16 << 20);
    _sl_limit(RLIMIT_CORE, 0);
    _sl_limit(RLIMIT_NOFILE, 256);
    if (d->memory_bytes) {
#ifdef RLIMIT_AS
        _sl_limit(RLIMIT_AS, (rlim_t)d->memory_bytes);
#endif
#ifdef RLIMIT_DATA
        _sl_limit(RLIMIT_DATA, (rlim_t)d->memory_bytes);
#endif
    }
    /* fds: 0 the job, 1 and 2 the output, 3 the channel; nothing else survives exec */
    int fds[4] = {d->stdin_fd, d->output_fd, d->output_fd, d->channel_fd};
    int moved[4];
    for (int i = 0; i < 4; i++)
        if ((moved[i] = fcntl(fds[i], F_DUPFD_CLOEXEC, 10)) < 0) _sl_fail(report_fd, "dup", errno);
    if (report_fd < 10) {
        int fd = fcntl(report_fd, F_DUPFD_CLOEXEC, 10);
        if (fd >= 0) report_fd = fd;
    }
    for (int i = 0; i < 4; i++)
        if (dup2(moved[i], i) != i) _sl_fail(report_fd, "dup2", errno);
    long max_fd = sysconf(_SC_OPEN_MAX);
    if (max_fd < 0 || max_fd > 4096) max_fd = 4096;
    for (int fd = 4; fd < max_fd; fd++)
        if (fd != report_fd) fcntl(fd, F_SETFD, FD_CLOEXEC);
    signal(SIGPIPE, SIG_DFL);
    char *const argv[] = {(char *)"shadowlab-runner", NULL};
    execve(d->runner, argv, (char *const *)d->environment);
    _sl_fail(report_fd, "cannot start the runner", errno);
}

static bool _sl_spawn(const sl_sandbox_spawn_desc *d, bool probe, pid_t *pid_out, char *err, size_t n) {
    static const char *const no_environment[] = {NULL};
    sl_sandbox_spawn_desc probe_desc;
    int report[2];
    if (pipe(report) != 0) {
        snprintf(err, n, "cannot make a pipe: %s", strerror(errno));
        return false;
    }
    fcntl(report[0], F_SETFD, FD_CLOEXEC);
    fcntl(report[1], F_SETFD, FD_CLOEXEC);
    if (probe) {
        /* only checks that the runner can be run */
        probe_desc = *d;
        d = &probe_desc;
    }
    if (!d->environment) {
        if (d != &probe_desc) probe_desc = *d;
        probe_desc.environment = no_environment;
        d = &probe_desc;
    }
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(err, n, "cannot start a process: %s", strerror(errno));
        close(report[0]);
        close(report[1]);
        return false;
    }
    if (pid == 0) {
        close(report[0]);
        if (probe) {
            if (access(d->runner, X_OK) != 0) _sl_fail(report[1], d->runner, errno);
            _exit(0);
        }
        _sl_child(d, report[1]);
    }
    close(report[1]);
    char text[400];
    ssize_t got;
    while ((got = read(report[0], text, sizeof text - 1)) < 0 && errno == EINTR) {}
    close(report[0]);
    if (got > 0) {
        text[got] = '\0';
        snprintf(err, n, "%s", text);
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
        return false;
    }
    if (probe)
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
    *pid_out = pid;
    return true;
}

bool sl_sandbox_open(sl_sandbox *sb, sl_sandbox_level at_most, const char *runner, char *err, size_t n) {
    (void)at_most; /* there is one level here */
    memset(sb, 0, sizeof *sb);
    sb->level = SL_SANDBOX_NONE;
    sb->self_check = true;
    sb->uid = geteuid();
    snprintf(sb->why_not_stronger, sizeof sb->why_not_stronger,
             "this build has no sandbox (its runners are plain processes)");
    sl_sandbox_spawn_desc probe = {.runner = runner};
    pid_t pid;
    char why[400];
    if (!_sl_spawn(&probe, true, &pid, why, sizeof why)) {
        snprintf(err, n, "cannot start a runner: %s", why);
        return false;
    }
    return true;
}

void sl_sandbox_close(sl_sandbox *sb) { (void)sb; }

void sl_sandbox_describe(const sl_sandbox *sb, char *out, size_t n) {
    (void)sb;
    snprintf(out, n, "none (a self-check: runners are plain processes of this user, with time and memory limits)");
}

bool sl_sandbox_spawn(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, sl_sandbox_process *out, char *err,
                      size_t n) {
    memset(out, 0, sizeof *out);
    out->uid_lock = -1;
    out->uid = sb->uid;
    if (!_sl_spawn(d, false, &out->pid, err, n)) return false;
    snprintf(out->labs_dir, sizeof out->labs_dir, "%s", d->labs_tree);
    snprintf(out->framework_dir, sizeof out->framework_dir, "%s", d->framework_dir);
    return true;
}

void sl_sandbox_end(const sl_sandbox *sb, sl_sandbox_process *p) {
    (void)sb;
    (void)p;
}

int sl_sandbox_readable(const sl_sandbox *sb, const char *const *paths, int count, bool *readable) {
    (void)sb;
    int found = 0;
    for (int i = 0; i < count; i++) {
        int fd = open(paths[i], O_RDONLY | O_CLOEXEC);
        readable[i] = fd >= 0;
        if (fd >= 0) close(fd);
        found += readable[i];
    }
    return found;
}

void sl_sandbox_kill(const sl_sandbox *sb, pid_t pid) {
    (void)sb;
    if (pid <= 0) return;
    /* the session it leads: what it started, too */
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
}

bool sl_sandbox_runs_runner(const sl_sandbox *sb, const sl_sandbox_process *p) {
    /* no portable way to ask; and lab code runs as the user here anyway */
    (void)sb;
    (void)p;
    return true;
}

bool sl_sandbox_usage(pid_t pid, double *cpu_seconds, double *waited_seconds) {
    /* no portable way to ask about a child still running: the wall clock alone */
    (void)pid;
    (void)cpu_seconds;
    (void)waited_seconds;
    return false;
}
