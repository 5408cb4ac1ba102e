#version 330 core
// Lab 7, step 5 (TODO lab7.5): the depth pass's fragment shader.
// A cube map's faces are six perspective cameras whose depth-buffer values
// (gl_FragCoord.z) measure distance along each face's own axis, non-linearly.
// The lookup has only a direction and a distance, so store the distance itself.

in Vertex {
    vec3 world_position;
} fs_in;

uniform vec3 u_light_position; // world space
uniform float u_light_far;     // the light's far plane: distance / far lies in [0, 1]

void main() {
    gl_FragDepth = length(fs_in.world_position - u_light_position) / u_light_far;
}
