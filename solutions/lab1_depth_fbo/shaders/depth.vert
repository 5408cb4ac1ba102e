#version 330 core
// Lab 1, step 4 (TODO lab1.4): the depth pass's vertex shader.
// Each vertex goes from object space to the light's clip space; the rasterizer
// then writes its depth into the shadow map.

layout(location = 0) in vec3 a_position;

uniform mat4 u_model;                 // object -> world
uniform mat4 u_light_view_projection; // world -> light clip space (Lp * Lv)

void main() {
    gl_Position = u_light_view_projection * u_model * vec4(a_position, 1.0);
}
