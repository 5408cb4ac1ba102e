/* sl_labs: the lab functions as a table, so one binary can run a student's
 * lab under test with the solutions' other labs (shadowlab-grade --isolate):
 * one early mistake then does not cost every later lab its marks. */
#ifndef SL_LABS_H
#define SL_LABS_H

#include "shadowlab.h"

#define SL_LAB_COUNT 4 /* labs in this build */

typedef struct sl_lab_functions {
    sl_status (*lab1_create_shadow_map)(int size, sl_shadow_map *map);
    sl_status (*lab1_begin_depth_pass)(const sl_shadow_map *map);
    void (*lab1_destroy_shadow_map)(sl_shadow_map *map);
    sl_status (*lab2_light_view)(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest);
    sl_status (*lab2_light_projection)(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest);
    sl_status (*lab2_shadow_matrix)(mat4 light_projection, mat4 light_view, mat4 dest);
    sl_status (*lab3_depth_pass_state)(const sl_bias_settings *bias);
    sl_status (*lab3_second_depth_state)(void);
    sl_status (*lab4_configure_shadow_texture)(GLuint depth_texture, sl_filter_mode mode);
} sl_lab_functions;

/* The labs this binary was built from (labs/ or solutions/). */
extern const sl_lab_functions sl_build_lab_functions;
/* The solutions, linked under other names for --isolate; NULL when this copy
 * has no solutions (a student handout). Set before main() runs. */
extern const sl_lab_functions *sl_isolation_lab_functions;
extern const char *sl_isolation_labs_dir;

/* Folder of lab N under a labs tree ("lab1_depth_fbo"), N = 1..SL_LAB_COUNT. */
const char *sl_lab_folder(int lab);

#endif
