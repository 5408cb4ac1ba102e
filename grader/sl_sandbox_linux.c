#define _GNU_SOURCE
#include "sl_sandbox.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/audit.h>
#include <linux/capability.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <linux/sockios.h>
#include <pwd.h>
#include <sched.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sl_sandbox_linux_cgroup.h"
#include "sl_sandbox_linux_child.h"
#include "sl_sandbox_linux_filters.h"
#include "sl_sandbox_linux_pool.h"

/* sl_sandbox on Linux: namespaces, seccomp, Landlock, prctl, /proc, runner
 * uids and pids cgroups (sl_sandbox.h). Elsewhere, sl_sandbox_fallback.c.
 * This file starts runners from the grader's side; the child's side is
 * sl_sandbox_linux_child.c (its filters sl_sandbox_linux_filters.c), the
 * runner uids sl_sandbox_linux_pool.c, the pids cgroups sl_sandbox_linux_cgroup.c. */

static const char *const _sl_level_names[] = {"basic", "uid", "namespaces"};

const char *sl_sandbox_module(void) { return "linux"; }

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

/* ---- the grader's side ---- */

/* Root's user namespace for a runner: its uid 1000 is the pool's uid outside. */
static bool _sl_map_ids(pid_t pid, uid_t uid, char *err, size_t n) {
    char path[64], map[64];
    snprintf(map, sizeof map, "%d %u 1\n", _SL_INNER_ID, (unsigned)uid);
    const char *files[] = {"uid_map", "gid_map"};
    for (int i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "/proc/%d/%s", (int)pid, files[i]);
        if (!_sl_write_text(path, map)) {
            snprintf(err, n, "cannot map uid %u into the runner's user namespace (%s): %s", (unsigned)uid, files[i],
                     strerror(errno));
            return false;
        }
    }
    return true;
}

static bool _sl_start(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, const _sl_plan *plan, bool probe,
                      pid_t *pid_out, char *err, size_t n) {
    int report[2], go[2] = {-1, -1};
    if (pipe2(report, O_CLOEXEC) != 0) {
        snprintf(err, n, "pipe: %s", strerror(errno));
        return false;
    }
    if (plan->maps_from_grader && pipe2(go, O_CLOEXEC) != 0) {
        snprintf(err, n, "pipe: %s", strerror(errno));
        close(report[0]);
        close(report[1]);
        return false;
    }
    uid_t uid = geteuid();
    gid_t gid = getegid();
    fflush(NULL);
    pid_t pid = _sl_fork(sb);
    if (pid < 0) {
        snprintf(err, n, "cannot start a process (%s sandbox): %s", sl_sandbox_level_name(sb->level), strerror(errno));
        close(report[0]);
        close(report[1]);
        if (go[0] >= 0) close(go[0]), close(go[1]);
        return false;
    }
    if (pid == 0) {
        close(report[0]);
        if (go[1] >= 0) close(go[1]);
        _sl_report_fd = report[1];
        _sl_child_exec(sb, d, plan, uid, gid, go[0], probe);
    }
    close(report[1]);
    if (go[0] >= 0) {
        close(go[0]);
        if (_sl_map_ids(pid, plan->mapped_uid, err, n) && write(go[1], "", 1) == 1) {
            close(go[1]);
        } else {
            close(go[1]);
            close(report[0]);
            kill(pid, SIGKILL);
            while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
            if (!err[0]) snprintf(err, n, "cannot release the runner's set-up: %s", strerror(errno));
            return false;
        }
    }
    char msg[512];
    ssize_t got, total = 0;
    while ((got = read(report[0], msg + total, sizeof msg - 1 - (size_t)total)) > 0 ||
           (got < 0 && errno == EINTR))
        if (got > 0) total += got;
    close(report[0]);
    msg[total] = '\0';
    if (total > 0 || probe) {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        if (total > 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            snprintf(err, n, "%s", total > 0 ? msg : "the sandbox's set-up process failed");
            return false;
        }
    }
    *pid_out = pid;
    return true;
}

/* ---- execute-only copies of the runners ----
 * The kernel leaves a process not dumpable when it execs a file it may not
 * read, from the exec on (before any lab code, constructors and ifunc
 * resolvers included). Not dumpable, no process of the same uid (another
 * runner, at `basic`) may trace it or open its memory in /proc. Each copy has
 * a random name in a folder others may pass through but not list: no runner
 * can find another grade's copies to run them. */

#define _SL_RUNNER_COPIES_MAX 24

struct _sl_sandbox_runners {
    char dir[64];
    int count;
    struct {
        char source[1100];
        char copy[128];
        dev_t dev;
        ino_t ino;
    } copies[_SL_RUNNER_COPIES_MAX];
};

static void _sl_runners_open(sl_sandbox *sb) {
    _sl_sandbox_runners *r = calloc(1, sizeof *r);
    if (!r) return;
    snprintf(r->dir, sizeof r->dir, "/tmp/shadowlab-runners-XXXXXX");
    struct statvfs st;
    if (!mkdtemp(r->dir)) {
        free(r);
        return;
    }
    if (chmod(r->dir, 0711) != 0 || statvfs(r->dir, &st) != 0 || (st.f_flag & ST_NOEXEC)) {
        rmdir(r->dir);
        free(r);
        return;
    }
    sb->runners = r;
}

static void _sl_runners_close(sl_sandbox *sb) {
    _sl_sandbox_runners *r = sb->runners;
    if (!r) return;
    for (int i = 0; i < r->count; i++) {
        unlink(r->copies[i].copy);
        char *slash = strrchr(r->copies[i].copy, '/');
        *slash = '\0';
        rmdir(r->copies[i].copy);
    }
    rmdir(r->dir);
    free(r);
    sb->runners = NULL;
}

static bool _sl_copy_file(int in, int out) {
    char buf[1 << 16];
    ssize_t got;
    while ((got = read(in, buf, sizeof buf)) != 0) {
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return false;
        for (ssize_t done = 0; done < got;) {
            ssize_t w = write(out, buf + done, (size_t)(got - done));
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) return false;
            done += w;
        }
    }
    return true;
}

/* The file a runner of `source` executes, and its identity; false with the reason. */
static bool _sl_runner_file(const sl_sandbox *sb, const char *source, _sl_plan *plan, sl_sandbox_process *out,
                            char *err, size_t n) {
    _sl_sandbox_runners *r = sb->runners;
    struct stat st;
    if (!r) {
        if (stat(source, &st) != 0) {
            snprintf(err, n, "%s: %s", source, strerror(errno));
            return false;
        }
        plan->runner = source;
        out->runner_dev = st.st_dev;
        out->runner_ino = st.st_ino;
        return true;
    }
    for (int i = 0; i < r->count; i++)
        if (strcmp(r->copies[i].source, source) == 0) {
            plan->runner = r->copies[i].copy;
            out->runner_dev = r->copies[i].dev;
            out->runner_ino = r->copies[i].ino;
            return true;
        }
    if (r->count >= _SL_RUNNER_COPIES_MAX || strlen(source) >= sizeof r->copies[0].source) {
        snprintf(err, n, "too many runners, or a path too long: %s", source);
        return false;
    }
    uint64_t random_name;
    if (getrandom(&random_name, sizeof random_name, 0) != sizeof random_name) {
        snprintf(err, n, "getrandom: %s", strerror(errno));
        return false;
    }
    /* <folder>/<random>/<the runner's own name>: what ps shows stays its name */
    char dir[sizeof r->dir + 20];
    const char *base = strrchr(source, '/') ? strrchr(source, '/') + 1 : source;
    snprintf(dir, sizeof dir, "%s/%016llx", r->dir, (unsigned long long)random_name);
    char *copy = r->copies[r->count].copy;
    if (mkdir(dir, 0711) != 0 || chmod(dir, 0711) != 0 ||
        (size_t)snprintf(copy, sizeof r->copies[0].copy, "%s/%.40s", dir, base) >= sizeof r->copies[0].copy) {
        snprintf(err, n, "cannot make a folder for the runner's copy in %s: %s", r->dir, strerror(errno));
        rmdir(dir);
        return false;
    }
    int in = open(source, O_RDONLY | O_CLOEXEC);
    int out_fd = in < 0 ? -1 : open(copy, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0700);
    bool ok = out_fd >= 0 && _sl_copy_file(in, out_fd) && fchmod(out_fd, 0111) == 0 && fstat(out_fd, &st) == 0;
    int saved = errno;
    if (out_fd >= 0 && close(out_fd) != 0) ok = false;
    if (in >= 0) close(in);
    if (!ok) {
        if (out_fd >= 0) unlink(copy);
        rmdir(dir);
        snprintf(err, n, "cannot copy the runner %s to %s: %s", source, r->dir, strerror(saved));
        return false;
    }
    snprintf(r->copies[r->count].source, sizeof r->copies[0].source, "%s", source);
    r->copies[r->count].dev = st.st_dev;
    r->copies[r->count].ino = st.st_ino;
    r->count++;
    plan->runner = copy;
    out->runner_dev = st.st_dev;
    out->runner_ino = st.st_ino;
    return true;
}

/* ---- starting runners ---- */

static int _sl_default_process_limit(void) {
    /* llvmpipe starts a thread per CPU (up to its own maximum) for drawing and
     * as many for compute; the runner needs a few more */
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    long limit = 2 * (cpus > 0 ? cpus : 1) + 16;
    return (int)(limit < 32 ? 32 : limit > 256 ? 256 : limit);
}

static void _sl_release(const sl_sandbox *sb, sl_sandbox_process *p) {
    if (p->cgroup[0]) _sl_cgroup_remove(p->cgroup);
    p->cgroup[0] = '\0';
    if (p->uid_lock >= 0) _sl_pool_release(sb, p->uid, p->uid_lock);
    p->uid_lock = -1;
}

static bool _sl_spawn(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, bool probe, sl_sandbox_process *out,
                      char *err, size_t n) {
    memset(out, 0, sizeof *out);
    out->uid_lock = -1;
    err[0] = '\0';
    _sl_plan plan = {0};
    if (!_sl_runner_file(sb, d->runner, &plan, out, err, n)) return false;
    bool root = geteuid() == 0;
    out->uid = sb->uid;
    if (sb->own_uids) {
        out->uid_lock = _sl_pool_claim(sb, &out->uid, err, n);
        if (out->uid_lock < 0) return false;
        plan.switch_uid = true;
        plan.uid = out->uid;
        if (sb->level == SL_SANDBOX_NAMESPACES && sb->user_namespace) {
            plan.maps_from_grader = true;
            plan.uid = _SL_INNER_ID;
            plan.mapped_uid = out->uid;
        }
        plan.process_limit = (rlim_t)sb->process_limit;
    } else if (sb->user_namespace) {
        /* a user namespace of its own: the limit counts this runner's tasks only */
        plan.process_limit = (rlim_t)sb->process_limit;
    } else if (!root) {
        /* the grader's uid: the limit counts every task of that user, so it
         * bounds them all together, no runner alone */
        _sl_task_count count = {geteuid(), 0};
        _sl_each_process(_sl_count_tasks, &count);
        plan.process_limit = (rlim_t)(count.tasks + sb->process_limit);
    }
    if (sb->pids_cgroup[0] && !probe &&
        !_sl_cgroup_make(sb, out->cgroup, sizeof out->cgroup, sb->process_limit, err, n)) {
        _sl_release(sb, out);
        return false;
    }
    snprintf(plan.cgroup, sizeof plan.cgroup, "%s", out->cgroup);
    if (!_sl_start(sb, d, &plan, probe, &out->pid, err, n)) {
        _sl_release(sb, out);
        return false;
    }
    return true;
}

/* Sets the sandbox up as a runner's would be, up to the exec, in a process
 * that then only checks it could run the runner. */
static bool _sl_try_level(sl_sandbox *sb, sl_sandbox_level level, bool user_namespace, const char *runner, char *why,
                          size_t n) {
    sb->level = level;
    sb->user_namespace = user_namespace;
    sb->own_uids = level > SL_SANDBOX_BASIC && geteuid() == 0;
    sl_sandbox_spawn_desc probe = {.runner = runner, .framework_dir = "/nonexistent"};
    sl_sandbox_process p;
    bool ok = _sl_spawn(sb, &probe, true, &p, why, n);
    _sl_release(sb, &p);
    return ok;
}

bool sl_sandbox_open(sl_sandbox *sb, sl_sandbox_level at_most, const char *runner, char *err, size_t n) {
    memset(sb, 0, sizeof *sb);
    bool root = geteuid() == 0;
#ifdef _SL_AUDIT_ARCH
    /* Can this kernel filter system calls? (PR_GET_SECCOMP fails without seccomp.) */
    sb->seccomp = prctl(PR_GET_SECCOMP, 0, 0, 0, 0) >= 0;
#endif
    sb->process_limit = _sl_default_process_limit();
    sb->landlock = _sl_landlock_abi();
    if (!_sl_find_pids_cgroup(sb)) sb->pids_cgroup[0] = '\0';
    _sl_runners_open(sb);
    /* As root, each runner gets a uid of its own: the pool must be usable. */
    if (root && at_most >= SL_SANDBOX_UID) {
        uid_t first, count;
        if (!_sl_pool_range(&first, &count, err, n) || !_sl_pool_lock_dir(sb->lock_dir, err, n)) {
            sl_sandbox_close(sb);
            return false;
        }
        sb->uid = first;
        sb->uid_count = count;
    }
    char why[256] = "";
    if (at_most >= SL_SANDBOX_NAMESPACES) {
        snprintf(sb->mount_point, sizeof sb->mount_point, "/tmp/shadowlab-sandbox-XXXXXX");
        if (!mkdtemp(sb->mount_point)) {
            snprintf(why, sizeof why, "cannot create a folder in /tmp: %s", strerror(errno));
            sb->mount_point[0] = '\0';
        } else {
            char second[256];
            chmod(sb->mount_point, 0755);
            /* as root: namespaces of its own, else a user namespace (as any user) */
            if (_sl_try_level(sb, SL_SANDBOX_NAMESPACES, !root, runner, why, sizeof why) ||
                (root && _sl_try_level(sb, SL_SANDBOX_NAMESPACES, true, runner, second, sizeof second))) {
                if (!sb->own_uids) sb->uid = geteuid();
                return true;
            }
        }
        snprintf(sb->why_not_stronger, sizeof sb->why_not_stronger, "no namespaces: %s", why);
    }
    char uid_why[256] = "";
    if (at_most >= SL_SANDBOX_UID && root && _sl_try_level(sb, SL_SANDBOX_UID, false, runner, uid_why, sizeof uid_why))
        return true;
    if (uid_why[0])
        snprintf(sb->why_not_stronger + strlen(sb->why_not_stronger),
                 sizeof sb->why_not_stronger - strlen(sb->why_not_stronger), "%sno other uid: %s",
                 sb->why_not_stronger[0] ? "; " : "", uid_why);
    if (at_most >= SL_SANDBOX_UID && !root && !sb->why_not_stronger[0])
        snprintf(sb->why_not_stronger, sizeof sb->why_not_stronger, "not root: no other uid");
    if (_sl_try_level(sb, SL_SANDBOX_BASIC, false, runner, why, sizeof why)) {
        sb->uid = geteuid();
        sb->uid_count = 0;
        return true;
    }
    snprintf(err, n, "cannot start a sandboxed process: %s", why);
    sl_sandbox_close(sb);
    return false;
}

void sl_sandbox_close(sl_sandbox *sb) {
    if (sb->mount_point[0]) rmdir(sb->mount_point);
    sb->mount_point[0] = '\0';
    _sl_runners_close(sb);
}

void sl_sandbox_describe(const sl_sandbox *sb, char *out, size_t n) {
    char uids[96], extra[256];
    if (sb->own_uids)
        snprintf(uids, sizeof uids, "a uid of its own per runner (%u-%u)", (unsigned)sb->uid,
                 (unsigned)(sb->uid + sb->uid_count - 1));
    else
        snprintf(uids, sizeof uids, "uid %u", (unsigned)sb->uid);
    bool per_runner = sb->own_uids || sb->user_namespace || sb->pids_cgroup[0];
    snprintf(extra, sizeof extra, "%s%s, at most %d threads %s%s%s", sb->seccomp ? ", seccomp" : "",
             sb->landlock ? ", Landlock" : "", sb->process_limit,
             per_runner ? "each" : "each beyond the user's others (shared with them)",
             sb->pids_cgroup[0] ? (sb->pids_cgroup_v2 ? " (pids cgroup, v2)" : " (pids cgroup)") : "",
             sb->runners ? "" : ", dumpable (no folder to run execute-only copies from)");
    switch (sb->level) {
    case SL_SANDBOX_NAMESPACES:
        snprintf(out, n, "namespaces (%s%s, read-only view of the shaders under test, no network%s)",
                 sb->user_namespace ? "user namespace, " : "", uids, extra);
        break;
    case SL_SANDBOX_UID:
        snprintf(out, n, "uid (%s%s; %s)", uids, extra, sb->why_not_stronger[0] ? sb->why_not_stronger : "by request");
        break;
    default:
        snprintf(out, n, "basic (the grader's uid%s; %s)", extra,
                 sb->why_not_stronger[0] ? sb->why_not_stronger : "by request");
        break;
    }
}

bool sl_sandbox_spawn(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, sl_sandbox_process *out, char *err,
                      size_t n) {
    if (!_sl_spawn(sb, d, false, out, err, n)) return false;
    if (sb->level == SL_SANDBOX_NAMESPACES) {
        snprintf(out->labs_dir, sizeof out->labs_dir, "/labs");
        snprintf(out->framework_dir, sizeof out->framework_dir, "/framework");
    } else {
        snprintf(out->labs_dir, sizeof out->labs_dir, "%s", d->labs_tree);
        snprintf(out->framework_dir, sizeof out->framework_dir, "%s", d->framework_dir);
    }
    return true;
}

void sl_sandbox_end(const sl_sandbox *sb, sl_sandbox_process *p) { _sl_release(sb, p); }

static bool _sl_can_read(const char *path) {
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    close(fd);
    return true;
}

int sl_sandbox_readable(const sl_sandbox *sb, const char *const *paths, int count, bool *readable) {
    memset(readable, 0, sizeof *readable * (size_t)count);
    if (sb->level == SL_SANDBOX_NAMESPACES || count > 32) return 0;
    uint32_t bits = 0;
    if (sb->level == SL_SANDBOX_UID) {
        /* ask as a runner's uid, in a child */
        char err[512];
        uid_t uid;
        int lock = _sl_pool_claim(sb, &uid, err, sizeof err);
        int report[2];
        if (lock < 0) return 0;
        if (pipe2(report, O_CLOEXEC) != 0) {
            _sl_pool_release(sb, uid, lock);
            return 0;
        }
        pid_t pid = fork();
        if (pid == 0) {
            uint32_t found = 0;
            if (_sl_setgroups_none() == 0 && _sl_setresgid((gid_t)uid) == 0 && _sl_setresuid(uid) == 0)
                for (int i = 0; i < count; i++) found |= (uint32_t)_sl_can_read(paths[i]) << i;
            ssize_t w = write(report[1], &found, sizeof found);
            _exit(w == sizeof found ? 0 : 1);
        }
        close(report[1]);
        if (pid > 0) {
            if (read(report[0], &bits, sizeof bits) != sizeof bits) bits = 0;
            while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
        }
        close(report[0]);
        _sl_pool_release(sb, uid, lock);
    } else {
        for (int i = 0; i < count; i++) bits |= (uint32_t)_sl_can_read(paths[i]) << i;
    }
    int n = 0;
    for (int i = 0; i < count; i++) n += readable[i] = (bits >> i) & 1u;
    return n;
}

void sl_sandbox_kill(const sl_sandbox *sb, pid_t pid) {
    if (pid <= 0) return;
    /* PID 1 of a namespace takes the namespace with it; otherwise the session. */
    if (sb->level != SL_SANDBOX_NAMESPACES) kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
}

bool sl_sandbox_runs_runner(const sl_sandbox *sb, const sl_sandbox_process *p) {
    char exe[64];
    snprintf(exe, sizeof exe, "/proc/%d/exe", (int)p->pid);
    struct stat st;
    if (stat(exe, &st) == 0) return st.st_dev == p->runner_dev && st.st_ino == p->runner_ino;
    /* The grader may not look (no CAP_SYS_PTRACE, as in a container, or the
     * runner's own uid at `basic`) because the process is not dumpable. Each
     * exec of a file it may read makes a process dumpable again, and the
     * filter keeps it from changing that itself: so it still runs an
     * execute-only file, and the only ones within its reach are the runners'
     * copies (random names in folders it cannot list). */
    return errno == EACCES && sb->seccomp && sb->runners;
}

/* Not dumpable: a process of the same uid (a runner in the basic sandbox)
 * can then neither trace the grader nor open its memory or fds in /proc. As
 * a constructor, from before main: the window after exec is the loader's
 * only (where the kernel has Landlock, runners cannot reach the grader at
 * all). Any program linking this module (the grader) gets it. */
__attribute__((constructor(101))) static void _sl_not_dumpable(void) { prctl(PR_SET_DUMPABLE, 0, 0, 0, 0); }

bool sl_sandbox_usage(pid_t pid, double *cpu_seconds, double *waited_seconds) {
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    ssize_t got = read(fd, buf, sizeof buf - 1);
    close(fd);
    if (got <= 0) return false;
    buf[got] = '\0';
    const char *after_name = strrchr(buf, ')');
    unsigned long user = 0, system = 0;
    /* fields 3..15: state ppid pgrp session tty tpgid flags minflt cminflt majflt cmajflt utime stime */
    if (!after_name || sscanf(after_name + 1, " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &user, &system) != 2)
        return false;
    long ticks = sysconf(_SC_CLK_TCK);
    *cpu_seconds = (double)(user + system) / (double)(ticks > 0 ? ticks : 100);
    /* schedstat: time on a CPU, time waiting, ready, on a run queue (ns), per thread */
    *waited_seconds = -1;
    snprintf(path, sizeof path, "/proc/%d/task", (int)pid);
    DIR *d = opendir(path);
    if (!d) return true;
    double waited = 0;
    bool any = false;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        char file[128], line[128];
        snprintf(file, sizeof file, "/proc/%d/task/%s/schedstat", (int)pid, e->d_name);
        int t = open(file, O_RDONLY | O_CLOEXEC);
        if (t < 0) continue;
        ssize_t n = read(t, line, sizeof line - 1);
        close(t);
        unsigned long long running, waiting;
        if (n <= 0) continue;
        line[n] = '\0';
        if (sscanf(line, "%llu %llu", &running, &waiting) == 2 && (running || waiting)) {
            waited += (double)waiting * 1e-9;
            any = true;
        }
    }
    closedir(d);
    if (any) *waited_seconds = waited;
    return true;
}
