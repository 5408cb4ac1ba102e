/* Force-included (-include) when the solutions are compiled a second time for
 * shadowlab-grade --isolate: their functions get names of their own, so they
 * link next to a student's. */
#define lab1_create_shadow_map sl_solution_lab1_create_shadow_map
#define lab1_begin_depth_pass sl_solution_lab1_begin_depth_pass
#define lab1_destroy_shadow_map sl_solution_lab1_destroy_shadow_map
#define lab2_light_view sl_solution_lab2_light_view
#define lab2_light_projection sl_solution_lab2_light_projection
#define lab2_shadow_matrix sl_solution_lab2_shadow_matrix
#define lab3_depth_pass_state sl_solution_lab3_depth_pass_state
#define lab3_second_depth_state sl_solution_lab3_second_depth_state
#define lab4_configure_shadow_texture sl_solution_lab4_configure_shadow_texture
