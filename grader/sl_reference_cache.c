/* sl_reference_cache: decoded reference images in a folder of the build
 * (sl_reference_cache.h says what is trusted and why). */
#define _POSIX_C_SOURCE 200809L
#include "sl_reference_cache.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <signal.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sl_platform.h"
#include "sl_sha256.h"

#define _SL_CACHE_MAGIC "SLREFC1\n"
#define _SL_CACHE_ORDER 0x01020304u /* written natively: an entry of another byte order does not parse */
#define _SL_CACHE_HEADER (8 + 4 * 4 + 64 + 64)
/* A reference file or an entry larger than this is not cached (the largest is well under 16 MiB). */
#define _SL_CACHE_MAX_BYTES ((size_t)256 << 20)
#define _SL_CACHE_ENTRY_PREFIX ".entry-"   /* temporary names: prefix, the writer's pid, "-", a number */
#define _SL_CACHE_DECODE_PREFIX ".decode-"
#define _SL_CACHE_UNUSED_DAYS 120          /* an entry no grade read for this long is removed */

struct sl_reference_cache {
    int dir_fd;
    char dir[1100];
    sl_reference_cache_counts counts;
};

bool sl_reference_cache_default_dir(char *out, size_t n) {
    char exe_dir[1024];
    if (!sl_platform_executable_dir(exe_dir, sizeof exe_dir)) return false;
    int written = snprintf(out, n, "%s/../cache/references", exe_dir);
    return written > 0 && (size_t)written < n;
}

/* The grader's own: owned by the effective uid, a folder, none of `forbidden`'s mode bits. */
static bool _sl_own_folder(int fd, mode_t forbidden, const char *path, char *why, size_t n) {
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(why, n, "%s is not a folder", path);
        return false;
    }
    if (st.st_uid != geteuid()) {
        snprintf(why, n, "%s belongs to uid %u, not the grader's (%u)", path, (unsigned)st.st_uid, (unsigned)geteuid());
        return false;
    }
    if (st.st_mode & forbidden) {
        snprintf(why, n, "%s has mode %04o: others may %s it", path, (unsigned)(st.st_mode & 07777),
                 (st.st_mode & forbidden & 022) ? "write" : "read");
        return false;
    }
    return true;
}

/* Opens `name` in `parent_fd` (made with 0700 if missing), never through a link. */
static int _sl_open_folder(int parent_fd, const char *name, const char *path, mode_t forbidden, char *why, size_t n) {
    if (mkdirat(parent_fd, name, 0700) != 0 && errno != EEXIST) {
        snprintf(why, n, "cannot make %s (%s)", path, strerror(errno));
        return -1;
    }
    int fd = openat(parent_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        snprintf(why, n, "cannot open %s (%s)", path, strerror(errno));
        return -1;
    }
    if (!_sl_own_folder(fd, forbidden, path, why, n)) {
        close(fd);
        return -1;
    }
    return fd;
}

/* What a grader that died while writing left (its temporary files carry its pid: gone for a minute
 * at least), and entries no grade has read for _SL_CACHE_UNUSED_DAYS (a hit renews an entry's time),
 * so the folder does not grow with every change of the references. Only the grader's own regular
 * files are touched; a failure leaves the file. */
static void _sl_sweep(sl_reference_cache *cache) {
    int fd = dup(cache->dir_fd);
    DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
    if (!d) {
        if (fd >= 0) close(fd);
        return;
    }
    rewinddir(d);
    time_t now = time(NULL);
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        struct stat st;
        if (fstatat(cache->dir_fd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode) ||
            st.st_uid != geteuid())
            continue;
        bool stale = false;
        const char *prefixes[] = {_SL_CACHE_ENTRY_PREFIX, _SL_CACHE_DECODE_PREFIX};
        for (int i = 0; i < 2; i++) {
            size_t k = strlen(prefixes[i]);
            if (strncmp(e->d_name, prefixes[i], k) != 0) continue;
            char *end;
            long pid = strtol(e->d_name + k, &end, 10);
            stale = end != e->d_name + k && *end == '-' && pid > 0 && now - st.st_mtime > 60 &&
                    kill((pid_t)pid, 0) != 0 && errno == ESRCH;
        }
        size_t len = strlen(e->d_name);
        if (len == 64 + 6 && strcmp(e->d_name + 64, ".slref") == 0)
            stale = now - st.st_mtime > (time_t)_SL_CACHE_UNUSED_DAYS * 24 * 3600;
        if (stale && unlinkat(cache->dir_fd, e->d_name, 0) == 0) cache->counts.removed++;
    }
    closedir(d);
}

sl_reference_cache *sl_reference_cache_open(const char *dir, char *why, size_t n) {
    /* The folder and its parent are checked: whoever may write the parent may swap the folder. */
    char parent[1100];
    snprintf(parent, sizeof parent, "%s", dir);
    char *slash = strrchr(parent, '/');
    if (!slash || slash == parent || !slash[1] || strlen(dir) >= sizeof parent) {
        snprintf(why, n, "%s: give a folder below another, by its path", dir);
        return NULL;
    }
    *slash = '\0';
    const char *leaf = slash + 1;
    char *parent_slash = strrchr(parent, '/');
    if (!parent_slash || !parent_slash[1]) {
        snprintf(why, n, "%s: give a folder below another, by its path", dir);
        return NULL;
    }
    *parent_slash = '\0';
    int top = open(parent[0] ? parent : "/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    *parent_slash = '/';
    if (top < 0) {
        snprintf(why, n, "cannot open the folder of %s (%s)", parent, strerror(errno));
        return NULL;
    }
    int parent_fd = _sl_open_folder(top, parent_slash + 1, parent, 022, why, n);
    close(top);
    if (parent_fd < 0) return NULL;
    int dir_fd = _sl_open_folder(parent_fd, leaf, dir, 077, why, n);
    close(parent_fd);
    if (dir_fd < 0) return NULL;
    sl_reference_cache *cache = calloc(1, sizeof *cache);
    if (!cache) {
        close(dir_fd);
        snprintf(why, n, "out of memory");
        return NULL;
    }
    cache->dir_fd = dir_fd;
    snprintf(cache->dir, sizeof cache->dir, "%s", dir);
    _sl_sweep(cache);
    return cache;
}

void sl_reference_cache_close(sl_reference_cache *cache) {
    if (!cache) return;
    close(cache->dir_fd);
    free(cache);
}

sl_reference_cache_counts sl_reference_cache_counts_of(const sl_reference_cache *cache) {
    return cache ? cache->counts : (sl_reference_cache_counts){0, 0, 0, 0};
}

const char *sl_reference_cache_dir(const sl_reference_cache *cache) { return cache ? cache->dir : ""; }

static bool _sl_is_hash(const char *text) {
    if (!text || strlen(text) != 64) return false;
    for (int i = 0; i < 64; i++)
        if (!((text[i] >= '0' && text[i] <= '9') || (text[i] >= 'a' && text[i] <= 'f'))) return false;
    return true;
}

/* All of an open file, at most `limit` bytes; NULL if it is not a regular file or larger. */
static unsigned char *_sl_read_fd(int fd, size_t limit, size_t *size, struct stat *st) {
    if (fstat(fd, st) != 0 || !S_ISREG(st->st_mode) || st->st_size < 0 || (uint64_t)st->st_size > limit) return NULL;
    size_t want = (size_t)st->st_size;
    unsigned char *bytes = malloc(want ? want : 1);
    size_t got = 0;
    while (bytes && got < want) {
        ssize_t r = read(fd, bytes + got, want - got);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        got += (size_t)r;
    }
    if (bytes && got != want) {
        free(bytes);
        bytes = NULL;
    }
    *size = want;
    return bytes;
}

static void _sl_sha256_of(const void *data, size_t n, char out[65]) {
    sl_sha256 h;
    sl_sha256_init(&h);
    sl_sha256_update(&h, data, n);
    sl_sha256_hex(&h, out);
}

/* The entry named by `sha256`, if there is one to trust: 1 read, 0 none, -1 one that was ignored. */
static int _sl_entry_read(sl_reference_cache *cache, const char *sha256, sl_image *out) {
    char name[80];
    snprintf(name, sizeof name, "%s.slref", sha256);
    int fd = openat(cache->dir_fd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return errno == ENOENT ? 0 : -1;
    struct stat st;
    size_t size = 0;
    /* the owner and mode first: a foreign entry is not even read */
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != geteuid() || (st.st_mode & 022)) {
        close(fd);
        return -1;
    }
    unsigned char *bytes = _sl_read_fd(fd, _SL_CACHE_MAX_BYTES, &size, &st);
    close(fd);
    if (!bytes) return -1;
    uint32_t w = 0, h = 0, c = 0, order = 0;
    bool ok = size >= _SL_CACHE_HEADER && memcmp(bytes, _SL_CACHE_MAGIC, 8) == 0;
    if (ok) {
        memcpy(&w, bytes + 8, 4);
        memcpy(&h, bytes + 12, 4);
        memcpy(&c, bytes + 16, 4);
        memcpy(&order, bytes + 20, 4);
        ok = order == _SL_CACHE_ORDER && w > 0 && h > 0 && c > 0 && w <= 65536 && h <= 65536 && c <= 4 &&
             size == _SL_CACHE_HEADER + (size_t)w * h * c * sizeof(float) && memcmp(bytes + 24, sha256, 64) == 0;
    }
    char pixels_hash[65];
    if (ok) {
        _sl_sha256_of(bytes + _SL_CACHE_HEADER, size - _SL_CACHE_HEADER, pixels_hash);
        ok = memcmp(bytes + 24 + 64, pixels_hash, 64) == 0;
    }
    if (ok) *out = sl_image_alloc((int)w, (int)h, (int)c);
    if (ok && out->data) memcpy(out->data, bytes + _SL_CACHE_HEADER, size - _SL_CACHE_HEADER);
    free(bytes);
    return ok && out->data ? 1 : -1;
}

static bool _sl_write_all(int fd, const void *data, size_t n) {
    const unsigned char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= (size_t)w;
    }
    return true;
}

/* A new file of the cache folder (mode 0600), made through the folder's
 * descriptor: if the folder's path were swapped after it was checked, no
 * file would go elsewhere. Its name is `prefix`, a number, `suffix`. */
static int _sl_new_file(sl_reference_cache *cache, const char *prefix, const char *suffix, char *name, size_t n) {
    static unsigned counter;
    for (int attempt = 0; attempt < 100; attempt++) {
        snprintf(name, n, "%s%ld-%u%s", prefix, (long)getpid(), counter++, suffix);
        int fd = openat(cache->dir_fd, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    return -1;
}

/* Writes the entry whole under a temporary name, then renames it into place
 * (over an ignored one too). Failing is no matter: the next grade decodes again. */
static bool _sl_entry_write(sl_reference_cache *cache, const char *sha256, const sl_image *image) {
    size_t count = (size_t)image->width * (size_t)image->height * (size_t)image->channels;
    unsigned char header[_SL_CACHE_HEADER];
    uint32_t fields[4] = {(uint32_t)image->width, (uint32_t)image->height, (uint32_t)image->channels, _SL_CACHE_ORDER};
    memcpy(header, _SL_CACHE_MAGIC, 8);
    memcpy(header + 8, fields, sizeof fields);
    memcpy(header + 24, sha256, 64);
    char pixels_hash[65];
    _sl_sha256_of(image->data, count * sizeof(float), pixels_hash);
    memcpy(header + 24 + 64, pixels_hash, 64);
    char temporary[80], name[80];
    snprintf(name, sizeof name, "%s.slref", sha256);
    int fd = _sl_new_file(cache, _SL_CACHE_ENTRY_PREFIX, "", temporary, sizeof temporary);
    if (fd < 0) return false;
    bool ok = _sl_write_all(fd, header, sizeof header) && _sl_write_all(fd, image->data, count * sizeof(float));
    ok = close(fd) == 0 && ok;
    ok = ok && renameat(cache->dir_fd, temporary, cache->dir_fd, name) == 0;
    if (!ok) unlinkat(cache->dir_fd, temporary, 0);
    return ok;
}

/* Decodes `bytes` (a file whose name ends in `extension`) from a private
 * copy in the cache folder: what is decoded is what was hashed. */
static bool _sl_decode_bytes(sl_reference_cache *cache, const unsigned char *bytes, size_t size, const char *extension,
                             sl_image *out) {
    char temporary[80], path[1300];
    int fd = _sl_new_file(cache, _SL_CACHE_DECODE_PREFIX, extension, temporary, sizeof temporary);
    if (fd < 0) return false;
    bool ok = _sl_write_all(fd, bytes, size);
    ok = close(fd) == 0 && ok;
    /* the image module takes a path: through the folder's descriptor where the system shows one */
    snprintf(path, sizeof path, "/proc/self/fd/%d/%s", cache->dir_fd, temporary);
    if (access(path, R_OK) != 0) snprintf(path, sizeof path, "%s/%s", cache->dir, temporary);
    char err[512];
    ok = ok && sl_image_read(path, out, err, sizeof err);
    unlinkat(cache->dir_fd, temporary, 0);
    if (!ok) sl_image_free(out);
    return ok;
}

bool sl_reference_cache_read(sl_reference_cache *cache, const char *path, const char *sha256, sl_image *out) {
    *out = (sl_image){0, 0, 0, NULL};
    if (!cache || !_sl_is_hash(sha256)) return false;
    const char *extension = strrchr(path, '.');
    if (!extension || strchr(extension, '/') || strlen(extension) > 16) return false;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat st;
    size_t size = 0;
    unsigned char *bytes = _sl_read_fd(fd, _SL_CACHE_MAX_BYTES, &size, &st);
    close(fd);
    if (!bytes) return false;
    char hash[65];
    _sl_sha256_of(bytes, size, hash);
    if (strcmp(hash, sha256) != 0) { /* not the manifest's file: the usual way says so */
        free(bytes);
        return false;
    }
    int found = _sl_entry_read(cache, sha256, out);
    if (found == 1) {
        cache->counts.hits++;
        char name[80];
        snprintf(name, sizeof name, "%s.slref", sha256);
        utimensat(cache->dir_fd, name, NULL, AT_SYMLINK_NOFOLLOW); /* in use: kept by the sweep */
        free(bytes);
        return true;
    }
    if (found < 0) cache->counts.ignored++;
    bool decoded = _sl_decode_bytes(cache, bytes, size, extension, out);
    free(bytes);
    if (decoded && _sl_entry_write(cache, sha256, out)) cache->counts.stored++;
    return decoded;
}
