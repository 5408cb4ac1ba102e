#version 330 core
// Camera pass: Lambert shading with the shadow test from lab 2.
// u_output 1 writes the visibility term alone (what the grader compares).
#include "lab2_projective/shaders/shadow_lookup.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;
in vec4 v_shadow_coord;

#ifdef SL_HARDWARE_COMPARE
uniform sampler2DShadow u_shadow_map;
#else
uniform sampler2D u_shadow_map;
#endif
uniform int u_shadows;        // 0 until labs 1 and 2 give a shadow map and matrices
uniform float u_depth_bias;
uniform int u_output;         // 0 shaded, 1 visibility
uniform int u_light_type;     // 0 directional, 1 spot, 2 point
uniform vec3 u_light_position;
uniform vec3 u_light_direction;
uniform vec3 u_light_radiance;
uniform float u_spot_cos;
uniform vec3 u_albedo;

out vec4 frag_color;

void main() {
    vec3 n = normalize(v_world_normal);
    vec3 to_light = u_light_type == 0 ? -u_light_direction : normalize(u_light_position - v_world_position);
    float n_dot_l = max(dot(n, to_light), 0.0);
    float cone = 1.0;
    if (u_light_type == 1) {
        // soft edge over the outer 10% of the cone
        float c = dot(-to_light, u_light_direction);
        cone = smoothstep(u_spot_cos, mix(u_spot_cos, 1.0, 0.1), c);
    }

    float visibility = 1.0;
    if (u_shadows != 0) {
#ifdef SL_HARDWARE_COMPARE
        visibility = shadow_compare_hardware(u_shadow_map, v_shadow_coord, u_depth_bias);
#else
        visibility = shadow_compare_manual(u_shadow_map, v_shadow_coord, u_depth_bias);
#endif
    }

    if (u_output == 1) {
        // Surfaces turned away from the light get no light whatever the map says.
        frag_color = vec4(vec3(n_dot_l > 0.0 ? visibility : 0.0), 1.0);
        return;
    }
    vec3 ambient = 0.18 * u_albedo;
    vec3 direct = u_albedo * u_light_radiance * n_dot_l * cone * visibility;
    frag_color = vec4(pow(ambient + direct, vec3(1.0 / 2.2)), 1.0);
}
