#version 330 core
// The test technique's visibility, the same everywhere, as grey (red in its debug view, its key T).
uniform float u_visibility;
uniform vec3 u_tint;

out vec4 frag_color;

void main() {
    frag_color = vec4(u_visibility * u_tint, 1.0);
}
