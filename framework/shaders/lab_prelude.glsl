// What a lab's GLSL file may call of the framework's (framework code): the
// light (its type, position, direction, near and far planes), the direction
// towards it, lab 5's linear depth. Every program that includes a lab file
// includes this first: the camera passes (through shading.glsl), the vertex,
// moments and blur passes, and the grader's probe of each function; so a lab
// file that compiles in the viewer compiles, with the same functions, where
// the grader calls its functions one by one. Included once per program.

// The light's type (0 directional, 1 spot, 2 point) is compiled in: the
// framework builds the camera pass per type (#define SL_LIGHT_TYPE), so a
// directional light's pixels do not also run the spot light's code. A
// program without a light (a probe, the blur) takes the directional one.
#ifndef SL_LIGHT_TYPE
#define SL_LIGHT_TYPE 0
#endif
const int sl_light_type = SL_LIGHT_TYPE;
uniform vec3 u_light_position;
uniform vec3 u_light_direction;

// Unit vector from a surface point towards the light.
vec3 sl_direction_to_light(vec3 world_position) {
    return sl_light_type == 0 ? -u_light_direction : normalize(u_light_position - world_position);
}

// The light's near and far planes (u_light_near, u_light_far), and lab 5's
// linear depth from them (sl_vsm_depth).
#include "vsm_depth.glsl"
