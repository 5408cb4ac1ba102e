// Lab 2, step 5: the shadow test (fragment shader).
// shadow_coord is W * Lp * Lv * world, interpolated: still homogeneous.
// Return 1.0 where the light reaches the point, 0.0 where it is in shadow.

// With a sampler2D: read the stored depth, compare it yourself.
float shadow_compare_manual(sampler2D shadow_map, vec4 shadow_coord, float bias) {
    // TODO(lab2.5): README.md, "The shadow test".
    //   1. perspective divide: p = shadow_coord.xyz / shadow_coord.w
    //   2. outside the light's frustum (w <= 0, or any of p.x, p.y, p.z
    //      outside [0,1]): return 1.0, nothing there can cast a shadow
    //   3. closest = depth stored in the map at p.xy
    //   4. in shadow (0.0) if p.z - bias is farther than closest, else lit (1.0)
    return 1.0;
}

// With a sampler2DShadow (GL_TEXTURE_COMPARE_MODE set, compare func GL_LEQUAL):
// texture(shadow_map, vec3(uv, depth)) does the comparison for you and
// returns its result.
float shadow_compare_hardware(sampler2DShadow shadow_map, vec4 shadow_coord, float bias) {
    // TODO(lab2.6): same steps 1 and 2 as above, then let the texture unit
    // compare p.z - bias with the stored depth.
    return 1.0;
}
