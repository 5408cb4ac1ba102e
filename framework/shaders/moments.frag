#version 330 core
// Lab 5's moments pass: the moments of the fragment's linear depth from the light.
#include "lab_prelude.glsl"
#include "vsm_depth.glsl"
#include "lab5_vsm/shaders/moments.glsl"

out vec4 frag_moments;

void main() {
    frag_moments = vec4(compute_moments(sl_vsm_depth(gl_FragCoord.z)), 0.0, 1.0);
}
