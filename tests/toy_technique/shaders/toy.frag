#version 330 core
// The test technique's visibility, the same everywhere, as grey.
uniform float u_visibility;

out vec4 frag_color;

void main() {
    frag_color = vec4(vec3(u_visibility), 1.0);
}
