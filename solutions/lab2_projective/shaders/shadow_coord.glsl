// Lab 2, step 4: the shadow coordinate of a world position (vertex shader).
// shadow_matrix = W * Lp * Lv (lab2_shadow_matrix); the model matrix M has
// already been applied to world_position.
vec4 shadow_coord(mat4 shadow_matrix, vec4 world_position) {
    return shadow_matrix * world_position;
}
