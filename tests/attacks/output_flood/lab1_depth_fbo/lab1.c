/* Attack: bury the grader in output (64 MiB per case, and a passing Score
 * line every few lines), to exhaust its memory or push its own lines away. */
#include "@SOURCE_DIR@/tests/attack_util.h"

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    static char block[1 << 16];
    memset(block, 'x', sizeof block);
    for (size_t i = 0; i + 1 < sizeof block; i += 64) block[i] = '\n';
    memcpy(block + 1, "Score: 57/57", 12);
    for (int i = 0; i < 1024; i++) {
        attack_write(1, block, sizeof block);
        if (i % 64 == 0) attack_write(2, block, sizeof block);
    }
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
