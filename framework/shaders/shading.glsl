// Lambert shading shared by the camera-pass shaders (framework code).
// The light (sl_light_type, its uniforms, sl_direction_to_light) is the lab
// files' prelude: they may call it wherever they are compiled.
#include "lab_prelude.glsl"
uniform int u_output;         // 0 shaded, 1 visibility
uniform vec3 u_light_radiance;
uniform float u_spot_cos;
uniform vec3 u_albedo;

// The colour of a surface point given the light's visibility there.
// u_output 1: the visibility term alone (what the grader compares);
// u_output 2: white where a surface faces the light (the "lit surfaces" mask).
vec4 sl_shade(vec3 world_position, vec3 world_normal, float visibility) {
    vec3 n = normalize(world_normal);
    vec3 to_light = sl_direction_to_light(world_position);
    float n_dot_l = max(dot(n, to_light), 0.0);
    if (u_output == 1) {
        // Surfaces turned away from the light get no light whatever the map says.
        return vec4(vec3(n_dot_l > 0.0 ? visibility : 0.0), 1.0);
    }
    if (u_output == 2) return vec4(vec3(n_dot_l > 0.0 ? 1.0 : 0.0), 1.0);
    float cone = 1.0;
    if (sl_light_type == 1) {
        // soft edge over the outer 10% of the cone
        float c = dot(-to_light, u_light_direction);
        cone = smoothstep(u_spot_cos, mix(u_spot_cos, 1.0, 0.1), c);
    }
    vec3 ambient = 0.18 * u_albedo;
    vec3 direct = u_albedo * u_light_radiance * n_dot_l * cone * visibility;
    return vec4(pow(ambient + direct, vec3(1.0 / 2.2)), 1.0);
}
