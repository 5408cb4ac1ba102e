#define _GNU_SOURCE
#include "sl_files.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* "dir/name.ext" -> "dir/.name.XXXXXX.ext": hidden, same folder (so rename is
 * atomic), same extension (image writers go by it). */
static bool _sl_temporary_name(const char *path, char *out, size_t n, int *suffix) {
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    const char *ext = dot && dot != base ? dot : "";
    int dir_len = (int)(base - path), stem_len = (int)(strlen(base) - strlen(ext));
    *suffix = (int)strlen(ext);
    return (size_t)snprintf(out, n, "%.*s.%.*s.XXXXXX%s", dir_len, path, stem_len, base, ext) < n;
}

bool sl_atomic_open(sl_atomic_file *file, const char *path, char *err, size_t err_size) {
    memset(file, 0, sizeof *file);
    snprintf(file->path, sizeof file->path, "%s", path);
    int suffix;
    if (!_sl_temporary_name(path, file->temporary, sizeof file->temporary, &suffix)) {
        snprintf(err, err_size, "%s: cannot write (path too long)", path);
        return false;
    }
    int fd = mkstemps(file->temporary, suffix);
    if (fd < 0 || !(file->f = fdopen(fd, "w"))) {
        snprintf(err, err_size, "%s: cannot write (%s)", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(file->temporary);
        }
        return false;
    }
    return true;
}

bool sl_atomic_commit(sl_atomic_file *file, char *err, size_t err_size) {
    bool ok = !ferror(file->f);
    ok = fclose(file->f) == 0 && ok;
    file->f = NULL;
    int saved = errno;
    if (ok) chmod(file->temporary, 0644); /* mkstemp makes 0600: reports are for others to read */
    if (ok && rename(file->temporary, file->path) != 0) {
        ok = false;
        saved = errno;
    }
    if (!ok) {
        unlink(file->temporary);
        snprintf(err, err_size, "%s: cannot write (%s)", file->path, strerror(saved));
    }
    return ok;
}

void sl_atomic_abort(sl_atomic_file *file) {
    if (file->f) fclose(file->f);
    file->f = NULL;
    unlink(file->temporary);
}

bool sl_atomic_write_image(const char *path, const sl_image *image, char *err, size_t err_size) {
    sl_atomic_file file;
    if (!sl_atomic_open(&file, path, err, err_size)) return false;
    fclose(file.f);
    file.f = NULL;
    if (!sl_image_write(file.temporary, image, err, err_size)) {
        unlink(file.temporary);
        snprintf(err, err_size, "%s: cannot write the image", path);
        return false;
    }
    chmod(file.temporary, 0644);
    if (rename(file.temporary, path) != 0) {
        snprintf(err, err_size, "%s: cannot write (%s)", path, strerror(errno));
        unlink(file.temporary);
        return false;
    }
    return true;
}

bool sl_mkdirs(const char *path) {
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s", path);
    for (char *p = tmp + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        mkdir(tmp, 0755);
        *p = '/';
    }
    struct stat st;
    return mkdir(tmp, 0755) == 0 || (stat(tmp, &st) == 0 && S_ISDIR(st.st_mode));
}

bool sl_csv_formula(const char *text) { return text[0] && strchr("=+-@\t\r", text[0]) != NULL; }

void sl_csv_field(FILE *f, const char *text, bool first) {
    if (!first) fputc(',', f);
    bool formula = sl_csv_formula(text);
    bool quote = formula || strpbrk(text, ",\"\n\r") != NULL;
    if (quote) fputc('"', f);
    if (formula) fputc('\'', f);
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        if (*p < 0x20 || *p == 0x7f) fputc(' ', f);
        else if (*p == '"') fputs("\"\"", f);
        else fputc(*p, f);
    }
    if (quote) fputc('"', f);
}
