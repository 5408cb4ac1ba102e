// Lab 5: one pass of the separable Gaussian blur of the moments (fragment
// shader). Called once per texel of the target; `uv` is that texel's centre,
// `direction` (1, 0) for the horizontal pass and (0, 1) for the vertical one.

// ---- Step 5: a 1D Gaussian along `direction` ------------------------------------
vec2 blur_moments(sampler2D moments, vec2 uv, vec2 direction, int radius) {
    // sigma = radius / 2: the weights at the ends are e^-2, about 0.14 of the centre's
    float sigma = max(float(radius) * 0.5, 0.5);
    // whole texels from the centre one: texelFetch, no filtering needed; the edge texels repeat
    ivec2 size = textureSize(moments, 0);
    ivec2 centre = ivec2(uv * vec2(size));
    ivec2 step = ivec2(direction);
    vec2 sum = vec2(0.0);
    float weights = 0.0;
    for (int i = -radius; i <= radius; i++) {
        float w = exp(-float(i * i) / (2.0 * sigma * sigma));
        sum += w * texelFetch(moments, clamp(centre + i * step, ivec2(0), size - 1), 0).rg;
        weights += w;
    }
    return sum / weights;
}
