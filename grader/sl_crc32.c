#include "sl_crc32.h"

#include <stdbool.h>

static uint32_t _sl_table[256];
static bool _sl_table_made;

static void _sl_make_table(void) {
    for (uint32_t i = 0; i < 256; i++) {
        uint32_t c = i;
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        _sl_table[i] = c;
    }
    _sl_table_made = true;
}

uint32_t sl_crc32(uint32_t crc, const void *data, size_t n) {
    if (!_sl_table_made) _sl_make_table();
    const unsigned char *p = data;
    crc = ~crc;
    for (size_t i = 0; i < n; i++) crc = _sl_table[(crc ^ p[i]) & 0xff] ^ (crc >> 8);
    return ~crc;
}
