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
