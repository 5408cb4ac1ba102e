// Lab 4: the filters (fragment shader). Each gets the biased shadow coordinate
// of lab 3 (homogeneous, not yet divided) and the bias, and returns the
// fraction of the light that reaches the point, 0.0 .. 1.0.
// Until a filter is written it returns 1.0: no shadow.
// Speed: the framework builds one program per filter (and per grid radius), so
// only the filter in use runs, and `radius` arrives as a constant. Work out what
// is the same for every sample (the divide, p.z - bias, the texel size, the
// rotation) once, before the loop, not inside it.

// ---- Given: shared by the filters below (no TODO here) --------------------

// 16 points in the unit disk, at least 0.41 apart (dart throwing, fixed seed):
// a fixed pattern, so results are the same on every run.
const vec2 PCF_POISSON_DISK[16] = vec2[](
    vec2(-0.0552, -0.8003), vec2(-0.0288,  0.2479), vec2(-0.2544,  0.6151), vec2(-0.8666,  0.0488),
    vec2( 0.5174, -0.0053), vec2(-0.5927, -0.6601), vec2( 0.1417, -0.3470), vec2( 0.4121,  0.6630),
    vec2(-0.6696,  0.6331), vec2( 0.4826, -0.8500), vec2( 0.9683, -0.1818), vec2(-0.4203, -0.0849),
    vec2( 0.0948,  0.9732), vec2( 0.6713, -0.4826), vec2( 0.9246,  0.2683), vec2(-0.8898, -0.3631));

// A rotation per pixel, from an integer hash of the pixel's position: it
// turns banding into fine noise, and is the same on every run and renderer
// (no time, no floating-point hash).
mat2 pcf_rotation(vec2 pixel) {
    uvec2 q = uvec2(pixel);
    uint h = q.x * 73856093u ^ q.y * 19349663u;
    h = (h ^ (h >> 13u)) * 1274126177u;
    float angle = float(h >> 22u) * (6.28318530718 / 1024.0);
    float c = cos(angle), s = sin(angle);
    return mat2(c, s, -s, c);
}

// A perspective depth-buffer value d in [0,1] back to the distance along the
// light's view direction (near..far).
float pcf_linear_depth(float d, float near, float far) {
    float z = d * 2.0 - 1.0;
    return 2.0 * near * far / (far + near - z * (far - near));
}

// ---- Step 2: hardware 2x2 PCF ------------------------------------------------
float pcf_hardware(sampler2DShadow shadow_map, vec4 shadow_coord, float bias) {
    // TODO(lab4.2): as lab 2's shadow_compare_hardware (divide, outside the
    // frustum means lit), then ONE texture() call. With GL_LINEAR set in
    // lab4_configure_shadow_texture, it returns the blend of 4 comparisons.
    return 1.0;
}

// ---- Step 3: (2r+1) x (2r+1) grid ------------------------------------------
float pcf_grid(sampler2D shadow_map, vec4 shadow_coord, float bias, int radius) {
    // TODO(lab4.3): divide and outside test as in lab 2, then for every
    // offset (x, y) in [-radius, radius]^2, compare p.z - bias with the depth
    // at p.xy + (x, y) texels (one texel = 1.0 / textureSize(shadow_map, 0)).
    // Return the average of the comparison results (1 lit, 0 shadowed):
    // average the RESULTS, never the depths. README.md, "Why not filter depths".
    return 1.0;
}

// ---- Step 4: rotated Poisson disk ----------------------------------------------
float pcf_poisson(sampler2D shadow_map, vec4 shadow_coord, float bias, float radius_texels, vec2 pixel) {
    // TODO(lab4.4): as pcf_grid, but the 16 offsets are
    // pcf_rotation(pixel) * PCF_POISSON_DISK[i] * radius_texels texels.
    return 1.0;
}

// ---- Step 5: percentage-closer soft shadows (Fernando 2005) --------------------
float pcss(sampler2D shadow_map, vec4 shadow_coord, float bias, float light_size_uv, float near, float far) {
    // TODO(lab4.5): README.md, "PCSS", with distances from pcf_linear_depth():
    //   1. blocker search: over the 16 rotated Poisson offsets scaled by
    //      light_size_uv * (d_receiver - near) / d_receiver, average the
    //      distances of the depths nearer than p.z - bias; none: return 1.0
    //   2. penumbra: w = (d_receiver - d_blocker) * light_size_uv / d_blocker,
    //      on the map: w * near / d_receiver
    //   3. Poisson PCF with that radius (in uv, not texels)
    return 1.0;
}
