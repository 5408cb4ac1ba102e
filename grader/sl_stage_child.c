#define _GNU_SOURCE
#include "sl_stage_child.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef SYS_openat2
#include <linux/openat2.h>
#endif

#include "sl_archive.h"
#include "sl_mount_point.h"
#include "sl_stage_channel.h"
#include "sl_stage_tree.h"
#include "sl_text.h"

/* ---- choosing the lab files ---- */

static void _sl_want(_sl_child *c, _sl_node *n, const char *target) {
    if (n->why_ignored) return;
    if (n->size > c->d->max_file_bytes) {
        snprintf(n->why_buffer, sizeof n->why_buffer, "more than %lld KiB", c->d->max_file_bytes >> 10);
        n->why_ignored = n->why_buffer;
        return;
    }
    long long size = n->size > 0 ? n->size : 0;
    if (c->want_count >= c->d->max_files || c->want_bytes + size > c->d->max_total_bytes) {
        snprintf(n->why_buffer, sizeof n->why_buffer, "past the limit of %d lab files or %lld MiB in all",
                 c->d->max_files, c->d->max_total_bytes >> 20);
        n->why_ignored = n->why_buffer;
        return;
    }
    c->want_bytes += size;
    _sl_wanted *w = &c->wants[c->want_count++];
    w->node = n;
    snprintf(w->target, sizeof w->target, "%s", target);
    n->selected = true;
}

static bool _sl_is_lab_folder_name(const _sl_child *c, const char *name) {
    return _sl_lab_index(c->labs, name) >= 0 || strcmp(name, "labs") == 0;
}

static bool _sl_has_lab_folder(_sl_child *c, _sl_node *base) {
    _sl_list_folder(c, base);
    for (_sl_node *n = base->first; n; n = n->next)
        if (n->kind == _SL_DIR && _sl_lab_index(c->labs, n->name) >= 0) return true;
    return false;
}

static void _sl_take_shaders(_sl_child *c, _sl_node *dir, const char *target, int depth) {
    _sl_list_folder(c, dir);
    dir->visited = dir->descended = true;
    for (_sl_node *n = dir->first; n; n = n->next) {
        char sub[600];
        snprintf(sub, sizeof sub, "%s/%s", target, n->name);
        if (_sl_clutter(n->name, n->kind)) continue;
        if (!_sl_stageable_name(n->name)) {
            if (n->kind == _SL_FILE || n->kind == _SL_DIR)
                n->why_ignored = "a name that cannot be staged (control characters, or not UTF-8)";
            continue;
        }
        if (n->kind == _SL_DIR) {
            if (depth < _SL_SHADERS_DEPTH) _sl_take_shaders(c, n, sub, depth + 1);
            else n->why_ignored = "more than 3 folders deep under shaders/: not looked into";
        } else if (n->kind == _SL_FILE) {
            _sl_want(c, n, sub);
        }
    }
}

/* Layouts 1 and 2: the lab folders under base. C files first, then shaders: a
 * limit reached on shaders does not cost another lab its C file. */
static void _sl_take_lab_folders(_sl_child *c, _sl_node *base) {
    base->visited = base->descended = true;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < c->labs->count; i++) {
            _sl_node *lab = _sl_child_named(base, c->labs->folder[i]);
            if (!lab || lab->kind != _SL_DIR) continue;
            _sl_list_folder(c, lab);
            lab->visited = lab->descended = true;
            if (pass == 0) {
                char name[32], target[128];
                snprintf(name, sizeof name, "lab%d.c", c->labs->number[i]);
                snprintf(target, sizeof target, "%s/%s", c->labs->folder[i], name);
                _sl_node *file = _sl_child_named(lab, name);
                if (file && file->kind == _SL_FILE) _sl_want(c, file, target);
            } else {
                _sl_node *shaders = _sl_child_named(lab, "shaders");
                char target[128];
                snprintf(target, sizeof target, "%s/shaders", c->labs->folder[i]);
                if (shaders && shaders->kind == _SL_DIR) _sl_take_shaders(c, shaders, target, 1);
            }
        }
}

/* Layout 3: files named as the handout's lab files, each where the handout has it. */
static void _sl_take_loose(_sl_child *c, _sl_node *from) {
    from->visited = from->descended = true;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < c->labs->file_count; i++) {
            const char *stub = c->labs->files[i];
            bool is_c = strstr(stub, "/shaders/") == NULL;
            if (is_c != (pass == 0)) continue;
            const char *base = strrchr(stub, '/') + 1;
            _sl_node *n = _sl_child_named(from, base);
            if (n && n->kind == _SL_FILE) _sl_want(c, n, stub);
        }
}

/* Says what was left out of each folder looked at, and why. */
static void _sl_report_left_out(_sl_node *dir) {
    if (!dir->visited) return;
    for (_sl_node *n = dir->first; n; n = n->next) {
        if (n->selected || n->reported) continue;
        if (n->descended) {
            _sl_report_left_out(n);
            continue;
        }
        n->reported = true;
        const char *refusal = _sl_refusal(n), *clutter = _sl_clutter(n->name, n->kind);
        char shown[_SL_TEXT_MAX];
        snprintf(shown, sizeof shown, "%s%s", n->path, n->kind == _SL_DIR ? "/" : "");
        if (refusal && !clutter) _sl_send_record(_SL_R_REFUSED, shown, refusal);
        else if (clutter) _sl_send_record(_SL_R_IGNORED, shown, clutter);
        else if (n->why_ignored) _sl_send_record(_SL_R_IGNORED, shown, n->why_ignored);
        else if (n->kind == _SL_DIR) _sl_send_record(_SL_R_IGNORED, shown, "a folder that is not part of a layout");
        else _sl_send_record(_SL_R_IGNORED, shown, "not a lab file");
    }
}

/* The entries of a folder that are not clutter, the one such entry in *only. */
static int _sl_real_entries(_sl_child *c, _sl_node *dir, _sl_node **only) {
    _sl_list_folder(c, dir);
    int count = 0;
    *only = NULL;
    for (_sl_node *n = dir->first; n; n = n->next)
        if (!_sl_clutter(n->name, n->kind)) {
            count++;
            *only = n;
        }
    return count;
}

/* Opens a file of the folder submission as the archive to read instead. */
static bool _sl_switch_to_archive(_sl_child *c, _sl_node *file) {
    int parent = _sl_dir_fd(c, file->parent);
    int fd = parent >= 0 ? _sl_open_beneath(parent, file->name, O_RDONLY | O_NONBLOCK | O_NOCTTY) : -1;
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_ino != file->ino) {
        if (fd >= 0) close(fd);
        else if (errno == EACCES) _sl_staff_problem(c, file->path, "cannot be read by the user that reads submissions");
        return false;
    }
    c->archive = true;
    c->archive_fd = fd;
    snprintf(c->archive_name, sizeof c->archive_name, "%s", file->path);
    return true;
}

static void _sl_child_stage(_sl_child *c, int root_fd, bool root_is_archive, const char *submission_name) {
    _sl_node *root;
    if (root_is_archive) {
        c->archive = true;
        c->archive_fd = root_fd;
        snprintf(c->archive_name, sizeof c->archive_name, "%s", submission_name);
        root = _sl_archive_tree(c, "");
    } else {
        root = _sl_new_node(NULL, "", _SL_DIR);
        root->fd = root_fd;
    }
    _sl_node *only;
    /* A folder holding one archive (beside clutter at most): the archive is the submission. */
    if (!c->archive && _sl_real_entries(c, root, &only) == 1 && only->kind == _SL_FILE &&
        sl_archive_name_is_archive(only->name) && _sl_switch_to_archive(c, only)) {
        root->visited = true;
        only->selected = true; /* looked into, not left out */
        _sl_report_left_out(root);
        root = _sl_archive_tree(c, only->path);
    }
    for (int attempt = 0; attempt < 2; attempt++) {
        /* One top folder (an unpacked archive, a project folder), up to three deep. */
        _sl_node *from = root;
        for (int i = 0; i < 3; i++) {
            if (_sl_real_entries(c, from, &only) != 1 || only->kind != _SL_DIR || _sl_is_lab_folder_name(c, only->name))
                break;
            from->visited = from->descended = true;
            from = only;
        }
        _sl_list_folder(c, from);
        from->visited = from->descended = true;
        _sl_node *labs = _sl_child_named(from, "labs");
        const char *layout;
        if (labs && labs->kind == _SL_DIR && _sl_has_lab_folder(c, labs)) {
            layout = "a labs/ folder";
            _sl_take_lab_folders(c, labs);
        } else if (_sl_has_lab_folder(c, from)) {
            layout = "the lab folders";
            _sl_take_lab_folders(c, from);
        } else {
            layout = "loose files";
            _sl_take_loose(c, from);
        }
        /* Nothing in the layouts, and one archive among what the folder holds: look into it. */
        _sl_node *archive = NULL;
        int archives = 0;
        if (c->want_count == 0 && !c->archive && attempt == 0) {
            for (_sl_node *n = from->first; n; n = n->next)
                if (n->kind == _SL_FILE && !_sl_clutter(n->name, n->kind) && sl_archive_name_is_archive(n->name)) {
                    archives++;
                    archive = n;
                }
        }
        if (archives == 1 && _sl_switch_to_archive(c, archive)) {
            archive->selected = true;
            _sl_report_left_out(root);
            root = _sl_archive_tree(c, archive->path);
            continue;
        }
        _sl_send_record(_SL_R_SOURCE, c->archive ? "archive" : "folder", from->path);
        _sl_send_record(_SL_R_LAYOUT, c->want_count ? layout : "", NULL);
        if (c->want_count == 0) {
            for (_sl_node *n = from->first; n; n = n->next) {
                char shown[_SL_TEXT_MAX];
                snprintf(shown, sizeof shown, "%s%s", n->path, n->kind == _SL_DIR ? "/" : "");
                _sl_send_record(_SL_R_FOUND, shown, _sl_clutter(n->name, n->kind) ? "clutter" : "");
            }
        }
        break;
    }
    /* the data */
    if (c->archive) _sl_archive_read_wanted(c);
    else
        for (int i = 0; i < c->want_count; i++)
            if (!c->wants[i].node->data && !c->wants[i].node->why_ignored) _sl_folder_read(c, c->wants[i].node);
    for (int i = 0; i < c->want_count; i++) {
        _sl_node *n = c->wants[i].node;
        if (!n->data) {
            n->selected = false; /* said below, with its reason */
            if (!n->why_ignored) n->why_ignored = "not found when read";
            continue;
        }
        _sl_send_record3(_SL_R_FILE, c->wants[i].target, strlen(c->wants[i].target), n->data, (size_t)n->data_len, n->path,
                  strlen(n->path));
    }
    _sl_report_left_out(root);
    if (c->entries_over) {
        char text[300];
        snprintf(text, sizeof text, "the submission has more than %d files and folders: the rest was not looked at",
                 c->d->max_entries);
        _sl_send_record(_SL_R_ERROR, text, NULL);
    }
}

/* ---- the fence: who reads the submission, and what it can see ---- */

static bool _sl_write_file(const char *path, const char *text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    bool ok = write(fd, text, strlen(text)) == (ssize_t)strlen(text);
    close(fd);
    return ok;
}

/* Returns false (with a staff problem sent) when privileges could not be dropped. */
static bool _sl_fence(const sl_stage_desc *d) {
    char said[_SL_TEXT_MAX] = "";
    bool root = geteuid() == 0;
    uid_t uid = getuid();
    gid_t gid = getgid();
    bool namespace = false;
    if (root) {
        namespace = unshare(CLONE_NEWNS) == 0;
    } else if (unshare(CLONE_NEWUSER | CLONE_NEWNS) == 0) {
        char map[64];
        snprintf(map, sizeof map, "0 %u 1", (unsigned)uid);
        namespace = _sl_write_file("/proc/self/uid_map", map) && _sl_write_file("/proc/self/setgroups", "deny");
        snprintf(map, sizeof map, "0 %u 1", (unsigned)gid);
        namespace = namespace && _sl_write_file("/proc/self/gid_map", map);
    }
    const char *private_point = namespace ? sl_private_mount_point() : NULL;
    if (!private_point) namespace = false;
    /* Under a chroot "/" is no mount point, and a folder hidden where it is would show outside too. The
     * reader needs no file by name any more (the submission is open): it moves into an empty root of its
     * own, a tmpfs over a mount point the chroot shows, where nothing of the file system is reachable. */
    bool empty_root = false;
    if (namespace && strcmp(private_point, "/") != 0) {
        empty_root = mount("shadowlab-reader", private_point, "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC,
                           "size=16k,mode=0555") == 0 &&
                     chdir(private_point) == 0 && chroot(".") == 0 && chdir("/") == 0;
        if (!empty_root) namespace = false;
    }
    int hidden = 0, existing = 0;
    char not_hidden[1024] = "";
    for (int i = 0; i < d->hidden_count; i++) {
        struct stat st;
        if (empty_root) { /* stat from the empty root cannot tell: every folder named is out of reach */
            existing++;
            hidden++;
            continue;
        }
        if (stat(d->hidden[i], &st) != 0 || !S_ISDIR(st.st_mode)) continue;
        existing++;
        if (namespace &&
            mount("shadowlab-hidden", d->hidden[i], "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "size=16k,mode=0") == 0)
            hidden++;
        else
            snprintf(not_hidden + strlen(not_hidden), sizeof not_hidden - strlen(not_hidden), "%s%s",
                     not_hidden[0] ? ", " : "", d->hidden[i]);
    }
    if (root) {
        unsigned user = d->user ? d->user : 65534;
        if (setgroups(0, NULL) != 0 || setresgid(user, user, user) != 0 || setresuid(user, user, user) != 0 ||
            getuid() != user || geteuid() != user) {
            char text[200];
            snprintf(text, sizeof text, "cannot switch to uid %u to read the submission (%s)", user, strerror(errno));
            _sl_send_record(_SL_R_STAFF, text, NULL);
            return false;
        }
    }
    /* after the uid changed (which resets it): no process of that uid may trace this one */
    prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
    prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
    struct rlimit none = {0, 0}, cpu = {60, 61}, memory = {1ull << 30, 1ull << 30};
    setrlimit(RLIMIT_FSIZE, &none); /* it writes no file */
    setrlimit(RLIMIT_CORE, &none);
    setrlimit(RLIMIT_NPROC, &none); /* and starts no process */
    setrlimit(RLIMIT_CPU, &cpu);
    setrlimit(RLIMIT_AS, &memory);
    snprintf(said, sizeof said, "uid %u%s", root ? (unsigned)getuid() : (unsigned)uid,
             root ? "" : namespace ? " (the caller's, in a user namespace)" : " (the caller's)");
    if (existing == 0)
        snprintf(said + strlen(said), sizeof said - strlen(said), "%s", namespace ? ", in a mount namespace" : "");
    else if (hidden == existing)
        snprintf(said + strlen(said), sizeof said - strlen(said), ", in a mount namespace where the answers are hidden%s",
                 empty_root ? " (an empty root of its own: \"/\" is no mount point here, a chroot)" : "");
    else
        snprintf(said + strlen(said), sizeof said - strlen(said), ", %s: it could see %s",
                 namespace ? "in a mount namespace" : "no mount namespace here", not_hidden);
    _sl_send_record(_SL_R_FENCE, said, NULL);
    return true;
}

/* Opens the submission itself, named by the staff: never through a link at its last step. */
static int _sl_open_submission(const char *path, bool *is_archive, char *why, size_t n) {
    char copy[4096];
    snprintf(copy, sizeof copy, "%s", path);
    size_t len = strlen(copy);
    while (len > 1 && copy[len - 1] == '/') copy[--len] = '\0'; /* "alice/" would follow a link named alice */
    char *slash = strrchr(copy, '/');
    const char *base = copy;
    int parent = AT_FDCWD;
    if (slash) {
        *slash = '\0';
        parent = open(slash == copy ? "/" : copy, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        base = slash + 1;
        if (parent < 0) {
            snprintf(why, n, "its folder cannot be opened (%s)", strerror(errno));
            return -1;
        }
    }
    struct stat st;
    int fd = -1;
    if (fstatat(parent, base, &st, AT_SYMLINK_NOFOLLOW) != 0) {
        snprintf(why, n, "cannot be found (%s)", strerror(errno));
    } else if (S_ISLNK(st.st_mode)) {
        char target[256];
        ssize_t l = readlinkat(parent, base, target, sizeof target - 1);
        target[l > 0 ? l : 0] = '\0';
        snprintf(why, n, "a symbolic link (to %.200s): links are never followed; give the folder or archive itself",
                 target);
    } else if (S_ISDIR(st.st_mode)) {
        fd = openat(parent, base, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        *is_archive = false;
    } else if (S_ISREG(st.st_mode)) {
        fd = openat(parent, base, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        *is_archive = true;
    } else {
        snprintf(why, n, "neither a folder nor an archive");
    }
    struct stat opened;
    if (fd >= 0 && (fstat(fd, &opened) != 0 || opened.st_ino != st.st_ino || opened.st_dev != st.st_dev)) {
        close(fd);
        fd = -1;
        snprintf(why, n, "it changed while being opened");
    } else if (fd < 0 && !why[0]) {
        snprintf(why, n, "cannot be opened (%s)", strerror(errno));
    }
    if (parent != AT_FDCWD) close(parent);
    return fd;
}

void _sl_child_main(const sl_stage_desc *d, const _sl_labs *labs, int channel) {
    _sl_channel_fd = channel;
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
    char why[600] = "";
    bool is_archive = false;
    char name[512];
    snprintf(name, sizeof name, "%s", d->submission);
    while (strlen(name) > 1 && name[strlen(name) - 1] == '/') name[strlen(name) - 1] = '\0';
    const char *shown = strrchr(name, '/') ? strrchr(name, '/') + 1 : name;
    /* opened before the fence: the hidden folders may hold it (a batch's submissions) */
    int fd = _sl_open_submission(d->submission, &is_archive, why, sizeof why);
    if (!_sl_fence(d)) _exit(SL_STAGE_PROBLEM);
    if (fd < 0) {
        _sl_send_record(_SL_R_REFUSED, shown, why);
        _sl_send_record(_SL_R_SOURCE, "folder", "");
        _sl_send_record(_SL_R_LAYOUT, "", NULL);
    } else {
        _sl_child c = {.d = d, .labs = labs, .archive_fd = -1};
        c.wants = calloc((size_t)d->max_files + 1, sizeof *c.wants);
        _sl_child_stage(&c, fd, is_archive, shown);
    }
    _sl_send_record(_SL_R_END, NULL, NULL);
    _exit(0);
}
