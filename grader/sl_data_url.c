#define _GNU_SOURCE
#include "sl_data_url.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char _sl_base64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

char *sl_image_data_url(const sl_image *image, size_t max_length) {
    if (!image || !image->data) return NULL;
    /* the image writer takes a path: a private temporary file (the grader runs no lab code) */
    char path[] = "/tmp/shadowlab-image-XXXXXX.png";
    int fd = mkstemps(path, 4);
    if (fd < 0) return NULL;
    close(fd);
    char err[256];
    char *url = NULL;
    if (sl_image_write(path, image, err, sizeof err)) {
        FILE *f = fopen(path, "rb");
        struct stat st;
        static const char prefix[] = "data:image/png;base64,";
        if (f && fstat(fileno(f), &st) == 0 && st.st_size > 0) {
            size_t size = (size_t)st.st_size, length = sizeof prefix - 1 + (size + 2) / 3 * 4;
            unsigned char *png = malloc(size);
            if (length <= max_length && png && fread(png, 1, size, f) == size && (url = malloc(length + 1))) {
                char *o = url + sizeof prefix - 1;
                memcpy(url, prefix, sizeof prefix - 1);
                for (size_t i = 0; i < size; i += 3) {
                    unsigned v = (unsigned)png[i] << 16 | (i + 1 < size ? (unsigned)png[i + 1] << 8 : 0) |
                                 (i + 2 < size ? png[i + 2] : 0);
                    *o++ = _sl_base64[v >> 18 & 63];
                    *o++ = _sl_base64[v >> 12 & 63];
                    *o++ = i + 1 < size ? _sl_base64[v >> 6 & 63] : '=';
                    *o++ = i + 2 < size ? _sl_base64[v & 63] : '=';
                }
                *o = '\0';
            }
            free(png);
        }
        if (f) fclose(f);
    }
    unlink(path);
    return url;
}
