/* sl_lab5_vsm: lab 5's passes before the camera pass, called by the renderer
 * when params.lab == 5:
 *
 *   1. lab 5 creates its moments targets (once per size) and begins the
 *      moments pass; the framework draws every object from the light with
 *      moments.vert/.frag (the student's compute_moments)
 *   2. the separable blur: lab 5 binds source and destination, the framework
 *      draws a full-screen triangle with blur.frag (blur_moments), once per
 *      direction; radius 0 skips it
 *   3. lab 5 builds the mipmaps and sets trilinear filtering
 *
 * The camera pass (scene_vsm.frag, drawn by sl_renderer.c) then reads
 * moments[0]. A stub or a shader that does not compile stops the passes;
 * the renderer falls back to lab 4. */
#ifndef SL_LAB5_VSM_H
#define SL_LAB5_VSM_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"
#include "sl_params.h"
#include "sl_protocol.h"
#include "sl_scene.h"
#include "shadowlab.h"

struct sl_renderer;
typedef struct sl_vsm sl_vsm; /* lab 5's targets and programs, one per renderer */

/* Runs the moments pass, the blur and the mipmaps for this frame (light
 * matrices from the renderer's frame info); true when the moments are ready
 * for the camera pass. Records stubs and shader errors in the frame info. */
bool sl_vsm_passes(struct sl_renderer *r, const sl_scene *scene, const sl_render_params *p);
/* The moments the camera pass reads (0 when none). */
GLuint sl_vsm_moments_texture(const struct sl_renderer *r);
/* The moments as a corner overlay: the mean depth and the second moment side by side. */
void sl_vsm_debug_view(struct sl_renderer *r, int width, int height);
/* Rebuilds lab 5's programs whose files changed (hot reload). */
bool sl_vsm_reload_changed(struct sl_renderer *r, bool *reloaded, char *err, size_t err_size);
void sl_vsm_destroy(struct sl_renderer *r);

/* Level 0 of a moments texture (2 channels, top row first), and what the
 * grader checks of the target: framebuffer status, the texture's internal
 * format, width, height, red and green bits, whether it is a float format,
 * the depth attachment's type, then for moments[0] and moments[1] the width of mipmap level 1 (0: none)
 * and the min filter, then framebuffer[1]'s status (0: not a framebuffer), and whether moments[0] is framebuffer[0]'s colour
 * attachment (SL_MOMENTS_TARGET_NUMBERS numbers). */
bool sl_vsm_capture_moments(GLuint texture, sl_image *out, char *err, size_t err_size);
void sl_vsm_describe_target(const sl_moments_target *t, double out[SL_MOMENTS_TARGET_NUMBERS]);

#endif
