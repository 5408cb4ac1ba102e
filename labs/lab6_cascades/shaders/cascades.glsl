// Lab 6, steps 4 and 5: pick a pixel's cascade, and compare in its layer.
// The camera pass (framework/shaders/scene_cascades.frag) calls both.

// TODO(lab6.4): the cascade a point uses. view_position is the point in the
// camera's view space (the camera looks down -z); split_far[i] is the view
// depth where cascade i ends. Returns 0..count-1: the first cascade whose far
// split is beyond the point's VIEW DEPTH (-view_position.z, not its distance
// to the camera), and the last one for anything further. README.md,
// "Choosing a cascade".
int cascade_index(vec3 view_position, vec4 split_far, int count) {
    return 0;
}

// TODO(lab6.5): the shadow test in layer `layer` of the cascade array:
// divide shadow_coord by w; beyond the far plane (p.z > 1) it is lit; read the
// stored depth with texture(cascades, vec3(p.xy, float(layer))).r and return
// 0.0 where p.z - bias is behind it, 1.0 otherwise (as in lab 2).
float cascade_compare(sampler2DArray cascades, int layer, vec4 shadow_coord, float bias) {
    return 1.0;
}

// TODO(lab6.6), bonus: a blend band. In the last `band` fraction of a
// cascade's depth range (split_near..split_far), return the weight of the
// NEXT cascade: 0 at split_far - band * (split_far - split_near), growing
// linearly to 1 at split_far; 0 before that, and 0 when band <= 0. The
// framework then mixes the two cascades' results (README.md, "Blend band").
float cascade_blend(float view_depth, float split_near, float split_far, float band) {
    return 0.0;
}
