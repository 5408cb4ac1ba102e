#version 330 core
// Camera pass for lab 4: lab 3's biased lookup, filtered by lab 4.
#include "shading.glsl"
#include "lab2_projective/shaders/shadow_lookup.glsl"
#include "lab3_bias/shaders/bias.glsl"
#include "lab4_pcf/shaders/pcf.glsl"
#include "shadow_inputs.glsl"

uniform int u_filter_mode;       // sl_filter_mode
uniform int u_grid_radius;       // texels
uniform float u_poisson_radius;  // texels
uniform float u_light_size_uv;   // the light's width over the width of its frustum at the near plane
uniform float u_light_near;
uniform float u_light_far;

out vec4 frag_color;

void main() {
    float visibility = 1.0;
    if (u_shadows != 0) {
        vec4 coord;
        float bias;
        sl_biased_lookup(coord, bias);
#ifdef SL_HARDWARE_COMPARE
        visibility = pcf_hardware(u_shadow_map, coord, bias);
#else
        if (u_filter_mode == 2)
            visibility = pcf_grid(u_shadow_map, coord, bias, u_grid_radius);
        else if (u_filter_mode == 3)
            visibility = pcf_poisson(u_shadow_map, coord, bias, u_poisson_radius, gl_FragCoord.xy);
        else if (u_filter_mode == 4)
            visibility = pcss(u_shadow_map, coord, bias, u_light_size_uv, u_light_near, u_light_far);
        else
            visibility = shadow_compare_manual(u_shadow_map, coord, bias);
#endif
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
