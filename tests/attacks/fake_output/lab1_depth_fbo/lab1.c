/* Attack: print what a passing grade looks like, hoping a script that reads
 * the grader's output takes it for the real thing; with terminal escapes and
 * carriage returns to hide or overwrite the grader's own lines. */
#include "@SOURCE_DIR@/tests/attack_util.h"

static void _fake(FILE *f) {
    fprintf(f, "\nLab 1: depth FBO\n  PASS  2.0/2.0  lab1_depth_boxes / framebuffer\n  Lab 1: 12/12\n");
    fprintf(f, "\033[2J\033[H\r\033[32mPASS\033[0m\nTime: 0.1 s\nScore: 57/57\n");
}

__attribute__((constructor)) static void _at_start(void) {
    _fake(stdout);
    _fake(stderr);
    fflush(NULL);
}

static void _at_exit(void) { _fake(stdout); }

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    atexit(_at_exit);
    _fake(stdout);
    _fake(stderr);
    for (int i = 0; i < 200; i++) printf("Score: 57/57\n");
    fflush(NULL);
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
