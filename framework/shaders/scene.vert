#version 330 core
// Camera pass: world position, normal and the lab 2 shadow coordinate per vertex.
#include "lab_prelude.glsl"
#include "lab2_projective/shaders/shadow_coord.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform mat4 u_shadow_matrix; // W * Lp * Lv, from lab2_shadow_matrix()

out vec3 v_world_position;
out vec3 v_world_normal;
out vec4 v_shadow_coord;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world_position = world.xyz;
    v_world_normal = u_normal_matrix * a_normal;
    v_shadow_coord = shadow_coord(u_shadow_matrix, world);
    gl_Position = u_projection * u_view * world;
}
