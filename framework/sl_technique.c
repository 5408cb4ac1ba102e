#include "sl_technique.h"

#include <string.h>

/* Each in its own module (sl_lab1_4_shadow_map.c, sl_lab5_vsm.c, sl_lab6_cascades.c, sl_lab7_cube.c). Labs
 * 2-4 add their steps to lab 1's shadow-map frame (sl_lab1_4_shadow_map.c): they build on each other inside
 * one frame, so they have no drawing hooks of their own, only what the viewer says of them
 * (sl_lab1_4_viewer.c, where their descriptors are). */
extern const sl_technique sl_lab1_technique;
extern const sl_technique sl_lab2_technique;
extern const sl_technique sl_lab3_technique;
extern const sl_technique sl_lab4_technique;
extern const sl_technique sl_lab5_technique;
extern const sl_technique sl_lab6_technique;
extern const sl_technique sl_lab7_technique;

/* Slot 0: the technique a build adds, NULL in the course's builds (sl_labs_program's TECHNIQUE, the top
 * CMakeLists.txt, defines this in each program's generated build info). */
extern const sl_technique *const sl_build_added_technique;

static const sl_technique *const _sl_techniques[SL_LAB_COUNT + 1] = {
    NULL, /* slot 0: sl_build_added_technique */
    &sl_lab1_technique,
    &sl_lab2_technique,
    &sl_lab3_technique,
    &sl_lab4_technique,
    &sl_lab5_technique,
    &sl_lab6_technique,
    &sl_lab7_technique,
};

const sl_technique *sl_technique_of(int lab) {
    if (lab == 0) return sl_build_added_technique;
    return lab >= 1 && lab <= SL_LAB_COUNT ? _sl_techniques[lab] : NULL;
}

const sl_technique_probe *sl_technique_probe_of(int lab, const char *function) {
    const sl_technique *t = sl_technique_of(lab);
    for (const sl_technique_probe *p = t ? t->probes : NULL; p && p->function; p++)
        if (strcmp(p->function, function) == 0) return p;
    return NULL;
}
