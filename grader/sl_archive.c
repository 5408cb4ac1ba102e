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

#include "sl_crc32.h"
#include "sl_zip_records.h"

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
    long long given; /* bytes of the entry's data given so far */
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
    a->given = 0;
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

#ifdef SL_ARCHIVE_FAULTS
/* Test builds only (tests/CMakeLists.txt): SL_ARCHIVE_FAULT=drop loses byte
 * 65536 of each entry's data, as a faulty read loop did; =flip changes a bit
 * of byte 1000. The shipped programs have no such code: the tests use it to
 * show that a file read or extracted wrong is caught. */
static long long _sl_fault(unsigned char *buf, long long from, long long got) {
    const char *fault = getenv("SL_ARCHIVE_FAULT");
    long long at = fault && strcmp(fault, "drop") == 0 ? 65536 : fault && strcmp(fault, "flip") == 0 ? 1000 : -1;
    if (at < from || at >= from + got) return got;
    if (at == 1000) {
        buf[at - from] ^= 1;
        return got;
    }
    memmove(buf + (at - from), buf + (at - from) + 1, (size_t)(from + got - at - 1));
    return got - 1;
}
#endif

long long sl_archive_read(sl_archive *a, void *buf, size_t cap, bool *more) {
    size_t got = 0;
    bool ended = false;
    if (a->has_ahead && cap > 0) {
        ((unsigned char *)buf)[got++] = a->ahead;
        a->has_ahead = false;
    }
    while (got < cap && !ended) {
        la_ssize_t n = archive_read_data(a->a, (char *)buf + got, cap - got);
        if (n < 0) goto failed;
        ended = n == 0;
        got += (size_t)n;
    }
    if (!ended && !a->has_ahead) {
        la_ssize_t n = archive_read_data(a->a, &a->ahead, 1);
        if (n < 0) goto failed;
        a->has_ahead = n > 0;
    }
    *more = a->has_ahead;
    long long from = a->given;
    a->given += (long long)got;
#ifdef SL_ARCHIVE_FAULTS
    got = (size_t)_sl_fault(buf, from, (long long)got);
#endif
    (void)from;
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

static void _sl_note(sl_archive_note_fn note, void *context, const char *path, const char *why) {
    if (note) note(context, path, why);
}

bool sl_archive_is_zip(const sl_archive *a) {
    return (archive_format(a->a) & ARCHIVE_FORMAT_BASE_MASK) == ARCHIVE_FORMAT_ZIP;
}

bool sl_archive_matches_records(const sl_zip_records *records, const char *path, long long header_size,
                                long long size, uint32_t crc, char *what, size_t n) {
    if (records) {
        int count;
        const sl_zip_record *const *r = sl_zip_records_find(records, path, &count);
        for (int i = 0; i < count; i++)
            if (r[i]->size == (unsigned long long)size && r[i]->crc32 == crc) return true;
        if (count == 0)
            snprintf(what, n, "%lld bytes, CRC-32 %08x, and the zip's central directory has no record of it", size,
                     (unsigned)crc);
        else
            snprintf(what, n, "%lld bytes, CRC-32 %08x, where the zip's central directory records %llu bytes, CRC-32 %08x",
                     size, (unsigned)crc, r[0]->size, (unsigned)r[0]->crc32);
        return false;
    }
    if (header_size >= 0 && header_size != size) {
        snprintf(what, n, "%lld bytes (CRC-32 %08x), where the archive's header records %lld bytes", size,
                 (unsigned)crc, header_size);
        return false;
    }
    return true;
}

/* What was extracted, checked against the archive's records once it is all out. */
typedef struct _sl_extracted {
    char **seen; /* every safe entry path libarchive gave */
    int seen_count, seen_cap;
} _sl_extracted;

static void _sl_seen(_sl_extracted *x, const char *path) {
    if (x->seen_count == x->seen_cap) {
        int cap = x->seen_cap ? 2 * x->seen_cap : 64;
        char **more = realloc(x->seen, (size_t)cap * sizeof *more);
        if (!more) return; /* then a record may be said unread: never silently less checked */
        x->seen = more;
        x->seen_cap = cap;
    }
    char *copy = strdup(path);
    if (copy) x->seen[x->seen_count++] = copy;
}

static int _sl_path_order(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static bool _sl_was_seen(const _sl_extracted *x, const char *path) {
    return path && x->seen_count &&
           bsearch(&path, x->seen, (size_t)x->seen_count, sizeof *x->seen, _sl_path_order) != NULL;
}


/* The file as it is on disk now: its size and CRC-32, read back. */
static bool _sl_read_back(int out, char *buf, size_t chunk, long long *size, uint32_t *crc) {
    *size = 0;
    *crc = 0;
    for (;;) {
        ssize_t r = pread(out, buf, chunk, (off_t)*size);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return false;
        if (r == 0) return true;
        *crc = sl_crc32(*crc, buf, (size_t)r);
        *size += r;
    }
}

sl_archive_outcome sl_archive_extract(int fd, const char *name, int dir_fd, const sl_archive_limits *limits,
                                      sl_archive_note_fn refused, sl_archive_note_fn mismatched, void *context,
                                      char *err, size_t err_size) {
    sl_archive_limits l = limits ? *limits : (sl_archive_limits){0};
    if (l.max_file_bytes <= 0) l.max_file_bytes = 64ll << 20;
    if (l.max_total_bytes <= 0) l.max_total_bytes = 1ll << 30;
    if (l.max_unpacked_bytes == 0) l.max_unpacked_bytes = 2ull << 30;
    if (l.max_entries <= 0) l.max_entries = 100000;
    if (err_size) err[0] = '\0';
    sl_archive *a = sl_archive_open(fd, name, err, err_size);
    if (!a) return SL_ARCHIVE_DAMAGED;
    size_t chunk = 1 << 16;
    char *buf = malloc(chunk);
    sl_archive_outcome outcome = SL_ARCHIVE_EXTRACTED;
    if (!buf) {
        snprintf(err, err_size, "%s: out of memory", name);
        outcome = SL_ARCHIVE_NOT_WRITTEN;
    }
    long long total = 0;
    int entries = 0, r = 0, mismatches = 0;
    _sl_extracted x = {0};
    sl_zip_records *records = NULL;
    bool zip = false;
    char first_mismatch[1200] = "";
    sl_archive_entry e;
    while (outcome == SL_ARCHIVE_EXTRACTED && (r = sl_archive_next(a, &e)) > 0) {
        char why[1200];
        if (++entries > l.max_entries) {
            snprintf(err, err_size, "%s: more than %d entries: the rest was not extracted", name, l.max_entries);
            outcome = SL_ARCHIVE_DAMAGED;
            break;
        }
        if (entries == 1 && (zip = sl_archive_is_zip(a))) {
            /* the zip's own records, read by code of ours, before anything is written */
            records = sl_zip_records_read(fd, l.max_entries, why, sizeof why);
            if (!records) {
                snprintf(err, err_size, "%s: a damaged zip: %s", name, why);
                outcome = SL_ARCHIVE_DAMAGED;
                break;
            }
        }
        if (sl_archive_unpacked_bytes(a) > l.max_unpacked_bytes) {
            snprintf(err, err_size, "%s: unpacks to more than %llu MiB: the rest was not extracted", name,
                     l.max_unpacked_bytes >> 20);
            outcome = SL_ARCHIVE_DAMAGED;
            break;
        }
        if (e.unsafe) {
            _sl_note(refused, context, e.path, e.unsafe);
            continue;
        }
        if (!e.path[0]) continue; /* the archive's own folder */
        _sl_seen(&x, e.path);
        if (e.kind != SL_ARCHIVE_FILE && e.kind != SL_ARCHIVE_FOLDER) {
            if (e.kind == SL_ARCHIVE_SYMLINK || e.kind == SL_ARCHIVE_HARDLINK)
                snprintf(why, sizeof why, "a %s (to %s): links are never followed", sl_archive_kind_name(e.kind),
                         e.link_target);
            else
                snprintf(why, sizeof why, "a %s, not a file", sl_archive_kind_name(e.kind));
            _sl_note(refused, context, e.path, why);
            continue;
        }
        if (e.kind == SL_ARCHIVE_FOLDER) {
            int d = _sl_open_folders(dir_fd, e.path, true);
            if (d < 0) _sl_note(refused, context, e.path, "a folder where the archive has a file of that name");
            else close(d);
            continue;
        }
        const char *slash = strrchr(e.path, '/');
        char parent[SL_ARCHIVE_PATH_MAX] = "";
        if (slash) snprintf(parent, sizeof parent, "%.*s", (int)(slash - e.path), e.path);
        int d = _sl_open_folders(dir_fd, parent, true);
        if (d < 0) {
            _sl_note(refused, context, e.path, "its folder is a file of the archive");
            continue;
        }
        const char *base = slash ? slash + 1 : e.path;
        int out = openat(d, base, O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (out < 0) {
            _sl_note(refused, context, e.path,
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
                outcome = SL_ARCHIVE_DAMAGED;
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
                outcome = SL_ARCHIVE_NOT_WRITTEN;
                snprintf(err, err_size, "%s: cannot write %s (%s)", name, e.path, errno ? strerror(errno) : "disk full?");
                break;
            }
            written += n;
        }
        long long size = 0;
        uint32_t crc = 0;
        if (!failed && !too_big && !_sl_read_back(out, buf, chunk, &size, &crc)) {
            failed = true;
            outcome = SL_ARCHIVE_NOT_WRITTEN;
            snprintf(err, err_size, "%s: cannot read back %s to check it (%s)", name, e.path, strerror(errno));
        }
        close(out);
        if (failed || too_big) unlinkat(d, base, 0);
        close(d);
        if (too_big) {
            snprintf(why, sizeof why, "more than %lld MiB, or past the %lld MiB of the whole extraction",
                     l.max_file_bytes >> 20, l.max_total_bytes >> 20);
            _sl_note(refused, context, e.path, why);
            continue;
        }
        if (failed) break;
        total += written;
        char what[800];
        if (!sl_archive_matches_records(records, e.path, zip ? -1 : e.size, size, crc, what, sizeof what)) {
            snprintf(why, sizeof why, "extracted as %s", what);
            _sl_note(mismatched, context, e.path, why);
            if (!mismatches++) snprintf(first_mismatch, sizeof first_mismatch, "%s %s", e.path, why);
        }
    }
    if (outcome == SL_ARCHIVE_EXTRACTED && r < 0) {
        snprintf(err, err_size, "%s", sl_archive_error(a));
        outcome = SL_ARCHIVE_DAMAGED;
    }
    if (outcome == SL_ARCHIVE_EXTRACTED && records) {
        /* every file the zip records was read: none was lost on the way */
        if (x.seen_count) qsort(x.seen, (size_t)x.seen_count, sizeof *x.seen, _sl_path_order);
        for (int i = 0; i < sl_zip_records_count(records); i++) {
            const sl_zip_record *rec = sl_zip_records_at(records, i);
            if (!rec->is_file || !rec->path || _sl_was_seen(&x, rec->path) || _sl_was_seen(&x, rec->unicode_path))
                continue;
            char why[300];
            snprintf(why, sizeof why, "recorded in the zip's central directory (%llu bytes, CRC-32 %08x) but never "
                     "extracted", rec->size, (unsigned)rec->crc32);
            _sl_note(mismatched, context, rec->path, why);
            if (!mismatches++) snprintf(first_mismatch, sizeof first_mismatch, "%s %s", rec->path, why);
        }
    }
    if (outcome == SL_ARCHIVE_EXTRACTED && mismatches) {
        snprintf(err, err_size, "%s: %d file%s extracted do%s not match the archive's own records, though the archive "
                 "passed its own checks: a fault of this extraction, not of the archive (first: %s)", name, mismatches,
                 mismatches == 1 ? "" : "s", mismatches == 1 ? "es" : "", first_mismatch);
        outcome = SL_ARCHIVE_MISMATCH;
    }
    for (int i = 0; i < x.seen_count; i++) free(x.seen[i]);
    free(x.seen);
    sl_zip_records_free(records);
    free(buf);
    sl_archive_close(a);
    return outcome;
}
