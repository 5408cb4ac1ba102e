#define _GNU_SOURCE
#include "sl_sandbox_linux_cgroup.h"

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
#include <time.h>
#include <sys/wait.h>
#include <unistd.h>

bool _sl_write_text(const char *path, const char *text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    ssize_t n = (ssize_t)strlen(text);
    bool ok = write(fd, text, (size_t)n) == n;
    return close(fd) == 0 && ok;
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
bool _sl_find_pids_cgroup(sl_sandbox *sb) {
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

/* A grader killed before it removed its runners' cgroups (SIGKILL, a crash) leaves
 * them behind, empty. Empty ones older than ten minutes are swept: a cgroup with a
 * process in it cannot be removed, and a live grader's empty one is minutes younger. */
static void _sl_cgroup_sweep(const char *folder) {
    DIR *d = opendir(folder);
    if (!d) return;
    struct dirent *e;
    time_t now = time(NULL);
    while ((e = readdir(d))) {
        if (strncmp(e->d_name, "shadowlab-runner-", 17) != 0) continue;
        char path[600];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", folder, e->d_name);
        if (stat(path, &st) == 0 && S_ISDIR(st.st_mode) && now - st.st_mtime > 600) rmdir(path);
    }
    closedir(d);
}

bool _sl_cgroup_make(const sl_sandbox *sb, char *cgroup, size_t n, int limit, char *err, size_t err_size) {
    static unsigned sequence;
    /* Graders in other PID namespaces (containers, chroots with their own /proc) share
     * this hierarchy and can have this pid: the name carries random bits of its own. */
    static uint64_t token;
    if (!token) {
        if (getrandom(&token, sizeof token, 0) != (ssize_t)sizeof token || !token)
            token = ((uint64_t)time(NULL) << 20) ^ (uint64_t)getpid() ^ (uint64_t)(uintptr_t)&token;
        _sl_cgroup_sweep(sb->pids_cgroup);
    }
    char file[400], value[32];
    snprintf(cgroup, n, "%s/shadowlab-runner-%d-%016llx-%u", sb->pids_cgroup, (int)getpid(),
             (unsigned long long)token, sequence++);
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

void _sl_cgroup_remove(const char *cgroup) {
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
