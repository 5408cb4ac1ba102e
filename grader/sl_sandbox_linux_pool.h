/* The pool of runner uids (the grader as root, sl_sandbox_linux.c): a uid of
 * its own per runner, claimed under a lock only root may take, and freed
 * with whatever still runs as it and what it left in the shared folders;
 * and the processes /proc shows, which a claim and the task count read. */
#ifndef SL_SANDBOX_LINUX_POOL_H
#define SL_SANDBOX_LINUX_POOL_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

#include "sl_sandbox.h"

/* Calls `each` with the real, effective, saved and file uids of every process and its thread count. */
void _sl_each_process(void (*each)(const uid_t uids[4], long threads, void *context), void *context);
/* The tasks of one uid (real), counted by _sl_count_tasks through _sl_each_process. */
typedef struct _sl_task_count {
    uid_t uid;
    long tasks;
} _sl_task_count;
void _sl_count_tasks(const uid_t uids[4], long threads, void *context);

/* The pool's uids (SHADOWLAB_RUNNER_UIDS, or the default range); false with the reason. */
bool _sl_pool_range(uid_t *first, uid_t *count, char *err, size_t n);
/* The folder of the pool's lock files, root's alone; false with the reason. */
bool _sl_pool_lock_dir(char out[64], char *err, size_t n);
/* Claims a uid of the pool for one runner: returns the lock that holds it
 * (close it to free the uid), or -1 with the reason. */
int _sl_pool_claim(const sl_sandbox *sb, uid_t *uid, char *err, size_t n);
/* Frees a uid of the pool (and, below namespaces, what runs as it and what it left). */
void _sl_pool_release(const sl_sandbox *sb, uid_t uid, int lock);

#endif
