#version 330 core
// Camera pass for lab 6: each pixel picks its cascade by its view depth in the
// camera the cascades were fitted to, and is compared in that cascade's layer.
#include "shading.glsl"
#include "lab6_cascades/shaders/cascades.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;

uniform int u_shadows;
uniform sampler2DArray u_cascades;
uniform int u_cascade_count;
uniform vec4 u_split_far;          // the far split of each cascade (view depth)
uniform vec4 u_split_near;         // the near split of each cascade
uniform float u_blend_band;        // bonus: the fraction of each cascade blended with the next (0: off)
uniform mat4 u_cascade_matrix[4];  // W * Lp * Lv per cascade (lab 2's shadow matrix)
uniform mat4 u_fit_view;           // the view matrix of the camera the cascades were fitted to
uniform vec4 u_texel_world;        // world size of one texel, per cascade
uniform vec4 u_depth_per_world;    // depth-buffer units per world unit along the light, per cascade
uniform int u_show_cascades;

out vec4 frag_color;

// One colour per cascade for the debug tint (sl_cascade_colours in sl_lab6_cascades.c, which the viewer's
// legend and the --case view show too).
uniform vec3 u_cascade_colours[4];

// The shadow test in cascade m (its matrix and texel size) at layer `layer`, as your cascade_compare() does it.
float sl_cascade_lookup(int layer, int m, vec3 n, float n_dot_l) {
    float texel = u_texel_world[m];
    vec3 moved = v_world_position + n * texel * (1.0 - 0.5 * n_dot_l);
    vec4 coord = u_cascade_matrix[m] * vec4(moved, 1.0);
    float bias = 1.5 * texel * u_depth_per_world[m];
    return cascade_compare(u_cascades, layer, coord, bias);
}

void main() {
    float visibility = 1.0;
    int layer = -1;
    if (u_shadows != 0) {
        vec3 view_position = (u_fit_view * vec4(v_world_position, 1.0)).xyz;
        layer = cascade_index(view_position, u_split_far, u_cascade_count);
        // an index outside the cascades reads no matrix (the lookup sees layer as given)
        int m = clamp(layer, 0, u_cascade_count - 1);
        // Bias in world units, so it follows each cascade's texel size: the
        // point moved one texel along its normal (less when it faces the light),
        // and one and a half texels of depth (Holbert's normal offset; framework code).
        vec3 n = normalize(v_world_normal);
        float n_dot_l = clamp(dot(n, sl_direction_to_light(v_world_position)), 0.0, 1.0);
        visibility = sl_cascade_lookup(layer, m, n, n_dot_l);
        // bonus (lab6.6): near the end of a cascade, fade into the next one
        if (u_blend_band > 0.0 && m < u_cascade_count - 1) {
            float w = cascade_blend(-view_position.z, u_split_near[m], u_split_far[m], u_blend_band);
            if (w > 0.0) visibility = mix(visibility, sl_cascade_lookup(layer + 1, m + 1, n, n_dot_l), w);
        }
    }
    if (u_output == 3) {
        frag_color = vec4(float(layer), 0.0, 0.0, 1.0);
        return;
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
    if (u_show_cascades != 0 && u_output == 0 && layer >= 0)
        frag_color.rgb = mix(frag_color.rgb, u_cascade_colours[clamp(layer, 0, 3)], 0.35);
}
