// What the camera-pass fragment shaders of labs 3 and 4 share (framework code):
// the shadow map, the bias settings, and lab 3's choice of lookup position and bias.

in vec3 v_world_position;
in vec3 v_world_normal;
in vec4 v_shadow_coord;

#ifdef SL_HARDWARE_COMPARE
uniform sampler2DShadow u_shadow_map;
#else
uniform sampler2D u_shadow_map;
#endif
uniform int u_shadows;           // 0 until labs 1 and 2 give a shadow map and matrices
uniform mat4 u_shadow_matrix;    // W * Lp * Lv
uniform float u_depth_bias;      // constant bias
uniform float u_slope_bias;
uniform float u_max_bias;
uniform float u_normal_offset;   // texels
uniform float u_texel_size;      // world size of a texel: directional; per unit distance: spot

const int SL_BIAS_NONE = 0;
const int SL_BIAS_CONSTANT = 1;
const int SL_BIAS_SLOPE_SCALED = 2;
const int SL_BIAS_POLYGON_OFFSET = 3;
const int SL_BIAS_FRONT_FACE_CULLING = 4;
const int SL_BIAS_NORMAL_OFFSET = 5;
const int SL_BIAS_MIDPOINT = 6;

// The bias mode (sl_bias_mode) is compiled in: the framework builds one program
// per mode (#define SL_BIAS_MODE), so the tests below are constant, the other
// modes' code is dropped, and a software rasteriser does not run it per pixel.
const int sl_bias_mode = SL_BIAS_MODE;

// Lab 3: where to look the point up, and with what bias, for the chosen mode.
void sl_biased_lookup(out vec4 shadow_coord, out float bias) {
    vec3 n = normalize(v_world_normal);
    float n_dot_l = dot(n, sl_direction_to_light(v_world_position));
    shadow_coord = v_shadow_coord;
    bias = 0.0;
    if (sl_bias_mode == SL_BIAS_CONSTANT) {
        bias = u_depth_bias;
    } else if (sl_bias_mode == SL_BIAS_SLOPE_SCALED) {
        bias = slope_scaled_bias(clamp(n_dot_l, 0.0, 1.0), u_depth_bias, u_slope_bias, u_max_bias);
    } else if (sl_bias_mode == SL_BIAS_MIDPOINT) {
        bias = 0.0; // handled by midpoint_compare (scene_bias.frag)
    } else if (sl_bias_mode == SL_BIAS_NORMAL_OFFSET) {
        float texel = sl_light_type == 0 ? u_texel_size : u_texel_size * distance(u_light_position, v_world_position);
        vec3 moved = normal_offset_position(v_world_position, n, clamp(n_dot_l, 0.0, 1.0), texel, u_normal_offset);
        shadow_coord = u_shadow_matrix * vec4(moved, 1.0);
        bias = u_depth_bias;
    }
}
