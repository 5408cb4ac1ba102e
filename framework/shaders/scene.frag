#version 330 core
// Camera pass with shadows: Lambert shading times lab 2's shadow test.
#include "shading.glsl"
#include "lab2_projective/shaders/shadow_lookup.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;
in vec4 v_shadow_coord;

#ifdef SL_HARDWARE_COMPARE
uniform sampler2DShadow u_shadow_map;
#else
uniform sampler2D u_shadow_map;
#endif
uniform int u_shadows;        // 0 until labs 1 and 2 give a shadow map and matrices
uniform float u_depth_bias;

out vec4 frag_color;

void main() {
    float visibility = 1.0;
    if (u_shadows != 0) {
#ifdef SL_HARDWARE_COMPARE
        visibility = shadow_compare_hardware(u_shadow_map, v_shadow_coord, u_depth_bias);
#else
        visibility = shadow_compare_manual(u_shadow_map, v_shadow_coord, u_depth_bias);
#endif
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
