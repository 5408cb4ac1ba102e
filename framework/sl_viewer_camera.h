/* sl_viewer_camera: the viewer's camera and light (private to the viewer's modules): the arrows'
 * light moves, the turning light, lab 6's frozen frustum seen from above, the camera path. */
#ifndef SL_VIEWER_CAMERA_H
#define SL_VIEWER_CAMERA_H

#include "sl_viewer_state.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* Turns a sun's or spot's direction by yaw and pitch (radians), kept below the horizon. */
void _sl_viewer_move_light(sl_light *light, float yaw, float pitch);
/* Freezes the cascades on the current camera and looks at its frustum from above, or goes back. */
void _sl_viewer_freeze(_sl_viewer *v, bool on);
/* Turns the light about the vertical axis by `angle` radians. */
void _sl_viewer_animate_light(sl_light *l, float angle);
/* The camera path at `phase` (0..1 a period) for this frame. */
void _sl_viewer_camera_path(_sl_viewer *v, double phase);
/* The scene camera's projection times view for a frame of width x height. */
void _sl_viewer_camera_view_projection(const sl_scene *scene, int width, int height, mat4 out);

#endif
