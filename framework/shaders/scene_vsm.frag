#version 330 core
// Camera pass for lab 5: the variance shadow map lookup. Labs 2-4's GLSL is
// compiled too, as every lab's camera pass compiles the labs' before it.
#include "shading.glsl"
#include "lab2_projective/shaders/shadow_lookup.glsl"
#include "lab3_bias/shaders/bias.glsl"
#include "lab3_bias/shaders/midpoint.glsl"
#include "lab4_pcf/shaders/pcf.glsl"
#include "lab5_vsm/shaders/vsm.glsl"
#include "shadow_inputs.glsl"
#include "vsm_depth.glsl"

uniform sampler2D u_moments;  // lab 5's blurred, mipmapped moments
uniform float u_min_variance;
uniform float u_bleeding;     // light-bleeding reduction amount

out vec4 frag_color;

void main() {
    float visibility = 1.0;
    if (u_shadows != 0) {
        vec3 p = v_shadow_coord.xyz / v_shadow_coord.w;
        // fetched before any branch: trilinear filtering needs the neighbours' coordinates
        vec2 moments = texture(u_moments, p.xy).rg;
        bool outside = v_shadow_coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)));
        if (!outside)
            visibility = reduce_light_bleeding(chebyshev_upper_bound(moments, sl_vsm_depth(p.z), u_min_variance),
                                               u_bleeding);
    }
    frag_color = sl_shade(v_world_position, v_world_normal, visibility);
}
