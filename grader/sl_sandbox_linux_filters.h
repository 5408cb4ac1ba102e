/* The process filters every runner enters last, before its exec
 * (sl_sandbox_linux.c): a seccomp filter of the system calls lab code never
 * needs, and a Landlock domain of its own. Linux only. */
#ifndef SL_SANDBOX_LINUX_FILTERS_H
#define SL_SANDBOX_LINUX_FILTERS_H

#include <stdbool.h>

#include <linux/audit.h>

/* The architectures the filter knows (none: no filter). */
#if defined(__x86_64__)
#define _SL_AUDIT_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define _SL_AUDIT_ARCH AUDIT_ARCH_AARCH64
#endif

/* Installs the filter; false where it cannot (or this architecture has none). */
bool _sl_install_seccomp(void);
/* The kernel's Landlock ABI, 0 without Landlock. */
int _sl_landlock_abi(void);
/* Enters a Landlock domain of its own; needs no_new_privs set first. */
bool _sl_enter_landlock_domain(int abi);

#endif
