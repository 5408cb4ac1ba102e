// Lab 6, steps 4 and 5: pick a pixel's cascade, and compare in its layer.
// The camera pass (framework/shaders/scene_cascades.frag) calls both.

// TODO(lab6.4): the cascade a point uses. view_position is the point in the
// camera's view space (the camera looks down -z); split_far[i] is the view
// depth where cascade i ends. Returns 0..count-1.
int cascade_index(vec3 view_position, vec4 split_far, int count) {
    // View depth, not distance: the splits cut the frustum with planes
    // perpendicular to the view direction, so a point off to the side at the
    // same depth belongs to the same slice.
    float depth = -view_position.z;
    for (int i = 0; i < 3; i++)
        if (i < count - 1 && depth < split_far[i]) return i;
    return count - 1;
}

// TODO(lab6.5): the shadow test in layer `layer` of the cascade array:
// divide by w, read the stored depth at (s, t) in that layer, compare.
float cascade_compare(sampler2DArray cascades, int layer, vec4 shadow_coord, float bias) {
    vec3 p = shadow_coord.xyz / shadow_coord.w;
    if (p.z > 1.0) return 1.0; // beyond the cascade's far plane: nothing recorded there
    float stored = texture(cascades, vec3(p.xy, float(layer))).r;
    return p.z - bias > stored ? 0.0 : 1.0;
}

// TODO(lab6.6), bonus: a blend band. In the last `band` fraction of a
// cascade's depth range (split_near..split_far), the weight of the NEXT
// cascade grows linearly from 0 to 1, so the change of texel size at a split
// fades in instead of showing as a line. 0 everywhere else, 0 when band <= 0.
float cascade_blend(float view_depth, float split_near, float split_far, float band) {
    if (band <= 0.0) return 0.0;
    float start = split_far - band * (split_far - split_near);
    return clamp((view_depth - start) / (split_far - start), 0.0, 1.0);
}
