// Lab 4: the filters (fragment shader). Each gets the biased shadow coordinate
// of lab 3 (homogeneous, not yet divided) and the bias, and returns the
// fraction of the light that reaches the point, 0.0 .. 1.0.
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

// Projects a shadow coordinate; false when the point is outside the light's frustum.
bool pcf_project(vec4 shadow_coord, out vec3 p) {
    p = shadow_coord.xyz / shadow_coord.w;
    return shadow_coord.w > 0.0 && all(greaterThanEqual(p, vec3(0.0))) && all(lessThanEqual(p, vec3(1.0)));
}

// ---- Step 2: hardware 2x2 PCF ------------------------------------------------
// With GL_LINEAR and compare mode on, one texture() call returns the bilinear
// blend of four comparison results.
float pcf_hardware(sampler2DShadow shadow_map, vec4 shadow_coord, float bias) {
    vec3 p;
    if (!pcf_project(shadow_coord, p)) return 1.0;
    return texture(shadow_map, vec3(p.xy, p.z - bias));
}

// One comparison at uv: 1.0 lit, 0.0 shadowed.
float pcf_compare(sampler2D shadow_map, vec2 uv, float depth) {
    return depth > texture(shadow_map, uv).r ? 0.0 : 1.0;
}

// ---- Step 3: (2r+1) x (2r+1) grid ------------------------------------------
// Average the comparisons, never the depths (Reeves et al. 1987).
float pcf_grid(sampler2D shadow_map, vec4 shadow_coord, float bias, int radius) {
    vec3 p;
    if (!pcf_project(shadow_coord, p)) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
    float lit = 0.0;
    for (int y = -radius; y <= radius; y++)
        for (int x = -radius; x <= radius; x++)
            lit += pcf_compare(shadow_map, p.xy + vec2(x, y) * texel, p.z - bias);
    float side = float(2 * radius + 1);
    return lit / (side * side);
}

// ---- Step 4: rotated Poisson disk ----------------------------------------------
float pcf_poisson(sampler2D shadow_map, vec4 shadow_coord, float bias, float radius_texels, vec2 pixel) {
    vec3 p;
    if (!pcf_project(shadow_coord, p)) return 1.0;
    vec2 scale = radius_texels / vec2(textureSize(shadow_map, 0));
    mat2 rotation = pcf_rotation(pixel);
    float lit = 0.0;
    for (int i = 0; i < 16; i++)
        lit += pcf_compare(shadow_map, p.xy + rotation * PCF_POISSON_DISK[i] * scale, p.z - bias);
    return lit / 16.0;
}

// ---- Step 5: percentage-closer soft shadows (Fernando 2005) --------------------
float pcss(sampler2D shadow_map, vec4 shadow_coord, float bias, float light_size_uv, float near, float far) {
    vec3 p;
    if (!pcf_project(shadow_coord, p)) return 1.0;
    float receiver = pcf_linear_depth(p.z, near, far);
    mat2 rotation = pcf_rotation(gl_FragCoord.xy);

    // 1. Blocker search: the part of the map through which the receiver sees the light.
    float search_uv = light_size_uv * (receiver - near) / receiver;
    float blocker_sum = 0.0;
    int blockers = 0;
    for (int i = 0; i < 16; i++) {
        float d = texture(shadow_map, p.xy + rotation * PCF_POISSON_DISK[i] * search_uv).r;
        if (d < p.z - bias) {
            blocker_sum += pcf_linear_depth(d, near, far);
            blockers++;
        }
    }
    if (blockers == 0) return 1.0; // nothing between the point and the light

    // 2. Penumbra width on the receiver, by similar triangles:
    //    w = (d_receiver - d_blocker) * w_light / d_blocker,
    //    then projected back onto the map (near plane): * near / d_receiver.
    float blocker = blocker_sum / float(blockers);
    float penumbra_uv = (receiver - blocker) * light_size_uv / blocker * near / receiver;

    // 3. PCF over that width.
    float lit = 0.0;
    for (int i = 0; i < 16; i++)
        lit += pcf_compare(shadow_map, p.xy + rotation * PCF_POISSON_DISK[i] * penumbra_uv, p.z - bias);
    return lit / 16.0;
}
