// Lab 2, step 5: the shadow test (fragment shader).
// shadow_coord is W * Lp * Lv * world, interpolated: still homogeneous.
// Returns 1.0 where the light reaches the point, 0.0 where it is in shadow.

// True when the point lies outside the light's frustum: nothing there can shadow it.
bool outside_light_frustum(vec4 shadow_coord, vec3 p) {
    return shadow_coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)));
}

// With a sampler2D: read the stored depth, compare it yourself.
float shadow_compare_manual(sampler2D shadow_map, vec4 shadow_coord, float bias) {
    vec3 p = shadow_coord.xyz / shadow_coord.w;   // perspective divide (w = 1 for ortho)
    if (outside_light_frustum(shadow_coord, p)) return 1.0; // nothing there casts a shadow
    float closest = texture(shadow_map, p.xy).r;  // depth of the nearest occluder
    return p.z - bias > closest ? 0.0 : 1.0;
}

// With a sampler2DShadow (GL_TEXTURE_COMPARE_MODE set, GL_LEQUAL): the texture
// unit does the comparison and returns its result.
float shadow_compare_hardware(sampler2DShadow shadow_map, vec4 shadow_coord, float bias) {
    vec3 p = shadow_coord.xyz / shadow_coord.w;
    if (outside_light_frustum(shadow_coord, p)) return 1.0;
    return texture(shadow_map, vec3(p.xy, p.z - bias));
}
