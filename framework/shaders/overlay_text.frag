#version 330 core
// A glyph's texel is 1 where the glyph is set; backings use a solid texel.
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_font;
out vec4 frag_color;

void main() {
    float ink = texture(u_font, v_uv).r;
    if (ink < 0.5) discard;
    frag_color = v_color;
}
