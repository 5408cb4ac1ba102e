// Lab 5 (framework code): the depth the moments are made of, and compared
// with: linear along the light's axis, in [0, 1], from a window depth z.
// A directional light's orthographic depth is linear already; a spot
// light's perspective depth is turned back into a distance first, so the
// moments average distances, not the depth buffer's 1/z values.
uniform float u_light_near;
uniform float u_light_far;

float sl_vsm_depth(float z) {
#if SL_LIGHT_TYPE == 0
    return z;
#else
    float n = u_light_near, f = u_light_far;
    float distance = 2.0 * n * f / (f + n - (z * 2.0 - 1.0) * (f - n));
    return (distance - n) / (f - n);
#endif
}
