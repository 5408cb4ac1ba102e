/* Attack: headers whose lengths overflow the grader's arithmetic (a payload
 * of nearly 2^64 bytes, a name of 2^32 - 1), hoping the parser loops, waits
 * forever, or allocates without bound; then keep the process alive. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <time.h>

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    sl_message_header h = {SL_MSG_IMAGE, 10, UINT64_MAX - 8};
    attack_write(SL_CHANNEL_FD, &h, sizeof h);
    attack_write(SL_CHANNEL_FD, "visibility", 10);
    sl_message_header name = {SL_MSG_STAGE, UINT32_MAX, 0};
    attack_write(SL_CHANNEL_FD, &name, sizeof name);
    struct timespec t = {30, 0};
    nanosleep(&t, NULL);
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
