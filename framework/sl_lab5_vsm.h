/* sl_lab5_vsm: lab 5's technique (sl_lab5_technique, in the table of
 * sl_technique.h): its passes before the camera pass, which the renderer
 * draws when params.lab == 5:
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
 * moments[0] (the technique's camera texture). A stub or a shader that does
 * not compile stops the passes; the renderer falls back to lab 4. */
#ifndef SL_LAB5_VSM_H
#define SL_LAB5_VSM_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"
#include "sl_params.h"
#include "sl_protocol.h"
#include "sl_scene.h"
#include "shadowlab.h"

/* The read-backs of its moments (sl_vsm_capture_moments, sl_vsm_describe_target) are in sl_capture.h. */
#include "sl_capture.h"

#endif
