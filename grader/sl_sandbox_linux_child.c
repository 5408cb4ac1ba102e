#define _GNU_SOURCE
#include "sl_sandbox_linux_child.h"

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

#include "sl_protocol.h" /* SL_TECHNIQUE_FOLDER */
#include "sl_mount_point.h"
#include "sl_sandbox_linux_filters.h"

#define _SL_COPY_FILE_MAX (1 << 20)
#define _SL_COPY_TOTAL_MAX (16 << 20)
#define _SL_COPY_DEPTH_MAX 8

/* ---- the child's side: everything below runs between fork and exec ---- */

/* Set-up failures travel to the parent over a close-on-exec pipe: an exec
 * that succeeds closes it empty. */
int _sl_report_fd = -1;

static void _sl_fail(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
static void _sl_fail(const char *fmt, ...) {
    char msg[512];
    va_list args;
    va_start(args, fmt);
    int n = vsnprintf(msg, sizeof msg, fmt, args);
    va_end(args);
    if (n > 0 && _sl_report_fd >= 0) {
        ssize_t w = write(_sl_report_fd, msg, (size_t)n < sizeof msg ? (size_t)n : sizeof msg - 1);
        (void)w;
    }
    _exit(127);
}

static void _sl_write_file(const char *path, const char *text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) _sl_fail("cannot open %s: %s", path, strerror(errno));
    ssize_t n = (ssize_t)strlen(text);
    if (write(fd, text, (size_t)n) != n) _sl_fail("cannot write %s: %s", path, strerror(errno));
    close(fd);
}

static void _sl_path(char *out, size_t n, const char *a, const char *b) {
    if ((size_t)snprintf(out, n, "%s/%s", a, b) >= n) _sl_fail("path too long: %s/%s", a, b);
}

static void _sl_mkdir(const char *path, mode_t mode) {
    if (mkdir(path, mode) != 0 && errno != EEXIST) _sl_fail("cannot create %s: %s", path, strerror(errno));
}

/* Mounts `source` read-only at `target`, keeping the flags the kernel locks
 * on mounts a user namespace inherits (nosuid, nodev, noexec). */
static void _sl_bind_read_only(const char *source, const char *target) {
    if (mount(source, target, NULL, MS_BIND | MS_REC, NULL) != 0)
        _sl_fail("cannot bind %s: %s", source, strerror(errno));
    struct statvfs st;
    unsigned long flags = MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID;
    if (statvfs(source, &st) == 0) {
        if (st.f_flag & ST_NODEV) flags |= MS_NODEV;
        if (st.f_flag & ST_NOEXEC) flags |= MS_NOEXEC;
        if (st.f_flag & ST_NOATIME) flags |= MS_NOATIME;
        if (st.f_flag & ST_RELATIME) flags |= MS_RELATIME;
    }
    if (mount(NULL, target, NULL, flags, NULL) != 0) _sl_fail("cannot make %s read-only: %s", target, strerror(errno));
}

/* A top-level system folder (/usr, /lib, ...): the same link where it is a
 * link (merged /usr), a read-only view where it is a folder. */
static void _sl_system_folder(const char *root, const char *name) {
    char source[64], target[600], link[256];
    snprintf(source, sizeof source, "/%s", name);
    _sl_path(target, sizeof target, root, name);
    struct stat st;
    if (lstat(source, &st) != 0) return;
    if (S_ISLNK(st.st_mode)) {
        ssize_t n = readlink(source, link, sizeof link - 1);
        if (n <= 0) return;
        link[n] = '\0';
        if (symlink(link, target) != 0) _sl_fail("cannot link %s: %s", target, strerror(errno));
    } else if (S_ISDIR(st.st_mode)) {
        _sl_mkdir(target, 0755);
        _sl_bind_read_only(source, target);
    }
}

static void _sl_bind_file(const char *source, const char *target, bool required) {
    struct stat st;
    if (stat(source, &st) != 0) {
        if (required) _sl_fail("%s: %s", source, strerror(errno));
        return;
    }
    int fd = open(target, O_WRONLY | O_CREAT | O_CLOEXEC, 0444);
    if (fd < 0) _sl_fail("cannot create %s: %s", target, strerror(errno));
    close(fd);
    _sl_bind_read_only(source, target);
}

/* Copies a folder of shaders: regular files only (no link is followed, a
 * file linked from elsewhere is skipped), bounded in size and depth. `dfd`
 * is the open folder (closed here). */
static void _sl_copy_tree(int dfd, const char *target, int depth, size_t *budget) {
    if (depth > _SL_COPY_DEPTH_MAX) {
        close(dfd);
        return;
    }
    DIR *d = fdopendir(dfd);
    if (!d) {
        close(dfd);
        return;
    }
    _sl_mkdir(target, 0755);
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' && (!e->d_name[1] || (e->d_name[1] == '.' && !e->d_name[2]))) continue;
        char to[1100];
        _sl_path(to, sizeof to, target, e->d_name);
        struct stat st;
        if (fstatat(dfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            int sub = openat(dfd, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub >= 0) _sl_copy_tree(sub, to, depth + 1, budget);
        } else if (S_ISREG(st.st_mode) && st.st_nlink == 1 && st.st_size <= _SL_COPY_FILE_MAX &&
                   (size_t)st.st_size <= *budget) {
            int in = openat(dfd, e->d_name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
            if (in < 0) continue;
            int out = open(to, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0444);
            if (out < 0) _sl_fail("cannot create %s: %s", to, strerror(errno));
            char buf[16384];
            ssize_t got;
            while ((got = read(in, buf, sizeof buf)) > 0 && *budget >= (size_t)got) {
                if (write(out, buf, (size_t)got) != got) _sl_fail("cannot write %s: %s", to, strerror(errno));
                *budget -= (size_t)got;
            }
            close(in);
            close(out);
        }
    }
    closedir(d);
}

/* A lab's shaders folder, <tree>/<folder>/shaders, opened without following
 * a link at either step: a submission's lab folder that links elsewhere (the
 * solutions) brings nothing in. -1 when there is none. */
static int _sl_open_shaders(const char *tree, const char *folder) {
    int top = open(tree, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (top < 0) return -1;
    int lab = openat(top, folder, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    close(top);
    if (lab < 0) return -1;
    int shaders = openat(lab, "shaders", O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    close(lab);
    return shaders;
}

/* --backend window: the runner's hidden window talks to the X server through
 * the display's socket file (the abstract socket belongs to another network
 * namespace) and shows the display's cookie, copied to the same path inside
 * (read where the grader's user may read it, before the uid changes). */
static void _sl_show_display(const char *root, const sl_sandbox_spawn_desc *d) {
    char path[1100];
    struct stat st;
    if (stat("/tmp/.X11-unix", &st) == 0 && S_ISDIR(st.st_mode)) {
        _sl_path(path, sizeof path, root, "tmp/.X11-unix");
        _sl_mkdir(path, 0755);
        _sl_bind_read_only("/tmp/.X11-unix", path);
    }
    const char *cookie = NULL;
    for (const char *const *e = d->environment; e && *e; e++)
        if (strncmp(*e, "XAUTHORITY=/", 12) == 0) cookie = *e + 11;
    if (!cookie || strstr(cookie, "/../") || strlen(cookie) > 512) return;
    int in = open(cookie, O_RDONLY | O_CLOEXEC);
    if (in < 0) return; /* the X server then says whether it wanted one */
    char data[16384];
    ssize_t size = read(in, data, sizeof data);
    close(in);
    if (size <= 0) return;
    _sl_path(path, sizeof path, root, cookie + 1);
    for (char *slash = path + strlen(root) + 1; (slash = strchr(slash, '/')) != NULL; slash++) {
        *slash = '\0';
        _sl_mkdir(path, 0755);
        *slash = '/';
    }
    int out = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0444);
    if (out < 0 || write(out, data, (size_t)size) != size) _sl_fail("cannot copy the display's cookie: %s", strerror(errno));
    close(out);
}

/* Where the sandbox's root is mounted, in this new mount namespace, so that
 * nothing mounted there reaches another namespace. Normally every mount is
 * made private and the grader's empty folder is used. Under a chroot, "/" is
 * no mount point and the mount holding it cannot be reached: a mount point
 * the chroot does show (/sys, /dev/pts) is made private and mounted over. */
static const char *_sl_private_mount_point(const sl_sandbox *sb) {
    const char *point = sl_private_mount_point();
    if (!point && errno != EINVAL) _sl_fail("cannot make the mounts private: %s", strerror(errno));
    if (!point) _sl_fail("cannot make the mounts private: \"/\" is no mount point (a chroot?) and no other mount is");
    return strcmp(point, "/") == 0 ? sb->mount_point : point;
}

/* Builds the sandbox's file system and enters it. */
static void _sl_enter_view(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, const char *runner) {
    const char *root = _sl_private_mount_point(sb);
    if (mount("tmpfs", root, "tmpfs", MS_NOSUID | MS_NODEV, "size=32m,mode=0755") != 0)
        _sl_fail("cannot mount a tmpfs on %s: %s", root, strerror(errno));
    static const char *const system[] = {"usr", "bin", "sbin", "lib", "lib32", "lib64", "libx32"};
    for (size_t i = 0; i < sizeof system / sizeof system[0]; i++) _sl_system_folder(root, system[i]);
    char path[1100], sub[1100];
    _sl_path(path, sizeof path, root, "etc");
    _sl_mkdir(path, 0755);
    _sl_path(path, sizeof path, root, "etc/ld.so.cache");
    _sl_bind_file("/etc/ld.so.cache", path, false);
    /* Debian's alternatives: some libraries are links through /etc/alternatives */
    struct stat alt;
    if (stat("/etc/alternatives", &alt) == 0 && S_ISDIR(alt.st_mode)) {
        _sl_path(path, sizeof path, root, "etc/alternatives");
        _sl_mkdir(path, 0755);
        _sl_bind_read_only("/etc/alternatives", path);
    }
    _sl_path(path, sizeof path, root, "dev");
    _sl_mkdir(path, 0755);
    static const char *const devices[] = {"null", "zero", "full", "random", "urandom"};
    for (size_t i = 0; i < sizeof devices / sizeof devices[0]; i++) {
        char source[32];
        snprintf(source, sizeof source, "/dev/%s", devices[i]);
        _sl_path(path, sizeof path, root, source + 1);
        _sl_bind_file(source, path, false);
    }
    /* A GPU, where there is one, for EGL's device platform. */
    struct stat st;
    if (stat("/dev/dri", &st) == 0 && S_ISDIR(st.st_mode)) {
        _sl_path(path, sizeof path, root, "dev/dri");
        _sl_mkdir(path, 0755);
        if (mount("/dev/dri", path, NULL, MS_BIND | MS_REC, NULL) != 0) rmdir(path);
    }
    _sl_path(path, sizeof path, root, "proc");
    _sl_mkdir(path, 0555);
    /* the new PID namespace's own /proc: only the runner's processes are in it */
    if (mount("proc", path, "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, NULL) != 0)
        _sl_fail("cannot mount /proc: %s", strerror(errno));
    _sl_path(path, sizeof path, root, "tmp");
    _sl_mkdir(path, 01777);
    if (mount("tmpfs", path, "tmpfs", MS_NOSUID | MS_NODEV, "size=16m,mode=1777") != 0)
        _sl_fail("cannot mount /tmp: %s", strerror(errno));
    if (d->display) _sl_show_display(root, d);
    _sl_path(path, sizeof path, root, "shadowlab-runner");
    _sl_bind_file(runner, path, true);

    /* The shaders under test, copied: regular files of the lab folders only,
     * no link followed, so the copy shows nothing from elsewhere and lab code
     * cannot change what a later case reads. */
    _sl_path(path, sizeof path, root, "labs");
    _sl_mkdir(path, 0755);
    _sl_path(path, sizeof path, root, "framework");
    _sl_mkdir(path, 0755);
    size_t budget = _SL_COPY_TOTAL_MAX;
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) {
        if (!d->lab_dirs[lab]) continue;
        _sl_path(path, sizeof path, root, "labs");
        _sl_path(sub, sizeof sub, path, sl_lab_folder(lab));
        _sl_mkdir(sub, 0755);
        _sl_path(path, sizeof path, sub, "shaders");
        int shaders = _sl_open_shaders(d->lab_dirs[lab], sl_lab_folder(lab));
        if (shaders >= 0) _sl_copy_tree(shaders, path, 0, &budget);
    }
    if (d->lab_dirs[0]) { /* the technique a build adds: its own folder's shaders/ */
        _sl_path(path, sizeof path, root, "labs/" SL_TECHNIQUE_FOLDER);
        _sl_mkdir(path, 0755);
        _sl_path(sub, sizeof sub, path, "shaders");
        int top = open(d->lab_dirs[0], O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        int shaders = top >= 0 ? openat(top, "shaders", O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC) : -1;
        if (top >= 0) close(top);
        if (shaders >= 0) _sl_copy_tree(shaders, sub, 0, &budget);
    }
    char source[1100];
    _sl_path(source, sizeof source, d->framework_dir, "shaders");
    _sl_path(path, sizeof path, root, "framework/shaders");
    int shaders = open(source, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (shaders >= 0) _sl_copy_tree(shaders, path, 0, &budget);
    /* The root itself read-only, then entered. */
    if (mount(NULL, root, NULL, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV, NULL) != 0)
        _sl_fail("cannot make the sandbox read-only: %s", strerror(errno));
    if (chdir(root) != 0 || chroot(".") != 0 || chdir("/tmp") != 0)
        _sl_fail("cannot enter the sandbox: %s", strerror(errno));
}

/* Raw system calls, not glibc's wrappers: these run in a child forked from the
 * grader's threads, and glibc's wrappers wait for every thread the parent had
 * (to change their ids too); a thread the parent was creating at the fork
 * never answers, and the child hung there under load. The child has one thread. */
int _sl_setgroups_none(void) { return (int)syscall(SYS_setgroups, 0, NULL); }
int _sl_setresgid(gid_t gid) { return (int)syscall(SYS_setresgid, gid, gid, gid); }
int _sl_setresuid(uid_t uid) { return (int)syscall(SYS_setresuid, uid, uid, uid); }

static void _sl_drop_to_uid(uid_t uid) {
    gid_t gid = (gid_t)uid;
    if (_sl_setgroups_none() != 0 || _sl_setresgid(gid) != 0 || _sl_setresuid(uid) != 0)
        _sl_fail("cannot switch to uid %u: %s", (unsigned)uid, strerror(errno));
}

/* In a user namespace the child holds every capability of it until the exec,
 * the right to read any file among them: without them, the exec of the
 * execute-only runner leaves the process not dumpable, as it does elsewhere. */
static void _sl_drop_capabilities(void) {
    struct __user_cap_header_struct header = {_LINUX_CAPABILITY_VERSION_3, 0};
    struct __user_cap_data_struct data[_LINUX_CAPABILITY_U32S_3];
    memset(data, 0, sizeof data);
    if (syscall(SYS_capset, &header, data) != 0) _sl_fail("cannot drop the capabilities: %s", strerror(errno));
}

static void _sl_limits(const sl_sandbox_spawn_desc *d, rlim_t processes) {
    rlim_t cpu = (rlim_t)(d->cpu_seconds > 0 ? d->cpu_seconds : 60) + 1;
    const struct {
        int resource;
        rlim_t soft, hard;
    } limits[] = {
        {RLIMIT_CPU, cpu, cpu + 1},     {RLIMIT_AS, d->memory_bytes, d->memory_bytes},
        {RLIMIT_FSIZE, 16 << 20, 16 << 20}, {RLIMIT_CORE, 0, 0},
        {RLIMIT_NOFILE, 256, 256},      {RLIMIT_NPROC, processes, processes},
    };
    for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++) {
        if ((limits[i].resource == RLIMIT_AS && d->memory_bytes == 0) || (limits[i].resource == RLIMIT_NPROC && processes == 0))
            continue;
        struct rlimit l = {limits[i].soft, limits[i].hard};
        if (setrlimit(limits[i].resource, &l) != 0) _sl_fail("cannot set a resource limit: %s", strerror(errno));
    }
}

void _sl_child_exec(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, const _sl_plan *plan, uid_t outer_uid,
                     gid_t outer_gid, int go_fd, bool probe) {
    /* Its own session and process group, so kill(0, ...) reaches nothing else. */
    if (setsid() < 0) _sl_fail("setsid: %s", strerror(errno));
    /* Its pids cgroup first, while it may still join it: every task it makes counts there. */
    if (plan->cgroup[0]) {
        char procs[400];
        snprintf(procs, sizeof procs, "%s/cgroup.procs", plan->cgroup);
        _sl_write_file(procs, "0");
    }
    if (sb->level == SL_SANDBOX_NAMESPACES) {
        if (plan->maps_from_grader) {
            char go = 0;
            ssize_t got;
            while ((got = read(go_fd, &go, 1)) < 0 && errno == EINTR) {}
            if (got != 1) _sl_fail("the grader could not map the runner's uid into its user namespace");
            /* only the runner's uid is mapped: the view is made as that uid */
            _sl_drop_to_uid(plan->uid);
        } else if (sb->user_namespace) {
            char map[64];
            /* the grader is not dumpable, and /proc/self then belongs to root */
            prctl(PR_SET_DUMPABLE, 1, 0, 0, 0);
            _sl_write_file("/proc/self/setgroups", "deny");
            snprintf(map, sizeof map, "%d %u 1\n", _SL_INNER_ID, (unsigned)outer_uid);
            _sl_write_file("/proc/self/uid_map", map);
            snprintf(map, sizeof map, "%d %u 1\n", _SL_INNER_ID, (unsigned)outer_gid);
            _sl_write_file("/proc/self/gid_map", map);
        }
        _sl_enter_view(sb, d, plan->runner);
    }
    if (plan->switch_uid && !plan->maps_from_grader) _sl_drop_to_uid(plan->uid);
    if (sb->user_namespace) _sl_drop_capabilities();
    if (probe) {
        /* the runner must be reachable for the uid it runs as */
        const char *runner = sb->level == SL_SANDBOX_NAMESPACES ? "/shadowlab-runner" : plan->runner;
        if (access(runner, X_OK) != 0) _sl_fail("uid %u cannot run %s: %s", (unsigned)geteuid(), runner, strerror(errno));
        _exit(0);
    }
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) _sl_fail("PR_SET_PDEATHSIG: %s", strerror(errno));
    _sl_limits(d, plan->process_limit);
    /* fds: 0 the job, 1 and 2 the output, 3 the channel; nothing else survives exec */
    int fds[4] = {d->stdin_fd, d->output_fd, d->output_fd, d->channel_fd};
    int moved[4];
    for (int i = 0; i < 4; i++) {
        moved[i] = fcntl(fds[i], F_DUPFD_CLOEXEC, 10);
        if (moved[i] < 0) _sl_fail("dup: %s", strerror(errno));
    }
    for (int i = 0; i < 4; i++)
        if (dup2(moved[i], i) != i) _sl_fail("dup2: %s", strerror(errno));
    if (_sl_report_fd < 10) {
        int fd = fcntl(_sl_report_fd, F_DUPFD_CLOEXEC, 10);
        if (fd >= 0) _sl_report_fd = fd;
    }
    if (syscall(__NR_close_range, 4, ~0u, CLOSE_RANGE_CLOEXEC) != 0)
        for (int fd = 4; fd < 1024; fd++) fcntl(fd, F_SETFD, FD_CLOEXEC);
    signal(SIGPIPE, SIG_DFL);
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) _sl_fail("PR_SET_NO_NEW_PRIVS: %s", strerror(errno));
    if (sb->landlock && !_sl_enter_landlock_domain(sb->landlock))
        _sl_fail("cannot enter a Landlock domain: %s", strerror(errno));
    if (sb->seccomp && !_sl_install_seccomp()) _sl_fail("cannot install the process filter: %s", strerror(errno));
    const char *path = sb->level == SL_SANDBOX_NAMESPACES ? "/shadowlab-runner" : plan->runner;
    char *const argv[] = {(char *)"shadowlab-runner", NULL};
    execve(path, argv, (char *const *)d->environment);
    _sl_fail("cannot start %s: %s", d->runner, strerror(errno));
}

/* fork, or clone into new namespaces: the child then is PID 1 of its own
 * PID namespace, and everything it starts dies with it. */
pid_t _sl_fork(const sl_sandbox *sb) {
    if (sb->level != SL_SANDBOX_NAMESPACES) return fork();
    unsigned long flags = CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS | SIGCHLD;
    if (sb->user_namespace) flags |= CLONE_NEWUSER;
    return (pid_t)syscall(SYS_clone, flags, NULL, NULL, NULL, NULL);
}
