/* Attack: let the solutions do the work. Look for their code linked into
 * this process, then for the solutions' runner on disk and become it (exec
 * keeps fd 0, the job, and fd 3, the channel: it would send the right
 * answers for this very case). */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <dlfcn.h>

typedef sl_status (*create_fn)(int, sl_shadow_map *);

static void _exec_if_there(const char *path) {
    if (access(path, X_OK) != 0) return;
    char *const argv[] = {(char *)"shadowlab-runner", NULL};
    execv(path, argv);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    /* the solutions under the names --isolate once linked them with */
    create_fn solution = (create_fn)dlsym(RTLD_DEFAULT, "sl_solution_lab1_create_shadow_map");
    if (solution) return solution(size, map);
    char project[PATH_MAX], path[PATH_MAX + 64];
    if (!attack_find_project(__FILE__, project, sizeof project)) return SL_NOT_IMPLEMENTED;
    static const char *const places[] = {"build/bin/solutions/shadowlab-runner", "build/tests/runners/solutions/shadowlab-runner",
                                         "build/bin/shadowlab-runner"};
    for (size_t i = 0; i < sizeof places / sizeof places[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", project, places[i]);
        _exec_if_there(path);
    }
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        *strrchr(exe, '/') = '\0';
        snprintf(path, sizeof path, "%s/../solutions/shadowlab-runner", exe);
        _exec_if_there(path);
    }
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
