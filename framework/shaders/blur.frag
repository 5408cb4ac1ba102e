#version 330 core
// Lab 5's blur: one direction of the separable Gaussian, one texel per fragment.
#include "lab5_vsm/shaders/blur.glsl"

in vec2 v_uv;
uniform sampler2D u_moments;
uniform vec2 u_direction;
uniform int u_radius;
out vec4 frag_moments;

void main() {
    frag_moments = vec4(blur_moments(u_moments, v_uv, u_direction, u_radius), 0.0, 1.0);
}
