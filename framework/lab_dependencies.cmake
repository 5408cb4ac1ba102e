# Which labs each lab builds on: the one place this is said. Read by
#   - the build (top CMakeLists.txt): lab N's per-lab runner links the
#     solutions of the labs in SL_LAB<N>_BUILDS_ON and the handout's stubs of
#     every other lab (never lab N's own solution, never a later lab's);
#   - the grader, through the header the build generates from it
#     (generated/include/sl_lab_dependencies.h, sl_lab_builds_on() and
#     sl_lab_shows() in sl_params.h): which labs' shaders a lab's sandbox
#     holds from the solutions, and "needs lab K first" in a lab's messages;
#   - the docs (each lab's README says what it builds on).
#
# SL_LAB<N>_BUILDS_ON: the earlier labs whose functions or shaders the
#   framework calls when it draws lab N's cases (framework/sl_renderer.c,
#   sl_lab5_vsm.c, sl_lab6_cascades.c, sl_lab7_cube.c): without them lab N's
#   own code does not run. Closed: a lab here brings the labs it builds on.
# SL_LAB<N>_SHOWS: those of them whose results show in lab N's pictures, so
#   that a mistake there is named in lab N ("needs lab K first"). A lab that
#   must only be there (its function returns SL_OK) is not one of them.
#
# Measured from the framework's code:
#   lab 2  lab 1's map (lab1_create_shadow_map, lab1_begin_depth_pass,
#          depth.vert): the camera pass runs only when the map is ready.
#   lab 3  lab 2's matrices and lookup (scene_bias.frag includes
#          shadow_lookup.glsl and compares with it) on lab 1's map.
#   lab 4  lab 3's biased lookup (scene_filter.frag: bias.glsl) and
#          lab3_depth_pass_state: the renderer falls back to lab 2 when the
#          depth pass did not use lab 3's state.
#   lab 5  lab 2's matrices (the moments pass and v_shadow_coord); lab 1 only
#          because lab 2 builds on it. VSM reads neither lab 1's map nor lab 3's
#          state, and runs the depth pass only when it falls back to lab 4.
#   lab 6  lab 1's depth shaders for every cascade and lab2_shadow_matrix per
#          cascade (sl_lab6_cascades.c); its own targets and lookup.
#   lab 7  its own cube map, matrices, depth shaders and lookup.
set(SL_LAB1_BUILDS_ON "")
set(SL_LAB2_BUILDS_ON 1)
set(SL_LAB3_BUILDS_ON 1 2)
set(SL_LAB4_BUILDS_ON 1 2 3)
set(SL_LAB5_BUILDS_ON 1 2)
set(SL_LAB6_BUILDS_ON 1 2)
set(SL_LAB7_BUILDS_ON "")

set(SL_LAB1_SHOWS "")
set(SL_LAB2_SHOWS 1)
set(SL_LAB3_SHOWS 1 2)
set(SL_LAB4_SHOWS 1 2 3)
set(SL_LAB5_SHOWS 2)
set(SL_LAB6_SHOWS 1 2)
set(SL_LAB7_SHOWS "")
