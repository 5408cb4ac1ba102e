/* sl_lab6_cascades: lab 6's frame, cascaded shadow maps for a directional light.
 *
 *   1. lab 6 splits the camera's depth range (lab6_split_distances), fits a
 *      sphere to each slice of its frustum (lab6_slice_sphere) and builds each
 *      cascade's light camera around it (lab6_cascade_matrices); lab 2's
 *      lab2_shadow_matrix turns each into a shadow matrix
 *   2. the framework draws one depth pass per cascade, with lab 1's depth
 *      shaders, into the layers of one depth texture array
 *      (GL_TEXTURE_2D_ARRAY, glFramebufferTextureLayer per layer)
 *   3. the camera pass (scene_cascades.frag) picks each pixel's cascade and
 *      compares with lab 6's GLSL (cascade_index, cascade_compare)
 *
 * Its technique (sl_lab6_technique, in the table of sl_technique.h) takes
 * every frame drawn for lab 6; it records the labs' calls in the renderer's
 * sl_frame_info like the other labs' steps. */
#ifndef SL_LAB6_CASCADES_H
#define SL_LAB6_CASCADES_H

#include "sl_renderer.h"

#endif
