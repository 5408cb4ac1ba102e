// Lab 5: the variance shadow map lookup (camera pass, fragment shader). The
// framework fetches the filtered moments at the point's shadow-map position
// and calls chebyshev_upper_bound, then reduce_light_bleeding; `t` is the
// point's depth from the light, as compute_moments got it.
// Until they are written, the bound returns 1.0 (no shadow) and the
// reduction returns p_max unchanged.

// ---- Given ------------------------------------------------------------------------
// 0 below lo, 1 above hi, linear between.
float linstep(float lo, float hi, float v) {
    return clamp((v - lo) / (hi - lo), 0.0, 1.0);
}

// ---- Step 7: Chebyshev's one-sided upper bound (Donnelly & Lauritzen 2006) --------
float chebyshev_upper_bound(vec2 moments, float t, float min_variance) {
    // TODO(lab5.7): README.md, "Chebyshev's inequality":
    //   mu = moments.x; if t <= mu the point is in front: return 1.0
    //   variance = max(moments.y - mu^2, min_variance)
    //   return variance / (variance + (t - mu)^2)
    return 1.0;
}

// ---- Step 8: light-bleeding reduction (Lauritzen 2007, GPU Gems 3 ch. 8) ----------
float reduce_light_bleeding(float p_max, float amount) {
    // TODO(lab5.8): README.md, "Light bleeding": cut off the tail of p_max
    // below `amount` and stretch the rest back to [0, 1], with linstep.
    return p_max;
}

// ---- Extension (bonus): exponential warps ------------------------------------------
// Exponential shadow maps (Annen et al. 2008; Salvi 2008): the map stores exp(c * d),
// filtered like the moments; `moment` is that filtered E[exp(c * d)], `t` the point's
// depth, `c` the exponent (at most about 80 with 32-bit floats: README.md, "Extensions").
float esm_visibility(float moment, float t, float c) {
    // TODO(lab5.9), optional: exp(-c * t) * moment, clamped to [0, 1].
    return 1.0;
}

// EVSM's warp (Lauritzen & McCool 2008): the depth mapped to a positive and a negative
// exponential, (exp(c+ * depth), -exp(-c- * depth)), exponents = (c+, c-); each warped
// depth then gets VSM's two moments.
vec2 evsm_warp(float depth, vec2 exponents) {
    // TODO(lab5.10), optional: the two warped depths.
    return vec2(0.0);
}
