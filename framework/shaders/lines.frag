#version 330 core
uniform vec3 u_albedo;
out vec4 frag_color;
void main() {
    frag_color = vec4(u_albedo, 1.0);
}
