// Lab 5: one pass of the separable Gaussian blur of the moments (fragment
// shader). Called once per texel of the target; `uv` is that texel's centre,
// `direction` (1, 0) for the horizontal pass and (0, 1) for the vertical one.
// Until it is written it returns the texel itself: no blur.

// ---- Step 5: a 1D Gaussian along `direction` ------------------------------------
vec2 blur_moments(sampler2D moments, vec2 uv, vec2 direction, int radius) {
    // TODO(lab5.5): README.md, "Separable blur": the weighted sum of the
    // 2 * radius + 1 texels i whole texels from uv along `direction`,
    // i in [-radius, radius], with Gaussian weights
    // exp(-float(i * i) / (2.0 * sigma * sigma)),
    // sigma = max(float(radius) * 0.5, 0.5) (float: radius / 2 would divide
    // integers), divided by the sum of the weights. Read level 0 only:
    // texelFetch(moments, texel, 0) with the texel clamped to the map (the edge
    // repeats), or textureLod(moments, uv + float(i) * direction /
    // vec2(textureSize(moments, 0)), 0.0). `radius` arrives as a constant: the loop
    // unrolls, so compute what does not change (sigma, the size) before it.
    return textureLod(moments, uv, 0.0).rg;
}
