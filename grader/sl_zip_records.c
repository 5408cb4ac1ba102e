#define _GNU_SOURCE
#include "sl_zip_records.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sl_archive_path.h"

struct sl_zip_records {
    sl_zip_record *records;
    int count;
    /* every path and unicode_path, sorted, for sl_zip_records_find */
    struct _sl_zip_key {
        const char *path;
        const sl_zip_record *record;
    } *keys;
    int key_count;
    const sl_zip_record **found; /* sl_zip_records_find's answer */
};

enum {
    _SL_EOCD_SIG = 0x06054b50,
    _SL_EOCD64_SIG = 0x06064b50,
    _SL_LOCATOR64_SIG = 0x07064b50,
    _SL_CENTRAL_SIG = 0x02014b50,
    _SL_LOCAL_SIG = 0x04034b50,
    _SL_DESCRIPTOR_SIG = 0x08074b50,
    _SL_LENGTH_AT_END = 1 << 3, /* the CRC and sizes follow the data, in a descriptor */
};

static unsigned _sl_u16(const unsigned char *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }
static uint32_t _sl_u32(const unsigned char *p) { return (uint32_t)_sl_u16(p) | (uint32_t)_sl_u16(p + 2) << 16; }
static unsigned long long _sl_u64(const unsigned char *p) {
    return (unsigned long long)_sl_u32(p) | (unsigned long long)_sl_u32(p + 4) << 32;
}

/* All of n bytes at offset, or false (a short file). */
static bool _sl_pread(int fd, void *buf, size_t n, long long offset) {
    size_t got = 0;
    while (got < n) {
        ssize_t r = pread(fd, (char *)buf + got, n - got, (off_t)(offset + (long long)got));
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        got += (size_t)r;
    }
    return true;
}

static char *_sl_clean(const char *raw, size_t len) {
    char *copy = strndup(raw, len), *out = malloc(SL_ARCHIVE_PATH_MAX);
    const char *why;
    bool ok = copy && out && strlen(copy) == len && len < SL_ARCHIVE_PATH_MAX &&
              sl_archive_clean_path(copy, out, SL_ARCHIVE_PATH_MAX, &why) && out[0];
    free(copy);
    if (!ok) {
        free(out);
        return NULL;
    }
    return out;
}

static int _sl_key_order(const void *a, const void *b) {
    const struct _sl_zip_key *x = a, *y = b;
    int c = strcmp(x->path, y->path);
    return c ? c : x->record < y->record ? -1 : x->record > y->record;
}

/* The end of central directory record: where the directory is and how big. */
static bool _sl_find_directory(int fd, long long file_size, long long *cd_start, unsigned long long *cd_size,
                               unsigned long long *entries, long long *delta, char *err, size_t n) {
    size_t tail_len = (size_t)(file_size < 22 + 65535 ? file_size : 22 + 65535);
    unsigned char *tail = malloc(tail_len ? tail_len : 1);
    if (!tail || !_sl_pread(fd, tail, tail_len, file_size - (long long)tail_len)) {
        free(tail);
        snprintf(err, n, "cannot read its end");
        return false;
    }
    long long eocd = -1;
    for (long long i = (long long)tail_len - 22; i >= 0 && eocd < 0; i--)
        if (_sl_u32(tail + i) == _SL_EOCD_SIG && i + 22 + _sl_u16(tail + i + 20) <= (long long)tail_len)
            eocd = i;
    if (eocd < 0) {
        free(tail);
        snprintf(err, n, "no end of central directory record (a zip cut short?)");
        return false;
    }
    const unsigned char *e = tail + eocd;
    long long eocd_at = file_size - (long long)tail_len + eocd;
    unsigned long long count = _sl_u16(e + 10), size = _sl_u32(e + 12), offset = _sl_u32(e + 16);
    long long cd_end = eocd_at;
    unsigned char loc[20], z[56];
    if (eocd_at >= 20 && _sl_pread(fd, loc, 20, eocd_at - 20) && _sl_u32(loc) == _SL_LOCATOR64_SIG) {
        /* zip64: the real numbers are in the zip64 record, usually just before the locator */
        long long at = (long long)_sl_u64(loc + 8);
        if (!(at >= 0 && at + 56 <= file_size && _sl_pread(fd, z, 56, at) && _sl_u32(z) == _SL_EOCD64_SIG)) {
            at = eocd_at - 20 - 56;
            if (!(at >= 0 && _sl_pread(fd, z, 56, at) && _sl_u32(z) == _SL_EOCD64_SIG)) {
                free(tail);
                snprintf(err, n, "a zip64 locator with no zip64 end of central directory record");
                return false;
            }
        }
        count = _sl_u64(z + 32);
        size = _sl_u64(z + 40);
        offset = _sl_u64(z + 48);
        cd_end = at;
    }
    free(tail);
    if (size > (unsigned long long)cd_end) {
        snprintf(err, n, "a central directory of %llu bytes, more than the zip before it", size);
        return false;
    }
    *cd_start = cd_end - (long long)size;
    *cd_size = size;
    *entries = count;
    /* data put before the zip (a self-extracting one) moves every offset alike */
    *delta = *cd_start - (long long)offset;
    return true;
}

/* What a record's local header (and data descriptor) say must be what the central directory says. */
static bool _sl_check_local(int fd, long long file_size, const sl_zip_record *r, const unsigned char *name,
                            size_t name_len, unsigned flags, long long at, char *err, size_t n) {
    unsigned char h[30];
    const char *shown = r->path ? r->path : "an entry";
    if (at < 0 || at + 30 > file_size || !_sl_pread(fd, h, 30, at) || _sl_u32(h) != _SL_LOCAL_SIG) {
        snprintf(err, n, "the central directory puts %s at offset %lld, where there is no local header", shown, at);
        return false;
    }
    unsigned local_flags = _sl_u16(h + 6), local_name_len = _sl_u16(h + 26), extra_len = _sl_u16(h + 28);
    unsigned char *local_name = malloc(local_name_len + 1u);
    bool same_name = local_name && local_name_len == name_len &&
                     _sl_pread(fd, local_name, local_name_len, at + 30) && memcmp(local_name, name, name_len) == 0;
    free(local_name);
    if (!same_name) {
        snprintf(err, n, "the central directory and the local header name %s differently", shown);
        return false;
    }
    uint32_t crc = _sl_u32(h + 14), packed = _sl_u32(h + 18), size = _sl_u32(h + 22);
    if (!((local_flags | flags) & _SL_LENGTH_AT_END)) {
        bool sizes_agree = (packed == 0xffffffffu || packed == (uint32_t)r->packed_size) &&
                           (size == 0xffffffffu || size == (uint32_t)r->size);
        if (crc != r->crc32 || !sizes_agree) {
            snprintf(err, n, "the central directory records %s as %llu bytes, CRC-32 %08x, its local header as %u bytes, "
                     "CRC-32 %08x", shown, r->size, (unsigned)r->crc32, (unsigned)size, (unsigned)crc);
            return false;
        }
        return true;
    }
    unsigned char d[8];
    long long descriptor = at + 30 + local_name_len + extra_len + (long long)r->packed_size;
    if (descriptor < 0 || !_sl_pread(fd, d, 8, descriptor)) {
        snprintf(err, n, "the data descriptor of %s is missing (cut short?)", shown);
        return false;
    }
    uint32_t written_crc = _sl_u32(d) == _SL_DESCRIPTOR_SIG ? _sl_u32(d + 4) : _sl_u32(d);
    if (written_crc != r->crc32) {
        snprintf(err, n, "the central directory records %s with CRC-32 %08x, its data descriptor with %08x", shown,
                 (unsigned)r->crc32, (unsigned)written_crc);
        return false;
    }
    return true;
}

sl_zip_records *sl_zip_records_read(int fd, int max_records, char *err, size_t n) {
    if (n) err[0] = '\0';
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, n, "not a file that can be read twice");
        return NULL;
    }
    long long file_size = (long long)st.st_size, cd_start, delta;
    unsigned long long cd_size, entries;
    if (!_sl_find_directory(fd, file_size, &cd_start, &cd_size, &entries, &delta, err, n)) return NULL;
    if (entries > (unsigned long long)max_records || entries > cd_size / 46) {
        snprintf(err, n, "the end record claims %llu entries in a central directory of %llu bytes", entries, cd_size);
        return NULL;
    }
    sl_zip_records *z = calloc(1, sizeof *z);
    unsigned char *cd = malloc(cd_size ? cd_size : 1);
    z->records = calloc(entries ? entries : 1, sizeof *z->records);
    z->keys = calloc(entries ? 2 * entries : 1, sizeof *z->keys);
    z->found = calloc(entries ? 2 * entries : 1, sizeof *z->found);
    if (!z->records || !z->keys || !z->found || !cd) {
        free(cd);
        sl_zip_records_free(z);
        snprintf(err, n, "out of memory for %llu entries", entries);
        return NULL;
    }
    if (!_sl_pread(fd, cd, cd_size, cd_start)) {
        free(cd);
        sl_zip_records_free(z);
        snprintf(err, n, "the central directory cannot be read (cut short?)");
        return NULL;
    }
    size_t at = 0;
    bool ok = true;
    for (unsigned long long i = 0; i < entries && ok; i++) {
        const unsigned char *c = cd + at;
        if (at + 46 > cd_size || _sl_u32(c) != _SL_CENTRAL_SIG) {
            snprintf(err, n, "the central directory ends after %llu of its %llu entries", i, entries);
            ok = false;
            break;
        }
        unsigned made_by = _sl_u16(c + 4), flags = _sl_u16(c + 8), name_len = _sl_u16(c + 28),
                 extra_len = _sl_u16(c + 30), comment_len = _sl_u16(c + 32);
        if (at + 46 + name_len + extra_len + comment_len > cd_size) {
            snprintf(err, n, "the central directory's entry %llu runs past its end", i + 1);
            ok = false;
            break;
        }
        sl_zip_record *r = &z->records[z->count++];
        r->crc32 = _sl_u32(c + 16);
        r->packed_size = _sl_u32(c + 20);
        r->size = _sl_u32(c + 24);
        unsigned long long local = _sl_u32(c + 42);
        const unsigned char *name = c + 46, *extra = name + name_len;
        r->path = _sl_clean((const char *)name, name_len);
        /* zip64 sizes and offset, in this order, for the fields the record left at 0xffffffff */
        for (unsigned x = 0; x + 4 <= extra_len;) {
            unsigned id = _sl_u16(extra + x), len = _sl_u16(extra + x + 2);
            const unsigned char *data = extra + x + 4;
            if (x + 4 + len > extra_len) break;
            if (id == 0x0001) {
                unsigned used = 0;
                if (r->size == 0xffffffffu && used + 8 <= len) r->size = _sl_u64(data + used), used += 8;
                if (r->packed_size == 0xffffffffu && used + 8 <= len) r->packed_size = _sl_u64(data + used), used += 8;
                if (local == 0xffffffffu && used + 8 <= len) local = _sl_u64(data + used);
            } else if (id == 0x7075 && len > 5 && data[0] == 1 && !r->unicode_path) {
                r->unicode_path = _sl_clean((const char *)data + 5, len - 5);
            }
            x += 4 + len;
        }
        unsigned mode = (unsigned)(_sl_u32(c + 38) >> 16);
        bool unix_kind = (made_by >> 8) == 3 && (mode & 0170000) != 0;
        r->is_file = !(name_len && name[name_len - 1] == '/') && (!unix_kind || (mode & 0170000) == 0100000);
        if (local > (unsigned long long)file_size || r->packed_size > (unsigned long long)file_size) {
            snprintf(err, n, "the central directory puts %s past the end of the zip", r->path ? r->path : "an entry");
            ok = false;
            break;
        }
        ok = _sl_check_local(fd, file_size, r, name, name_len, flags, (long long)local + delta, err, n);
        at += 46u + name_len + extra_len + comment_len;
    }
    free(cd);
    if (!ok) {
        sl_zip_records_free(z);
        return NULL;
    }
    for (int i = 0; i < z->count; i++) {
        if (z->records[i].path) z->keys[z->key_count++] = (struct _sl_zip_key){z->records[i].path, &z->records[i]};
        if (z->records[i].unicode_path)
            z->keys[z->key_count++] = (struct _sl_zip_key){z->records[i].unicode_path, &z->records[i]};
    }
    qsort(z->keys, (size_t)z->key_count, sizeof *z->keys, _sl_key_order);
    return z;
}

int sl_zip_records_count(const sl_zip_records *z) { return z->count; }

const sl_zip_record *sl_zip_records_at(const sl_zip_records *z, int i) { return &z->records[i]; }

const sl_zip_record *const *sl_zip_records_find(const sl_zip_records *z, const char *path, int *count) {
    int lo = 0, hi = z->key_count;
    while (lo < hi) { /* the first key not before path */
        int mid = lo + (hi - lo) / 2;
        if (strcmp(z->keys[mid].path, path) < 0) lo = mid + 1;
        else hi = mid;
    }
    *count = 0;
    for (int i = lo; i < z->key_count && strcmp(z->keys[i].path, path) == 0; i++) {
        /* a record whose path and unicode_path are the same is found once */
        if (*count && z->found[*count - 1] == z->keys[i].record) continue;
        z->found[(*count)++] = z->keys[i].record;
    }
    return z->found;
}

void sl_zip_records_free(sl_zip_records *z) {
    if (!z) return;
    for (int i = 0; i < z->count; i++) {
        free(z->records[i].path);
        free(z->records[i].unicode_path);
    }
    free(z->records);
    free(z->keys);
    free(z->found);
    free(z);
}
