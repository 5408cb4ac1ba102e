#version 330 core
// Lab 7, optional: the geometry shader of one layered pass (README, "Six
// passes or one"). Used only when lab7_begin_cube_pass(map, SL_CUBE_ALL_FACES)
// attaches the whole cube with glFramebufferTexture and returns SL_OK; the
// six-pass way never compiles this file.

layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

uniform mat4 u_face_view_projection[6]; // projection * view of face 0..5 (+X, -X, +Y, -Y, +Z, -Z)

in Vertex {
    vec3 world_position;
} gs_in[];

out Vertex {
    vec3 world_position;
} gs_out;

void main() {
    // Optional (layered pass): for each face 0..5, set gl_Layer = face (the
    // cube face it lands on), then emit the triangle's three vertices with
    // gl_Position = u_face_view_projection[face] * vec4(world position, 1)
    // and gs_out.world_position set, and end the primitive.
}
