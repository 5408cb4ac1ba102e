#define _GNU_SOURCE
#include "sl_sandbox_linux_filters.h"

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
bool _sl_install_seccomp(void) {
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
bool _sl_install_seccomp(void) { return false; }
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

int _sl_landlock_abi(void) {
#ifdef __NR_landlock_create_ruleset
    long abi = syscall(__NR_landlock_create_ruleset, NULL, 0, 1u /* LANDLOCK_CREATE_RULESET_VERSION */);
    return abi > 0 ? (int)abi : 0;
#else
    return 0;
#endif
}

/* Needs no_new_privs set first. */
bool _sl_enter_landlock_domain(int abi) {
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
