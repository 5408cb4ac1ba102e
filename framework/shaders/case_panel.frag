#version 330 core
// The viewer's --case panels: a picture as it is, no shading.
in vec2 v_uv;
uniform sampler2D u_texture;
out vec4 frag_color;

void main() {
    frag_color = vec4(texture(u_texture, v_uv).rgb, 1.0);
}
