#version 330 core
// A glyph's texel is its coverage: 0 or 1 in the bitmap font, anti-aliased
// edges in a TrueType face; backings use a solid texel.
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_font;
out vec4 frag_color;

void main() {
    float ink = texture(u_font, v_uv).r;
    if (ink <= 0.0) discard;
    frag_color = vec4(v_color.rgb, v_color.a * ink);
}
