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

#include "sl_mount_point.h"

#define _SL_INNER_ID 1000      /* the runner's uid inside a user namespace */
#define _SL_COPY_FILE_MAX (1 << 20)
#define _SL_COPY_TOTAL_MAX (16 << 20)
#define _SL_COPY_DEPTH_MAX 8

/* sl_sandbox on Linux: namespaces, seccomp, Landlock, prctl, /proc, runner
 * uids and pids cgroups (sl_sandbox.h). Elsewhere, sl_sandbox_fallback.c. */

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
 * other processes (to trace, read, write, compare or advise their memory,
 * watch them, move their pages), namespaces and mounts, and kernel
 * interfaces that bypass or widen this filter (io_uring, bpf). */
static const int _sl_denied_syscalls[] = {
    __NR_tkill, __NR_ptrace, __NR_process_vm_readv, __NR_process_vm_writev, __NR_kcmp, __NR_perf_event_open,
    __NR_move_pages, __NR_migrate_pages, __NR_get_robust_list, __NR_ioprio_set, __NR_setsid, __NR_setpgid,
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
#ifdef __NR_process_madvise
    __NR_process_madvise,
#endif
#ifdef __NR_process_mrelease
    __NR_process_mrelease,
#endif
#ifdef __NR_io_uring_setup
    __NR_io_uring_setup,
#endif
#ifdef __NR_fsopen
    __NR_fsopen, __NR_fsmount, __NR_move_mount, __NR_open_tree,
#endif
};

/* Calls that act on the process (or thread) their first argument names:
 * allowed on this one only (0 or its own pid). Setting another thread's
 * affinity by its id is refused too; nothing the runner needs does it. */
static const int _sl_own_process_syscalls[] = {
    __NR_prlimit64, __NR_sched_setaffinity, __NR_sched_setscheduler, __NR_sched_setparam, __NR_sched_setattr,
};

#define _SL_COUNT(array) ((int)(sizeof array / sizeof array[0]))
#define _SL_EMIT(instruction) filter[n++] = (struct sock_filter)instruction
#define _SL_LOAD(field) _SL_EMIT(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, (uint32_t)offsetof(struct seccomp_data, field)))
#define _SL_RETURN(value) _SL_EMIT(BPF_STMT(BPF_RET | BPF_K, (value)))
#define _SL_IF_EQUAL(value, skip_if_true, skip_if_false) \
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, (value), (skip_if_true), (skip_if_false)))

/* The process filter: lab code may start threads but no processes, signal
 * only itself, touch no other process (its memory, limits, scheduling,
 * priority, signals sent on I/O), not make itself dumpable again, and not
 * trace, remount or leave its namespaces. Arguments are compared on their
 * low 32 bits: the kernel reads each one here as an int. */
static bool _sl_install_seccomp(void) {
    const uint32_t self = (uint32_t)getpid(); /* exec keeps the pid */
    const uint32_t eperm = SECCOMP_RET_ERRNO | EPERM, allow = SECCOMP_RET_ALLOW;
    struct sock_filter filter[96 + _SL_COUNT(_sl_own_process_syscalls) + _SL_COUNT(_sl_denied_syscalls)];
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
    /* limits and scheduling: this process only */
    const int own = _SL_COUNT(_sl_own_process_syscalls);
    for (int i = 0; i < own; i++) _SL_IF_EQUAL((uint32_t)_sl_own_process_syscalls[i], (uint8_t)(own - i), 0);
    _SL_EMIT(BPF_JUMP(BPF_JMP | BPF_JA, 5, 0, 0));
    _SL_LOAD(args[0]);
    _SL_IF_EQUAL(0, 2, 0);
    _SL_IF_EQUAL(self, 1, 0);
    _SL_RETURN(eperm);
    _SL_RETURN(allow);
    /* priority: this process only (PRIO_USER would renice every process of the uid) */
    _SL_IF_EQUAL(__NR_setpriority, 0, 7);
    _SL_LOAD(args[0]);
    _SL_IF_EQUAL(PRIO_PROCESS, 0, 3);
    _SL_LOAD(args[1]);
    _SL_IF_EQUAL(0, 2, 0);
    _SL_IF_EQUAL(self, 1, 0);
    _SL_RETURN(eperm);
    _SL_RETURN(allow);
    /* SIGIO and SIGURG go to the owner a descriptor names, with any signal F_SETSIG picks */
    _SL_IF_EQUAL(__NR_fcntl, 0, 5);
    _SL_LOAD(args[1]);
    _SL_IF_EQUAL(F_SETOWN, 2, 0);
    _SL_IF_EQUAL(F_SETOWN_EX, 1, 0);
    _SL_RETURN(allow);
    _SL_RETURN(eperm);
    _SL_IF_EQUAL(__NR_ioctl, 0, 6);
    _SL_LOAD(args[1]);
    _SL_IF_EQUAL(FIOSETOWN, 3, 0);
    _SL_IF_EQUAL(SIOCSPGRP, 2, 0);
    _SL_IF_EQUAL(TIOCSTI, 1, 0);
    _SL_RETURN(allow);
    _SL_RETURN(eperm);
    /* Not dumpable it stays: then no process of its uid can open its memory,
     * and the grader knows it still runs the (execute-only) runner. */
    _SL_IF_EQUAL(__NR_prctl, 0, 4);
    _SL_LOAD(args[0]);
    _SL_IF_EQUAL(PR_SET_DUMPABLE, 1, 0);
    _SL_RETURN(allow);
    _SL_RETURN(eperm);
    const int denied = _SL_COUNT(_sl_denied_syscalls);
    for (int i = 0; i < denied; i++) _SL_IF_EQUAL((uint32_t)_sl_denied_syscalls[i], (uint8_t)(denied - i), 0);
    _SL_RETURN(allow);
    _SL_RETURN(eperm);
    struct sock_fprog program = {(unsigned short)n, filter};
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    return syscall(__NR_seccomp, SECCOMP_SET_MODE_FILTER, 0, &program) == 0;
}
#else
static bool _sl_install_seccomp(void) { return false; }
#endif

/* Landlock (Linux 5.13+), where the kernel has it: a process in a Landlock
 * domain may trace, or open the memory of, only processes in its own domain
 * or one nested in it, and from ABI 6 signal only those and connect to no
 * abstract socket made outside it. Each runner gets a domain of its own: none
 * reaches the grader, another runner, or any other process of its uid (at
 * `basic`, the grader user's shells and scripts). Its rules forbid only what
 * lab code never does (making device files); the domain is what matters. */
struct _sl_landlock_ruleset_attr {
    uint64_t handled_access_fs, handled_access_net, scoped;
};
#define _SL_LANDLOCK_MAKE_CHAR (1ull << 7)
#define _SL_LANDLOCK_MAKE_BLOCK (1ull << 11)
#define _SL_LANDLOCK_SCOPE_ABSTRACT_UNIX_SOCKET (1ull << 0)
#define _SL_LANDLOCK_SCOPE_SIGNAL (1ull << 1)

static int _sl_landlock_abi(void) {
#ifdef __NR_landlock_create_ruleset
    long abi = syscall(__NR_landlock_create_ruleset, NULL, 0, 1u /* LANDLOCK_CREATE_RULESET_VERSION */);
    return abi > 0 ? (int)abi : 0;
#else
    return 0;
#endif
}

/* Needs no_new_privs set first. */
static bool _sl_enter_landlock_domain(int abi) {
#ifdef __NR_landlock_create_ruleset
    struct _sl_landlock_ruleset_attr attr = {.handled_access_fs = _SL_LANDLOCK_MAKE_CHAR | _SL_LANDLOCK_MAKE_BLOCK};
    size_t size = sizeof attr.handled_access_fs;
    if (abi >= 6) {
        attr.scoped = _SL_LANDLOCK_SCOPE_ABSTRACT_UNIX_SOCKET | _SL_LANDLOCK_SCOPE_SIGNAL;
        size = sizeof attr;
    }
    int fd = (int)syscall(__NR_landlock_create_ruleset, &attr, size, 0);
    if (fd < 0) return false;
    bool ok = syscall(__NR_landlock_restrict_self, fd, 0) == 0;
    close(fd);
    return ok;
#else
    (void)abi;
    return false;
#endif
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

/* In a user namespace the child holds every capability of it until the exec,
 * the right to read any file among them: without them, the exec of the
 * execute-only runner leaves the process not dumpable, as it does elsewhere. */
static void _sl_drop_capabilities(void) {
    struct __user_cap_header_struct header = {_LINUX_CAPABILITY_VERSION_3, 0};
    struct __user_cap_data_struct data[_LINUX_CAPABILITY_U32S_3];
    memset(data, 0, sizeof data);
    if (syscall(SYS_capset, &header, data) != 0) _sl_fail("cannot drop the capabilities: %s", strerror(errno));
}

/* What one start of a runner needs besides its desc, settled by the grader before the fork. */
typedef struct _sl_plan {
    const char *runner;       /* the file to execute: the runner's execute-only copy where there is one */
    bool switch_uid;          /* become `uid` (and gid `uid`), without supplementary groups */
    uid_t uid;                /* with maps_from_grader, inside the runner's user namespace */
    uid_t mapped_uid;         /* with maps_from_grader: what `uid` is outside */
    bool maps_from_grader;    /* root in a user namespace: the grader maps the runner's ids (to a uid of the pool) */
    rlim_t process_limit;     /* RLIMIT_NPROC; 0: unchanged */
    char cgroup[320];         /* a pids cgroup to join first, or "" */
} _sl_plan;

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

static void _sl_child(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, const _sl_plan *plan, uid_t outer_uid,
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
static pid_t _sl_fork(const sl_sandbox *sb) {
    if (sb->level != SL_SANDBOX_NAMESPACES) return fork();
    unsigned long flags = CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS | SIGCHLD;
    if (sb->user_namespace) flags |= CLONE_NEWUSER;
    return (pid_t)syscall(SYS_clone, flags, NULL, NULL, NULL, NULL);
}

/* ---- the grader's side ---- */

static bool _sl_write_text(const char *path, const char *text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    ssize_t n = (ssize_t)strlen(text);
    bool ok = write(fd, text, (size_t)n) == n;
    return close(fd) == 0 && ok;
}

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
        _sl_child(sb, d, plan, uid, gid, go[0], probe);
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

/* ---- processes and tasks, as /proc shows them ---- */

/* Calls `each` with the real, effective, saved and file uids of every process and its thread count. */
static void _sl_each_process(void (*each)(const uid_t uids[4], long threads, void *context), void *context) {
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

typedef struct _sl_task_count {
    uid_t uid;
    long tasks;
} _sl_task_count;

static void _sl_count_tasks(const uid_t uids[4], long threads, void *context) {
    _sl_task_count *c = context;
    if (uids[0] == c->uid) c->tasks += threads;
}

/* ---- the pool of runner uids (the grader as root) ---- */

#define _SL_POOL_FIRST 60800 /* unused by Debian's and systemd's conventions (systemd: 60578-61183 unused) */
#define _SL_POOL_COUNT 256
#define _SL_POOL_MAX 65536

static bool _sl_pool_range(uid_t *first, uid_t *count, char *err, size_t n) {
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
static bool _sl_pool_lock_dir(char out[64], char *err, size_t n) {
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
static int _sl_pool_claim(const sl_sandbox *sb, uid_t *uid, char *err, size_t n) {
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
static void _sl_pool_release(const sl_sandbox *sb, uid_t uid, int lock) {
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

/* ---- a pids cgroup per runner, where the grader may make them ---- */

/* Whether `file` (a cgroup's controllers list) names the pids controller. */
static bool _sl_lists_pids(const char *file) {
    char text[512] = "";
    FILE *f = fopen(file, "re");
    if (!f) return false;
    bool read = fgets(text, sizeof text, f) != NULL;
    fclose(f);
    if (!read) return false;
    for (char *c = strtok(text, " \n"); c; c = strtok(NULL, " \n"))
        if (strcmp(c, "pids") == 0) return true;
    return false;
}

/* The folder of cgroup `own` (a path of /proc/self/cgroup) where its hierarchy
 * is mounted: cgroup v1's pids hierarchy (v2 false), or v2's unified one. */
static bool _sl_cgroup_folder(const char *own, bool v2, char *out, size_t n) {
    char line[1200], mount_point[512] = "", mount_root[512] = "";
    FILE *f = fopen("/proc/self/mountinfo", "re");
    if (!f) return false;
    while (fgets(line, sizeof line, f)) {
        /* id parent major:minor root mount-point options ... - type source super-options */
        char root[512], point[512], type[64], super[512];
        const char *dash = strstr(line, " - ");
        if (!dash || sscanf(line, "%*s %*s %*s %511s %511s", root, point) != 2 ||
            sscanf(dash + 3, "%63s %*s %511s", type, super) != 2 || strcmp(type, v2 ? "cgroup2" : "cgroup") != 0)
            continue;
        bool pids = v2;
        for (char *c = strtok(super, ","); c && !pids; c = strtok(NULL, ",")) pids = strcmp(c, "pids") == 0;
        if (!pids) continue;
        snprintf(mount_point, sizeof mount_point, "%s", point);
        snprintf(mount_root, sizeof mount_root, "%s", root);
    }
    fclose(f);
    if (!mount_point[0]) return false;
    size_t root_length = strcmp(mount_root, "/") == 0 ? 0 : strlen(mount_root);
    if (root_length && strncmp(own, mount_root, root_length) != 0) return false;
    const char *below = own + root_length;
    return (size_t)snprintf(out, n, "%s%s", mount_point, strcmp(below, "/") == 0 ? "" : below) < n;
}

/* Whether a process can join cgroup folder `cgroup`: a child that joins it and leaves. */
static bool _sl_cgroup_joinable(const char *cgroup) {
    char procs[1100];
    snprintf(procs, sizeof procs, "%s/cgroup.procs", cgroup);
    pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) _exit(_sl_write_text(procs, "0") ? 0 : 1);
    int status = 0;
    pid_t waited;
    while ((waited = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {}
    return waited == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* Whether the grader may make children of cgroup folder `folder` that each get
 * a pids.max and a runner can join; a probe child made, joined and removed.
 * In v2 the pids controller must be given to the folder and enabled for its
 * children, or enabled here: a cgroup that holds processes (the grader's own)
 * may enable pids, a threaded controller, for its children, which are then
 * threaded cgroups (*threaded). */
static bool _sl_pids_children_allowed(const char *folder, bool v2, bool *threaded) {
    char file[1100], probe[1100];
    *threaded = false;
    if (v2) {
        snprintf(file, sizeof file, "%s/cgroup.controllers", folder);
        if (!_sl_lists_pids(file)) return false;
        snprintf(file, sizeof file, "%s/cgroup.subtree_control", folder);
        if (!_sl_lists_pids(file) && !_sl_write_text(file, "+pids")) return false;
    }
    snprintf(probe, sizeof probe, "%s/shadowlab-probe-%d", folder, (int)getpid());
    if (mkdir(probe, 0755) != 0) return false;
    snprintf(file, sizeof file, "%s/pids.max", probe);
    bool allowed = access(file, W_OK) == 0;
    if (allowed && !_sl_cgroup_joinable(probe)) {
        snprintf(file, sizeof file, "%s/cgroup.type", probe);
        *threaded = v2 && _sl_write_text(file, "threaded");
        allowed = *threaded && _sl_cgroup_joinable(probe);
    }
    /* the probe's process is gone; the kernel may take a moment to say the cgroup is empty */
    for (int attempt = 0; attempt < 50 && rmdir(probe) != 0 && errno == EBUSY; attempt++) usleep(2000);
    return allowed;
}

/* This process's own pids cgroup folder, when the grader may make children
 * in it that each get a pids.max: in cgroup v1's pids hierarchy (as root, or
 * where staff gave it the folder), else in cgroup v2's unified one (its own
 * cgroup delegated to it: writable, with the pids controller). False: none,
 * and a runner's thread limit is RLIMIT_NPROC alone. */
static bool _sl_find_pids_cgroup(sl_sandbox *sb) {
    char line[1200], own_v1[1024] = "", own_v2[1024] = "";
    char *out = sb->pids_cgroup;
    size_t n = sizeof sb->pids_cgroup;
    FILE *f = fopen("/proc/self/cgroup", "re");
    if (!f) return false;
    while (fgets(line, sizeof line, f)) {
        char *controllers = strchr(line, ':'), *path = controllers ? strchr(controllers + 1, ':') : NULL;
        if (!path) continue;
        *path++ = '\0';
        path[strcspn(path, "\n")] = '\0';
        if (strcmp(line, "0") == 0 && controllers[1] == '\0') snprintf(own_v2, sizeof own_v2, "%s", path);
        for (char *c = strtok(controllers + 1, ","); c; c = strtok(NULL, ","))
            if (strcmp(c, "pids") == 0) snprintf(own_v1, sizeof own_v1, "%s", path);
    }
    fclose(f);
    bool threaded = false;
    if (own_v1[0] && _sl_cgroup_folder(own_v1, false, out, n) && _sl_pids_children_allowed(out, false, &threaded))
        return true;
    if (own_v2[0] && _sl_cgroup_folder(own_v2, true, out, n) && _sl_pids_children_allowed(out, true, &threaded)) {
        sb->pids_cgroup_v2 = true;
        sb->pids_cgroup_threaded = threaded;
        return true;
    }
    out[0] = '\0';
    return false;
}

static bool _sl_cgroup_make(const sl_sandbox *sb, char *cgroup, size_t n, int limit, char *err, size_t err_size) {
    static unsigned sequence;
    char file[400], value[32];
    snprintf(cgroup, n, "%s/shadowlab-runner-%d-%u", sb->pids_cgroup, (int)getpid(), sequence++);
    snprintf(file, sizeof file, "%s/pids.max", cgroup);
    snprintf(value, sizeof value, "%d", limit);
    char type[400];
    snprintf(type, sizeof type, "%s/cgroup.type", cgroup);
    if (mkdir(cgroup, 0755) == 0 && (!sb->pids_cgroup_threaded || _sl_write_text(type, "threaded")) &&
        _sl_write_text(file, value))
        return true;
    snprintf(err, err_size, "cannot make the runner's pids cgroup %s: %s", cgroup, strerror(errno));
    rmdir(cgroup);
    cgroup[0] = '\0';
    return false;
}

static void _sl_cgroup_remove(const char *cgroup) {
    /* its processes, or in a threaded cgroup (v2), which lists none, its threads (killing one kills its process) */
    static const char *const lists[] = {"cgroup.procs", "cgroup.threads"};
    for (int attempt = 0; attempt < 50; attempt++) {
        if (rmdir(cgroup) == 0 || errno == ENOENT) return;
        for (int l = 0; l < 2; l++) {
            char file[400];
            snprintf(file, sizeof file, "%s/%s", cgroup, lists[l]);
            FILE *f = fopen(file, "re");
            int pid;
            while (f && fscanf(f, "%d", &pid) == 1) kill(pid, SIGKILL);
            if (f) fclose(f);
        }
        usleep(2000);
    }
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
