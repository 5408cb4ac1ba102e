// Lab 3, steps 2 and 3: the lookup's share of the bias (fragment shader).

// Slope-scaled bias: a surface seen at a grazing angle spans a wide depth
// range inside one texel, so it needs more bias. tan(theta) = sin/cos, with
// cos(theta) = N.L; clamped, because tan grows without bound at 90 degrees.
float slope_scaled_bias(float n_dot_l, float constant_bias, float slope, float max_bias) {
    float cos_theta = max(n_dot_l, 1e-4);
    float tan_theta = sqrt(1.0 - cos_theta * cos_theta) / cos_theta;
    return min(constant_bias + slope * tan_theta, max_bias);
}

// Normal offset (Holbein 2011): look the point up a little off the surface,
// along its normal, by a few texels, more the more the surface turns away
// from the light.
vec3 normal_offset_position(vec3 world_position, vec3 normal, float n_dot_l, float texel_world_size, float texels) {
    return world_position + normal * (texels * texel_world_size * (1.0 - n_dot_l));
}
