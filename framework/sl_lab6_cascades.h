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
 * The renderer calls this when params->lab == 6; it records the labs' calls
 * in the renderer's sl_frame_info like the other labs' steps. */
#ifndef SL_LAB6_CASCADES_H
#define SL_LAB6_CASCADES_H

#include "sl_renderer.h"

/* Each cascade's colour (K's tint, the frozen view's boxes; red, green, blue, yellow): the viewer's legend
 * and the --case view's cascade-index panels use the same. */
extern const float sl_cascade_colours[SL_MAX_CASCADES][3];

void sl_lab6_draw(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target, int width,
                  int height);
/* The cascades' layers side by side along the bottom of the picture (viewer overlay). */
void sl_lab6_debug_view(sl_renderer *r, int width, int height);
/* Where the debug view puts layer `layer` of `count`: its top-left corner from the frame's top-left, and its
 * side, in pixels (the viewer's labels). */
void sl_lab6_layer_rect(int width, int height, int count, int layer, int *x, int *y, int *side);
void sl_lab6_release(sl_renderer *r);
/* Adds lab 6's program builds (and their time) and the programs it holds to out. */
void sl_lab6_program_stats(const sl_renderer *r, sl_program_stats *out);
/* Rebuilds lab 6's programs whose files changed (the viewer's hot reload); false with err set if one failed. */
bool sl_lab6_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size);

/* The camera the cascades of this frame are fitted to: params' frozen one, or the scene's. */
const sl_camera *sl_lab6_fit_camera(const sl_scene *scene, const sl_render_params *params);

#endif
