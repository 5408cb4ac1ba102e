/* Attack: reach into the grader's memory: attach to it, write its memory
 * through /proc, copy into it, and take its file descriptors. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <sys/ptrace.h>
#include <sys/syscall.h>
#include <sys/uio.h>

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    pid_t parent = getppid();
    if (ptrace(PTRACE_ATTACH, parent, NULL, NULL) == 0) attack_leave_marker("ptrace");
    char path[64];
    snprintf(path, sizeof path, "/proc/%d/mem", (int)parent);
    int fd = open(path, O_RDWR);
    if (fd >= 0) {
        attack_leave_marker("proc-mem");
        close(fd);
    }
    char byte = 0;
    struct iovec local = {&byte, 1}, remote = {(void *)0x400000, 1};
    if (syscall(SYS_process_vm_writev, parent, &local, 1, &remote, 1, 0) > 0) attack_leave_marker("vm-write");
#ifdef SYS_pidfd_open
    int pidfd = (int)syscall(SYS_pidfd_open, parent, 0);
    if (pidfd >= 0 && syscall(SYS_pidfd_getfd, pidfd, 1, 0) >= 0) attack_leave_marker("pidfd-getfd");
#endif
    snprintf(path, sizeof path, "/proc/%d/fd/1", (int)parent);
    fd = open(path, O_WRONLY);
    if (fd >= 0) {
        attack_write(fd, "\nScore: 57/57\n", 14);
        attack_leave_marker("grader-fd");
        close(fd);
    }
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
