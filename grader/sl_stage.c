#define _GNU_SOURCE
#include "sl_stage.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
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

#include <cjson/cJSON.h>

#include "sl_archive.h"
#include "sl_files.h"
#include "sl_mount_point.h"
#include "sl_text.h"

#define _SL_TEXT_MAX 4096      /* a name or a reason on the channel */
#define _SL_LIST_MAX 400       /* entries kept per list in the summary */
#define _SL_SHADERS_DEPTH 3    /* folders under a lab's shaders/ */
#define _SL_MAX_LABS 16

/* ---- the handout's lab files, from the stage's stubs (trusted) ---- */

typedef struct _sl_labs {
    char folder[_SL_MAX_LABS][64]; /* lab1_depth_fbo, ... in order */
    int number[_SL_MAX_LABS];
    int count;
    char (*files)[256]; /* every stub file: "lab1_depth_fbo/lab1.c", "lab1_depth_fbo/shaders/depth.vert" */
    int file_count;
} _sl_labs;

static int _sl_compare_strings(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void _sl_add_stub_files(_sl_labs *labs, int dir_fd, const char *rel, int depth) {
    int fd = openat(dir_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        if (fd >= 0) close(fd);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue;
        struct stat st;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
        char path[256];
        if ((size_t)snprintf(path, sizeof path, "%s/%s", rel, e->d_name) >= sizeof path) continue;
        if (S_ISDIR(st.st_mode) && depth < _SL_SHADERS_DEPTH) {
            int sub = openat(dirfd(d), e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub >= 0) {
                _sl_add_stub_files(labs, sub, path, depth + 1);
                close(sub);
            }
        } else if (S_ISREG(st.st_mode) && labs->file_count < 512) {
            snprintf(labs->files[labs->file_count++], 256, "%s", path);
        }
    }
    closedir(d);
}

static bool _sl_read_labs(int stage_fd, _sl_labs *labs, char *err, size_t n) {
    int fd = openat(stage_fd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        snprintf(err, n, "cannot list the stage (%s)", strerror(errno));
        if (fd >= 0) close(fd);
        return false;
    }
    char *names[_SL_MAX_LABS];
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < _SL_MAX_LABS) {
        int number = 0, used = 0;
        if (sscanf(e->d_name, "lab%d_%n", &number, &used) != 1 || used == 0 || number < 1 ||
            strlen(e->d_name) >= sizeof labs->folder[0])
            continue;
        struct stat st;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISDIR(st.st_mode))
            names[count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], _sl_compare_strings);
    labs->files = calloc(512, sizeof *labs->files);
    for (int i = 0; i < count; i++) {
        snprintf(labs->folder[i], sizeof labs->folder[i], "%s", names[i]);
        sscanf(names[i], "lab%d_", &labs->number[i]);
        free(names[i]);
        char c_file[96];
        snprintf(c_file, sizeof c_file, "%s/lab%d.c", labs->folder[i], labs->number[i]);
        struct stat st;
        if (fstatat(stage_fd, c_file, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode) && labs->file_count < 512)
            snprintf(labs->files[labs->file_count++], 256, "%s", c_file);
        char shaders[96];
        snprintf(shaders, sizeof shaders, "%s/shaders", labs->folder[i]);
        int sub = openat(stage_fd, shaders, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (sub >= 0) {
            _sl_add_stub_files(labs, sub, shaders, 1);
            close(sub);
        }
    }
    labs->count = count;
    if (!count) {
        snprintf(err, n, "the stage holds no lab folder (lab1_..., lab2_...): not a labs tree");
        return false;
    }
    return true;
}

static int _sl_lab_index(const _sl_labs *labs, const char *name) {
    for (int i = 0; i < labs->count; i++)
        if (strcmp(labs->folder[i], name) == 0) return i;
    return -1;
}

/* A name a staged file may have under shaders/: valid UTF-8 without control
 * characters or separators (spaces and letters of any language are fine). */
static bool _sl_stageable_name(const char *name) {
    size_t len = strlen(name);
    if (len == 0 || len > 255 || strcmp(name, ".") == 0 || strcmp(name, "..") == 0) return false;
    for (size_t i = 0; i < len; i++)
        if ((unsigned char)name[i] < 0x20 || name[i] == 0x7f || name[i] == '/' || name[i] == '\\') return false;
    sl_text_problems p;
    return sl_text_check(name, len, &p);
}

/* ---- the channel: child -> parent ---- */

typedef struct _sl_record_header {
    uint8_t kind;
    uint32_t len[3];
} __attribute__((packed)) _sl_record_header;

enum {
    _SL_R_FENCE = 'A',   /* how the submission was read */
    _SL_R_SOURCE = 'S',  /* "folder" | "archive", the folder looked into */
    _SL_R_LAYOUT = 'L',
    _SL_R_FOUND = 'T',   /* what the folder looked into holds (for "no lab file") */
    _SL_R_IGNORED = 'I', /* path, reason */
    _SL_R_REFUSED = 'R', /* path, reason */
    _SL_R_ERROR = 'E',   /* the submission's fault: a corrupt archive, a limit */
    _SL_R_STAFF = 'X',   /* not the submission's fault: unreadable files, a fence that failed */
    _SL_R_FILE = 'F',    /* target, content, source path */
    _SL_R_END = 'Z',
};

static void _sl_write_all(int fd, const void *data, size_t n) {
    const char *p = data;
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) _exit(SL_STAGE_PROBLEM); /* the parent is gone */
        p += w;
        n -= (size_t)w;
    }
}

static int _sl_channel = -1;

static void _sl_send3(int kind, const char *a, size_t la, const char *b, size_t lb, const char *c, size_t lc) {
    _sl_record_header h = {.kind = (uint8_t)kind, .len = {(uint32_t)la, (uint32_t)lb, (uint32_t)lc}};
    _sl_write_all(_sl_channel, &h, sizeof h);
    if (la) _sl_write_all(_sl_channel, a, la);
    if (lb) _sl_write_all(_sl_channel, b, lb);
    if (lc) _sl_write_all(_sl_channel, c, lc);
}

static void _sl_send(int kind, const char *a, const char *b) {
    size_t la = a ? strlen(a) : 0, lb = b ? strlen(b) : 0;
    if (la > _SL_TEXT_MAX) la = _SL_TEXT_MAX;
    if (lb > _SL_TEXT_MAX) lb = _SL_TEXT_MAX;
    _sl_send3(kind, a, la, b, lb, NULL, 0);
}

/* ---- the child: the submission as a tree, listed as it is needed ---- */

typedef enum _sl_kind {
    _SL_FILE,
    _SL_DIR,
    _SL_SYMLINK,
    _SL_HARDLINK,
    _SL_DEVICE,
    _SL_FIFO,
    _SL_SOCKET,
    _SL_OTHER,
    _SL_UNREADABLE,
} _sl_kind;

typedef struct _sl_node {
    char *name, *path;      /* one part; the path shown to people (from the submission's folder) */
    char *archive_path;     /* an archive's entry: its cleaned path there */
    _sl_kind kind;
    long long size;
    long nlink;
    char *link;             /* a link's target, as written */
    dev_t dev;
    ino_t ino;
    struct _sl_node *parent, *first, *next;
    bool listed, visited, descended, selected, reported;
    const char *why_ignored; /* set when a lab file is left out (a limit) */
    char why_buffer[160];
    int fd;                 /* a folder of a folder submission, once opened */
    char *data;             /* a chosen file's content */
    long long data_len;
} _sl_node;

typedef struct _sl_wanted {
    _sl_node *node;
    char target[600];
} _sl_wanted;

typedef struct _sl_child {
    const sl_stage_desc *d;
    const _sl_labs *labs;
    bool archive;           /* the tree is an archive's */
    int archive_fd;
    char archive_name[512]; /* shown in messages */
    int entries;
    bool entries_over;
    _sl_wanted *wants;
    int want_count;
    long long want_bytes;
} _sl_child;

static char *_sl_join(const char *a, const char *b) {
    size_t la = strlen(a), lb = strlen(b);
    char *s = malloc(la + lb + 2);
    if (!s) _exit(SL_STAGE_PROBLEM);
    if (la) {
        memcpy(s, a, la);
        s[la] = '/';
        memcpy(s + la + 1, b, lb + 1);
    } else {
        memcpy(s, b, lb + 1);
    }
    return s;
}

static _sl_node *_sl_new_node(_sl_node *parent, const char *name, _sl_kind kind) {
    _sl_node *n = calloc(1, sizeof *n);
    if (!n) _exit(SL_STAGE_PROBLEM);
    n->name = strdup(name);
    n->path = parent ? _sl_join(parent->path, name) : strdup(name);
    n->kind = kind;
    n->parent = parent;
    n->fd = -1;
    n->size = -1;
    return n;
}

/* Children are kept in name order: what is said is the same on every machine. */
static void _sl_add_child(_sl_node *parent, _sl_node *child) {
    _sl_node **p = &parent->first;
    while (*p && strcmp((*p)->name, child->name) < 0) p = &(*p)->next;
    child->next = *p;
    *p = child;
}

static _sl_node *_sl_child_named(_sl_node *parent, const char *name) {
    for (_sl_node *c = parent->first; c; c = c->next)
        if (strcmp(c->name, name) == 0) return c;
    return NULL;
}

/* One step down, never through a link: openat2 where the kernel has it. */
static int _sl_open_beneath(int dir_fd, const char *name, int flags) {
#ifdef SYS_openat2
    struct open_how how = {.flags = (uint64_t)(flags | O_NOFOLLOW | O_CLOEXEC),
                           .resolve = RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS};
    long fd = syscall(SYS_openat2, dir_fd, name, &how, sizeof how);
    if (fd >= 0 || (errno != ENOSYS && errno != EPERM && errno != E2BIG && errno != EINVAL)) return (int)fd;
#endif
    return openat(dir_fd, name, flags | O_NOFOLLOW | O_CLOEXEC);
}

static const char *_sl_clutter(const char *name, _sl_kind kind) {
    if (kind == _SL_DIR && strcmp(name, "__MACOSX") == 0) return "macOS archive metadata";
    if (strncmp(name, "._", 2) == 0) return "macOS metadata (AppleDouble)";
    if (strcmp(name, ".DS_Store") == 0) return "macOS folder settings";
    if (strcasecmp(name, "Thumbs.db") == 0 || strcasecmp(name, "desktop.ini") == 0) return "Windows folder settings";
    return NULL;
}

static void _sl_staff_problem(_sl_child *c, const char *path, const char *what) {
    char text[_SL_TEXT_MAX];
    snprintf(text, sizeof text, "%s: %s", path, what);
    _sl_send(_SL_R_STAFF, text, NULL);
    (void)c;
}

static int _sl_dir_fd(_sl_child *c, _sl_node *n) {
    if (n->fd >= 0 || !n->parent) return n->fd;
    int parent = _sl_dir_fd(c, n->parent);
    if (parent < 0) return -1;
    int fd = _sl_open_beneath(parent, n->name, O_RDONLY | O_DIRECTORY);
    struct stat st;
    if (fd >= 0 && (fstat(fd, &st) != 0 || st.st_dev != n->dev || st.st_ino != n->ino)) {
        close(fd);
        fd = -1;
        errno = ESTALE;
    }
    if (fd < 0) {
        if (errno == EACCES) {
            char what[200];
            snprintf(what, sizeof what, "the folder cannot be read by uid %u, which reads submissions: make them "
                                        "readable to all (chmod -R a+rX)", (unsigned)getuid());
            _sl_staff_problem(c, n->path, what);
        }
        n->kind = _SL_UNREADABLE;
        snprintf(n->why_buffer, sizeof n->why_buffer, "cannot be opened (%s)", errno == ESTALE ? "it changed while "
                 "being read" : strerror(errno));
        n->why_ignored = n->why_buffer;
        return -1;
    }
    n->fd = fd;
    return fd;
}

static void _sl_list(_sl_child *c, _sl_node *n) {
    if (n->listed || n->kind != _SL_DIR) return;
    n->listed = true;
    if (c->archive) return; /* an archive's tree is whole from the start */
    int fd = _sl_dir_fd(c, n);
    if (fd < 0) return;
    int copy = dup(fd);
    DIR *d = copy >= 0 ? fdopendir(copy) : NULL;
    if (!d) {
        if (copy >= 0) close(copy);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        if (c->entries >= c->d->max_entries) {
            c->entries_over = true;
            break;
        }
        c->entries++;
        struct stat st;
        _sl_node *child = _sl_new_node(n, e->d_name, _SL_OTHER);
        if (fstatat(fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) {
            child->kind = _SL_UNREADABLE;
            snprintf(child->why_buffer, sizeof child->why_buffer, "cannot be read (%s)", strerror(errno));
        } else {
            child->dev = st.st_dev;
            child->ino = st.st_ino;
            child->size = (long long)st.st_size;
            child->nlink = (long)st.st_nlink;
            if (S_ISDIR(st.st_mode)) child->kind = _SL_DIR;
            else if (S_ISREG(st.st_mode)) child->kind = st.st_nlink > 1 ? _SL_HARDLINK : _SL_FILE;
            else if (S_ISLNK(st.st_mode)) {
                child->kind = _SL_SYMLINK;
                char target[256];
                ssize_t len = readlinkat(fd, e->d_name, target, sizeof target - 1);
                target[len > 0 ? len : 0] = '\0';
                child->link = strdup(target);
            } else if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) child->kind = _SL_DEVICE;
            else if (S_ISFIFO(st.st_mode)) child->kind = _SL_FIFO;
            else if (S_ISSOCK(st.st_mode)) child->kind = _SL_SOCKET;
        }
        _sl_add_child(n, child);
    }
    closedir(d);
}

/* Why an entry is refused, or NULL when it is a file or a folder. */
static const char *_sl_refusal(_sl_node *n) {
    switch (n->kind) {
    case _SL_SYMLINK:
        snprintf(n->why_buffer, sizeof n->why_buffer, "a symbolic link (to %.100s): links are never followed",
                 n->link ? n->link : "?");
        return n->why_buffer;
    case _SL_HARDLINK:
        if (n->link)
            snprintf(n->why_buffer, sizeof n->why_buffer, "a hard link (to %.100s): links are never followed", n->link);
        else
            snprintf(n->why_buffer, sizeof n->why_buffer, "a file with %ld names (a hard link): it may be a file from "
                     "outside the submission", n->nlink);
        return n->why_buffer;
    case _SL_DEVICE: return "a device, not a file";
    case _SL_FIFO: return "a FIFO (named pipe), not a file";
    case _SL_SOCKET: return "a socket, not a file";
    case _SL_OTHER: return "neither a file nor a folder";
    case _SL_UNREADABLE: return n->why_buffer[0] ? n->why_buffer : "cannot be read";
    default: return NULL;
    }
}

/* ---- an archive as a tree ---- */

static _sl_node *_sl_archive_insert(_sl_child *c, _sl_node *root, const sl_archive_entry *e) {
    _sl_node *at = root;
    const char *p = e->path;
    int depth = 0;
    while (*p) {
        size_t len = strcspn(p, "/");
        char part[256];
        snprintf(part, sizeof part, "%.*s", (int)len, p);
        bool last = p[len] == '\0';
        if (++depth > c->d->max_depth) {
            char text[_SL_TEXT_MAX];
            snprintf(text, sizeof text, "%s%s%s/", at->path, at->path[0] ? "/" : "", part);
            char why[80];
            snprintf(why, sizeof why, "deeper than %d folders: not looked into", c->d->max_depth);
            if (!at->reported) _sl_send(_SL_R_IGNORED, text, why);
            at->reported = true;
            return NULL;
        }
        _sl_node *child = _sl_child_named(at, part);
        if (last) {
            _sl_kind kind = e->kind == SL_ARCHIVE_FILE       ? _SL_FILE
                            : e->kind == SL_ARCHIVE_FOLDER   ? _SL_DIR
                            : e->kind == SL_ARCHIVE_SYMLINK  ? _SL_SYMLINK
                            : e->kind == SL_ARCHIVE_HARDLINK ? _SL_HARDLINK
                            : e->kind == SL_ARCHIVE_DEVICE   ? _SL_DEVICE
                            : e->kind == SL_ARCHIVE_FIFO     ? _SL_FIFO
                            : e->kind == SL_ARCHIVE_SOCKET   ? _SL_SOCKET
                                                             : _SL_OTHER;
            if (child) {
                if (kind == _SL_DIR && child->kind == _SL_DIR) return child; /* a folder named again */
                char text[_SL_TEXT_MAX];
                snprintf(text, sizeof text, "%s/%s", at->path, part);
                _sl_send(_SL_R_IGNORED, at->path[0] ? text : part, "a second entry of the same name in the archive");
                return NULL;
            }
            child = _sl_new_node(at, part, kind);
            child->size = e->size;
            child->listed = true;
            child->archive_path = strdup(e->path);
            if (e->link_target[0]) child->link = strdup(e->link_target);
            _sl_add_child(at, child);
            return child;
        }
        if (!child) {
            child = _sl_new_node(at, part, _SL_DIR);
            child->listed = true;
            _sl_add_child(at, child);
        } else if (child->kind != _SL_DIR) {
            return NULL; /* a file's name used as a folder: the file is what counts */
        }
        at = child;
        p += len + 1;
    }
    return NULL;
}

/* Reads the archive's entries into a tree whose root is named `label`. */
static _sl_node *_sl_archive_tree(_sl_child *c, const char *label) {
    _sl_node *root = _sl_new_node(NULL, label, _SL_DIR);
    root->listed = true;
    char err[1600];
    sl_archive *a = sl_archive_open(c->archive_fd, c->archive_name, err, sizeof err);
    if (!a) {
        _sl_send(_SL_R_ERROR, err, NULL);
        return root;
    }
    sl_archive_entry *e = malloc(sizeof *e);
    int r;
    while ((r = sl_archive_next(a, e)) > 0) {
        if (c->entries >= c->d->max_entries) {
            c->entries_over = true;
            break;
        }
        c->entries++;
        if (sl_archive_unpacked_bytes(a) > c->d->max_unpacked_bytes) {
            char text[1200];
            snprintf(text, sizeof text, "%s unpacks to more than %llu MiB: the entries after %s were not looked at",
                     c->archive_name, c->d->max_unpacked_bytes >> 20, e->path);
            _sl_send(_SL_R_ERROR, text, NULL);
            break;
        }
        char shown[SL_ARCHIVE_PATH_MAX + 8];
        snprintf(shown, sizeof shown, "%s%s%s", label, label[0] ? "/" : "", e->path);
        if (e->unsafe) {
            _sl_send(_SL_R_REFUSED, shown, e->unsafe);
            continue;
        }
        if (!e->path[0]) continue;
        _sl_archive_insert(c, root, e);
    }
    if (r < 0) _sl_send(_SL_R_ERROR, sl_archive_error(a), NULL);
    free(e);
    sl_archive_close(a);
    return root;
}

/* Pass two: the chosen entries' data, bounded whatever the headers say. */
static void _sl_archive_read_wanted(_sl_child *c) {
    char err[1600];
    sl_archive *a = sl_archive_open(c->archive_fd, c->archive_name, err, sizeof err);
    if (!a) return; /* said in pass one */
    sl_archive_entry *e = malloc(sizeof *e);
    char *buf = malloc((size_t)c->d->max_file_bytes);
    int left = 0;
    for (int i = 0; i < c->want_count; i++) left += c->wants[i].node->data == NULL;
    int r;
    while (left > 0 && (r = sl_archive_next(a, e)) > 0) {
        if (e->unsafe || e->kind != SL_ARCHIVE_FILE) continue;
        for (int i = 0; i < c->want_count; i++) {
            _sl_node *n = c->wants[i].node;
            if (n->data || n->why_ignored || strcmp(n->archive_path, e->path) != 0) continue;
            bool more = false;
            long long got = sl_archive_read(a, buf, (size_t)c->d->max_file_bytes, &more);
            left--;
            if (got < 0) {
                _sl_send(_SL_R_ERROR, sl_archive_error(a), NULL);
                n->why_ignored = "its data cannot be read (a corrupt archive)";
            } else if (more) {
                snprintf(n->why_buffer, sizeof n->why_buffer, "more than %lld KiB", c->d->max_file_bytes >> 10);
                n->why_ignored = n->why_buffer;
            } else {
                n->data = malloc((size_t)got + 1);
                memcpy(n->data, buf, (size_t)got);
                n->data_len = got;
            }
            break; /* this entry's data is read */
        }
    }
    free(buf);
    free(e);
    sl_archive_close(a);
}

static void _sl_folder_read(_sl_child *c, _sl_node *n) {
    int parent = _sl_dir_fd(c, n->parent);
    if (parent < 0) return;
    int fd = _sl_open_beneath(parent, n->name, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        if (errno == EACCES) {
            char what[200];
            snprintf(what, sizeof what, "the file cannot be read by uid %u, which reads submissions: make them "
                                        "readable to all (chmod -R a+rX)", (unsigned)getuid());
            _sl_staff_problem(c, n->path, what);
        }
        snprintf(n->why_buffer, sizeof n->why_buffer, "cannot be read (%s)", strerror(errno));
        n->why_ignored = n->why_buffer;
        if (fd >= 0) close(fd);
        return;
    }
    if (!S_ISREG(st.st_mode) || st.st_dev != n->dev || st.st_ino != n->ino || st.st_nlink != 1) {
        n->why_ignored = "it changed while being read (now a link or another file)";
        close(fd);
        return;
    }
    long long cap = c->d->max_file_bytes;
    n->data = malloc((size_t)cap + 1);
    long long got = 0;
    while (got <= cap) {
        ssize_t r = read(fd, n->data + got, (size_t)(cap + 1 - got));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        got += r;
    }
    close(fd);
    if (got > cap) {
        free(n->data);
        n->data = NULL;
        snprintf(n->why_buffer, sizeof n->why_buffer, "more than %lld KiB", cap >> 10);
        n->why_ignored = n->why_buffer;
        return;
    }
    n->data_len = got;
}

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
    _sl_list(c, base);
    for (_sl_node *n = base->first; n; n = n->next)
        if (n->kind == _SL_DIR && _sl_lab_index(c->labs, n->name) >= 0) return true;
    return false;
}

static void _sl_take_shaders(_sl_child *c, _sl_node *dir, const char *target, int depth) {
    _sl_list(c, dir);
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
            _sl_list(c, lab);
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
        if (refusal && !clutter) _sl_send(_SL_R_REFUSED, shown, refusal);
        else if (clutter) _sl_send(_SL_R_IGNORED, shown, clutter);
        else if (n->why_ignored) _sl_send(_SL_R_IGNORED, shown, n->why_ignored);
        else if (n->kind == _SL_DIR) _sl_send(_SL_R_IGNORED, shown, "a folder that is not part of a layout");
        else _sl_send(_SL_R_IGNORED, shown, "not a lab file");
    }
}

/* The entries of a folder that are not clutter, the one such entry in *only. */
static int _sl_real_entries(_sl_child *c, _sl_node *dir, _sl_node **only) {
    _sl_list(c, dir);
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
        _sl_list(c, from);
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
        _sl_send(_SL_R_SOURCE, c->archive ? "archive" : "folder", from->path);
        _sl_send(_SL_R_LAYOUT, c->want_count ? layout : "", NULL);
        if (c->want_count == 0) {
            for (_sl_node *n = from->first; n; n = n->next) {
                char shown[_SL_TEXT_MAX];
                snprintf(shown, sizeof shown, "%s%s", n->path, n->kind == _SL_DIR ? "/" : "");
                _sl_send(_SL_R_FOUND, shown, _sl_clutter(n->name, n->kind) ? "clutter" : "");
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
        _sl_send3(_SL_R_FILE, c->wants[i].target, strlen(c->wants[i].target), n->data, (size_t)n->data_len, n->path,
                  strlen(n->path));
    }
    _sl_report_left_out(root);
    if (c->entries_over) {
        char text[300];
        snprintf(text, sizeof text, "the submission has more than %d files and folders: the rest was not looked at",
                 c->d->max_entries);
        _sl_send(_SL_R_ERROR, text, NULL);
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
            _sl_send(_SL_R_STAFF, text, NULL);
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
    _sl_send(_SL_R_FENCE, said, NULL);
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

static void _sl_child_main(const sl_stage_desc *d, const _sl_labs *labs, int channel) {
    _sl_channel = channel;
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
        _sl_send(_SL_R_REFUSED, shown, why);
        _sl_send(_SL_R_SOURCE, "folder", "");
        _sl_send(_SL_R_LAYOUT, "", NULL);
    } else {
        _sl_child c = {.d = d, .labs = labs, .archive_fd = -1};
        c.wants = calloc((size_t)d->max_files + 1, sizeof *c.wants);
        _sl_child_stage(&c, fd, is_archive, shown);
    }
    _sl_send(_SL_R_END, NULL, NULL);
    _exit(0);
}

/* ---- the parent: checks what it is sent, writes the stage and the summary ---- */

typedef struct _sl_item {
    char *a, *b;
} _sl_item;

typedef struct _sl_items {
    _sl_item *items;
    int count, dropped;
} _sl_items;

/* Text for people: control characters and bytes that are not UTF-8 as \xNN. */
static char *_sl_printable(const char *s, size_t len) {
    char *out = malloc(len * 4 + 1), *o = out;
    for (size_t i = 0; i < len;) {
        unsigned char ch = (unsigned char)s[i];
        sl_text_problems p;
        size_t seq = 1;
        if (ch >= 0x80) {
            seq = 0;
            for (size_t k = 2; k <= 4 && i + k <= len && !seq; k++)
                if (sl_text_check(s + i, k, &p)) seq = k;
        }
        if (ch < 0x20 || ch == 0x7f || seq == 0) {
            o += sprintf(o, "\\x%02X", ch);
            i++;
        } else {
            memcpy(o, s + i, seq);
            o += seq;
            i += seq;
        }
    }
    *o = '\0';
    return out;
}

static void _sl_list_add(_sl_items *l, const char *a, size_t la, const char *b, size_t lb) {
    if (l->count >= _SL_LIST_MAX) {
        l->dropped++;
        return;
    }
    if (!l->items) l->items = calloc(_SL_LIST_MAX, sizeof *l->items);
    l->items[l->count].a = _sl_printable(a, la);
    l->items[l->count].b = _sl_printable(b ? b : "", b ? lb : 0);
    l->count++;
}

typedef struct _sl_result {
    char fence[_SL_TEXT_MAX], source[16], from[_SL_TEXT_MAX], layout[64];
    bool layout_said, ended;
    _sl_items taken, ignored, refused, found, errors, staff, normalised, text_problems;
    long long taken_bytes;
} _sl_result;

/* A target the stage may receive: LAB/labN.c or LAB/shaders/NAME[/NAME...] (three folders at most). */
static bool _sl_valid_target(const _sl_labs *labs, const char *target) {
    char folder[64];
    const char *slash = strchr(target, '/');
    if (!slash || (size_t)(slash - target) >= sizeof folder) return false;
    snprintf(folder, sizeof folder, "%.*s", (int)(slash - target), target);
    int lab = _sl_lab_index(labs, folder);
    if (lab < 0) return false;
    char c_file[32];
    snprintf(c_file, sizeof c_file, "lab%d.c", labs->number[lab]);
    if (strcmp(slash + 1, c_file) == 0) return true;
    if (strncmp(slash + 1, "shaders/", 8) != 0) return false;
    const char *p = slash + 9;
    int parts = 0;
    while (*p) {
        size_t len = strcspn(p, "/");
        char part[256];
        if (len == 0 || len >= sizeof part) return false;
        snprintf(part, sizeof part, "%.*s", (int)len, p);
        if (!_sl_stageable_name(part) || ++parts > _SL_SHADERS_DEPTH + 1) return false;
        p += len;
        if (*p) p++;
    }
    return parts > 0;
}

/* Writes content at target under the stage, making its folders; never through a link. */
static bool _sl_stage_write(int stage_fd, const char *target, const char *content, size_t len, char *err, size_t n) {
    int dir = dup(stage_fd);
    const char *p = target;
    for (;;) {
        size_t part_len = strcspn(p, "/");
        char part[256];
        snprintf(part, sizeof part, "%.*s", (int)part_len, p);
        if (!p[part_len]) {
            int fd = openat(dir, part, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
            close(dir);
            if (fd < 0) {
                snprintf(err, n, "cannot write %s in the stage (%s)", target, strerror(errno));
                return false;
            }
            bool ok = write(fd, content, len) == (ssize_t)len;
            fchmod(fd, 0644);
            ok = close(fd) == 0 && ok;
            if (!ok) snprintf(err, n, "cannot write %s in the stage", target);
            return ok;
        }
        if (mkdirat(dir, part, 0755) != 0 && errno != EEXIST) {
            snprintf(err, n, "cannot make the folder of %s in the stage (%s)", target, strerror(errno));
            close(dir);
            return false;
        }
        int next = openat(dir, part, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        close(dir);
        if (next < 0) {
            snprintf(err, n, "cannot open the folder of %s in the stage", target);
            return false;
        }
        dir = next;
        p += part_len + 1;
    }
}

static bool _sl_read_exact(int fd, void *buf, size_t n, double deadline) {
    char *p = buf;
    while (n) {
        struct timespec now;
        clock_gettime(CLOCK_MONOTONIC, &now);
        double left = deadline - ((double)now.tv_sec + (double)now.tv_nsec * 1e-9);
        if (left <= 0) return false;
        struct pollfd pfd = {.fd = fd, .events = POLLIN};
        int r = poll(&pfd, 1, (int)(left * 1000) + 1);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        ssize_t got = read(fd, p, n);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        p += got;
        n -= (size_t)got;
    }
    return true;
}

static void _sl_take_file(const sl_stage_desc *d, const _sl_labs *labs, int stage_fd, _sl_result *res, char *target,
                          char *content, size_t len, const char *source, size_t source_len) {
    char *shown_target = _sl_printable(target, strlen(target));
    char err[1400];
    if (!_sl_valid_target(labs, target)) {
        snprintf(err, sizeof err, "the reader sent a file for %s, which is no lab file's place: refused", shown_target);
        _sl_list_add(&res->errors, err, strlen(err), NULL, 0);
    } else if ((long long)len > d->max_file_bytes || res->taken.count >= d->max_files ||
               res->taken_bytes + (long long)len > d->max_total_bytes) {
        _sl_list_add(&res->ignored, source, source_len, "past the limits", 15);
    } else {
        for (int i = 0; i < res->taken.count; i++)
            if (strcmp(res->taken.items[i].b, shown_target) == 0) {
                free(shown_target);
                return; /* one file per place */
            }
        char *shown_source = _sl_printable(source, source_len);
        sl_text_problems problems;
        if (!sl_text_check(content, len, &problems)) {
            char text[1400];
            sl_text_problems_describe(&problems, shown_source, text, sizeof text);
            _sl_list_add(&res->text_problems, text, strlen(text), NULL, 0);
        }
        sl_text_fix fix;
        size_t new_len = problems.utf16 ? len : sl_text_normalize(content, len, &fix);
        if (!problems.utf16 && sl_text_fix_any(&fix)) {
            char what[200];
            sl_text_fix_describe(&fix, what, sizeof what);
            _sl_list_add(&res->normalised, shown_target, strlen(shown_target), what, strlen(what));
        }
        if (_sl_stage_write(stage_fd, target, content, new_len, err, sizeof err)) {
            _sl_list_add(&res->taken, source, source_len, target, strlen(target));
            res->taken_bytes += (long long)len;
        } else {
            _sl_list_add(&res->staff, err, strlen(err), NULL, 0);
        }
        free(shown_source);
    }
    free(shown_target);
}

/* Reads the child's records until its end; false if it stopped without one. */
static bool _sl_receive(const sl_stage_desc *d, const _sl_labs *labs, int stage_fd, int channel, _sl_result *res) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    double deadline = (double)now.tv_sec + (double)now.tv_nsec * 1e-9 + d->timeout;
    size_t content_max = (size_t)d->max_file_bytes;
    char *buf[3] = {malloc(_SL_TEXT_MAX + 1), malloc((content_max > _SL_TEXT_MAX ? content_max : _SL_TEXT_MAX) + 1),
                    malloc(_SL_TEXT_MAX + 1)};
    bool ok = false;
    for (long records = 0; records < 200000; records++) {
        _sl_record_header h;
        if (!_sl_read_exact(channel, &h, sizeof h, deadline)) break;
        bool file = h.kind == _SL_R_FILE;
        if (h.len[0] > _SL_TEXT_MAX || h.len[2] > _SL_TEXT_MAX || h.len[1] > (file ? content_max : _SL_TEXT_MAX)) break;
        bool complete = true;
        for (int k = 0; k < 3 && complete; k++) {
            complete = _sl_read_exact(channel, buf[k], h.len[k], deadline);
            buf[k][h.len[k]] = '\0';
        }
        if (!complete) break;
        const char *a = buf[0], *b = buf[1];
        size_t la = h.len[0], lb = h.len[1];
        switch (h.kind) {
        case _SL_R_FENCE: snprintf(res->fence, sizeof res->fence, "%s", a); break;
        case _SL_R_SOURCE: {
            snprintf(res->source, sizeof res->source, "%s", strcmp(a, "archive") == 0 ? "archive" : "folder");
            char *p = _sl_printable(b, lb);
            snprintf(res->from, sizeof res->from, "%s", p);
            free(p);
            break;
        }
        case _SL_R_LAYOUT: {
            static const char *const layouts[] = {"a labs/ folder", "the lab folders", "loose files"};
            res->layout_said = true;
            for (size_t i = 0; i < 3; i++)
                if (strcmp(a, layouts[i]) == 0) snprintf(res->layout, sizeof res->layout, "%s", layouts[i]);
            break;
        }
        case _SL_R_FOUND: _sl_list_add(&res->found, a, la, b, lb); break;
        case _SL_R_IGNORED: _sl_list_add(&res->ignored, a, la, b, lb); break;
        case _SL_R_REFUSED: _sl_list_add(&res->refused, a, la, b, lb); break;
        case _SL_R_ERROR: _sl_list_add(&res->errors, a, la, NULL, 0); break;
        case _SL_R_STAFF: _sl_list_add(&res->staff, a, la, NULL, 0); break;
        case _SL_R_FILE: _sl_take_file(d, labs, stage_fd, res, buf[0], buf[1], lb, buf[2], h.len[2]); break;
        case _SL_R_END: ok = true; break;
        default: break;
        }
        if (ok) break;
    }
    for (int k = 0; k < 3; k++) free(buf[k]);
    return ok;
}

/* "a, b, c and 4 more" from a list's first fields (with its second in brackets when with_reason). */
static void _sl_join_list(const _sl_items *l, bool with_reason, int max, bool skip_clutter, char *out, size_t n) {
    out[0] = '\0';
    int shown = 0, left = 0;
    for (int i = 0; i < l->count; i++) {
        if (skip_clutter && strcmp(l->items[i].b, "clutter") == 0) continue;
        if (shown >= max) {
            left++;
            continue;
        }
        size_t used = strlen(out);
        if (with_reason && l->items[i].b[0])
            snprintf(out + used, n - used, "%s%s (%s)", shown ? ", " : "", l->items[i].a, l->items[i].b);
        else
            snprintf(out + used, n - used, "%s%s", shown ? ", " : "", l->items[i].a);
        shown++;
    }
    left += l->dropped;
    if (left) snprintf(out + strlen(out), n - strlen(out), " and %d more", left);
}

static cJSON *_sl_json_list(const _sl_items *l, const char *first, const char *second) {
    cJSON *array = cJSON_CreateArray();
    for (int i = 0; i < l->count; i++) {
        if (!second) {
            cJSON_AddItemToArray(array, cJSON_CreateString(l->items[i].a));
            continue;
        }
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, first, l->items[i].a);
        cJSON_AddStringToObject(o, second, l->items[i].b);
        cJSON_AddItemToArray(array, o);
    }
    return array;
}

static void _sl_accepted_layouts(const _sl_labs *labs, char *out, size_t n) {
    const char *shader = NULL;
    for (int i = 0; i < labs->file_count && !shader; i++)
        if (strstr(labs->files[i], "/shaders/")) shader = strrchr(labs->files[i], '/') + 1;
    snprintf(out, n,
             "a labs/ folder (labs/%s/lab%d.c, ...), the lab folders (%s/lab%d.c, %s/shaders/%s, ...), or the lab "
             "files loose (lab%d.c, %s, ...); as a folder, a .zip or a .tar.gz, possibly inside one top folder",
             labs->folder[0], labs->number[0], labs->folder[0], labs->number[0], labs->folder[0],
             shader ? shader : "...", labs->number[0], shader ? shader : "...");
}

/* Sentences for the reports, the most important first. */
static cJSON *_sl_notes(const _sl_labs *labs, const _sl_result *res, bool no_lab_file) {
    cJSON *notes = cJSON_CreateArray();
    char text[8192], list[6000];
    if (no_lab_file) {
        char accepted[1000];
        _sl_accepted_layouts(labs, accepted, sizeof accepted);
        _sl_join_list(&res->found, false, 12, true, list, sizeof list);
        bool clutter_only = !list[0] && res->found.count > 0;
        if (!list[0] && clutter_only) {
            _sl_join_list(&res->found, false, 6, false, list, sizeof list);
            snprintf(text, sizeof text, "No lab file found: the submission holds only what macOS or Windows add (%s). "
                     "Accepted layouts: %s. Every lab is graded as the handout's stub.", list, accepted);
        } else if (!list[0] && (res->errors.count || res->refused.count)) {
            snprintf(text, sizeof text, "No lab file found: %s. Accepted layouts: %s. Every lab is graded as the "
                     "handout's stub.", res->errors.count ? res->errors.items[0].a : "nothing but what was refused (below)",
                     accepted);
        } else if (!list[0]) {
            snprintf(text, sizeof text, "No lab file found: the submission is empty. Accepted layouts: %s. Every lab "
                     "is graded as the handout's stub.", accepted);
        } else {
            snprintf(text, sizeof text, "No lab file found: found %s. Accepted layouts: %s. Every lab is graded as the "
                     "handout's stub.", list, accepted);
        }
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    for (int i = 0; i < res->errors.count; i++) cJSON_AddItemToArray(notes, cJSON_CreateString(res->errors.items[i].a));
    if (res->refused.count) {
        _sl_join_list(&res->refused, true, 12, false, list, sizeof list);
        snprintf(text, sizeof text, "Refused, never read (the handout's stub stays in its place): %s.", list);
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    for (int i = 0; i < res->text_problems.count; i++)
        cJSON_AddItemToArray(notes, cJSON_CreateString(res->text_problems.items[i].a));
    for (int i = 0; i < res->ignored.count; i++)
        if (strncmp(res->ignored.items[i].b, "more than", 9) == 0 || strncmp(res->ignored.items[i].b, "past the", 8) == 0 ||
            strncmp(res->ignored.items[i].b, "deeper", 6) == 0) {
            snprintf(text, sizeof text, "Left out: %s (%s).", res->ignored.items[i].a, res->ignored.items[i].b);
            cJSON_AddItemToArray(notes, cJSON_CreateString(text));
        }
    if (res->normalised.count) {
        _sl_join_list(&res->normalised, false, 40, false, list, sizeof list);
        snprintf(text, sizeof text, "Line ends and byte-order marks made plain before compiling (as Windows and "
                 "old macOS editors write them): %s.", list);
        cJSON_AddItemToArray(notes, cJSON_CreateString(text));
    }
    return notes;
}

static void _sl_say(const sl_stage_desc *d, const char *format, const char *text) {
    fprintf(d->log, "%s", d->log_prefix);
    fprintf(d->log, format, text);
    fputc('\n', d->log);
}

static int _sl_finish(const sl_stage_desc *d, const _sl_labs *labs, _sl_result *res) {
    bool no_lab_file = res->taken.count == 0;
    bool staff = res->staff.count > 0;
    char list[8192];
    if (res->fence[0]) _sl_say(d, "read the submission as %s", res->fence);
    if (!no_lab_file) {
        char line[9000];
        _sl_join_list(&res->taken, false, 400, false, list, sizeof list);
        /* the places in the stage, as before: "took lab1_depth_fbo/lab1.c ..." */
        list[0] = '\0';
        for (int i = 0; i < res->taken.count; i++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", i ? " " : "", res->taken.items[i].b);
        snprintf(line, sizeof line, "layout: %s%s%s%s; took %s", res->layout, res->from[0] ? " (in " : "", res->from,
                 res->from[0] ? "/)" : "", list);
        _sl_say(d, "%s", line);
    }
    if (res->ignored.count) {
        _sl_join_list(&res->ignored, true, 40, false, list, sizeof list);
        _sl_say(d, "ignored: %s", list);
    }
    if (res->refused.count) {
        _sl_join_list(&res->refused, true, 40, false, list, sizeof list);
        _sl_say(d, "refused (never read): %s", list);
    }
    if (res->normalised.count) {
        _sl_join_list(&res->normalised, true, 40, false, list, sizeof list);
        _sl_say(d, "normalised: %s", list);
    }
    for (int i = 0; i < res->text_problems.count; i++) _sl_say(d, "%s", res->text_problems.items[i].a);
    for (int i = 0; i < res->errors.count; i++) _sl_say(d, "%s", res->errors.items[i].a);
    for (int i = 0; i < res->staff.count; i++) _sl_say(d, "PROBLEM (not the submission's fault) %s", res->staff.items[i].a);
    cJSON *notes = _sl_notes(labs, res, no_lab_file);
    if (no_lab_file) _sl_say(d, "%s", cJSON_GetArrayItem(notes, 0)->valuestring);

    int status = staff ? SL_STAGE_PROBLEM : no_lab_file ? SL_STAGE_NO_LAB_FILE : SL_STAGE_TAKEN;
    if (d->summary) {
        cJSON *root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "submission", d->submission);
        cJSON_AddStringToObject(root, "source", res->source[0] ? res->source : "folder");
        cJSON_AddStringToObject(root, "looked_into", res->from);
        if (no_lab_file) cJSON_AddNullToObject(root, "layout");
        else cJSON_AddStringToObject(root, "layout", res->layout);
        cJSON_AddBoolToObject(root, "lab_files_found", !no_lab_file);
        cJSON_AddStringToObject(root, "read_as", res->fence);
        cJSON_AddItemToObject(root, "taken", _sl_json_list(&res->taken, "path", "as"));
        cJSON_AddItemToObject(root, "ignored", _sl_json_list(&res->ignored, "path", "reason"));
        cJSON_AddItemToObject(root, "refused", _sl_json_list(&res->refused, "path", "reason"));
        cJSON_AddItemToObject(root, "normalised", _sl_json_list(&res->normalised, "file", "what"));
        cJSON_AddItemToObject(root, "text_errors", _sl_json_list(&res->text_problems, NULL, NULL));
        cJSON_AddItemToObject(root, "errors", _sl_json_list(&res->errors, NULL, NULL));
        cJSON_AddItemToObject(root, "staff_problems", _sl_json_list(&res->staff, NULL, NULL));
        if (no_lab_file) {
            cJSON *found = cJSON_AddArrayToObject(root, "found");
            for (int i = 0; i < res->found.count; i++)
                cJSON_AddItemToArray(found, cJSON_CreateString(res->found.items[i].a));
            char accepted[1000];
            _sl_accepted_layouts(labs, accepted, sizeof accepted);
            cJSON_AddStringToObject(root, "accepted_layouts", accepted);
        }
        cJSON_AddItemToObject(root, "notes", notes);
        notes = NULL;
        char *text = cJSON_Print(root);
        cJSON_Delete(root);
        sl_atomic_file f;
        char err[1500];
        bool ok = text && sl_atomic_open(&f, d->summary, err, sizeof err);
        if (ok) {
            fputs(text, f.f);
            fputc('\n', f.f);
            ok = sl_atomic_commit(&f, err, sizeof err);
        }
        free(text);
        if (!ok) {
            _sl_say(d, "PROBLEM %s", err);
            status = SL_STAGE_PROBLEM;
        }
    }
    cJSON_Delete(notes);
    return status;
}

int sl_stage_run(const sl_stage_desc *given) {
    sl_stage_desc d = *given;
    if (!d.max_files) d.max_files = 256;
    if (!d.max_file_bytes) d.max_file_bytes = 1 << 20;
    if (!d.max_total_bytes) d.max_total_bytes = 16 << 20;
    if (!d.max_entries) d.max_entries = 20000;
    if (!d.max_depth) d.max_depth = 16;
    if (!d.max_unpacked_bytes) d.max_unpacked_bytes = 512ull << 20;
    if (d.timeout <= 0) d.timeout = 120;
    if (!d.log) d.log = stdout;
    if (!d.log_prefix) d.log_prefix = "shadowlab-stage: ";
    int stage_fd = open(d.stage, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (stage_fd < 0) {
        fprintf(stderr, "%sthe stage %s cannot be opened (%s)\n", d.log_prefix, d.stage, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    _sl_labs labs = {0};
    char err[600];
    if (!_sl_read_labs(stage_fd, &labs, err, sizeof err)) {
        fprintf(stderr, "%s%s: %s\n", d.log_prefix, d.stage, err);
        close(stage_fd);
        return SL_STAGE_PROBLEM;
    }
    int channel[2];
    if (pipe2(channel, O_CLOEXEC) != 0) {
        fprintf(stderr, "%scannot make a pipe (%s)\n", d.log_prefix, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    fflush(NULL);
    pid_t child = fork();
    if (child < 0) {
        fprintf(stderr, "%scannot start the process that reads the submission (%s)\n", d.log_prefix, strerror(errno));
        return SL_STAGE_PROBLEM;
    }
    if (child == 0) {
        close(channel[0]);
        close(stage_fd);
        signal(SIGPIPE, SIG_DFL);
        _sl_child_main(&d, &labs, channel[1]);
        _exit(SL_STAGE_PROBLEM);
    }
    close(channel[1]);
    _sl_result res = {0};
    bool ended = _sl_receive(&d, &labs, stage_fd, channel[0], &res);
    close(channel[0]);
    if (!ended) kill(child, SIGKILL);
    int wstatus = 0;
    while (waitpid(child, &wstatus, 0) < 0 && errno == EINTR) {
    }
    close(stage_fd);
    if (!ended) {
        char text[300];
        if (WIFSIGNALED(wstatus))
            snprintf(text, sizeof text, "the submission could not be read to its end: its reader was stopped (signal "
                     "%d%s)", WTERMSIG(wstatus), WTERMSIG(wstatus) == SIGXCPU || WTERMSIG(wstatus) == SIGKILL ?
                     ": too slow, a damaged or huge archive?" : "");
        else
            snprintf(text, sizeof text, "the submission could not be read to its end (its reader exited with %d)",
                     WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
        if (!res.fence[0] || (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == SL_STAGE_PROBLEM))
            _sl_list_add(&res.staff, text, strlen(text), NULL, 0);
        else
            _sl_list_add(&res.errors, text, strlen(text), NULL, 0);
    }
    return _sl_finish(&d, &labs, &res);
}
