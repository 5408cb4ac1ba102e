/* sl_sandbox: starts the runner (lab code) for one case in a sandbox as
 * strong as the system allows, and says which level it got.
 *
 *   SL_SANDBOX_NAMESPACES  new PID, mount, network, IPC and UTS namespaces (a
 *                          user namespace too when the grader is not root); a
 *                          read-only root holding only the system libraries,
 *                          the runner and a copy of the shaders under test; a
 *                          private /tmp; no network; as root, uid 65534.
 *   SL_SANDBOX_UID         root without namespaces: the runner runs as uid
 *                          65534, so it reads only what any user may read.
 *   SL_SANDBOX_BASIC       neither: the runner runs as the grader's user and
 *                          can read what that user reads.
 *
 * Always: a cleared environment, its own session, rlimits (CPU, address
 * space, file size, core), killed with the grader (PR_SET_PDEATHSIG), only
 * fds 0-3 open, and a seccomp filter: no new processes (threads only), no
 * signals to other processes, no ptrace, no namespaces or mounts. */
#ifndef SL_SANDBOX_H
#define SL_SANDBOX_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

#include "sl_params.h"

typedef enum sl_sandbox_level {
    SL_SANDBOX_BASIC = 0,
    SL_SANDBOX_UID = 1,
    SL_SANDBOX_NAMESPACES = 2,
} sl_sandbox_level;

typedef struct sl_sandbox {
    sl_sandbox_level level;
    bool user_namespace;     /* namespaces owned by a new user namespace (grader not root) */
    bool seccomp;            /* the process filter could be installed */
    uid_t uid;               /* the runner's uid outside the sandbox */
    char mount_point[64];    /* an empty folder the sandbox's root is mounted on */
    char why_not_stronger[512];
} sl_sandbox;

/* Finds the strongest level up to `at_most` that works here: it sets each up
 * as far as starting `runner` (an executable the cases will run). False
 * only when nothing at all can be started. */
bool sl_sandbox_open(sl_sandbox *sandbox, sl_sandbox_level at_most, const char *runner, char *err, size_t err_size);
void sl_sandbox_close(sl_sandbox *sandbox);
const char *sl_sandbox_level_name(sl_sandbox_level level);
bool sl_sandbox_level_parse(const char *name, sl_sandbox_level *level);
/* One line for the report: "namespaces (uid 65534, read-only view, no network, seccomp)". */
void sl_sandbox_describe(const sl_sandbox *sandbox, char *out, size_t out_size);

typedef struct sl_sandbox_spawn_desc {
    const char *runner;                     /* the executable */
    /* Where each lab's folder comes from: its shaders/ are what the runner may
     * read (copied into the sandbox at SL_SANDBOX_NAMESPACES). */
    const char *lab_dirs[SL_LAB_COUNT + 1];
    /* One labs tree holding every lab's folder, read in place below
     * SL_SANDBOX_NAMESPACES (for --isolate, a tree of links). */
    const char *labs_tree;
    const char *framework_dir;              /* framework/: its shaders/ */
    const char *const *environment;         /* NULL-terminated "NAME=value" */
    /* The runner renders in a hidden window (--backend window): the namespaces
     * sandbox shows it the X display's socket folder and cookie (XAUTHORITY). */
    bool display;
    int stdin_fd, channel_fd, output_fd;    /* the runner's fds 0, 3 and 1+2 */
    double cpu_seconds;
    unsigned long long memory_bytes;
} sl_sandbox_spawn_desc;

typedef struct sl_sandbox_process {
    pid_t pid;
    char labs_dir[512];      /* the labs tree as the runner sees it: for the job */
    char framework_dir[512]; /* framework/, likewise */
} sl_sandbox_process;

/* Starts the runner; false with the reason in err (nothing is left running). */
bool sl_sandbox_spawn(const sl_sandbox *sandbox, const sl_sandbox_spawn_desc *desc, sl_sandbox_process *out,
                      char *err, size_t err_size);
/* Which of `paths` a runner could read (a folder: list it): none in the
 * namespaces sandbox, whose view holds only copies of the shaders; below
 * it, whatever the runner's uid may read. Returns how many. */
int sl_sandbox_readable(const sl_sandbox *sandbox, const char *const *paths, int count, bool *readable);

/* Kills the runner and everything it started. */
void sl_sandbox_kill(const sl_sandbox *sandbox, pid_t pid);
/* True when `pid` is still running the runner executable (not another program it exec'ed). */
bool sl_sandbox_runs_runner(pid_t pid, const char *runner);

#endif
