/* fuzz_archive: a libFuzzer target for what reads uploaded archives: the
 * archive reader (sl_archive: listing, reading with caps that cross the
 * look-ahead byte), the zip records reader (sl_zip_records), the extraction
 * with its checks (sl_archive_extract, into a scratch folder), and the
 * stager's side of an archive (the reading child's tree of entries and its
 * read of the chosen files, sl_stage_tree.c), all in one process.
 * Built with clang -fsanitize=fuzzer,address (tests/CMakeLists.txt), run by
 * tests/fuzz_archive.sh: a bounded run from tests/fuzz/archive_seeds, then
 * every input of tests/fuzz/archive_regressions replayed. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <ftw.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sl_archive.h"
#include "sl_crc32.h"
#include "sl_stage_channel.h"
#include "sl_stage_tree.h"
#include "sl_zip_records.h"

static char _sl_scratch[64];

static int _sl_remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
    (void)st;
    (void)flag;
    if (ftw->level > 0) remove(path);
    return 0;
}

static void _sl_empty_scratch(void) { nftw(_sl_scratch, _sl_remove_one, 16, FTW_DEPTH | FTW_PHYS); }

static void _sl_remove_scratch(void) {
    _sl_empty_scratch();
    rmdir(_sl_scratch);
}

int LLVMFuzzerInitialize(int *argc, char ***argv) {
    (void)argc;
    (void)argv;
    snprintf(_sl_scratch, sizeof _sl_scratch, "%s", "/tmp/fuzz_archive.XXXXXX");
    if (!mkdtemp(_sl_scratch)) {
        perror("fuzz_archive: a scratch folder");
        exit(1);
    }
    atexit(_sl_remove_scratch);
    /* the stager's records go nowhere: only what it does on the way counts */
    _sl_channel_fd = open("/dev/null", O_WRONLY | O_CLOEXEC);
    return 0;
}

static void _sl_ignore(void *context, const char *path, const char *why) {
    (void)context;
    (void)path;
    (void)why;
}

/* Listing and reading: caps of 0, 1 and odd sizes cross the byte read ahead. */
static void _sl_list_and_read(int fd) {
    char err[1600];
    sl_archive *a = sl_archive_open(fd, "fuzz", err, sizeof err);
    if (!a) return;
    static unsigned char buf[5000];
    static const size_t caps[] = {0, 1, 7, 4096, 5000};
    sl_archive_entry e;
    int entries = 0;
    while (entries++ < 200 && sl_archive_next(a, &e) > 0) {
        bool more = true;
        long long total = 0;
        for (int i = 0; more && total < (1 << 20); i++) {
            long long n = sl_archive_read(a, buf, caps[i % 5], &more);
            if (n < 0) break;
            total += n;
            if (n == 0 && caps[i % 5] > 0) break;
        }
    }
    sl_archive_close(a);
}

static void _sl_records(int fd) {
    char err[1600];
    sl_zip_records *r = sl_zip_records_read(fd, 1000, err, sizeof err);
    if (!r) return;
    for (int i = 0; i < sl_zip_records_count(r); i++) {
        const sl_zip_record *rec = sl_zip_records_at(r, i);
        int count;
        if (rec->path) sl_zip_records_find(r, rec->path, &count);
        if (rec->unicode_path) sl_zip_records_find(r, rec->unicode_path, &count);
    }
    sl_zip_records_free(r);
}

static void _sl_extract(int fd) {
    int dir = open(_sl_scratch, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) abort();
    char err[1600];
    sl_archive_limits limits = {.max_file_bytes = 1 << 20, .max_total_bytes = 4 << 20,
                                .max_unpacked_bytes = 16 << 20, .max_entries = 1000};
    sl_archive_extract(fd, "fuzz", dir, &limits, _sl_ignore, _sl_ignore, NULL, err, sizeof err);
    close(dir);
    _sl_empty_scratch();
}

static void _sl_free_tree(_sl_node *n) {
    while (n) {
        _sl_node *next = n->next;
        _sl_free_tree(n->first);
        free(n->name);
        free(n->path);
        free(n->archive_path);
        free(n->link);
        free(n->data);
        free(n);
        n = next;
    }
}

static void _sl_want_files(_sl_child *c, _sl_node *n) {
    for (; n; n = n->next) {
        if (n->kind == _SL_FILE && c->want_count < 64) c->wants[c->want_count++].node = n;
        _sl_want_files(c, n->first);
    }
}

/* The stager's child on the archive: its tree, then every file in it read as a chosen lab file. */
static void _sl_stage(int fd) {
    sl_stage_desc d = {.max_files = 64, .max_file_bytes = 1 << 16, .max_total_bytes = 1 << 20, .max_entries = 1000,
                       .max_depth = 16, .max_unpacked_bytes = 16 << 20};
    static _sl_wanted wants[64];
    _sl_child c = {.d = &d, .archive = true, .archive_fd = fd, .wants = wants};
    snprintf(c.archive_name, sizeof c.archive_name, "fuzz.zip");
    _sl_node *root = _sl_archive_tree(&c, "");
    _sl_want_files(&c, root->first);
    _sl_archive_read_wanted(&c);
    _sl_free_tree(root);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    int fd = memfd_create("fuzz_archive", MFD_CLOEXEC);
    if (fd < 0) abort();
    if (size && write(fd, data, size) != (ssize_t)size) abort();
    _sl_list_and_read(fd);
    _sl_records(fd);
    _sl_extract(fd);
    _sl_stage(fd);
    close(fd);
    return 0;
}
