// Attack: lab 2's lookup made of calls into lab 4's helpers (a 0-radius grid
// is one comparison; lab 4's hardware lookup is lab 2's): where lab 2 is
// graded with a later lab's solution in its reach (its shaders in the sandbox,
// linked into the same program), these calls answer for lab 2.
#include "lab4_pcf/shaders/pcf.glsl"

float shadow_compare_manual(sampler2D shadow_map, vec4 shadow_coord, float bias) {
    return pcf_grid(shadow_map, shadow_coord, bias, 0);
}

float shadow_compare_hardware(sampler2DShadow shadow_map, vec4 shadow_coord, float bias) {
    return pcf_hardware(shadow_map, shadow_coord, bias);
}
