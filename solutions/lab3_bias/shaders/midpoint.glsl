// Lab 3, extension: midpoint shadow maps (Woo 1992) (fragment shader).
// first_depth holds the nearest surface along each light ray, second_depth the
// second one (the far side of a closed object). A receiver is shadowed when it
// lies beyond their midpoint: far from both surfaces, so no bias is needed.
float midpoint_compare(sampler2D first_depth, sampler2D second_depth, vec4 shadow_coord) {
    vec3 p = shadow_coord.xyz / shadow_coord.w;
    if (shadow_coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    float midpoint = 0.5 * (texture(first_depth, p.xy).r + texture(second_depth, p.xy).r);
    return p.z > midpoint ? 0.0 : 1.0;
}
