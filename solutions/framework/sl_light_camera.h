/* The staff build's light camera for lab 1 (sl_light_camera.c). */
#ifndef SL_LIGHT_CAMERA_H
#define SL_LIGHT_CAMERA_H

#include "sl_scene.h"

bool sl_light_camera_compute(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection);

#endif
