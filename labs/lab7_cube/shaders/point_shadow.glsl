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
    // TODO(lab7.6): the direction from the light to the fragment picks the
    // texel: texture(cube_map, light_to_fragment).r is the nearest surface's
    // distance / far along it (no need to normalise: only the direction counts).
    // Compare the fragment's own distance, divided by far_plane too, minus
    // bias, with it: farther means something is in front (0.0), else 1.0.
    return 1.0;
}

// ---- Step 7: the soft lookup ------------------------------------------------
float point_shadow_soft(samplerCube cube_map, vec3 light_to_fragment, float far_plane, float bias, float radius) {
    // TODO(lab7.7): the same comparison on 20 directions around
    // light_to_fragment: light_to_fragment + POINT_SHADOW_OFFSETS[i] * disk,
    // where disk = radius * distance / far_plane grows with the distance from
    // the light (radius is the disk's size at the far plane, world units).
    // Return the fraction of the 20 comparisons that are lit.
    return 1.0;
}
