/* sl_lab7_cube: lab 7's frame, omnidirectional shadows for a point light.
 *
 *   1. lab 7 gives the shared 90-degree projection and the six face views
 *   2. lab 7 creates the depth cube map (once per size) and begins each pass:
 *      six passes (one face each, lab7_begin_cube_pass(map, 0..5)) or, when
 *      lab7_begin_cube_pass(map, SL_CUBE_ALL_FACES) says it can, one layered
 *      pass where the lab's geometry shader sends each triangle to six layers;
 *      the framework draws every object with lab 7's depth shaders, which
 *      store distance / far
 *   3. the camera pass looks each pixel up in the cube map with lab 7's
 *      point_shadow() (or point_shadow_soft())
 *
 * Its technique (sl_lab7_technique, in the table of sl_technique.h) takes a
 * frame when params.lab is 7 and the scene's light is a point light; every
 * call into lab code goes through the renderer's table, so a crash or a stub
 * is pinned on the function. */
#ifndef SL_LAB7_CUBE_H
#define SL_LAB7_CUBE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"
#include "sl_params.h"
#include "sl_scene.h"

/* The read-back of its faces (sl_capture_cube_face) is in sl_capture.h. */
#include "sl_capture.h"

#endif
