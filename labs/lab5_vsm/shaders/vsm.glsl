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
