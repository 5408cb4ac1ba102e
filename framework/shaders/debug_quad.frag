#version 330 core
// Shows a depth texture in grey: near = black, far = white. A perspective
// (spot) light's depths crowd near 1, so they are shown linearised.
in vec2 v_uv;
uniform sampler2D u_texture;
uniform int u_perspective;
uniform float u_near;
uniform float u_far;
out vec4 frag_color;
void main() {
    float d = texture(u_texture, v_uv).r;
    if (u_perspective != 0 && d < 1.0) {
        float z = d * 2.0 - 1.0;
        float distance = 2.0 * u_near * u_far / (u_far + u_near - z * (u_far - u_near));
        d = (distance - u_near) / (u_far - u_near);
    }
    frag_color = vec4(vec3(d), 1.0);
}
