#define _GNU_SOURCE
#include "sl_archive.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <archive.h>
#include <archive_entry.h>

struct sl_archive {
    struct archive *a;
    char name[256];
    char last_entry[SL_ARCHIVE_PATH_MAX]; /* for messages: where a corrupt archive stopped */
    char error[1600];
    bool at_end;
    /* sl_archive_read looks one byte past its cap to say whether the data
     * goes on: that byte is the first of the next read of the same entry. */
    unsigned char ahead;
    bool has_ahead;
};

const char *sl_archive_kind_name(sl_archive_kind kind) {
    switch (kind) {
    case SL_ARCHIVE_FILE: return "file";
    case SL_ARCHIVE_FOLDER: return "folder";
    case SL_ARCHIVE_SYMLINK: return "symbolic link";
    case SL_ARCHIVE_HARDLINK: return "hard link";
    case SL_ARCHIVE_DEVICE: return "device";
    case SL_ARCHIVE_FIFO: return "FIFO";
    case SL_ARCHIVE_SOCKET: return "socket";
    default: return "other";
    }
}

bool sl_archive_name_is_archive(const char *name) {
    static const char *const endings[] = {".zip", ".tar", ".tgz", ".tar.gz", ".tbz2", ".tar.bz2", ".txz", ".tar.xz",
                                          ".tar.zst"};
    size_t len = strlen(name);
    for (size_t i = 0; i < sizeof endings / sizeof endings[0]; i++) {
        size_t n = strlen(endings[i]);
        if (len > n && strcasecmp(name + len - n, endings[i]) == 0) return true;
    }
    return false;
}

bool sl_archive_clean_path(const char *raw, char *out, size_t n, const char **why) {
    *why = NULL;
    if (n) out[0] = '\0';
    size_t len = strlen(raw);
    if (raw[0] == '/' || raw[0] == '\\') {
        *why = "an absolute path (it would leave the submission)";
        return false;
    }
    if (len >= 2 && raw[1] == ':' && ((raw[0] >= 'A' && raw[0] <= 'Z') || (raw[0] >= 'a' && raw[0] <= 'z'))) {
        *why = "a path with a drive letter (it would leave the submission)";
        return false;
    }
    size_t used = 0;
    const char *p = raw;
    while (*p) {
        size_t part = strcspn(p, "/\\");
        if (part == 2 && p[0] == '.' && p[1] == '.') {
            *why = "a '..' in the path (it would leave the submission)";
            return false;
        }
        bool skip = part == 0 || (part == 1 && p[0] == '.');
        for (size_t i = 0; i < part && !skip; i++)
            if ((unsigned char)p[i] < 0x20 || p[i] == 0x7f) {
                *why = "control characters in the name";
                return false;
            }
        if (!skip) {
            if (used + part + 2 > n || part > 255) {
                *why = "a path or name too long";
                return false;
            }
            if (used) out[used++] = '/';
            memcpy(out + used, p, part);
            used += part;
            out[used] = '\0';
        }
        p += part;
        if (*p) p++;
    }
    return true;
}

sl_archive *sl_archive_open(int fd, const char *name, char *err, size_t err_size) {
    sl_archive *a = calloc(1, sizeof *a);
    if (!a) {
        snprintf(err, err_size, "%s: out of memory", name);
        return NULL;
    }
    snprintf(a->name, sizeof a->name, "%s", name);
    if (lseek(fd, 0, SEEK_SET) != 0) {
        snprintf(err, err_size, "%s: cannot read it from its start (%s)", name, strerror(errno));
        free(a);
        return NULL;
    }
    a->a = archive_read_new();
    /* zip and tar only, and the compressions libarchive does in-process: no
     * format or filter that would start an external program. */
    archive_read_support_format_zip(a->a);
    archive_read_support_format_tar(a->a);
    archive_read_support_format_gnutar(a->a);
    archive_read_support_filter_gzip(a->a);
    archive_read_support_filter_bzip2(a->a);
    archive_read_support_filter_xz(a->a);
    archive_read_support_filter_zstd(a->a);
    if (archive_read_open_fd(a->a, fd, 65536) != ARCHIVE_OK) {
        snprintf(err, err_size, "%s: not an archive this grader reads (.zip, .tar, .tar.gz, ...), or a corrupt one: %s",
                 name, archive_error_string(a->a) ? archive_error_string(a->a) : "unknown format");
        archive_read_free(a->a);
        free(a);
        return NULL;
    }
    return a;
}

static void _sl_cut_copy(char *dst, size_t n, const char *src) {
    snprintf(dst, n, "%s", src ? src : "");
}

int sl_archive_next(sl_archive *a, sl_archive_entry *e) {
    if (a->at_end) return 0;
    a->has_ahead = false; /* a byte looked at belongs to the entry left */
    struct archive_entry *ae;
    int r = archive_read_next_header(a->a, &ae);
    if (r == ARCHIVE_EOF) {
        a->at_end = true;
        return 0;
    }
    if (r < ARCHIVE_WARN) {
        const char *why = archive_error_string(a->a);
        if (a->last_entry[0])
            snprintf(a->error, sizeof a->error, "%s: corrupt or cut short after the entry %s: %s", a->name,
                     a->last_entry, why ? why : "unreadable");
        else
            snprintf(a->error, sizeof a->error, "%s: corrupt or cut short (no entry could be read): %s", a->name,
                     why ? why : "unreadable");
        a->at_end = true;
        return -1;
    }
    memset(e, 0, sizeof *e);
    const char *raw = archive_entry_pathname_utf8(ae);
    if (!raw) raw = archive_entry_pathname(ae);
    if (!raw) raw = "";
    _sl_cut_copy(e->raw_path, sizeof e->raw_path, raw);
    if (strlen(raw) >= sizeof e->raw_path) e->unsafe = "a path too long";
    else if (!sl_archive_clean_path(raw, e->path, sizeof e->path, &e->unsafe)) {
        /* e->unsafe says why */
    }
    if (e->unsafe) _sl_cut_copy(e->path, sizeof e->path, e->raw_path);
    _sl_cut_copy(a->last_entry, sizeof a->last_entry, e->raw_path);
    e->size = archive_entry_size_is_set(ae) ? (long long)archive_entry_size(ae) : -1;
    const char *hardlink = archive_entry_hardlink(ae);
    if (hardlink) {
        e->kind = SL_ARCHIVE_HARDLINK;
        _sl_cut_copy(e->link_target, sizeof e->link_target, hardlink);
        return 1;
    }
    switch (archive_entry_filetype(ae)) {
    case AE_IFREG: e->kind = SL_ARCHIVE_FILE; break;
    case AE_IFDIR: e->kind = SL_ARCHIVE_FOLDER; break;
    case AE_IFLNK:
        e->kind = SL_ARCHIVE_SYMLINK;
        _sl_cut_copy(e->link_target, sizeof e->link_target, archive_entry_symlink(ae));
        break;
    case AE_IFCHR:
    case AE_IFBLK: e->kind = SL_ARCHIVE_DEVICE; break;
    case AE_IFIFO: e->kind = SL_ARCHIVE_FIFO; break;
    case AE_IFSOCK: e->kind = SL_ARCHIVE_SOCKET; break;
    default: e->kind = SL_ARCHIVE_OTHER;
    }
    return 1;
}

long long sl_archive_read(sl_archive *a, void *buf, size_t cap, bool *more) {
    size_t got = 0;
    *more = false;
    if (a->has_ahead && cap > 0) {
        ((unsigned char *)buf)[got++] = a->ahead;
        a->has_ahead = false;
    }
    while (got < cap) {
        la_ssize_t n = archive_read_data(a->a, (char *)buf + got, cap - got);
        if (n < 0) goto failed;
        if (n == 0) return (long long)got;
        got += (size_t)n;
    }
    if (a->has_ahead) {
        *more = true; /* cap 0, a byte already looked at */
        return 0;
    }
    la_ssize_t n = archive_read_data(a->a, &a->ahead, 1);
    if (n < 0) goto failed;
    a->has_ahead = *more = n > 0;
    return (long long)got;
failed:;
    const char *why = archive_error_string(a->a);
    snprintf(a->error, sizeof a->error, "%s: the data of %s cannot be read (corrupt?): %s", a->name, a->last_entry,
             why ? why : "unreadable");
    return -1;
}

unsigned long long sl_archive_unpacked_bytes(sl_archive *a) {
    la_int64_t n = archive_filter_bytes(a->a, 0);
    return n > 0 ? (unsigned long long)n : 0;
}

const char *sl_archive_error(const sl_archive *a) { return a->error; }

void sl_archive_close(sl_archive *a) {
    if (!a) return;
    archive_read_free(a->a);
    free(a);
}

/* ---- extraction ---- */

/* Opens (making it if needed) the folder `path` under dir_fd, one part at a
 * time and never through a link. -1 if a part is not a folder. */
static int _sl_open_folders(int dir_fd, const char *path, bool make) {
    int fd = dup(dir_fd);
    char part[256];
    const char *p = path;
    while (fd >= 0 && *p) {
        size_t len = strcspn(p, "/");
        if (len == 0 || len >= sizeof part) {
            close(fd);
            return -1;
        }
        memcpy(part, p, len);
        part[len] = '\0';
        if (make && mkdirat(fd, part, 0755) != 0 && errno != EEXIST) {
            close(fd);
            return -1;
        }
        int next = openat(fd, part, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        close(fd);
        fd = next;
        p += len;
        if (*p) p++;
    }
    return fd;
}

static void _sl_refuse(sl_archive_refused_fn refused, void *context, const char *path, const char *why) {
    if (refused) refused(context, path, why);
}

bool sl_archive_extract(int fd, const char *name, int dir_fd, const sl_archive_limits *limits,
                        sl_archive_refused_fn refused, void *context, char *err, size_t err_size) {
    sl_archive_limits l = limits ? *limits : (sl_archive_limits){0};
    if (l.max_file_bytes <= 0) l.max_file_bytes = 64ll << 20;
    if (l.max_total_bytes <= 0) l.max_total_bytes = 1ll << 30;
    if (l.max_unpacked_bytes == 0) l.max_unpacked_bytes = 2ull << 30;
    if (l.max_entries <= 0) l.max_entries = 100000;
    if (err_size) err[0] = '\0';
    sl_archive *a = sl_archive_open(fd, name, err, err_size);
    if (!a) return false;
    size_t chunk = 1 << 16;
    char *buf = malloc(chunk);
    bool ok = buf != NULL;
    if (!ok) snprintf(err, err_size, "%s: out of memory", name);
    long long total = 0;
    int entries = 0, r = 0;
    sl_archive_entry e;
    while (ok && (r = sl_archive_next(a, &e)) > 0) {
        char why[400];
        if (++entries > l.max_entries) {
            snprintf(err, err_size, "%s: more than %d entries: the rest was not extracted", name, l.max_entries);
            ok = false;
            break;
        }
        if (sl_archive_unpacked_bytes(a) > l.max_unpacked_bytes) {
            snprintf(err, err_size, "%s: unpacks to more than %llu MiB: the rest was not extracted", name,
                     l.max_unpacked_bytes >> 20);
            ok = false;
            break;
        }
        if (e.unsafe) {
            _sl_refuse(refused, context, e.path, e.unsafe);
            continue;
        }
        if (!e.path[0]) continue; /* the archive's own folder */
        if (e.kind != SL_ARCHIVE_FILE && e.kind != SL_ARCHIVE_FOLDER) {
            if (e.kind == SL_ARCHIVE_SYMLINK || e.kind == SL_ARCHIVE_HARDLINK)
                snprintf(why, sizeof why, "a %s (to %s): links are never followed", sl_archive_kind_name(e.kind),
                         e.link_target);
            else
                snprintf(why, sizeof why, "a %s, not a file", sl_archive_kind_name(e.kind));
            _sl_refuse(refused, context, e.path, why);
            continue;
        }
        if (e.kind == SL_ARCHIVE_FOLDER) {
            int d = _sl_open_folders(dir_fd, e.path, true);
            if (d < 0) _sl_refuse(refused, context, e.path, "a folder where the archive has a file of that name");
            else close(d);
            continue;
        }
        const char *slash = strrchr(e.path, '/');
        char parent[SL_ARCHIVE_PATH_MAX] = "";
        if (slash) snprintf(parent, sizeof parent, "%.*s", (int)(slash - e.path), e.path);
        int d = _sl_open_folders(dir_fd, parent, true);
        if (d < 0) {
            _sl_refuse(refused, context, e.path, "its folder is a file of the archive");
            continue;
        }
        const char *base = slash ? slash + 1 : e.path;
        int out = openat(d, base, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (out < 0) {
            _sl_refuse(refused, context, e.path,
                       errno == EEXIST ? "a second entry of the same name" : "cannot be written here");
            close(d);
            continue;
        }
        long long written = 0;
        bool more = true, failed = false, too_big = false;
        while (more) {
            long long want = l.max_file_bytes - written + 1;
            long long n = sl_archive_read(a, buf, (size_t)(want < (long long)chunk ? want : (long long)chunk), &more);
            if (n < 0) {
                failed = true;
                snprintf(err, err_size, "%s", sl_archive_error(a));
                break;
            }
            if (n == 0 && !more) break;
            if (written + n > l.max_file_bytes || total + written + n > l.max_total_bytes) {
                too_big = true;
                break;
            }
            if (write(out, buf, (size_t)n) != n) {
                failed = true;
                snprintf(err, err_size, "%s: cannot write %s (%s)", name, e.path, strerror(errno));
                break;
            }
            written += n;
        }
        close(out);
        if (failed || too_big) unlinkat(d, base, 0);
        close(d);
        if (too_big) {
            snprintf(why, sizeof why, "more than %lld MiB, or past the %lld MiB of the whole extraction",
                     l.max_file_bytes >> 20, l.max_total_bytes >> 20);
            _sl_refuse(refused, context, e.path, why);
            continue;
        }
        if (failed) {
            ok = false;
            break;
        }
        total += written;
    }
    if (ok && r < 0) {
        snprintf(err, err_size, "%s", sl_archive_error(a));
        ok = false;
    }
    free(buf);
    sl_archive_close(a);
    return ok;
}
