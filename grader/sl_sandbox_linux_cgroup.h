/* A pids cgroup per runner, where the grader may make them (sl_sandbox_linux.c):
 * found once, one child per runner with its pids.max, removed with what is
 * left in it. */
#ifndef SL_SANDBOX_LINUX_CGROUP_H
#define SL_SANDBOX_LINUX_CGROUP_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_sandbox.h"

/* Writes `text` to an existing file (a cgroup's, /proc's); false if it could not. */
bool _sl_write_text(const char *path, const char *text);
/* This process's own pids cgroup folder into sb->pids_cgroup, where the grader may make
 * children in it that each get a pids.max; false: none. */
bool _sl_find_pids_cgroup(sl_sandbox *sb);
/* Makes a runner's pids cgroup with at most `limit` tasks; false with the reason. */
bool _sl_cgroup_make(const sl_sandbox *sb, char *cgroup, size_t n, int limit, char *err, size_t err_size);
/* Removes a runner's pids cgroup, killing what is left in it. */
void _sl_cgroup_remove(const char *cgroup);

#endif
