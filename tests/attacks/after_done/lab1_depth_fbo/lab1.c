/* Attack: act after the runner has reported: a destructor, an atexit handler
 * and a thread write a forged, passing stream once the real one is done. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <pthread.h>
#include <time.h>

static void _forge(void) {
    double fbo[SL_FBO_NUMBERS] = {GL_FRAMEBUFFER_COMPLETE, GL_TEXTURE, 1, 24, 1024, 1024, 0, 0, 0, 1024};
    attack_send(SL_MSG_NUMBERS, "fbo", fbo, sizeof fbo);
    attack_send(SL_MSG_DONE, NULL, NULL, 0);
    printf("Score: 57/57\n");
    fflush(stdout);
}

static void *_late(void *arg) {
    (void)arg;
    struct timespec t = {0, 200 * 1000 * 1000};
    nanosleep(&t, NULL); /* by now the runner has sent DONE and waits for the grader */
    _forge();
    return NULL;
}

__attribute__((destructor)) static void _at_end(void) { _forge(); }
static void _at_exit(void) { _forge(); }

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    static bool started;
    if (!started) {
        started = true;
        atexit(_at_exit);
        pthread_t thread;
        if (pthread_create(&thread, NULL, _late, NULL) == 0) pthread_detach(thread);
    }
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
