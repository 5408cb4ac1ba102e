// Lab 2, step 4: the shadow coordinate of a world position (vertex shader).
// shadow_matrix = W * Lp * Lv (lab2_shadow_matrix); the model matrix M has
// already been applied to world_position.
vec4 shadow_coord(mat4 shadow_matrix, vec4 world_position) {
    // TODO(lab2.4): return the shadow coordinate of world_position.
    // README.md, "The coordinate chain". Do NOT divide by w here: the
    // division must happen per fragment, after interpolation.
    return vec4(0.0);
}
