// Lab 3, steps 2 and 3: the lookup's share of the bias (fragment shader).

// Slope-scaled bias: a surface seen at a grazing angle spans a wide depth
// range inside one texel, so it needs more bias.
//   n_dot_l        cos(theta), theta the angle between the normal and the light (>= 0)
//   constant_bias  the bias a surface facing the light head-on gets
//   slope          how much bias per unit of tan(theta)
//   max_bias       the largest bias to return
float slope_scaled_bias(float n_dot_l, float constant_bias, float slope, float max_bias) {
    // TODO(lab3.2): return constant_bias + slope * tan(theta), at most max_bias.
    // tan(theta) = sin(theta) / cos(theta); sin from cos with sqrt(1 - cos^2).
    // Guard against cos(theta) = 0. README.md, "Slope-scaled bias".
    // Until then: no bias, so acne everywhere.
    return 0.0;
}

// Normal offset: look the point up a little off the surface, along its normal.
//   texel_world_size  the world size of one shadow-map texel at this point
//   texels            how many texels to move at most
vec3 normal_offset_position(vec3 world_position, vec3 normal, float n_dot_l, float texel_world_size, float texels) {
    // TODO(lab3.3): move world_position along normal by
    // texels * texel_world_size * (1 - n_dot_l). README.md, "Normal offset".
    return world_position;
}
