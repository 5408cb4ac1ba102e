/* sl_labs: the lab functions of this binary as a table: the renderer calls
 * lab code only through it, so every call can be named (a crash is pinned on
 * the function it happened in) and a stub's SL_NOT_IMPLEMENTED recorded. */
#ifndef SL_LABS_H
#define SL_LABS_H

#include "shadowlab.h"
#include "sl_params.h"

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
    /* lab 5 */
    sl_status (*lab5_create_moments_target)(int size, sl_moments_target *target);
    sl_status (*lab5_begin_moments_pass)(const sl_moments_target *target);
    sl_status (*lab5_begin_blur_pass)(const sl_moments_target *target, int direction);
    sl_status (*lab5_filter_moments)(const sl_moments_target *target);
    void (*lab5_destroy_moments_target)(sl_moments_target *target);
    /* lab 6 */
    sl_status (*lab6_split_distances)(float near, float far, int count, float lambda, float *splits);
    sl_status (*lab6_slice_sphere)(mat4 inv_view_projection, float near, float far, float split_near, float split_far,
                                   vec4 dest);
    sl_status (*lab6_cascade_matrices)(const sl_light *light, vec4 sphere, float caster_margin, int map_size,
                                       mat4 light_view, mat4 light_projection);
    /* lab 7 */
    sl_status (*lab7_create_cube_map)(int size, sl_cube_map *map);
    sl_status (*lab7_begin_cube_pass)(const sl_cube_map *map, int face);
    void (*lab7_destroy_cube_map)(sl_cube_map *map);
    sl_status (*lab7_face_view)(vec3 light_position, int face, mat4 dest);
    sl_status (*lab7_face_projection)(float near, float far, mat4 dest);
} sl_lab_functions;

/* The labs this binary was built from (labs/, solutions/, or for the
 * grader's --isolate, one lab's files with the solutions' others). */
extern const sl_lab_functions sl_build_lab_functions;

#endif
