/* sl_mount_point: where a process in a new mount namespace can mount a root
 * of its own (the runners' sandbox, the compile fence, the stager's reader).
 * Header only: the compile fence's probe is built from one source file. */
#ifndef SL_MOUNT_POINT_H
#define SL_MOUNT_POINT_H

#include <errno.h>
#include <stddef.h>
#include <sys/mount.h>

/* Makes every mount private (nothing mounted here shows outside) and returns
 * "/". Under a chroot "/" is no mount point, and making it private fails
 * (EINVAL): then the first mount point the chroot does show, of a few, is
 * made private and returned, to mount over. NULL (errno set) where none is. */
static inline const char *sl_private_mount_point(void) {
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) == 0) return "/";
    if (errno != EINVAL) return NULL;
    static const char *const visible[] = {"/sys", "/dev/pts", "/dev/shm", "/run", "/proc"};
    for (size_t i = 0; i < sizeof visible / sizeof visible[0]; i++)
        if (mount(NULL, visible[i], NULL, MS_REC | MS_PRIVATE, NULL) == 0) return visible[i];
    errno = EINVAL;
    return NULL;
}

#endif
