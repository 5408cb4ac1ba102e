/* Attack: end the process from lab code with exit(0) and a passing Score
 * line, so atexit handlers and destructors run, as if all went well. */
#include "@SOURCE_DIR@/tests/attack_util.h"

static void _at_exit(void) { printf("Score: 57/57\n"); }

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    atexit(_at_exit);
    exit(0);
}

ATTACK_LAB1_STUBS
