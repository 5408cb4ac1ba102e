#version 330 core
// Lab 5's debug view: one channel of the moments in grey (u_channel 0: the
// mean depth; 1: the second moment), and the variance in red on top where
// it is above the minimum: what the blur spreads across edges.
in vec2 v_uv;
uniform sampler2D u_texture;
uniform int u_channel;
out vec4 frag_color;
void main() {
    vec2 m = textureLod(u_texture, v_uv, 0.0).rg;
    float grey = u_channel == 0 ? m.x : m.y;
    float variance = max(m.y - m.x * m.x, 0.0);
    float red = clamp(sqrt(variance) * 20.0, 0.0, 1.0);
    frag_color = vec4(mix(vec3(grey), vec3(1.0, 0.2, 0.1), red * 0.8), 1.0);
}
