/* stage_fixtures: the archives and special files tests/stage.sh stages, made
 * at test time (no binary fixture in the repository). libarchive writes what
 * an ordinary archiver would refuse to: '..' and absolute paths, links,
 * devices, backslash separators.
 *
 *   stage_fixtures archive OUT zip|zip-stored|tar|tgz|tbz2|txz|tzst SPEC...
 *     file:PATH=TEXT      a file holding TEXT
 *     copy:PATH=FILE      a file holding FILE's bytes
 *     tree:PREFIX=DIR     every regular file under DIR, as PREFIX/<its path>
 *     zeros:PATH=N        a file of N zero bytes
 *     dir:PATH            a folder
 *     symlink:PATH=TARGET, hardlink:PATH=TARGET, chardev:PATH, fifo:PATH
 *   stage_fixtures socket PATH   a Unix socket bound at PATH (left behind)
 *   stage_fixtures text OUT N SEED   N bytes of text that never repeats (letters
 *     and digits from a generator seeded by SEED, a newline every 61st byte):
 *     a byte lost or added shifts all that follows, and staging (which
 *     normalises line ends) leaves it as it is
 *   stage_fixtures zip-flip IN OUT cd-crc|data   IN with one bit changed: the
 *     first entry's CRC-32 in the central directory only (the zip contradicts
 *     itself), or its first byte of data (the data fails its own CRC) */
#define _GNU_SOURCE
#include <dirent.h>
#include <fcntl.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <archive.h>
#include <archive_entry.h>

static void _sl_die(const char *what, struct archive *a) {
    fprintf(stderr, "stage_fixtures: %s: %s\n", what, a ? archive_error_string(a) : "");
    exit(1);
}

static void _sl_add(struct archive *a, const char *path, unsigned type, const char *data, size_t len,
                    const char *link) {
    struct archive_entry *e = archive_entry_new();
    archive_entry_set_pathname_utf8(e, path);
    archive_entry_set_filetype(e, type);
    archive_entry_set_perm(e, type == AE_IFDIR ? 0755 : 0644);
    archive_entry_set_mtime(e, 1700000000, 0);
    if (type == AE_IFREG) archive_entry_set_size(e, (la_int64_t)len);
    if (type == AE_IFLNK) archive_entry_set_symlink_utf8(e, link);
    if (type == AE_IFCHR) archive_entry_set_rdev(e, makedev(1, 3));
    if (link && type == AE_IFREG) {
        archive_entry_set_hardlink_utf8(e, link);
        archive_entry_set_size(e, 0);
    }
    if (archive_write_header(a, e) < ARCHIVE_WARN) _sl_die(path, a);
    if (type == AE_IFREG && len && !link && archive_write_data(a, data, len) != (la_ssize_t)len) _sl_die(path, a);
    archive_entry_free(e);
}

static char *_sl_read(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) _sl_die(path, NULL);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *data = malloc((size_t)n + 1);
    *len = fread(data, 1, (size_t)n, f);
    fclose(f);
    return data;
}

static int _sl_compare(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void _sl_tree(struct archive *a, const char *prefix, const char *dir) {
    DIR *d = opendir(dir);
    if (!d) _sl_die(dir, NULL);
    char *names[512];
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < 512)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) names[count++] = strdup(e->d_name);
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], _sl_compare);
    for (int i = 0; i < count; i++) {
        char path[2048], inside[2048];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        snprintf(inside, sizeof inside, "%s%s%s", prefix, prefix[0] ? "/" : "", names[i]);
        struct stat st;
        if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
            _sl_add(a, inside, AE_IFDIR, NULL, 0, NULL);
            _sl_tree(a, inside, path);
        } else if (S_ISREG(st.st_mode)) {
            size_t len;
            char *data = _sl_read(path, &len);
            _sl_add(a, inside, AE_IFREG, data, len, NULL);
            free(data);
        }
        free(names[i]);
    }
}

static int _sl_archive(int argc, char **argv) {
    const char *out = argv[2], *format = argv[3];
    struct archive *a = archive_write_new();
    if (strncmp(format, "zip", 3) == 0) {
        archive_write_set_format_zip(a);
        if (strcmp(format, "zip-stored") == 0 && archive_write_set_format_option(a, "zip", "compression", "store") != ARCHIVE_OK)
            _sl_die("zip-stored", a);
    } else {
        archive_write_set_format_pax_restricted(a);
    }
    int filter = ARCHIVE_OK;
    if (strcmp(format, "tgz") == 0) filter = archive_write_add_filter_gzip(a);
    else if (strcmp(format, "tbz2") == 0) filter = archive_write_add_filter_bzip2(a);
    else if (strcmp(format, "txz") == 0) filter = archive_write_add_filter_xz(a);
    else if (strcmp(format, "tzst") == 0) filter = archive_write_add_filter_zstd(a);
    if (filter != ARCHIVE_OK) _sl_die(format, a);
    if (archive_write_open_filename(a, out) != ARCHIVE_OK) _sl_die(out, a);
    for (int i = 4; i < argc; i++) {
        char *spec = strdup(argv[i]), *colon = strchr(spec, ':');
        if (!colon) _sl_die(argv[i], NULL);
        *colon = '\0';
        char *path = colon + 1, *eq = strchr(path, '=');
        char *value = eq ? eq + 1 : "";
        if (eq) *eq = '\0';
        if (strcmp(spec, "file") == 0) _sl_add(a, path, AE_IFREG, value, strlen(value), NULL);
        else if (strcmp(spec, "copy") == 0) {
            size_t len;
            char *data = _sl_read(value, &len);
            _sl_add(a, path, AE_IFREG, data, len, NULL);
            free(data);
        } else if (strcmp(spec, "tree") == 0) _sl_tree(a, path, value);
        else if (strcmp(spec, "zeros") == 0) {
            size_t len = (size_t)atol(value);
            char *data = calloc(1, len + 1);
            _sl_add(a, path, AE_IFREG, data, len, NULL);
            free(data);
        } else if (strcmp(spec, "dir") == 0) _sl_add(a, path, AE_IFDIR, NULL, 0, NULL);
        else if (strcmp(spec, "symlink") == 0) _sl_add(a, path, AE_IFLNK, NULL, 0, value);
        else if (strcmp(spec, "hardlink") == 0) _sl_add(a, path, AE_IFREG, NULL, 0, value);
        else if (strcmp(spec, "chardev") == 0) _sl_add(a, path, AE_IFCHR, NULL, 0, NULL);
        else if (strcmp(spec, "fifo") == 0) _sl_add(a, path, AE_IFIFO, NULL, 0, NULL);
        else _sl_die(argv[i], NULL);
        free(spec);
    }
    if (archive_write_close(a) != ARCHIVE_OK) _sl_die(out, a);
    archive_write_free(a);
    return 0;
}

static int _sl_text(const char *out, long long n, unsigned long long seed) {
    static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 ";
    FILE *f = fopen(out, "wb");
    if (!f) _sl_die(out, NULL);
    unsigned long long x = seed * 0x9E3779B97F4A7C15ull + 1;
    for (long long i = 0; i < n; i++) {
        x ^= x << 13; /* xorshift64: no period a test file could reach */
        x ^= x >> 7;
        x ^= x << 17;
        fputc(i % 61 == 60 ? '\n' : letters[(x >> 32) % (sizeof letters - 1)], f);
    }
    if (fclose(f) != 0) _sl_die(out, NULL);
    return 0;
}

static unsigned _sl_le16(const unsigned char *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }

static int _sl_zip_flip(const char *in, const char *out, const char *what) {
    size_t len;
    unsigned char *z = (unsigned char *)_sl_read(in, &len);
    size_t at = len;
    if (strcmp(what, "cd-crc") == 0) {
        for (size_t i = 0; i + 46 <= len && at == len; i++)
            if (memcmp(z + i, "PK\1\2", 4) == 0) at = i + 16;
    } else if (strcmp(what, "data") == 0 && len > 30 && memcmp(z, "PK\3\4", 4) == 0) {
        at = 30 + _sl_le16(z + 26) + _sl_le16(z + 28);
    }
    if (at >= len) _sl_die("zip-flip: nothing to change", NULL);
    z[at] ^= 1;
    FILE *f = fopen(out, "wb");
    if (!f || fwrite(z, 1, len, f) != len || fclose(f) != 0) _sl_die(out, NULL);
    free(z);
    return 0;
}

int main(int argc, char **argv) {
    setlocale(LC_CTYPE, "C.UTF-8");
    if (argc >= 4 && strcmp(argv[1], "archive") == 0) return _sl_archive(argc, argv);
    if (argc == 3 && strcmp(argv[1], "socket") == 0) {
        int fd = socket(AF_UNIX, SOCK_STREAM, 0);
        struct sockaddr_un addr = {.sun_family = AF_UNIX};
        snprintf(addr.sun_path, sizeof addr.sun_path, "%s", argv[2]);
        if (fd < 0 || bind(fd, (struct sockaddr *)&addr, sizeof addr) != 0) _sl_die(argv[2], NULL);
        return 0;
    }
    if (argc == 5 && strcmp(argv[1], "text") == 0) return _sl_text(argv[2], atoll(argv[3]), strtoull(argv[4], NULL, 10));
    if (argc == 5 && strcmp(argv[1], "zip-flip") == 0) return _sl_zip_flip(argv[2], argv[3], argv[4]);
    fprintf(stderr, "usage: stage_fixtures archive OUT FORMAT SPEC... | socket PATH | text OUT N SEED | "
                    "zip-flip IN OUT cd-crc|data\n");
    return 2;
}
