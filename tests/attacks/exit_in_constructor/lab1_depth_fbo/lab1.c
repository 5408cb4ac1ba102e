/* Attack: leave before any grading is done, with exit status 0 and a
 * passing Score line, from a constructor that runs before the runner's main. */
#include "@SOURCE_DIR@/tests/attack_util.h"

__attribute__((constructor)) static void _at_start(void) {
    printf("Score: 57/57\n");
    fflush(stdout);
    _exit(0);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
