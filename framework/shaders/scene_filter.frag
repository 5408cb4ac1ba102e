#version 330 core
// Camera pass for lab 4: lab 3's biased lookup, filtered by lab 4.
#include "shading.glsl"
#include "lab2_projective/shaders/shadow_lookup.glsl"
#include "lab3_bias/shaders/bias.glsl"
// not called here, but compiled like every earlier lab's GLSL: lab 4 runs on labs 1-3
#include "lab3_bias/shaders/midpoint.glsl"
#include "lab4_pcf/shaders/pcf.glsl"
#include "shadow_inputs.glsl"

// The filter and the grid's radius are compiled in: the framework builds one
// program per filter and radius (#define SL_FILTER_MODE, SL_GRID_RADIUS), so each
// pixel runs only the chosen filter, and the grid's loops have constant bounds
// once pcf_grid() is inlined. Values as in sl_filter_mode.
#define SL_FILTER_NONE 0
#define SL_FILTER_HARDWARE 1
#define SL_FILTER_GRID 2
#define SL_FILTER_POISSON 3
#define SL_FILTER_PCSS 4

uniform float u_poisson_radius;  // texels
uniform float u_light_size_uv;   // the light's width over the width of its frustum at the near plane
// u_light_near, u_light_far: the light's planes, in the lab files' prelude (lab_prelude.glsl)

out vec4 frag_color;

void main() {
    float visibility = 1.0;
    if (u_shadows != 0) {
        vec4 coord;
        float bias;
        sl_biased_lookup(coord, bias);
#if SL_FILTER_MODE == SL_FILTER_HARDWARE
        visibility = pcf_hardware(u_shadow_map, coord, bias);
#elif SL_FILTER_MODE == SL_FILTER_GRID
        visibility = pcf_grid(u_shadow_map, coord, bias, SL_GRID_RADIUS);
#elif SL_FILTER_MODE == SL_FILTER_POISSON
        visibility = pcf_poisson(u_shadow_map, coord, bias, u_poisson_radius, gl_FragCoord.xy);
#elif SL_FILTER_MODE == SL_FILTER_PCSS
        visibility = pcss(u_shadow_map, coord, bias, u_light_size_uv, u_light_near, u_light_far);
#else
        visibility = shadow_compare_manual(u_shadow_map, coord, bias);
#endif
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
