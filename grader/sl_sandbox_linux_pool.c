#define _GNU_SOURCE
#include "sl_sandbox_linux_pool.h"

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

#include "sl_sandbox_linux_child.h"

/* ---- processes and tasks, as /proc shows them ---- */

/* Calls `each` with the real, effective, saved and file uids of every process and its thread count. */
void _sl_each_process(void (*each)(const uid_t uids[4], long threads, void *context), void *context) {
    DIR *d = opendir("/proc");
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] < '1' || e->d_name[0] > '9') continue;
        char path[300], buf[4096];
        snprintf(path, sizeof path, "/proc/%s/status", e->d_name);
        int fd = open(path, O_RDONLY | O_CLOEXEC);
        if (fd < 0) continue;
        ssize_t got = read(fd, buf, sizeof buf - 1);
        close(fd);
        if (got <= 0) continue;
        buf[got] = '\0';
        const char *u = strstr(buf, "\nUid:"), *t = strstr(buf, "\nThreads:");
        unsigned long v[4];
        if (!u || sscanf(u + 5, "%lu %lu %lu %lu", &v[0], &v[1], &v[2], &v[3]) != 4) continue;
        uid_t uids[4] = {(uid_t)v[0], (uid_t)v[1], (uid_t)v[2], (uid_t)v[3]};
        each(uids, t ? atol(t + 9) : 1, context);
    }
    closedir(d);
}

void _sl_count_tasks(const uid_t uids[4], long threads, void *context) {
    _sl_task_count *c = context;
    if (uids[0] == c->uid) c->tasks += threads;
}

/* ---- the pool of runner uids (the grader as root) ---- */

#define _SL_POOL_FIRST 60800 /* unused by Debian's and systemd's conventions (systemd: 60578-61183 unused) */
#define _SL_POOL_COUNT 256
#define _SL_POOL_MAX 65536

bool _sl_pool_range(uid_t *first, uid_t *count, char *err, size_t n) {
    *first = _SL_POOL_FIRST;
    *count = _SL_POOL_COUNT;
    const char *v = getenv("SHADOWLAB_RUNNER_UIDS");
    if (!v || !*v) return true;
    unsigned long a = 0, b = 0;
    char tail;
    if (sscanf(v, "%lu-%lu%c", &a, &b, &tail) != 2 || a == 0 || b < a || b - a >= _SL_POOL_MAX || b >= 4294967295ul) {
        snprintf(err, n, "SHADOWLAB_RUNNER_UIDS=%s: give FIRST-LAST, unused uids above 0, at most %d of them", v,
                 _SL_POOL_MAX);
        return false;
    }
    *first = (uid_t)a;
    *count = (uid_t)(b - a + 1);
    return true;
}

/* The pool's lock files live in a folder only root may write to: no runner
 * can take, hold or fake a lock. */
bool _sl_pool_lock_dir(char out[64], char *err, size_t n) {
    static const char *const candidates[] = {"/run/shadowlab-runner-uids", "/tmp/shadowlab-runner-uids"};
    for (size_t i = 0; i < sizeof candidates / sizeof candidates[0]; i++) {
        struct stat st;
        if (mkdir(candidates[i], 0700) != 0 && errno != EEXIST) continue;
        if (lstat(candidates[i], &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == 0 && (st.st_mode & 022) == 0) {
            snprintf(out, 64, "%s", candidates[i]);
            return true;
        }
    }
    snprintf(err, n, "no folder for the runner uids' locks: %s and %s are missing or not root's alone", candidates[0],
             candidates[1]);
    return false;
}

typedef struct _sl_pool_scan {
    uid_t first, count;
    uint8_t *busy;
} _sl_pool_scan;

static void _sl_mark_busy(const uid_t uids[4], long threads, void *context) {
    (void)threads;
    _sl_pool_scan *s = context;
    for (int i = 0; i < 4; i++)
        if (uids[i] >= s->first && uids[i] - s->first < s->count) s->busy[uids[i] - s->first] = 1;
}

/* A uid with a user or group name belongs to someone (asked once per grader). */
static bool _sl_uid_named(uid_t first, uid_t count, uid_t uid) {
    static uint8_t *known; /* 0 not asked, 1 nameless, 2 named */
    static uid_t known_first, known_count;
    if (!known || known_first != first || known_count != count) {
        free(known);
        known = calloc(count, 1);
        known_first = first;
        known_count = count;
        if (!known) return true;
    }
    uint8_t *k = &known[uid - first];
    if (!*k) *k = getpwuid(uid) || getgrgid((gid_t)uid) ? 2 : 1;
    return *k == 2;
}

static const char *const _sl_shared_folders[] = {"/tmp", "/var/tmp", "/dev/shm", "/dev/mqueue"};

/* Whether `uid` owns something at the top of the folders every user may write to. */
static bool _sl_owns_shared_files(uid_t uid) {
    bool found = false;
    for (size_t i = 0; i < sizeof _sl_shared_folders / sizeof _sl_shared_folders[0] && !found; i++) {
        DIR *d = opendir(_sl_shared_folders[i]);
        if (!d) continue;
        struct dirent *e;
        struct stat st;
        while (!found && (e = readdir(d)))
            found = fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && st.st_uid == uid;
        closedir(d);
    }
    return found;
}

/* Removes `name` in `dfd` and, a folder, what it holds, never following a
 * link; at most *budget entries. */
static void _sl_remove_at(int dfd, const char *name, int depth, long *budget) {
    struct stat st;
    if (*budget <= 0 || fstatat(dfd, name, &st, AT_SYMLINK_NOFOLLOW) != 0) return;
    --*budget;
    if (S_ISDIR(st.st_mode)) {
        int sub = depth < 32 ? openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC) : -1;
        DIR *d = sub >= 0 ? fdopendir(sub) : NULL;
        if (!d && sub >= 0) close(sub);
        struct dirent *e;
        while (d && (e = readdir(d)))
            if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) _sl_remove_at(dirfd(d), e->d_name, depth + 1, budget);
        if (d) closedir(d);
        unlinkat(dfd, name, AT_REMOVEDIR);
    } else {
        unlinkat(dfd, name, 0);
    }
}

/* What a runner of `uid` left in the shared folders (its processes are gone:
 * nothing of that uid writes there while this runs). */
static void _sl_remove_shared_files(uid_t uid) {
    long budget = 100000;
    for (size_t i = 0; i < sizeof _sl_shared_folders / sizeof _sl_shared_folders[0]; i++) {
        DIR *d = opendir(_sl_shared_folders[i]);
        if (!d) continue;
        struct dirent *e;
        struct stat st;
        while ((e = readdir(d)))
            if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && st.st_uid == uid &&
                strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
                _sl_remove_at(dirfd(d), e->d_name, 0, &budget);
        closedir(d);
    }
}

/* Claims a uid of the pool for one runner: returns the lock that holds it
 * (close it to free the uid), or -1 with the reason. */
int _sl_pool_claim(const sl_sandbox *sb, uid_t *uid, char *err, size_t n) {
    _sl_pool_scan scan = {sb->uid, sb->uid_count, calloc(sb->uid_count, 1)};
    if (!scan.busy) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    _sl_each_process(_sl_mark_busy, &scan);
    /* graders start at different places of the pool, so they rarely try the same locks */
    uid_t start = (uid_t)getpid() % sb->uid_count;
    int lock = -1;
    for (uid_t i = 0; i < sb->uid_count && lock < 0; i++) {
        uid_t candidate = sb->uid + (start + i) % sb->uid_count;
        if (scan.busy[candidate - sb->uid] || _sl_uid_named(sb->uid, sb->uid_count, candidate)) continue;
        char path[128];
        snprintf(path, sizeof path, "%s/%u", sb->lock_dir, (unsigned)candidate);
        int fd = open(path, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0) continue;
        if (flock(fd, LOCK_EX | LOCK_NB) != 0 || _sl_owns_shared_files(candidate)) {
            close(fd);
            continue;
        }
        *uid = candidate;
        lock = fd;
    }
    free(scan.busy);
    if (lock < 0)
        snprintf(err, n, "no free runner uid in %u-%u (each has a runner, a process, a user or group name, or files in "
                         "/tmp, /var/tmp or /dev/shm): set SHADOWLAB_RUNNER_UIDS=FIRST-LAST to a range of unused uids",
                 (unsigned)sb->uid, (unsigned)(sb->uid + sb->uid_count - 1));
    return lock;
}

/* Frees a uid of the pool: below the namespaces sandbox, whatever still runs
 * as it is killed and what it left in the shared folders removed first (in
 * namespaces, its PID namespace and private /tmp went with the runner). */
void _sl_pool_release(const sl_sandbox *sb, uid_t uid, int lock) {
    if (sb->level != SL_SANDBOX_NAMESPACES) {
        pid_t pid = fork();
        if (pid == 0) {
            /* kill(-1) as the uid reaches exactly its processes */
            if (_sl_setgroups_none() == 0 && _sl_setresgid((gid_t)uid) == 0 && _sl_setresuid(uid) == 0) kill(-1, SIGKILL);
            _exit(0);
        }
        while (pid > 0 && waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
        _sl_remove_shared_files(uid);
    }
    close(lock);
}
