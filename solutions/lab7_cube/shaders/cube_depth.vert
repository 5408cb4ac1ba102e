#version 330 core
// Lab 7: the depth pass's vertex shader (given, nothing to do here).
// Six passes: each vertex goes into the current face's clip space
// (u_light_view_projection = projection * face view). One layered pass:
// u_light_view_projection is the identity and cube_depth.geom projects each
// triangle into all six faces. Either way the world position goes on, so the
// fragment shader can measure its distance from the light.

layout(location = 0) in vec3 a_position;

uniform mat4 u_model;
uniform mat4 u_light_view_projection;

out Vertex {
    vec3 world_position;
} vs_out;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vs_out.world_position = world.xyz;
    gl_Position = u_light_view_projection * world;
}
