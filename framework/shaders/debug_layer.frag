#version 330 core
// Shows one layer of lab 6's cascade array in grey: near = black, far = white.
in vec2 v_uv;
uniform sampler2DArray u_layers;
uniform int u_layer;
out vec4 frag_color;
void main() {
    float d = texture(u_layers, vec3(v_uv, float(u_layer))).r;
    frag_color = vec4(vec3(d), 1.0);
}
