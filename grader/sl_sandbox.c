#define _GNU_SOURCE
#include "sl_sandbox.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#define _SL_SANDBOX_UID 65534 /* "nobody": owns nothing on the grading machine */
#define _SL_INNER_ID 1000      /* the runner's uid inside a user namespace */
#define _SL_COPY_FILE_MAX (1 << 20)
#define _SL_COPY_TOTAL_MAX (16 << 20)
#define _SL_COPY_DEPTH_MAX 8

static const char *const _sl_level_names[] = {"basic", "uid", "namespaces"};

const char *sl_sandbox_level_name(sl_sandbox_level level) {
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

/* ---- the child's side: everything below runs between fork and exec ---- */

/* Set-up failures travel to the parent over a close-on-exec pipe: an exec
 * that succeeds closes it empty. */
static int _sl_report_fd = -1;

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

#if defined(__x86_64__)
#define _SL_AUDIT_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define _SL_AUDIT_ARCH AUDIT_ARCH_AARCH64
#endif

#ifdef _SL_AUDIT_ARCH
/* System calls lab code never needs and that could reach past the sandbox:
 * other processes, namespaces and mounts, and kernel interfaces that bypass
 * or widen this filter (io_uring, bpf). */
static const int _sl_denied_syscalls[] = {
    __NR_tkill, __NR_ptrace, __NR_process_vm_readv, __NR_process_vm_writev, __NR_setsid, __NR_setpgid,
    __NR_unshare, __NR_setns, __NR_mount, __NR_umount2, __NR_pivot_root, __NR_chroot, __NR_bpf,
    __NR_userfaultfd, __NR_keyctl, __NR_add_key, __NR_request_key,
#ifdef __NR_pidfd_open
    __NR_pidfd_open,
#endif
#ifdef __NR_pidfd_send_signal
    __NR_pidfd_send_signal,
#endif
#ifdef __NR_pidfd_getfd
    __NR_pidfd_getfd,
#endif
#ifdef __NR_io_uring_setup
    __NR_io_uring_setup,
#endif
#ifdef __NR_fsopen
    __NR_fsopen, __NR_fsmount, __NR_move_mount, __NR_open_tree,
#endif
};

#define _SL_DENIED_COUNT ((int)(sizeof _sl_denied_syscalls / sizeof _sl_denied_syscalls[0]))
#define _SL_EMIT(instruction) filter[n++] = (struct sock_filter)instruction
#define _SL_LOAD(field) _SL_EMIT(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, (uint32_t)offsetof(struct seccomp_data, field)))
#define _SL_RETURN(value) _SL_EMIT(BPF_STMT(BPF_RET | BPF_K, (value)))
#define _SL_IF_EQUAL(value, skip_if_true, skip_if_false) \
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, (value), (skip_if_true), (skip_if_false)))

/* The process filter: lab code may start threads but no processes, signal
 * only itself, and not trace, remount or leave its namespaces. */
static bool _sl_install_seccomp(void) {
    const uint32_t self = (uint32_t)getpid(); /* exec keeps the pid */
    const uint32_t eperm = SECCOMP_RET_ERRNO | EPERM, allow = SECCOMP_RET_ALLOW;
    struct sock_filter filter[32 + _SL_DENIED_COUNT];
    int n = 0;
    _SL_LOAD(arch);
    _SL_IF_EQUAL(_SL_AUDIT_ARCH, 1, 0);
    _SL_RETURN(SECCOMP_RET_KILL_PROCESS);
    _SL_LOAD(nr);
#if defined(__x86_64__)
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u /* the x32 ABI */, 0, 1));
    _SL_RETURN(eperm);
    _SL_IF_EQUAL(__NR_fork, 2, 0);
    _SL_IF_EQUAL(__NR_vfork, 1, 0);
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JA, 1, 0, 0));
    _SL_RETURN(eperm);
#endif
    /* clone: threads only */
    _SL_IF_EQUAL(__NR_clone, 0, 4);
    _SL_LOAD(args[0]);
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, CLONE_THREAD, 1, 0));
    _SL_RETURN(eperm);
    _SL_RETURN(allow);
    /* clone3 passes its flags in memory a filter cannot read: glibc then falls back to clone */
    _SL_IF_EQUAL(__NR_clone3, 0, 1);
    _SL_RETURN(SECCOMP_RET_ERRNO | ENOSYS);
    /* kill: this process, or 0 (its own process group) */
    _SL_IF_EQUAL(__NR_kill, 0, 5);
    _SL_LOAD(args[0]);
    _SL_IF_EQUAL(self, 2, 0);
    _SL_IF_EQUAL(0, 1, 0);
    _SL_RETURN(eperm);
    _SL_RETURN(allow);
    /* the thread-directed signals: this process's threads only */
    _SL_IF_EQUAL(__NR_tgkill, 2, 0);
    _SL_IF_EQUAL(__NR_rt_sigqueueinfo, 1, 0);
    _SL_IF_EQUAL(__NR_rt_tgsigqueueinfo, 0, 4);
    _SL_LOAD(args[0]);
    _SL_IF_EQUAL(self, 1, 0);
    _SL_RETURN(eperm);
    _SL_RETURN(allow);
    for (int i = 0; i < _SL_DENIED_COUNT; i++) _SL_IF_EQUAL((uint32_t)_sl_denied_syscalls[i], (uint8_t)(_SL_DENIED_COUNT - i), 0);
    _SL_RETURN(allow);
    _SL_RETURN(eperm);
    struct sock_fprog program = {(unsigned short)n, filter};
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    return syscall(__NR_seccomp, SECCOMP_SET_MODE_FILTER, 0, &program) == 0;
}
#else
static bool _sl_install_seccomp(void) { return false; }
#endif

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
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) == 0) return sb->mount_point;
    if (errno != EINVAL) _sl_fail("cannot make the mounts private: %s", strerror(errno));
    static const char *const visible[] = {"/sys", "/dev/pts", "/dev/shm", "/run", "/proc"};
    for (size_t i = 0; i < sizeof visible / sizeof visible[0]; i++)
        if (mount(NULL, visible[i], NULL, MS_REC | MS_PRIVATE, NULL) == 0) return visible[i];
    _sl_fail("cannot make the mounts private: \"/\" is no mount point (a chroot?) and no other mount is");
}

/* Builds the sandbox's file system and enters it. */
static void _sl_enter_view(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d) {
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
    _sl_bind_file(d->runner, path, true);

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
static int _sl_setgroups_none(void) { return (int)syscall(SYS_setgroups, 0, NULL); }
static int _sl_setresgid(gid_t gid) { return (int)syscall(SYS_setresgid, gid, gid, gid); }
static int _sl_setresuid(uid_t uid) { return (int)syscall(SYS_setresuid, uid, uid, uid); }

static void _sl_drop_to_uid(uid_t uid) {
    gid_t gid = (gid_t)uid;
    if (_sl_setgroups_none() != 0 || _sl_setresgid(gid) != 0 || _sl_setresuid(uid) != 0)
        _sl_fail("cannot switch to uid %u: %s", (unsigned)uid, strerror(errno));
}

static void _sl_limits(const sl_sandbox_spawn_desc *d) {
    rlim_t cpu = (rlim_t)(d->cpu_seconds > 0 ? d->cpu_seconds : 60) + 1;
    struct rlimit limits[][1] = {{{cpu, cpu + 1}}, {{d->memory_bytes, d->memory_bytes}}, {{16 << 20, 16 << 20}}, {{0, 0}},
                                 {{256, 256}}};
    int resources[] = {RLIMIT_CPU, RLIMIT_AS, RLIMIT_FSIZE, RLIMIT_CORE, RLIMIT_NOFILE};
    for (size_t i = 0; i < sizeof resources / sizeof resources[0]; i++) {
        if (resources[i] == RLIMIT_AS && d->memory_bytes == 0) continue;
        if (setrlimit(resources[i], limits[i]) != 0)
            _sl_fail("cannot set a resource limit: %s", strerror(errno));
    }
}

static void _sl_child(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, uid_t outer_uid, gid_t outer_gid,
                      bool probe) {
    bool as_root = outer_uid == 0 && !sb->user_namespace;
    /* Its own session and process group, so kill(0, ...) reaches nothing else. */
    if (setsid() < 0) _sl_fail("setsid: %s", strerror(errno));
    if (sb->level == SL_SANDBOX_NAMESPACES) {
        if (sb->user_namespace) {
            char map[64];
            /* the grader is not dumpable, and /proc/self then belongs to root */
            prctl(PR_SET_DUMPABLE, 1, 0, 0, 0);
            _sl_write_file("/proc/self/setgroups", "deny");
            snprintf(map, sizeof map, "%d %u 1\n", _SL_INNER_ID, (unsigned)outer_uid);
            _sl_write_file("/proc/self/uid_map", map);
            snprintf(map, sizeof map, "%d %u 1\n", _SL_INNER_ID, (unsigned)outer_gid);
            _sl_write_file("/proc/self/gid_map", map);
        }
        _sl_enter_view(sb, d);
    }
    if ((as_root && sb->level == SL_SANDBOX_NAMESPACES) || sb->level == SL_SANDBOX_UID) _sl_drop_to_uid(_SL_SANDBOX_UID);
    if (probe) {
        /* the runner must be reachable for the uid it runs as */
        const char *runner = sb->level == SL_SANDBOX_NAMESPACES ? "/shadowlab-runner" : d->runner;
        if (access(runner, X_OK) != 0) _sl_fail("uid %u cannot run %s: %s", (unsigned)geteuid(), runner, strerror(errno));
        _exit(0);
    }
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) _sl_fail("PR_SET_PDEATHSIG: %s", strerror(errno));
    _sl_limits(d);
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
    if (sb->seccomp && !_sl_install_seccomp()) _sl_fail("cannot install the process filter: %s", strerror(errno));
    const char *path = sb->level == SL_SANDBOX_NAMESPACES ? "/shadowlab-runner" : d->runner;
    char *const argv[] = {(char *)"shadowlab-runner", NULL};
    execve(path, argv, (char *const *)d->environment);
    _sl_fail("cannot start %s: %s", d->runner, strerror(errno));
}

/* fork, or clone into new namespaces: the child then is PID 1 of its own
 * PID namespace, and everything it starts dies with it. */
static pid_t _sl_fork(const sl_sandbox *sb) {
    if (sb->level != SL_SANDBOX_NAMESPACES) return fork();
    unsigned long flags = CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS | SIGCHLD;
    if (sb->user_namespace) flags |= CLONE_NEWUSER;
    return (pid_t)syscall(SYS_clone, flags, NULL, NULL, NULL, NULL);
}

static bool _sl_start(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, bool probe, pid_t *pid_out, char *err,
                      size_t n) {
    int report[2];
    if (pipe2(report, O_CLOEXEC) != 0) {
        snprintf(err, n, "pipe: %s", strerror(errno));
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
        return false;
    }
    if (pid == 0) {
        close(report[0]);
        _sl_report_fd = report[1];
        _sl_child(sb, d, uid, gid, probe);
    }
    close(report[1]);
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

/* Sets the sandbox up as a runner's would be, up to the exec, in a process
 * that then only checks it could run the runner. */
static bool _sl_try_level(sl_sandbox *sb, sl_sandbox_level level, bool user_namespace, const char *runner, char *why,
                          size_t n) {
    sb->level = level;
    sb->user_namespace = user_namespace;
    sl_sandbox_spawn_desc probe = {.runner = runner, .framework_dir = "/nonexistent"};
    pid_t pid;
    return _sl_start(sb, &probe, true, &pid, why, n);
}

bool sl_sandbox_open(sl_sandbox *sb, sl_sandbox_level at_most, const char *runner, char *err, size_t n) {
    memset(sb, 0, sizeof *sb);
    bool root = geteuid() == 0;
#ifdef _SL_AUDIT_ARCH
    /* Can this kernel filter system calls? (PR_GET_SECCOMP fails without seccomp.) */
    sb->seccomp = prctl(PR_GET_SECCOMP, 0, 0, 0, 0) >= 0;
#endif
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
                sb->uid = root && !sb->user_namespace ? _SL_SANDBOX_UID : geteuid();
                return true;
            }
        }
        snprintf(sb->why_not_stronger, sizeof sb->why_not_stronger, "no namespaces: %s", why);
    }
    char uid_why[256] = "";
    if (at_most >= SL_SANDBOX_UID && root && _sl_try_level(sb, SL_SANDBOX_UID, false, runner, uid_why, sizeof uid_why)) {
        sb->uid = _SL_SANDBOX_UID;
        return true;
    }
    if (uid_why[0])
        snprintf(sb->why_not_stronger + strlen(sb->why_not_stronger),
                 sizeof sb->why_not_stronger - strlen(sb->why_not_stronger), "%sno other uid: %s",
                 sb->why_not_stronger[0] ? "; " : "", uid_why);
    if (at_most >= SL_SANDBOX_UID && !root && !sb->why_not_stronger[0])
        snprintf(sb->why_not_stronger, sizeof sb->why_not_stronger, "not root: no other uid");
    if (_sl_try_level(sb, SL_SANDBOX_BASIC, false, runner, why, sizeof why)) {
        sb->uid = geteuid();
        return true;
    }
    snprintf(err, n, "cannot start a sandboxed process: %s", why);
    return false;
}

void sl_sandbox_close(sl_sandbox *sb) {
    if (sb->mount_point[0]) rmdir(sb->mount_point);
    sb->mount_point[0] = '\0';
}

void sl_sandbox_describe(const sl_sandbox *sb, char *out, size_t n) {
    switch (sb->level) {
    case SL_SANDBOX_NAMESPACES:
        snprintf(out, n, "namespaces (%suid %u, read-only view of the shaders under test, no network%s)",
                 sb->user_namespace ? "user namespace, " : "", (unsigned)sb->uid, sb->seccomp ? ", seccomp" : "");
        break;
    case SL_SANDBOX_UID:
        snprintf(out, n, "uid (runs as uid %u%s; %s)", (unsigned)sb->uid, sb->seccomp ? ", seccomp" : "",
                 sb->why_not_stronger[0] ? sb->why_not_stronger : "by request");
        break;
    default:
        snprintf(out, n, "basic (the grader's uid%s; %s)", sb->seccomp ? ", seccomp" : "",
                 sb->why_not_stronger[0] ? sb->why_not_stronger : "by request");
        break;
    }
}

bool sl_sandbox_spawn(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, sl_sandbox_process *out, char *err,
                      size_t n) {
    memset(out, 0, sizeof *out);
    if (sb->level == SL_SANDBOX_NAMESPACES) {
        snprintf(out->labs_dir, sizeof out->labs_dir, "/labs");
        snprintf(out->framework_dir, sizeof out->framework_dir, "/framework");
    } else {
        snprintf(out->labs_dir, sizeof out->labs_dir, "%s", d->labs_tree);
        snprintf(out->framework_dir, sizeof out->framework_dir, "%s", d->framework_dir);
    }
    return _sl_start(sb, d, false, &out->pid, err, n);
}

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
        /* ask as the runner's uid, in a child */
        int report[2];
        if (pipe2(report, O_CLOEXEC) != 0) return 0;
        pid_t pid = fork();
        if (pid == 0) {
            uint32_t found = 0;
            gid_t gid = (gid_t)sb->uid;
            if (_sl_setgroups_none() == 0 && _sl_setresgid(gid) == 0 && _sl_setresuid(sb->uid) == 0)
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

bool sl_sandbox_runs_runner(pid_t pid, const char *runner) {
    char exe[64];
    snprintf(exe, sizeof exe, "/proc/%d/exe", (int)pid);
    struct stat a, b;
    return stat(exe, &a) == 0 && stat(runner, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}
