#define _GNU_SOURCE
#include "sl_stage_tree.h"

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
#include "sl_crc32.h"
#include "sl_stage_channel.h"
#include "sl_text.h"
#include "sl_zip_records.h"

/* ---- the child: the submission as a tree, listed as it is needed ---- */

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

_sl_node *_sl_new_node(_sl_node *parent, const char *name, _sl_kind kind) {
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

_sl_node *_sl_child_named(_sl_node *parent, const char *name) {
    for (_sl_node *c = parent->first; c; c = c->next)
        if (strcmp(c->name, name) == 0) return c;
    return NULL;
}

int _sl_open_beneath(int dir_fd, const char *name, int flags) {
#ifdef SYS_openat2
    struct open_how how = {.flags = (uint64_t)(flags | O_NOFOLLOW | O_CLOEXEC),
                           .resolve = RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS};
    long fd = syscall(SYS_openat2, dir_fd, name, &how, sizeof how);
    if (fd >= 0 || (errno != ENOSYS && errno != EPERM && errno != E2BIG && errno != EINVAL)) return (int)fd;
#endif
    return openat(dir_fd, name, flags | O_NOFOLLOW | O_CLOEXEC);
}

const char *_sl_clutter(const char *name, _sl_kind kind) {
    if (kind == _SL_DIR && strcmp(name, "__MACOSX") == 0) return "macOS archive metadata";
    if (strncmp(name, "._", 2) == 0) return "macOS metadata (AppleDouble)";
    if (strcmp(name, ".DS_Store") == 0) return "macOS folder settings";
    if (strcasecmp(name, "Thumbs.db") == 0 || strcasecmp(name, "desktop.ini") == 0) return "Windows folder settings";
    return NULL;
}

void _sl_staff_problem(_sl_child *c, const char *path, const char *what) {
    char text[_SL_TEXT_MAX];
    snprintf(text, sizeof text, "%s: %s", path, what);
    _sl_send_record(_SL_R_STAFF, text, NULL);
    (void)c;
}

int _sl_dir_fd(_sl_child *c, _sl_node *n) {
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

void _sl_list_folder(_sl_child *c, _sl_node *n) {
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

const char *_sl_refusal(_sl_node *n) {
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
            if (!at->reported) _sl_send_record(_SL_R_IGNORED, text, why);
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
                _sl_send_record(_SL_R_IGNORED, at->path[0] ? text : part, "a second entry of the same name in the archive");
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

_sl_node *_sl_archive_tree(_sl_child *c, const char *label) {
    _sl_node *root = _sl_new_node(NULL, label, _SL_DIR);
    root->listed = true;
    char err[1600];
    sl_archive *a = sl_archive_open(c->archive_fd, c->archive_name, err, sizeof err);
    if (!a) {
        _sl_send_record(_SL_R_ERROR, err, NULL);
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
            _sl_send_record(_SL_R_ERROR, text, NULL);
            break;
        }
        char shown[SL_ARCHIVE_PATH_MAX + 8];
        snprintf(shown, sizeof shown, "%s%s%s", label, label[0] ? "/" : "", e->path);
        if (e->unsafe) {
            _sl_send_record(_SL_R_REFUSED, shown, e->unsafe);
            continue;
        }
        if (!e->path[0]) continue;
        _sl_archive_insert(c, root, e);
    }
    if (r < 0) _sl_send_record(_SL_R_ERROR, sl_archive_error(a), NULL);
    free(e);
    sl_archive_close(a);
    return root;
}

void _sl_archive_read_wanted(_sl_child *c) {
    char err[1600];
    sl_archive *a = sl_archive_open(c->archive_fd, c->archive_name, err, sizeof err);
    if (!a) return; /* said in pass one */
    sl_archive_entry *e = malloc(sizeof *e);
    char *buf = malloc((size_t)c->d->max_file_bytes);
    int left = 0;
    for (int i = 0; i < c->want_count; i++) left += c->wants[i].node->data == NULL;
    sl_zip_records *records = NULL;
    bool first = true;
    int r;
    while (left > 0 && (r = sl_archive_next(a, e)) > 0) {
        if (first && sl_archive_is_zip(a)) {
            /* the zip's own records, to check each file read against */
            records = sl_zip_records_read(c->archive_fd, c->d->max_entries, err, sizeof err);
            if (!records) {
                char text[1800];
                snprintf(text, sizeof text, "%s: a damaged zip: %s", c->archive_name, err);
                _sl_send_record(_SL_R_ERROR, text, NULL);
                for (int i = 0; i < c->want_count; i++)
                    if (!c->wants[i].node->data) c->wants[i].node->why_ignored = "in a damaged zip (see the error)";
                break;
            }
        }
        first = false;
        if (e->unsafe || e->kind != SL_ARCHIVE_FILE) continue;
        for (int i = 0; i < c->want_count; i++) {
            _sl_node *n = c->wants[i].node;
            if (n->data || n->why_ignored || strcmp(n->archive_path, e->path) != 0) continue;
            bool more = false;
            long long got = sl_archive_read(a, buf, (size_t)c->d->max_file_bytes, &more);
            left--;
            char what[800];
            if (got < 0) {
                _sl_send_record(_SL_R_ERROR, sl_archive_error(a), NULL);
                n->why_ignored = "its data cannot be read (a corrupt archive)";
            } else if (more) {
                snprintf(n->why_buffer, sizeof n->why_buffer, "more than %lld KiB", c->d->max_file_bytes >> 10);
                n->why_ignored = n->why_buffer;
            } else if (!sl_archive_matches_records(records, e->path, records ? -1 : e->size, got,
                                                   sl_crc32(0, buf, (size_t)got), what, sizeof what)) {
                char text[_SL_TEXT_MAX];
                snprintf(text, sizeof text, "%s: %s was read as %s", c->archive_name, n->path, what);
                _sl_send_record(_SL_R_MISMATCH, text, NULL);
                n->why_ignored = "not staged: it was read wrong (a fault of shadowlab-stage, said above)";
            } else {
                n->data = malloc((size_t)got + 1);
                memcpy(n->data, buf, (size_t)got);
                n->data_len = got;
            }
            break; /* this entry's data is read */
        }
    }
    sl_zip_records_free(records);
    free(buf);
    free(e);
    sl_archive_close(a);
}

void _sl_folder_read(_sl_child *c, _sl_node *n) {
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
