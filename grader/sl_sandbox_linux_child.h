/* The runner's side of a start (sl_sandbox_linux.c): everything that runs
 * between fork and exec, in the child: its session, cgroup, ids and
 * namespaces, the file system it sees, its limits and fds, its filters,
 * then the runner. Set-up failures travel to the parent over _sl_report_fd. */
#ifndef SL_SANDBOX_LINUX_CHILD_H
#define SL_SANDBOX_LINUX_CHILD_H

#include <stdbool.h>
#include <sys/resource.h>
#include <sys/types.h>

#include "sl_sandbox.h"

#define _SL_INNER_ID 1000      /* the runner's uid inside a user namespace */

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

/* The close-on-exec pipe the child reports a set-up failure on (-1: none). */
extern int _sl_report_fd;

/* The child: sets the sandbox up as `plan` says and runs the runner; exits 127 on a set-up failure. */
void _sl_child_exec(const sl_sandbox *sb, const sl_sandbox_spawn_desc *d, const _sl_plan *plan, uid_t outer_uid,
                    gid_t outer_gid, int go_fd, bool probe);
/* fork, or clone into new namespaces (the sandbox's level). */
pid_t _sl_fork(const sl_sandbox *sb);

/* Raw system calls, safe in a child forked from a process with threads. */
int _sl_setgroups_none(void);
int _sl_setresgid(gid_t gid);
int _sl_setresuid(uid_t uid);

#endif
