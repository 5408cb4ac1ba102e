/* Registers the solutions for shadowlab-grade --isolate. Compiled only where
 * solutions/ exists, with sl_solution_names.h force-included, so the names
 * below are the solutions' renamed functions. */
#include "sl_labs.h"

static const sl_lab_functions _sl_solutions = {
    lab1_create_shadow_map, lab1_begin_depth_pass, lab1_destroy_shadow_map,
    lab2_light_view,        lab2_light_projection, lab2_shadow_matrix,
    lab3_depth_pass_state,  lab3_second_depth_state,
    lab4_configure_shadow_texture,
};

__attribute__((constructor)) static void _sl_register_solutions(void) {
    sl_isolation_lab_functions = &_sl_solutions;
    sl_isolation_labs_dir = SL_SOLUTIONS_DIR;
}
