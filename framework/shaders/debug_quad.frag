#version 330 core
// Shows a depth texture in grey: near = black, far = white.
in vec2 v_uv;
uniform sampler2D u_texture;
out vec4 frag_color;
void main() {
    float d = texture(u_texture, v_uv).r;
    frag_color = vec4(vec3(d), 1.0);
}
