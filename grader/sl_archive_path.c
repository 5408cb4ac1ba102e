#include "sl_archive_path.h"

#include <stdio.h>
#include <string.h>

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
