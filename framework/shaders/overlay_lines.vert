#version 330 core
// The overlay's lines (a light's frustum, a marker): quads already in clip
// space, built on the CPU so they can be wider than a pixel.
layout(location = 0) in vec4 a_clip;
layout(location = 1) in vec4 a_color;
out vec4 v_color;
void main() {
    gl_Position = a_clip;
    v_color = a_color;
}
