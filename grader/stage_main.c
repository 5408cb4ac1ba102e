/* shadowlab-stage: a submission made into a labs tree (sl_stage.h), and the
 * archive reading it uses, for scripts (--list, --extract; sl_archive.h). */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sl_archive.h"
#include "sl_stage.h"
#include "sl_zip_records.h"

static void _sl_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab-stage [options] SUBMISSION STAGE\n"
            "       shadowlab-stage --list ARCHIVE\n"
            "       shadowlab-stage --extract ARCHIVE FOLDER\n"
            "Puts a submission's lab files over the handout's stubs in STAGE (a copy of labs/).\n"
            "SUBMISSION is a folder or an archive (.zip, .tar, .tar.gz/.tgz, .tar.bz2, .tar.xz, .tar.zst), holding\n"
            "a labs/ folder, the lab folders (lab1_depth_fbo/, ...) or the lab files loose (lab1.c, depth.vert,\n"
            "...), possibly inside one top folder; what macOS and Windows add (__MACOSX/, ._*, .DS_Store,\n"
            "Thumbs.db, desktop.ini) is ignored, and a folder holding one archive is read through it.\n"
            "It is read by a separate process: as uid 65534 when this runs as root, in a mount namespace where\n"
            "the --hide folders are empty (where the system allows one), never through a link. Links, hard\n"
            "links, devices, FIFOs, sockets and archive paths that leave the archive are refused by name.\n"
            "Lab files are staged with a UTF-8 byte-order mark removed and CRLF or CR line ends made LF.\n"
            "  --summary FILE       write what was found, taken, ignored, refused and normalised (JSON), with\n"
            "                       notes for the reports (shadowlab-grade --submission-summary FILE)\n"
            "  --hide DIR           a folder the reading process must not see (several times)\n"
            "  --user UID           when root: the uid (and gid) that reads the submission (default 65534)\n"
            "  --prefix TEXT        put before each line said (default \"shadowlab-stage: \")\n"
            "  --max-files N        lab files taken (default 256)\n"
            "  --max-file-bytes N   bytes per lab file (default 1048576)\n"
            "  --max-bytes N        bytes of all lab files (default 16777216)\n"
            "  --max-entries N      files and folders looked at (default 20000)\n"
            "  --max-depth N        folders deep in an archive (default 16)\n"
            "  --max-unpacked N     bytes an archive may unpack to (default 536870912)\n"
            "  --timeout SECONDS    for reading the submission (default 120)\n"
            "  --list ARCHIVE       print each entry: kind, size the header claims (-1: none), path, and\n"
            "                       why it would be refused; a zip's central directory is checked against\n"
            "                       its local headers\n"
            "  --extract ARCHIVE FOLDER  extract the files and folders only (nothing through a link, nothing\n"
            "                       outside FOLDER, no name replaced); refused entries are named on stderr\n"
            "Each lab file staged from an archive, and each file --extract writes (read back from the disk),\n"
            "is checked against the archive's own records: its size and CRC-32 in a zip's central directory\n"
            "(read apart from the extraction), its size in a tar header.\n"
            "Exit status:\n"
            "  0  lab files staged (--list, --extract: done, every file as the archive records it)\n"
            "  1  --list, --extract: the archive is damaged (corrupt, cut short, its data failing its own\n"
            "     CRC, its records contradicting each other) or past a limit: the upload's problem\n"
            "  2  could not stage or extract (the staff's side: arguments, STAGE or FOLDER, a full disk, files\n"
            "     the reading user cannot read: make submissions readable to all, chmod -R a+rX)\n"
            "  3  no lab file found (STAGE holds the stubs; the summary says what was found)\n"
            "  4  a file extracted or staged does not match the archive's records though the archive passed\n"
            "     its own checks: a fault of shadowlab-stage (the staff's side, never the student's); each\n"
            "     such file is named with both sizes and CRC-32s\n");
}

static int _sl_open_archive(const char *path) {
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        fprintf(stderr, "shadowlab-stage: %s: not a readable file (%s)\n", path, fd < 0 ? strerror(errno) : "not a file");
        if (fd >= 0) close(fd);
        return -1;
    }
    return fd;
}

static int _sl_list(const char *path) {
    int fd = _sl_open_archive(path);
    if (fd < 0) return 2;
    char err[1600];
    sl_archive *a = sl_archive_open(fd, path, err, sizeof err);
    if (!a) {
        fprintf(stderr, "shadowlab-stage: %s\n", err);
        close(fd);
        return 1;
    }
    sl_archive_entry *e = malloc(sizeof *e);
    int r;
    while ((r = sl_archive_next(a, e)) > 0) {
        printf("%s\t%lld\t%s", sl_archive_kind_name(e->kind), e->size, e->path);
        if (e->link_target[0]) printf(" -> %s", e->link_target);
        if (e->unsafe) printf("\t(refused: %s)", e->unsafe);
        printf("\n");
    }
    if (r < 0) fprintf(stderr, "shadowlab-stage: %s\n", sl_archive_error(a));
    if (r == 0 && sl_archive_is_zip(a)) {
        /* a zip whose records contradict each other is damaged, however libarchive listed it */
        sl_zip_records *records = sl_zip_records_read(fd, 1 << 20, err, sizeof err);
        if (!records) {
            fprintf(stderr, "shadowlab-stage: %s: a damaged zip: %s\n", path, err);
            r = -1;
        }
        sl_zip_records_free(records);
    }
    free(e);
    sl_archive_close(a);
    close(fd);
    return r < 0 ? SL_STAGE_DAMAGED : SL_STAGE_TAKEN;
}

static void _sl_say_refused(void *context, const char *path, const char *why) {
    (void)context;
    fprintf(stderr, "shadowlab-stage: refused %s: %s\n", path, why);
}

static void _sl_say_mismatch(void *context, const char *path, const char *why) {
    fprintf(stderr, "shadowlab-stage: PROBLEM (not the submission's fault) %s: %s %s\n", (const char *)context, path,
            why);
}

static int _sl_extract(const char *path, const char *folder) {
    int fd = _sl_open_archive(path);
    if (fd < 0) return 2;
    mkdir(folder, 0755);
    int dir = open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) {
        fprintf(stderr, "shadowlab-stage: %s: cannot open the folder (%s)\n", folder, strerror(errno));
        close(fd);
        return 2;
    }
    char err[1600];
    sl_archive_outcome outcome =
        sl_archive_extract(fd, path, dir, NULL, _sl_say_refused, _sl_say_mismatch, (void *)path, err, sizeof err);
    if (outcome != SL_ARCHIVE_EXTRACTED) fprintf(stderr, "shadowlab-stage: %s\n", err);
    close(dir);
    close(fd);
    switch (outcome) {
    case SL_ARCHIVE_EXTRACTED: return SL_STAGE_TAKEN;
    case SL_ARCHIVE_DAMAGED: return SL_STAGE_DAMAGED;
    case SL_ARCHIVE_MISMATCH: return SL_STAGE_MISMATCH;
    default: return SL_STAGE_PROBLEM;
    }
}

static bool _sl_number(const char *text, long long *out) {
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (errno || *end || v <= 0) return false;
    *out = v;
    return true;
}

int main(int argc, char **argv) {
    /* names in archives come out as UTF-8 */
    if (!setlocale(LC_CTYPE, "C.UTF-8")) setlocale(LC_CTYPE, "");
    static const char *hidden[64];
    sl_stage_desc d = {.hidden = hidden};
    const char *positional[2] = {0};
    int positionals = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        long long number = 0;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            _sl_usage(stdout);
            return 0;
        } else if (strcmp(a, "--list") == 0 && v && i + 2 == argc) {
            return _sl_list(v);
        } else if (strcmp(a, "--extract") == 0 && v && i + 3 == argc) {
            return _sl_extract(v, argv[i + 2]);
        } else if (a[0] == '-' && a[1] == '-' && !v) {
            fprintf(stderr, "shadowlab-stage: %s needs a value\n", a);
            return 2;
        } else if (strcmp(a, "--summary") == 0) {
            d.summary = v;
        } else if (strcmp(a, "--hide") == 0) {
            if (d.hidden_count >= 64) {
                fprintf(stderr, "shadowlab-stage: at most 64 --hide folders\n");
                return 2;
            }
            hidden[d.hidden_count++] = v;
        } else if (strcmp(a, "--prefix") == 0) {
            d.log_prefix = v;
        } else if (strcmp(a, "--timeout") == 0) {
            d.timeout = atof(v);
        } else if (strncmp(a, "--", 2) == 0 && !_sl_number(v, &number)) {
            fprintf(stderr, "shadowlab-stage: %s takes a positive whole number\n", a);
            return 2;
        } else if (strcmp(a, "--user") == 0) {
            d.user = (unsigned)number;
        } else if (strcmp(a, "--max-files") == 0) {
            d.max_files = (int)number;
        } else if (strcmp(a, "--max-file-bytes") == 0) {
            d.max_file_bytes = number;
        } else if (strcmp(a, "--max-bytes") == 0) {
            d.max_total_bytes = number;
        } else if (strcmp(a, "--max-entries") == 0) {
            d.max_entries = (int)number;
        } else if (strcmp(a, "--max-depth") == 0) {
            d.max_depth = (int)number;
        } else if (strcmp(a, "--max-unpacked") == 0) {
            d.max_unpacked_bytes = (unsigned long long)number;
        } else if (strncmp(a, "--", 2) == 0) {
            fprintf(stderr, "shadowlab-stage: unknown option %s\n", a);
            _sl_usage(stderr);
            return 2;
        } else {
            if (positionals == 2) {
                fprintf(stderr, "shadowlab-stage: one submission and one stage\n");
                return 2;
            }
            positional[positionals++] = a;
            continue;
        }
        i++;
    }
    if (positionals != 2) {
        _sl_usage(stderr);
        return 2;
    }
    d.submission = positional[0];
    d.stage = positional[1];
    return sl_stage_run(&d);
}
