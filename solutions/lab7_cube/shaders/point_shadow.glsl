// Lab 7: the lookup in the cube map (fragment shader). Each function gets the
// vector from the light to the fragment (world space, not normalised), the
// light's far plane and the bias (in units of distance / far), and returns the
// fraction of the light that reaches the fragment: 1.0 lit, 0.0 shadowed.
// Until a function is written it returns 1.0: no shadow.

// ---- Given: the 20 offset directions of the soft lookup (no TODO here) ----
// The 8 corners and 12 edge midpoints of a cube: spread over every side of
// the lookup direction, a fixed pattern so results are the same on every run.
const vec3 POINT_SHADOW_OFFSETS[20] = vec3[](
    vec3( 1,  1,  1), vec3( 1, -1,  1), vec3(-1, -1,  1), vec3(-1,  1,  1),
    vec3( 1,  1, -1), vec3( 1, -1, -1), vec3(-1, -1, -1), vec3(-1,  1, -1),
    vec3( 1,  1,  0), vec3( 1, -1,  0), vec3(-1, -1,  0), vec3(-1,  1,  0),
    vec3( 1,  0,  1), vec3(-1,  0,  1), vec3( 1,  0, -1), vec3(-1,  0, -1),
    vec3( 0,  1,  1), vec3( 0, -1,  1), vec3( 0, -1, -1), vec3( 0,  1, -1));

// ---- Step 6: the lookup ------------------------------------------------------
float point_shadow(samplerCube cube_map, vec3 light_to_fragment, float far_plane, float bias) {
    float closest = texture(cube_map, light_to_fragment).r;
    float current = length(light_to_fragment) / far_plane;
    return current - bias > closest ? 0.0 : 1.0;
}

// ---- Step 7: the soft lookup ------------------------------------------------
float point_shadow_soft(samplerCube cube_map, vec3 light_to_fragment, float far_plane, float bias, float radius) {
    float distance = length(light_to_fragment);
    float current = distance / far_plane - bias;
    // The disk grows with the distance: the same angle seen from the light.
    float disk = radius * distance / far_plane;
    float lit = 0.0;
    for (int i = 0; i < 20; i++) {
        float closest = texture(cube_map, light_to_fragment + POINT_SHADOW_OFFSETS[i] * disk).r;
        lit += current > closest ? 0.0 : 1.0;
    }
    return lit / 20.0;
}
