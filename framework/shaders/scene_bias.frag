#version 330 core
// Camera pass for lab 3: lab 2's comparison with lab 3's bias.
#include "shading.glsl"
#include "lab2_projective/shaders/shadow_lookup.glsl"
#include "lab3_bias/shaders/bias.glsl"
#include "lab3_bias/shaders/midpoint.glsl"
#include "shadow_inputs.glsl"

uniform sampler2D u_second_map; // extension: depths of the second surface

out vec4 frag_color;

void main() {
    float visibility = 1.0;
    if (u_shadows != 0) {
        vec4 coord;
        float bias;
        sl_biased_lookup(coord, bias);
#ifdef SL_HARDWARE_COMPARE
        visibility = shadow_compare_hardware(u_shadow_map, coord, bias);
#else
        if (sl_bias_mode == SL_BIAS_MIDPOINT)
            visibility = midpoint_compare(u_shadow_map, u_second_map, coord);
        else
            visibility = shadow_compare_manual(u_shadow_map, coord, bias);
#endif
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
