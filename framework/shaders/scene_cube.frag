#version 330 core
// Camera pass of lab 7: Lambert shading from a point light times the cube-map
// lookup (point_shadow or, with SL_CUBE_SOFT, point_shadow_soft). Without
// SL_CUBE_SHADOWS (lab 7 not done yet) the scene is drawn unshadowed.
#include "shading.glsl"
#if SL_CUBE_SHADOWS
#include "lab7_cube/shaders/point_shadow.glsl"
#endif

in vec3 v_world_position;
in vec3 v_world_normal;

uniform samplerCube u_cube_map;
// u_light_far (the lab files' prelude, lab_prelude.glsl): the cube map stores distance / far
uniform float u_cube_bias;    // in the same units
uniform float u_soft_radius;  // point_shadow_soft's disk, world units at distance far

out vec4 frag_color;

void main() {
    float visibility = 1.0;
#if SL_CUBE_SHADOWS
    vec3 light_to_fragment = v_world_position - u_light_position;
#if SL_CUBE_SOFT
    visibility = point_shadow_soft(u_cube_map, light_to_fragment, u_light_far, u_cube_bias, u_soft_radius);
#else
    visibility = point_shadow(u_cube_map, light_to_fragment, u_light_far, u_cube_bias);
#endif
#endif
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
