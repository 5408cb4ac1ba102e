#version 330 core
// Camera pass without shadows (see plain.vert).
#include "shading.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;

out vec4 frag_color;

void main() {
    frag_color = sl_shade(v_world_position, v_world_normal, 1.0);
}
