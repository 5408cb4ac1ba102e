/* shadowlab-fence: runs the compiler (or the linker) on untrusted lab code so
 * that it sees the system, the folders it needs and nothing else: a lab file
 * cannot #include, .incbin or __has_include its way to a solution, a
 * reference, a case, a test, another submission, .git or the staff's build.
 * The build runs it as the C compiler launcher of every lab object made from an
 * untrusted labs tree, and as the linker launcher of a submission's runners
 * (top CMakeLists.txt); scripts/grade-submission asks it which fence the
 * machine gives. One process and a few system calls: it runs once per file.
 *
 *   shadowlab-fence --probe [--hide PATH]...
 *       prints the fence this machine gives (exit 0):
 *         namespaces  a mount namespace (in a user namespace when not root)
 *                     whose root holds /usr, /bin, /lib*, /sbin, /etc read-only,
 *                     the folders the command needs, an empty /tmp and
 *                     /dev/null: no /proc, no /home, no project beyond those
 *         uid         root without namespaces, and every --hide PATH is
 *                     unreadable to uid 65534: the compiler runs as 65534
 *         none: WHY   neither
 *   shadowlab-fence --fence namespaces|uid [--link] [--expose DIR]...
 *                   [--expose-rw DIR]... [--hide PATH]... -- COMMAND ARGS...
 *       runs COMMAND in that fence; exit 97 when the fence cannot be made (the
 *       command never runs unfenced). A compile sees the --expose folders, the
 *       folders of the files it names (its source) and its -I/-isystem/-iquote
 *       folders, read-only; it writes its outputs (-o, -MF) into a folder of its
 *       own, copied into place afterwards; as root it runs as uid 65534. A link
 *       (--link) sees the --expose folders read-only and writes the
 *       --expose-rw ones (it reads only what its command line names). --hide
 *       paths stay empty even inside a system folder (a project under
 *       /usr/local). */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <limits.h>
#include <sched.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sl_mount_point.h"

#define _SL_FENCE_FAILED 97 /* the fence could not be made: nothing ran */
#define _SL_NOBODY 65534
#define _SL_MAX_PATHS 256
#define _SL_MAX_OUTPUTS 8

typedef struct _sl_fence {
    const char *readable[_SL_MAX_PATHS], *writable[_SL_MAX_PATHS], *hidden[_SL_MAX_PATHS];
    int readable_count, writable_count, hidden_count;
    char cwd[PATH_MAX];
    bool drop_to_nobody;
} _sl_fence;

static void _sl_die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
static void _sl_die(const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    fputs("shadowlab-fence: ", stderr);
    vfprintf(stderr, fmt, args);
    fputc('\n', stderr);
    va_end(args);
    _exit(_SL_FENCE_FAILED);
}

static void _sl_add(const char **list, int *count, const char *path) {
    if (*count < _SL_MAX_PATHS && path && path[0]) list[(*count)++] = path;
}

/* An absolute path for `path`, relative to `cwd` (kept in a buffer of its own). */
static const char *_sl_absolute(const char *cwd, const char *path) {
    char *out = malloc(PATH_MAX);
    if (!out) _sl_die("out of memory");
    if (path[0] == '/') snprintf(out, PATH_MAX, "%s", path);
    else snprintf(out, PATH_MAX, "%s/%s", cwd, path);
    return out;
}

static const char *_sl_dirname(const char *path) {
    char *out = strdup(path);
    if (!out) _sl_die("out of memory");
    char *slash = strrchr(out, '/');
    if (slash == out) out[1] = '\0';
    else if (slash) *slash = '\0';
    return out;
}

static void _sl_write_file(const char *path, const char *text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) _sl_die("cannot open %s: %s", path, strerror(errno));
    ssize_t n = write(fd, text, strlen(text));
    close(fd);
    if (n != (ssize_t)strlen(text)) _sl_die("cannot write %s", path);
}

/* mkdir -p of `path` (absolute), each new folder 0755. */
static void _sl_mkdirs(const char *path) {
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0755) != 0 && errno != EEXIST) _sl_die("cannot create %s: %s", buf, strerror(errno));
        *p = '/';
    }
    if (mkdir(buf, 0755) != 0 && errno != EEXIST) _sl_die("cannot create %s: %s", buf, strerror(errno));
}

/* A read-only bind of what `target` shows. In a user namespace a remount must
 * keep the flags the mount already has (they are locked), so they are read first. */
static void _sl_make_read_only(const char *target) {
    struct statvfs st;
    unsigned long flags = MS_REMOUNT | MS_BIND | MS_RDONLY;
    if (statvfs(target, &st) == 0) {
        if (st.f_flag & ST_NOSUID) flags |= MS_NOSUID;
        if (st.f_flag & ST_NODEV) flags |= MS_NODEV;
        if (st.f_flag & ST_NOEXEC) flags |= MS_NOEXEC;
    }
    mount(NULL, target, NULL, flags, NULL); /* best effort: a compiler writes only its outputs */
}

static void _sl_bind(const char *source, const char *target, bool read_only, bool recursive) {
    if (mount(source, target, NULL, MS_BIND | (recursive ? MS_REC : 0), NULL) != 0)
        _sl_die("cannot show %s: %s", source, strerror(errno));
    if (read_only) _sl_make_read_only(target);
}

/* No more privileges than uid 65534's: false when the switch fails. */
static bool _sl_become_nobody(void) {
    gid_t gid = _SL_NOBODY;
    return setgroups(0, NULL) == 0 && setresgid(gid, gid, gid) == 0 &&
           setresuid(_SL_NOBODY, _SL_NOBODY, _SL_NOBODY) == 0;
}

/* In the child, in its new mount namespace: the root, then the command. */
static void _sl_enter(const char *newroot, const _sl_fence *f, char **command) {
    /* Under a chroot "/" is no mount point, and the mount that holds the fresh
     * folder cannot be made private: mount over a mount point the chroot does
     * show, made private first, as the runners' sandbox does. */
    const char *private_point = sl_private_mount_point();
    if (!private_point && errno != EINVAL) _sl_die("cannot make the mounts private: %s", strerror(errno));
    if (!private_point) _sl_die("cannot make the mounts private: \"/\" is no mount point (a chroot?) and no other mount is");
    if (strcmp(private_point, "/") != 0) newroot = private_point;
    if (mount("compile-fence", newroot, "tmpfs", MS_NOSUID | MS_NODEV, "size=256m,mode=0755") != 0)
        _sl_die("cannot mount a tmpfs on %s: %s", newroot, strerror(errno));
    char path[PATH_MAX * 2];
    static const char *const system[] = {"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc"};
    for (size_t i = 0; i < sizeof system / sizeof system[0]; i++) {
        struct stat st;
        if (lstat(system[i], &st) != 0) continue;
        snprintf(path, sizeof path, "%s%s", newroot, system[i]);
        if (S_ISLNK(st.st_mode)) {
            char link[PATH_MAX];
            ssize_t n = readlink(system[i], link, sizeof link - 1);
            if (n <= 0) continue;
            link[n] = '\0';
            if (symlink(link, path) != 0) _sl_die("cannot link %s: %s", path, strerror(errno));
        } else if (S_ISDIR(st.st_mode)) {
            _sl_mkdirs(path);
            _sl_bind(system[i], path, true, true);
        }
    }
    snprintf(path, sizeof path, "%s/tmp", newroot);
    _sl_mkdirs(path);
    chmod(path, 01777);
    snprintf(path, sizeof path, "%s/dev", newroot);
    _sl_mkdirs(path);
    snprintf(path, sizeof path, "%s/dev/null", newroot);
    int fd = open(path, O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) _sl_die("cannot create %s: %s", path, strerror(errno));
    close(fd);
    _sl_bind("/dev/null", path, false, false);
    /* answers inside a system folder stay empty */
    for (int i = 0; i < f->hidden_count; i++) {
        struct stat st;
        snprintf(path, sizeof path, "%s%s", newroot, f->hidden[i]);
        if (lstat(path, &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            if (mount("hidden", path, "tmpfs", MS_NOSUID | MS_NODEV, "size=4k,mode=0") != 0)
                _sl_die("cannot hide %s: %s", f->hidden[i], strerror(errno));
        } else {
            _sl_bind("/dev/null", path, false, false);
        }
    }
    for (int pass = 0; pass < 2; pass++) {
        const char *const *list = pass ? f->writable : f->readable;
        int count = pass ? f->writable_count : f->readable_count;
        for (int i = 0; i < count; i++) {
            struct stat st;
            if (stat(list[i], &st) != 0 || !S_ISDIR(st.st_mode)) continue;
            snprintf(path, sizeof path, "%s%s", newroot, list[i]);
            _sl_mkdirs(path);
            _sl_bind(list[i], path, pass == 0, false);
        }
    }
    snprintf(path, sizeof path, "%s%s", newroot, f->cwd);
    _sl_mkdirs(path);
    if (chdir(newroot) != 0 || chroot(".") != 0) _sl_die("cannot enter the fence: %s", strerror(errno));
    if (f->drop_to_nobody && !_sl_become_nobody()) _sl_die("cannot switch to uid %d: %s", _SL_NOBODY, strerror(errno));
    if (chdir(f->cwd) != 0) _sl_die("cannot enter %s in the fence: %s", f->cwd, strerror(errno));
}

/* The command's environment: nothing of the build's own. */
static char *const _sl_environment[] = {"PATH=/usr/local/bin:/usr/bin:/bin", "HOME=/tmp", "TMPDIR=/tmp", "LANG=C",
                                        NULL};

static void _sl_limits(void) {
    struct rlimit memory = {4ull << 30, 4ull << 30}, file = {256ull << 20, 256ull << 20};
    setrlimit(RLIMIT_AS, &memory);
    setrlimit(RLIMIT_FSIZE, &file);
}

/* The child's exit status, as a shell gives it (128 + the signal that ended it). */
static int _sl_wait_for(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WEXITSTATUS(status);
}

/* Runs `command` in a new mount namespace rooted at a fresh tmpfs; its exit status. */
static int _sl_run_in_namespace(const _sl_fence *f, char **command) {
    char newroot[] = "/tmp/shadowlab-fence-XXXXXX";
    if (!mkdtemp(newroot)) _sl_die("cannot create a folder under /tmp: %s", strerror(errno));
    uid_t uid = getuid();
    gid_t gid = getgid();
    pid_t pid = fork();
    if (pid < 0) _sl_die("fork: %s", strerror(errno));
    if (pid == 0) {
        int flags = CLONE_NEWNS | (uid != 0 ? CLONE_NEWUSER : 0);
        if (unshare(flags) != 0) _sl_die("cannot make a mount namespace: %s", strerror(errno));
        if (uid != 0) {
            char map[64];
            _sl_write_file("/proc/self/setgroups", "deny");
            snprintf(map, sizeof map, "0 %u 1\n", (unsigned)uid);
            _sl_write_file("/proc/self/uid_map", map);
            snprintf(map, sizeof map, "0 %u 1\n", (unsigned)gid);
            _sl_write_file("/proc/self/gid_map", map);
        }
        _sl_enter(newroot, f, command);
        _sl_limits();
        execve(command[0], command, _sl_environment);
        /* a bare name: through the fence's PATH */
        if (!strchr(command[0], '/')) execvpe(command[0], command, _sl_environment);
        fprintf(stderr, "shadowlab-fence: cannot run %s: %s\n", command[0], strerror(errno));
        _exit(127);
    }
    int status = _sl_wait_for(pid);
    rmdir(newroot);
    return status;
}

/* uid: runs `command` as 65534 without a namespace (the probe checked that it cannot read the answers). */
static int _sl_run_as_nobody(const _sl_fence *f, char **command) {
    pid_t pid = fork();
    if (pid < 0) _sl_die("fork: %s", strerror(errno));
    if (pid == 0) {
        if (!_sl_become_nobody()) _sl_die("cannot switch to uid %d: %s", _SL_NOBODY, strerror(errno));
        if (chdir(f->cwd) != 0 && chdir("/") != 0) _sl_die("chdir: %s", strerror(errno));
        _sl_limits();
        execve(command[0], command, _sl_environment);
        if (!strchr(command[0], '/')) execvpe(command[0], command, _sl_environment);
        fprintf(stderr, "shadowlab-fence: cannot run %s: %s\n", command[0], strerror(errno));
        _exit(127);
    }
    return _sl_wait_for(pid);
}

static bool _sl_copy_file(const char *from, const char *to) {
    int in = open(from, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (in < 0) return errno == ENOENT; /* an output the command did not write */
    int out = open(to, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0) {
        close(in);
        fprintf(stderr, "shadowlab-fence: cannot write %s: %s\n", to, strerror(errno));
        return false;
    }
    char buf[65536];
    ssize_t n;
    bool ok = true;
    while ((n = read(in, buf, sizeof buf)) > 0)
        if (write(out, buf, (size_t)n) != n) ok = false;
    close(in);
    if (close(out) != 0) ok = false;
    unlink(from);
    return ok && n == 0;
}

/* The probe: can a command run in the namespace fence, and not see a file left out? */
static int _sl_probe(const _sl_fence *hidden) {
    char secret_dir[] = "/tmp/shadowlab-fence-probe-XXXXXX";
    if (!mkdtemp(secret_dir)) {
        printf("none: cannot create a folder under /tmp\n");
        return 0;
    }
    char secret[PATH_MAX];
    snprintf(secret, sizeof secret, "%s/secret", secret_dir);
    int fd = open(secret, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd >= 0) close(fd);
    _sl_fence f = {.readable_count = 0};
    snprintf(f.cwd, sizeof f.cwd, "/");
    char *test[] = {"/bin/sh", "-c", NULL, NULL};
    char script[PATH_MAX + 32];
    snprintf(script, sizeof script, "test ! -e '%s'", secret);
    test[2] = script;
    /* quiet: a refusal is the answer, not an error */
    int saved = dup(2), null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) dup2(null, 2);
    int status = _sl_run_in_namespace(&f, test);
    if (saved >= 0) dup2(saved, 2);
    unlink(secret);
    rmdir(secret_dir);
    if (status == 0) {
        printf("namespaces\n");
        return 0;
    }
    if (getuid() != 0) {
        printf("none: no mount namespace here (not root, and no user namespaces): the compiler would read every "
               "file this user can\n");
        return 0;
    }
    for (int i = 0; i < hidden->hidden_count; i++) {
        pid_t pid = fork();
        if (pid == 0) {
            if (!_sl_become_nobody()) _exit(2);
            _exit(access(hidden->hidden[i], R_OK) == 0 ? 1 : 0);
        }
        int s = 0;
        while (pid > 0 && waitpid(pid, &s, 0) < 0 && errno == EINTR) {}
        if (pid < 0 || !WIFEXITED(s) || WEXITSTATUS(s) == 2) {
            printf("none: no mount namespace here, and this process cannot switch to uid 65534\n");
            return 0;
        }
        if (WEXITSTATUS(s) == 1) {
            printf("none: no mount namespace here, and uid 65534 can read %s (make it unreadable to other users: "
                   "chmod -R go-rwx)\n", hidden->hidden[i]);
            return 0;
        }
    }
    /* The compiler, as 65534, must still reach the system and the project's
     * folder (the one holding the first hidden path): a tree closed to other
     * users (a clone under /root) leaves no fence of this kind. */
    char project[PATH_MAX] = "/";
    if (hidden->hidden_count > 0) {
        snprintf(project, sizeof project, "%s", hidden->hidden[0]);
        char *slash = strrchr(project, '/');
        if (slash && slash != project) *slash = '\0';
    }
    const char *reach[] = {"/", "/usr/bin", project};
    for (size_t i = 0; i < sizeof reach / sizeof reach[0]; i++) {
        pid_t pid = fork();
        if (pid == 0) {
            if (!_sl_become_nobody()) _exit(2);
            _exit(access(reach[i], X_OK) == 0 ? 0 : 1);
        }
        int s = 0;
        while (pid > 0 && waitpid(pid, &s, 0) < 0 && errno == EINTR) {}
        if (pid < 0 || !WIFEXITED(s) || WEXITSTATUS(s) != 0) {
            printf("none: no mount namespace here, and uid 65534 cannot reach %s, where the compiler must read\n",
                   reach[i]);
            return 0;
        }
    }
    printf("uid\n");
    return 0;
}

int main(int argc, char **argv) {
    _sl_fence f = {0};
    const char *fence = NULL;
    bool probe = false, link = false;
    int i = 1;
    for (; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--") == 0) {
            i++;
            break;
        } else if (strcmp(a, "--probe") == 0) probe = true;
        else if (strcmp(a, "--link") == 0) link = true;
        else if (v && strcmp(a, "--fence") == 0) fence = argv[++i];
        else if (v && strcmp(a, "--expose") == 0) _sl_add(f.readable, &f.readable_count, argv[++i]);
        else if (v && strcmp(a, "--expose-rw") == 0) _sl_add(f.writable, &f.writable_count, argv[++i]);
        else if (v && strcmp(a, "--hide") == 0) _sl_add(f.hidden, &f.hidden_count, argv[++i]);
        else {
            fprintf(stderr, "shadowlab-fence: unknown argument %s (grader/fence_main.c says what it takes)\n", a);
            return 2;
        }
    }
    if (probe) return _sl_probe(&f);
    bool namespaces = fence && strcmp(fence, "namespaces") == 0, uid = fence && strcmp(fence, "uid") == 0;
    if ((!namespaces && !uid) || i >= argc) {
        fprintf(stderr, "shadowlab-fence: --fence namespaces|uid ... -- COMMAND ARGS...\n");
        return 2;
    }
    if (!getcwd(f.cwd, sizeof f.cwd)) _sl_die("getcwd: %s", strerror(errno));
    char **command = argv + i;
    int count = argc - i;
    if (link) {
        /* The linker reads only what its command line names. */
        if (uid) {
            execve(command[0], command, _sl_environment);
            _sl_die("cannot run %s: %s", command[0], strerror(errno));
        }
        return _sl_run_in_namespace(&f, command);
    }

    /* A compile: what it reads, from its arguments; its outputs go to a folder of its own. */
    char out_dir[] = "/tmp/shadowlab-fence-out-XXXXXX";
    if (!mkdtemp(out_dir)) _sl_die("cannot create a folder under /tmp: %s", strerror(errno));
    bool root = getuid() == 0;
    if (root && chown(out_dir, _SL_NOBODY, _SL_NOBODY) != 0) _sl_die("chown: %s", strerror(errno));
    char **args = calloc((size_t)count + 1, sizeof *args);
    const char *targets[_SL_MAX_OUTPUTS];
    int outputs = 0;
    if (!args) _sl_die("out of memory");
    args[0] = command[0];
    for (int k = 1; k < count; k++) {
        const char *a = command[k], *next = k + 1 < count ? command[k + 1] : NULL;
        args[k] = command[k];
        static const char *const include_options[] = {"-I", "-isystem", "-iquote", "-idirafter"};
        bool taken = false;
        for (size_t o = 0; o < sizeof include_options / sizeof include_options[0] && !taken; o++) {
            size_t len = strlen(include_options[o]);
            if (strncmp(a, include_options[o], len) != 0) continue;
            if (a[len]) _sl_add(f.readable, &f.readable_count, _sl_absolute(f.cwd, a + len));
            else if (next) {
                _sl_add(f.readable, &f.readable_count, _sl_absolute(f.cwd, next));
                args[k + 1] = command[k + 1];
                k++;
            }
            taken = true;
        }
        if (taken) continue;
        struct stat st;
        if (a[0] == '@' && a[1]) { /* a response file: the compiler reads it */
            _sl_add(f.readable, &f.readable_count, _sl_dirname(_sl_absolute(f.cwd, a + 1)));
        } else if (a[0] != '-' && stat(_sl_absolute(f.cwd, a), &st) == 0 && S_ISREG(st.st_mode)) {
            /* a file the command line names (the source): its folder, read-only */
            _sl_add(f.readable, &f.readable_count, _sl_dirname(_sl_absolute(f.cwd, a)));
        } else if ((strcmp(a, "-o") == 0 || strcmp(a, "-MF") == 0) && next) {
            if (outputs == _SL_MAX_OUTPUTS) _sl_die("too many outputs");
            targets[outputs] = _sl_absolute(f.cwd, next);
            char *path = malloc(PATH_MAX);
            if (!path) _sl_die("out of memory");
            snprintf(path, PATH_MAX, "%s/%d", out_dir, outputs++);
            args[++k] = path;
        }
    }
    _sl_add(f.writable, &f.writable_count, out_dir);
    f.drop_to_nobody = root;
    int status;
    if (namespaces) {
        status = _sl_run_in_namespace(&f, args);
    } else {
        if (!root) _sl_die("the uid fence needs root");
        status = _sl_run_as_nobody(&f, args);
    }
    for (int k = 0; k < outputs; k++) {
        char from[PATH_MAX + 16];
        snprintf(from, sizeof from, "%s/%d", out_dir, k);
        if (!_sl_copy_file(from, targets[k]) && status == 0) status = 1;
    }
    rmdir(out_dir);
    return status;
}
