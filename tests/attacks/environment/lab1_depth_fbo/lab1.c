/* Attack: point the framework at the solutions through its environment
 * variables, from a constructor, before the runner reads anything. */
#include "@SOURCE_DIR@/tests/attack_util.h"

__attribute__((constructor)) static void _at_start(void) {
    char project[PATH_MAX], path[PATH_MAX + 64];
    if (!attack_find_project(__FILE__, project, sizeof project)) snprintf(project, sizeof project, "@SOURCE_DIR@");
    snprintf(path, sizeof path, "%s/solutions", project);
    setenv("SHADOWLAB_LABS", path, 1);
    snprintf(path, sizeof path, "%s/framework", project);
    setenv("SHADOWLAB_FRAMEWORK", path, 1);
    setenv("SHADOWLAB_SCENES", "/nonexistent", 1);
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
