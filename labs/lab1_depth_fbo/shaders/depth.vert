#version 330 core
// Lab 1, step 4 (TODO lab1.4): the depth pass's vertex shader.
// Each vertex goes from object space to the light's clip space; the rasterizer
// then writes its depth into the shadow map.

layout(location = 0) in vec3 a_position;

uniform mat4 u_model;                 // object -> world
uniform mat4 u_light_view_projection; // world -> light clip space (Lp * Lv)

void main() {
    // TODO(lab1.4): transform a_position (object space) into the light's clip
    // space with u_model and u_light_view_projection. See README.md, "The depth pass".
    // Until then every vertex is put outside the clip volume, so nothing is drawn.
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
}
