#version 330 core
// Lab 5's blur: one direction of the separable Gaussian, one texel per fragment.
#include "lab_prelude.glsl"
#include "lab5_vsm/shaders/blur.glsl"

in vec2 v_uv;
uniform sampler2D u_moments;
uniform vec2 u_direction;
// The radius is compiled in (#define SL_BLUR_RADIUS, one program per radius, as
// lab 4's grid): once blur_moments() is inlined its loop has constant bounds and
// its weights are constants, and llvmpipe unrolls it.
out vec4 frag_moments;

void main() {
    frag_moments = vec4(blur_moments(u_moments, v_uv, u_direction, SL_BLUR_RADIUS), 0.0, 1.0);
}
