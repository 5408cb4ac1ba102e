#include "sl_labs.h"

const sl_lab_functions sl_build_lab_functions = {
    lab1_create_shadow_map, lab1_begin_depth_pass, lab1_destroy_shadow_map,
    lab2_light_view,        lab2_light_projection, lab2_shadow_matrix,
    lab3_depth_pass_state,  lab3_second_depth_state,
    lab4_configure_shadow_texture,
    /* lab 5 */
    lab5_create_moments_target, lab5_begin_moments_pass, lab5_begin_blur_pass, lab5_filter_moments,
    lab5_destroy_moments_target,
    lab6_split_distances,   lab6_slice_sphere,     lab6_cascade_matrices,
    .lab7_create_cube_map = lab7_create_cube_map, .lab7_begin_cube_pass = lab7_begin_cube_pass,
    .lab7_destroy_cube_map = lab7_destroy_cube_map, .lab7_face_view = lab7_face_view,
    .lab7_face_projection = lab7_face_projection,
};
