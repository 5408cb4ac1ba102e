// Lab 5: the variance shadow map lookup (camera pass, fragment shader). The
// framework fetches the filtered moments at the point's shadow-map position
// and calls chebyshev_upper_bound, then reduce_light_bleeding; `t` is the
// point's depth from the light, as compute_moments got it.

// ---- Given ------------------------------------------------------------------------
// 0 below lo, 1 above hi, linear between.
float linstep(float lo, float hi, float v) {
    return clamp((v - lo) / (hi - lo), 0.0, 1.0);
}

// ---- Step 7: Chebyshev's one-sided upper bound (Donnelly & Lauritzen 2006) --------
float chebyshev_upper_bound(vec2 moments, float t, float min_variance) {
    float mu = moments.x;
    // in front of (or on) the mean occluder: fully lit; the bound only holds for t > mu
    if (t <= mu) return 1.0;
    // E[x^2] - E[x]^2 can come out below zero in floating point: the minimum keeps it a variance
    float variance = max(moments.y - mu * mu, min_variance);
    float d = t - mu;
    return variance / (variance + d * d);
}

// ---- Step 8: light-bleeding reduction (Lauritzen 2007, GPU Gems 3 ch. 8) ----------
float reduce_light_bleeding(float p_max, float amount) {
    // cut the tail below `amount` off and stretch the rest back to [0, 1]
    return linstep(amount, 1.0, p_max);
}

// ---- Extension (bonus): exponential warps ------------------------------------------
// Exponential shadow maps (Annen et al. 2008; Salvi 2008): the map stores exp(c * d),
// filtered like the moments; `moment` is that filtered E[exp(c * d)], `t` the point's
// depth, `c` the exponent (at most about 80 with 32-bit floats: README.md, "Extensions").
float esm_visibility(float moment, float t, float c) {
    // E[exp(c (d - t))]: 1 on the occluder's own surface, falling off exponentially behind it
    return clamp(moment * exp(-c * t), 0.0, 1.0);
}

// EVSM's warp (Lauritzen & McCool 2008): the depth mapped to a positive and a negative
// exponential, (exp(c+ * depth), -exp(-c- * depth)), exponents = (c+, c-); each warped
// depth then gets VSM's two moments.
vec2 evsm_warp(float depth, vec2 exponents) {
    return vec2(exp(exponents.x * depth), -exp(-exponents.y * depth));
}
