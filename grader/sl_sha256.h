/* sl_sha256: SHA-256 (FIPS 180-4), to tell when a reference file changed
 * after --update-references wrote it (grader/references/MANIFEST.json). */
#ifndef SL_SHA256_H
#define SL_SHA256_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct sl_sha256 {
    uint32_t state[8];
    uint64_t length; /* bytes so far */
    uint8_t block[64];
    size_t used;
} sl_sha256;

void sl_sha256_init(sl_sha256 *h);
void sl_sha256_update(sl_sha256 *h, const void *data, size_t n);
/* 64 lowercase hex digits and a terminator. */
void sl_sha256_hex(sl_sha256 *h, char out[65]);
/* The hash of a file's bytes; false if it cannot be read. */
bool sl_sha256_file(const char *path, char out[65]);

#endif
