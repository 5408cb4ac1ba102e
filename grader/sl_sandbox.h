/* sl_sandbox: starts the runner (lab code) for one case in a sandbox as
 * strong as the system allows, and says which level it got.
 *
 * Two modules implement this header, chosen when the project is configured
 * (SL_SANDBOX): sl_sandbox_linux.c, the levels below, and
 * sl_sandbox_fallback.c, for systems without them (macOS, BSD) or by request:
 *
 *   SL_SANDBOX_NONE        the runner is a plain child process of the
 *                          grader's user, with a time limit (a wall-clock
 *                          kill) and the CPU, memory and file size limits the
 *                          system has. Nothing stops lab code from reading
 *                          what the user reads: a student's self-check, never
 *                          a course's grade (sl_sandbox.self_check).
 *
 * The Linux module's levels:
 *
 *   SL_SANDBOX_NAMESPACES  new PID, mount, network, IPC and UTS namespaces (a
 *                          user namespace too when the grader is not root); a
 *                          read-only root holding only the system libraries,
 *                          the runner and a copy of the shaders under test; a
 *                          private /tmp; no network; as root, a uid of its own.
 *   SL_SANDBOX_UID         root without namespaces: each runner runs as a uid
 *                          of its own, so it reads only what any user may read
 *                          and reaches no other runner.
 *   SL_SANDBOX_BASIC       neither: the runner runs as the grader's user and
 *                          can read what that user reads.
 *
 * At every Linux level: a cleared environment, its own session, rlimits (CPU, address
 * space, file size, core, processes), killed with the grader
 * (PR_SET_PDEATHSIG), only fds 0-3 open, not dumpable from its first
 * instruction (it runs an execute-only copy of the runner), in a Landlock
 * domain of its own where the kernel has Landlock (it reaches no process
 * outside it), and a seccomp filter: no new processes (threads only), no
 * signals to other processes, no ptrace or other reach into another process,
 * no namespaces or mounts.
 *
 * Runner uids (as root, below a user namespace): a pool, by default
 * 60800-61055, or SHADOWLAB_RUNNER_UIDS=FIRST-LAST in the grader's
 * environment. A runner holds its uid alone (a lock file per uid in a
 * root-owned folder, so several graders on one machine share the pool); a
 * uid with a user name, a process or a file at the top of /tmp, /var/tmp or
 * /dev/shm is skipped. After the runner, everything of its uid is killed and
 * what it left there removed. */
#ifndef SL_SANDBOX_H
#define SL_SANDBOX_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

#include "sl_params.h"

typedef enum sl_sandbox_level {
    SL_SANDBOX_NONE = -1,
    SL_SANDBOX_BASIC = 0,
    SL_SANDBOX_UID = 1,
    SL_SANDBOX_NAMESPACES = 2,
} sl_sandbox_level;

typedef struct _sl_sandbox_runners _sl_sandbox_runners;

typedef struct sl_sandbox {
    sl_sandbox_level level;
    bool self_check;         /* runners are plain child processes: a grade here is a self-check only */
    bool user_namespace;     /* namespaces owned by a new user namespace (grader not root) */
    bool seccomp;            /* the process filter could be installed */
    int landlock;            /* the kernel's Landlock ABI: each runner in a domain of its own; 0 = none */
    bool own_uids;           /* each runner gets a uid of the pool (the grader is root) */
    uid_t uid;               /* the runners' uid outside the sandbox; with own_uids, the pool's first */
    uid_t uid_count;         /* with own_uids: the pool's size */
    int process_limit;       /* threads (and processes) one runner may have at once */
    char pids_cgroup[256];   /* a pids cgroup folder each runner gets a child of, or "" */
    bool pids_cgroup_v2;     /* that folder is cgroup v2's */
    bool pids_cgroup_threaded; /* v2: each child is a threaded cgroup (the folder holds the grader) */
    char lock_dir[64];       /* with own_uids: the pool's lock files */
    char mount_point[64];    /* an empty folder the sandbox's root is mounted on */
    _sl_sandbox_runners *runners; /* the execute-only copies of the runners started so far */
    char why_not_stronger[512];
} sl_sandbox;

/* Finds the strongest level up to `at_most` that works here: it sets each up
 * as far as starting `runner` (an executable the cases will run). False
 * only when nothing at all can be started. */
/* What a report's header says where self_check is set, in a student's words. */
#define SL_SANDBOX_SELF_CHECK_NOTE                                                                                 \
    "This is a self-check. On this computer your lab code ran as an ordinary program, without the course "      \
    "grader's sandbox, so this score is a guide for you only: your grade for the course comes from the course's " \
    "own grader."

bool sl_sandbox_open(sl_sandbox *sandbox, sl_sandbox_level at_most, const char *runner, char *err, size_t err_size);
void sl_sandbox_close(sl_sandbox *sandbox);
/* "none", "basic", "uid", "namespaces"; --sandbox takes the last three. */
const char *sl_sandbox_level_name(sl_sandbox_level level);
bool sl_sandbox_level_parse(const char *name, sl_sandbox_level *level);
/* Which module this build has: "linux" or "fallback". */
const char *sl_sandbox_module(void);
/* One line for the report: "namespaces (uid of its own per runner, read-only view, no network, seccomp)". */
void sl_sandbox_describe(const sl_sandbox *sandbox, char *out, size_t out_size);

typedef struct sl_sandbox_spawn_desc {
    const char *runner;                     /* the executable */
    /* Where each lab's folder comes from: its shaders/ are what the runner may
     * read (copied into the sandbox at SL_SANDBOX_NAMESPACES). [0]: the folder
     * of the technique the runner's build adds (lab 0), itself, not a tree: its
     * shaders/ become SL_TECHNIQUE_FOLDER/shaders of the sandbox's labs tree. */
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
    uid_t uid;               /* the runner's uid (outside a user namespace) */
    int uid_lock;            /* with own_uids: holds the uid for this runner; else -1 */
    char cgroup[320];        /* its pids cgroup, or "" */
    dev_t runner_dev;        /* the executable it runs */
    ino_t runner_ino;
} sl_sandbox_process;

/* Starts the runner; false with the reason in err (nothing is left running).
 * A failure here is never lab code's: none of it has run yet. */
bool sl_sandbox_spawn(const sl_sandbox *sandbox, const sl_sandbox_spawn_desc *desc, sl_sandbox_process *out,
                      char *err, size_t err_size);
/* After the runner was waited for: kills whatever of it is left, frees its
 * uid and cgroup. */
void sl_sandbox_end(const sl_sandbox *sandbox, sl_sandbox_process *process);
/* Which of `paths` a runner could read (a folder: list it): none in the
 * namespaces sandbox, whose view holds only copies of the shaders; below
 * it, whatever the runner's uid may read. Returns how many. */
int sl_sandbox_readable(const sl_sandbox *sandbox, const char *const *paths, int count, bool *readable);

/* Kills the runner and everything it started. */
void sl_sandbox_kill(const sl_sandbox *sandbox, pid_t pid);
/* True when the process still runs the runner executable it was started
 * with (not another program it exec'ed). */
bool sl_sandbox_runs_runner(const sl_sandbox *sandbox, const sl_sandbox_process *process);

/* How a running runner used the machine so far: its CPU time, and how long
 * its threads waited, ready, for a CPU others held (-1 where the system does
 * not say). False when the process is gone. */
bool sl_sandbox_usage(pid_t pid, double *cpu_seconds, double *waited_seconds);

#endif
