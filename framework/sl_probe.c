#include "sl_probe.h"

#include <math.h>
#include <string.h>

#define _SL_F(n) {n, SL_PROBE_FLOAT}
#define _SL_I(n) {n, SL_PROBE_INT}
#define _SL_V2(n) {n, SL_PROBE_VEC2}
#define _SL_V3(n) {n, SL_PROBE_VEC3}
#define _SL_V4(n) {n, SL_PROBE_VEC4}
#define _SL_M4(n) {n, SL_PROBE_MAT4}
#define _SL_MAP(n) {n, SL_PROBE_MAP}
#define _SL_SHADOW(n) {n, SL_PROBE_SHADOW_MAP}
#define _SL_CUBE(n) {n, SL_PROBE_CUBE_MAP}
#define _SL_ARRAY(n) {n, SL_PROBE_ARRAY_MAP}
#define _SL_MOMENTS(n) {n, SL_PROBE_MOMENTS_MAP}
#define _SL_MATRIX_OUT "m00,m10,m20,m30,m01,m11,m21,m31,m02,m12,m22,m32,m03,m13,m23,m33"

/* Every function the labs ask students to write, with its signature as the
 * stubs declare it. Outputs of matrices are column-major, as cglm and GLSL store them. */
static const sl_probe_function _sl_functions[] = {
    /* lab 1: the map as lab1_create_shadow_map makes it: its filtering, what a lookup past its edge reads,
     * and its size (the argument's, not a constant's), also as map->size records it (the depth pass's viewport) */
    {.name = "lab1_create_shadow_map", .lab = 1, .file = "lab1_depth_fbo/lab1.c", .todo = "lab1.1",
     .outputs = "min filter,mag filter,wrap s,wrap t,border depth,texture width,texture height,map->size,"
                "framebuffer status,texture at the stencil attachment,status asked of the map,returned SL_OK",
     .output_count = 12,
     .params = {_SL_I("size")},
     .param_count = 1, .stub_param = -1, .stub_value = NAN, .reports_status = true},
    /* lab 1: the depth pass's state, on a map the probe makes (its depth texture filled with 0.5) */
    {.name = "lab1_begin_depth_pass", .lab = 1, .file = "lab1_depth_fbo/lab1.c", .todo = "lab1.3",
     .outputs = "map's framebuffer bound,viewport width,viewport height,depth test,depth function,depth writes,"
                "depth after the call,culling on",
     .output_count = 8, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN},
    /* lab 1: the map given back, beside objects of the probe's own; the stub does nothing */
    {.name = "lab1_destroy_shadow_map", .lab = 1, .file = "lab1_depth_fbo/lab1.c", .todo = "lab1.5",
     .outputs = "map's framebuffer deleted,map's depth texture deleted,map's framebuffer field 0,"
                "map's depth_texture field 0,map's size field 0,other objects untouched",
     .output_count = 6, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN,
     .stub_outputs = (const double[]){0.0, 0.0, 0.0, 0.0, 0.0, 1.0}},
    /* lab 1: the depth pass's vertex shader, on its own: gl_Position for a vertex, a model and a light */
    {.name = "depth.vert", .lab = 1, .glsl = true, .stage = SL_PROBE_VERTEX_MAIN,
     .file = "lab1_depth_fbo/shaders/depth.vert", .todo = "lab1.4", .outputs = "x,y,z,w", .output_count = 4,
     .params = {_SL_V3("a_position"), _SL_M4("u_model"), _SL_M4("u_light_view_projection")}, .param_count = 3,
     .stub_param = -1, .stub_value = NAN, .stub_outputs = (const double[]){0.0, 0.0, 2.0, 1.0}},
    /* lab 2 */
    {.name = "lab2_light_view", .lab = 2, .file = "lab2_projective/lab2.c", .todo = "lab2.1",
     .outputs = _SL_MATRIX_OUT, .output_count = 16,
     .params = {_SL_I("light_type"), _SL_V3("direction"), _SL_V3("position"), _SL_V3("bounds_min"), _SL_V3("bounds_max")},
     .param_count = 5, .stub_param = -1, .stub_value = NAN},
    {.name = "lab2_light_projection", .lab = 2, .file = "lab2_projective/lab2.c", .todo = "lab2.2",
     .outputs = _SL_MATRIX_OUT, .output_count = 16,
     .params = {_SL_I("light_type"), _SL_V3("direction"), _SL_V3("position"), _SL_F("spot_angle_deg"), _SL_F("near"),
                _SL_F("far"), _SL_V3("bounds_min"), _SL_V3("bounds_max"), _SL_V3("view_eye"), _SL_V3("view_target"),
                _SL_V3("view_up")},
     .param_count = 11, .stub_param = -1, .stub_value = NAN},
    {.name = "lab2_shadow_matrix", .lab = 2, .file = "lab2_projective/lab2.c", .todo = "lab2.3",
     .outputs = _SL_MATRIX_OUT, .output_count = 16,
     .params = {_SL_V2("ortho_left_right"), _SL_V2("ortho_bottom_top"), _SL_V2("ortho_near_far"), _SL_V3("eye"),
                _SL_V3("target"), _SL_V3("up")},
     .param_count = 6, .stub_param = -1, .stub_value = NAN},
    {.name = "shadow_coord", .lab = 2, .glsl = true, .file = "lab2_projective/shaders/shadow_coord.glsl",
     .todo = "lab2.4", .outputs = "s,t,r,q", .output_count = 4,
     .params = {_SL_M4("shadow_matrix"), _SL_V4("world_position")}, .param_count = 2, .stub_param = -1,
     .stub_value = 0.0},
    {.name = "shadow_compare_manual", .lab = 2, .glsl = true, .file = "lab2_projective/shaders/shadow_lookup.glsl",
     .todo = "lab2.5", .outputs = "visibility", .output_count = 1,
     .params = {_SL_MAP("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias")}, .param_count = 3, .stub_param = -1,
     .stub_value = 1.0},
    {.name = "shadow_compare_hardware", .lab = 2, .glsl = true, .file = "lab2_projective/shaders/shadow_lookup.glsl",
     .todo = "lab2.6", .outputs = "visibility", .output_count = 1,
     .params = {_SL_SHADOW("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias")}, .param_count = 3, .stub_param = -1,
     .stub_value = 1.0},
    /* lab 3: the depth pass's state for a mode, from a neutral start or (previous_mode >= 0) right after
     * the same function set another mode in the same context, as the viewer switches modes */
    {.name = "lab3_depth_pass_state", .lab = 3, .file = "lab3_bias/lab3.c", .todo = "lab3.1",
     .outputs = "polygon offset on,factor,units,culling on,cull face", .output_count = 5,
     .params = {_SL_I("mode"), _SL_F("polygon_offset_factor"), _SL_F("polygon_offset_units"), _SL_I("previous_mode")},
     .param_count = 4,
     .stub_param = -1, .stub_value = NAN},
    /* lab 3's extension: the state of the second depth pass, called as the framework calls it (right after
     * lab 1's pass state), from a start with culling off or with back faces culled (a pass before may leave
     * that on); which faces are culled is read as front or back for the current winding, so culling GL_BACK
     * with glFrontFace(GL_CW) counts as culling the front faces */
    {.name = "lab3_second_depth_state", .lab = 3, .file = "lab3_bias/lab3.c", .todo = "lab3.4",
     .outputs = "front faces culled,back faces culled,faces chosen with culling off,depth test on,depth func,"
                "depth writes on",
     .output_count = 6, .params = {_SL_I("culling_before")}, .param_count = 1, .stub_param = -1,
     .stub_value = NAN, .bonus = true},
    {.name = "slope_scaled_bias", .lab = 3, .glsl = true, .file = "lab3_bias/shaders/bias.glsl", .todo = "lab3.2",
     .outputs = "bias", .output_count = 1,
     .params = {_SL_F("n_dot_l"), _SL_F("constant_bias"), _SL_F("slope"), _SL_F("max_bias")}, .param_count = 4,
     .stub_param = -1, .stub_value = 0.0},
    {.name = "normal_offset_position", .lab = 3, .glsl = true, .file = "lab3_bias/shaders/bias.glsl",
     .todo = "lab3.3", .outputs = "x,y,z", .output_count = 3,
     .params = {_SL_V3("world_position"), _SL_V3("normal"), _SL_F("n_dot_l"), _SL_F("texel_world_size"),
                _SL_F("texels")},
     .param_count = 5, .stub_param = 0},
    {.name = "midpoint_compare", .lab = 3, .glsl = true, .file = "lab3_bias/shaders/midpoint.glsl",
     .todo = "lab3.5", .outputs = "visibility", .output_count = 1,
     .params = {_SL_MAP("first_depth"), _SL_MAP("second_depth"), _SL_V4("shadow_coord")}, .param_count = 3,
     .stub_param = -1, .stub_value = 1.0, .bonus = true},
    /* lab 4 */
    {.name = "lab4_configure_shadow_texture", .lab = 4, .file = "lab4_pcf/lab4.c", .todo = "lab4.1",
     .outputs = "min filter,mag filter", .output_count = 2, .params = {_SL_I("mode")}, .param_count = 1,
     .stub_param = -1, .stub_value = NAN},
    {.name = "pcf_hardware", .lab = 4, .glsl = true, .file = "lab4_pcf/shaders/pcf.glsl", .todo = "lab4.2",
     .outputs = "visibility", .output_count = 1,
     .params = {_SL_SHADOW("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias")}, .param_count = 3,
     .linear_maps = true, .stub_param = -1, .stub_value = 1.0},
    {.name = "pcf_grid", .lab = 4, .glsl = true, .file = "lab4_pcf/shaders/pcf.glsl", .todo = "lab4.3",
     .outputs = "visibility", .output_count = 1,
     .params = {_SL_MAP("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias"), _SL_I("radius")}, .param_count = 4,
     .stub_param = -1, .stub_value = 1.0},
    {.name = "pcf_poisson", .lab = 4, .glsl = true, .file = "lab4_pcf/shaders/pcf.glsl", .todo = "lab4.4",
     .outputs = "visibility", .output_count = 1,
     .params = {_SL_MAP("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias"), _SL_F("radius_texels"),
                _SL_V2("pixel")},
     .param_count = 5, .stub_param = -1, .stub_value = 1.0},
    {.name = "pcss", .lab = 4, .glsl = true, .file = "lab4_pcf/shaders/pcf.glsl", .todo = "lab4.5",
     .outputs = "visibility", .output_count = 1,
     .params = {_SL_MAP("shadow_map"), _SL_V4("shadow_coord"), _SL_F("bias"), _SL_F("light_size_uv"), _SL_F("near"),
                _SL_F("far")},
     .param_count = 6, .stub_param = -1, .stub_value = 1.0},
    /* lab 5 */
    /* lab 5: the two moments targets as lab5_create_moments_target makes them */
    {.name = "lab5_create_moments_target", .lab = 5, .file = "lab5_vsm/lab5.c", .todo = "lab5.1",
     .outputs = "moments[0] internal format,moments[1] internal format,texture width,moments[0] min filter,"
                "moments[0] mag filter,moments[0] wrap s,moments[0] wrap t,moments[1] min filter,moments[1] mag filter,"
                "moments[1] wrap s,moments[1] wrap t,each framebuffer's own texture at GL_COLOR_ATTACHMENT0,"
                "a depth buffer on framebuffer[0],framebuffers complete,target->size,framebuffer[0]'s own texture",
     .output_count = 16, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN},
    {.name = "lab5_begin_moments_pass", .lab = 5, .file = "lab5_vsm/lab5.c", .todo = "lab5.2",
     .outputs = "framebuffer bound (0 or 1),viewport width,viewport height,depth test,depth function,depth writes,"
                "framebuffer[0]'s depth after the call,framebuffer[0]'s first moment after the call,"
                "framebuffer[0]'s second moment after the call",
     .output_count = 9, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN},
    {.name = "lab5_begin_blur_pass", .lab = 5, .file = "lab5_vsm/lab5.c", .todo = "lab5.4",
     .outputs = "framebuffer bound (0 or 1),moments texture on unit 0 (0 or 1),viewport width,viewport height,"
                "depth test",
     .output_count = 5, .params = {_SL_I("direction"), _SL_I("size")}, .param_count = 2, .stub_param = -1,
     .stub_value = NAN},
    {.name = "compute_moments", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/moments.glsl", .todo = "lab5.3",
     .outputs = "first moment,second moment", .output_count = 2, .params = {_SL_F("depth")}, .param_count = 1,
     .stub_param = -1, .stub_value = 1.0},
    /* the stub returns the texel at uv, unblurred: no constant (lab5.c's verdict names it) */
    {.name = "blur_moments", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/blur.glsl", .todo = "lab5.5",
     .outputs = "first moment,second moment", .output_count = 2,
     .params = {_SL_MOMENTS("moments"), _SL_V2("uv"), _SL_V2("direction"), _SL_I("radius")}, .param_count = 4,
     .stub_param = -1, .stub_value = NAN},
    {.name = "chebyshev_upper_bound", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/vsm.glsl", .todo = "lab5.7",
     .outputs = "p_max", .output_count = 1, .params = {_SL_V2("moments"), _SL_F("t"), _SL_F("min_variance")},
     .param_count = 3, .stub_param = -1, .stub_value = 1.0},
    {.name = "reduce_light_bleeding", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/vsm.glsl", .todo = "lab5.8",
     .outputs = "visibility", .output_count = 1, .params = {_SL_F("p_max"), _SL_F("amount")}, .param_count = 2,
     .stub_param = 0},
    {.name = "esm_visibility", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/vsm.glsl", .todo = "lab5.9",
     .outputs = "visibility", .output_count = 1, .params = {_SL_F("moment"), _SL_F("t"), _SL_F("c")},
     .param_count = 3, .stub_param = -1, .stub_value = 1.0, .bonus = true},
    {.name = "evsm_warp", .lab = 5, .glsl = true, .file = "lab5_vsm/shaders/vsm.glsl", .todo = "lab5.10",
     .outputs = "positive,negative", .output_count = 2, .params = {_SL_F("depth"), _SL_V2("exponents")},
     .param_count = 2, .stub_param = -1, .stub_value = 0.0, .bonus = true},
    /* lab 6: splits (unused ones 0), a slice's sphere from a camera the probe builds, one cascade's light camera
     * (its projection * view: the light's camera is free to sit anywhere along the light's ray) */
    {.name = "lab6_split_distances", .lab = 6, .file = "lab6_cascades/lab6.c", .todo = "lab6.1",
     .outputs = "splits[0],splits[1],splits[2],splits[3],splits[4]", .output_count = 5,
     .params = {_SL_F("near"), _SL_F("far"), _SL_I("count"), _SL_F("lambda")}, .param_count = 4, .stub_param = -1,
     .stub_value = NAN},
    {.name = "lab6_slice_sphere", .lab = 6, .file = "lab6_cascades/lab6.c", .todo = "lab6.2",
     .outputs = "x,y,z,radius", .output_count = 4,
     .params = {_SL_V3("eye"), _SL_V3("target"), _SL_F("fov_deg"), _SL_F("aspect"), _SL_F("near"), _SL_F("far"),
                _SL_F("split_near"), _SL_F("split_far")},
     .param_count = 8, .stub_param = -1, .stub_value = NAN},
    {.name = "lab6_cascade_matrices", .lab = 6, .file = "lab6_cascades/lab6.c", .todo = "lab6.3",
     .outputs = _SL_MATRIX_OUT, .output_count = 16,
     .params = {_SL_V3("direction"), _SL_V4("sphere"), _SL_F("caster_margin"), _SL_I("map_size")}, .param_count = 4,
     .stub_param = -1, .stub_value = NAN},
    {.name = "cascade_index", .lab = 6, .glsl = true, .file = "lab6_cascades/shaders/cascades.glsl", .todo = "lab6.4",
     .outputs = "layer", .output_count = 1,
     .params = {_SL_V3("view_position"), _SL_V4("split_far"), _SL_I("count")}, .param_count = 3, .stub_param = -1,
     .stub_value = 0.0},
    {.name = "cascade_compare", .lab = 6, .glsl = true, .file = "lab6_cascades/shaders/cascades.glsl",
     .todo = "lab6.5", .outputs = "visibility", .output_count = 1,
     .params = {_SL_ARRAY("cascades"), _SL_I("layer"), _SL_V4("shadow_coord"), _SL_F("bias")}, .param_count = 4,
     .stub_param = -1, .stub_value = 1.0},
    {.name = "cascade_blend", .lab = 6, .glsl = true, .file = "lab6_cascades/shaders/cascades.glsl", .todo = "lab6.6",
     .outputs = "weight", .output_count = 1,
     .params = {_SL_F("view_depth"), _SL_F("split_near"), _SL_F("split_far"), _SL_F("band")}, .param_count = 4,
     .stub_param = -1, .stub_value = 0.0, .bonus = true},
    /* lab 7 */
    {.name = "lab7_create_cube_map", .lab = 7, .file = "lab7_cube/lab7.c", .todo = "lab7.1",
     .outputs = "a cube map,face width,face height,a depth format,faces with storage,filters nearest,clamp to edge,"
                "framebuffer complete,colour buffers off",
     .output_count = 9, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN},
    {.name = "lab7_begin_cube_pass", .lab = 7, .file = "lab7_cube/lab7.c", .todo = "lab7.2",
     .outputs = "map's framebuffer bound,attached face,viewport width,viewport height,depth test,depth writes,"
                "depth after the call,viewport x,viewport y,depth function",
     .output_count = 10, .params = {_SL_I("face"), _SL_I("size")}, .param_count = 2, .stub_param = -1,
     .stub_value = NAN},
    {.name = "lab7_face_view", .lab = 7, .file = "lab7_cube/lab7.c", .todo = "lab7.3", .outputs = _SL_MATRIX_OUT,
     .output_count = 16, .params = {_SL_I("face"), _SL_V3("light_position")}, .param_count = 2, .stub_param = -1,
     .stub_value = NAN},
    {.name = "lab7_face_projection", .lab = 7, .file = "lab7_cube/lab7.c", .todo = "lab7.4",
     .outputs = _SL_MATRIX_OUT, .output_count = 16, .params = {_SL_F("near"), _SL_F("far")}, .param_count = 2,
     .stub_param = -1, .stub_value = NAN},
    {.name = "lab7_destroy_cube_map", .lab = 7, .file = "lab7_cube/lab7.c", .todo = "lab7.8",
     .outputs = "map's framebuffer deleted,map's cube map deleted,map's framebuffer field 0,map's depth_cube field 0,"
                "map's size field 0,other objects untouched",
     .output_count = 6, .params = {_SL_I("size")}, .param_count = 1, .stub_param = -1, .stub_value = NAN,
     .stub_outputs = (const double[]){0.0, 0.0, 0.0, 0.0, 0.0, 1.0}},
    /* lab 7: the depth pass's fragment shader, on its own: the depth it writes for a fragment at a world
     * position, drawn at a depth (gl_FragCoord.z) of the probe's */
    {.name = "cube_depth.frag", .lab = 7, .glsl = true, .stage = SL_PROBE_FRAGMENT_MAIN,
     .file = "lab7_cube/shaders/cube_depth.frag", .todo = "lab7.5", .outputs = "gl_FragDepth", .output_count = 1,
     .stage_inputs = "Vertex { vec3 world_position; }",
     .params = {_SL_V3("world_position"), _SL_V3("u_light_position"), _SL_F("u_light_far"), _SL_F("gl_FragCoord.z")},
     .param_count = 4, .stub_param = 3},
    {.name = "point_shadow", .lab = 7, .glsl = true, .file = "lab7_cube/shaders/point_shadow.glsl", .todo = "lab7.6",
     .outputs = "visibility", .output_count = 1,
     .params = {_SL_CUBE("cube_map"), _SL_V3("light_to_fragment"), _SL_F("far_plane"), _SL_F("bias")},
     .param_count = 4, .stub_param = -1, .stub_value = 1.0},
    {.name = "point_shadow_soft", .lab = 7, .glsl = true, .file = "lab7_cube/shaders/point_shadow.glsl",
     .todo = "lab7.7", .outputs = "visibility", .output_count = 1,
     .params = {_SL_CUBE("cube_map"), _SL_V3("light_to_fragment"), _SL_F("far_plane"), _SL_F("bias"),
                _SL_F("radius")},
     .param_count = 5, .stub_param = -1, .stub_value = 1.0},
};

#define _SL_FUNCTION_COUNT ((int)(sizeof _sl_functions / sizeof _sl_functions[0]))

/* Functions described since (sl_probe_describe): indices _SL_FUNCTION_COUNT and up. */
static sl_probe_function _sl_described[SL_PROBE_MAX_DESCRIBED];
static int _sl_described_count;

const sl_probe_function *sl_probe_find(const char *name) {
    for (int i = 0; i < _SL_FUNCTION_COUNT; i++)
        if (strcmp(_sl_functions[i].name, name) == 0) return &_sl_functions[i];
    for (int i = 0; i < _sl_described_count; i++)
        if (strcmp(_sl_described[i].name, name) == 0) return &_sl_described[i];
    return NULL;
}

const char *sl_probe_parens(const char *name) { return name && strchr(name, '.') ? "" : "()"; }

const char *sl_probe_entry(const sl_probe_function *f) { return f->stage == SL_PROBE_FUNCTION ? f->name : "main"; }

const sl_probe_function *sl_probe_describe(const sl_probe_function *f) {
    for (int i = 0; i < _SL_FUNCTION_COUNT; i++)
        if (strcmp(_sl_functions[i].name, f->name) == 0) return NULL;
    const sl_probe_function *known = sl_probe_find(f->name);
    if (known) return known;
    if (_sl_described_count == SL_PROBE_MAX_DESCRIBED || strlen(f->name) >= SL_PROBE_NAME_MAX) return NULL;
    _sl_described[_sl_described_count] = *f;
    return &_sl_described[_sl_described_count++];
}

const sl_probe_function *sl_probe_at(int index) {
    if (index >= 0 && index < _SL_FUNCTION_COUNT) return &_sl_functions[index];
    index -= _SL_FUNCTION_COUNT;
    return index >= 0 && index < _sl_described_count ? &_sl_described[index] : NULL;
}

int sl_probe_index(const sl_probe_function *f) {
    if (f >= _sl_described && f < _sl_described + SL_PROBE_MAX_DESCRIBED)
        return _SL_FUNCTION_COUNT + (int)(f - _sl_described);
    return (int)(f - _sl_functions);
}

int sl_probe_type_size(sl_probe_type type) {
    static const int sizes[] = {[SL_PROBE_FLOAT] = 1, [SL_PROBE_INT] = 1, [SL_PROBE_VEC2] = 2, [SL_PROBE_VEC3] = 3,
                                [SL_PROBE_VEC4] = 4, [SL_PROBE_MAT4] = 16, [SL_PROBE_MAP] = 1, [SL_PROBE_SHADOW_MAP] = 1,
                                [SL_PROBE_CUBE_MAP] = 1, [SL_PROBE_ARRAY_MAP] = 1, [SL_PROBE_MOMENTS_MAP] = 1};
    return sizes[type];
}

int sl_probe_input_count(const sl_probe_function *f) {
    int n = 0;
    for (int i = 0; i < f->param_count; i++) n += sl_probe_type_size(f->params[i].type);
    return n;
}

const float *sl_probe_row_param(const sl_probe_function *f, const float *row, const char *name) {
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        if (strcmp(f->params[i].name, name) == 0) return row + offset;
        offset += sl_probe_type_size(f->params[i].type);
    }
    return NULL;
}

static const char *const _sl_map_names[SL_PROBE_MAP_COUNT] = {"lit",      "occluded",      "step",
                                                              "ramp",     "cube_lit",      "cube_occluded",
                                                              "cube_room", "cube_positive", "step_floor", "cascades", "moments_flat", "moments_step_x", "moments_step_y", "step_v", "corner"};

const char *sl_probe_map_name(sl_probe_map map) {
    return (unsigned)map < SL_PROBE_MAP_COUNT ? _sl_map_names[map] : "?";
}

int sl_probe_map_parse(const char *name) {
    for (int i = 0; i < SL_PROBE_MAP_COUNT; i++)
        if (strcmp(name, _sl_map_names[i]) == 0) return i;
    return -1;
}

float sl_probe_map_depth(sl_probe_map map, int x, int y) {
    float u = ((float)x + 0.5f) / SL_PROBE_MAP_SIZE, v = ((float)y + 0.5f) / SL_PROBE_MAP_SIZE;
    switch (map) {
    case SL_PROBE_MAP_OCCLUDED: return 0.25f;
    case SL_PROBE_MAP_STEP: return u < 0.5f ? 0.25f : 1.0f;
    case SL_PROBE_MAP_RAMP: return u;
    case SL_PROBE_MAP_STEP_FLOOR: return u < 0.5f ? 0.25f : 0.9f;
    case SL_PROBE_MAP_STEP_V: return v < 0.5f ? 0.25f : 1.0f;
    case SL_PROBE_MAP_CORNER: return u < 0.5f && v < 0.5f ? 0.25f : 1.0f;
    default: return 1.0f;
    }
}

bool sl_probe_map_is_cube(sl_probe_map map) { return map >= SL_PROBE_MAP_CUBE_LIT && map <= SL_PROBE_MAP_CUBE_POSITIVE; }

sl_probe_type sl_probe_map_type(sl_probe_map map) {
    if (map >= SL_PROBE_MAP_MOMENTS_FLAT && map <= SL_PROBE_MAP_MOMENTS_STEP_Y) return SL_PROBE_MOMENTS_MAP;
    return map == SL_PROBE_MAP_CASCADES ? SL_PROBE_ARRAY_MAP : sl_probe_map_is_cube(map) ? SL_PROBE_CUBE_MAP : SL_PROBE_MAP;
}

float sl_probe_moments_depth(sl_probe_map map, int x, int y) {
    switch (map) {
    case SL_PROBE_MAP_MOMENTS_STEP_X: return 2 * x < SL_PROBE_MAP_SIZE ? 0.25f : 0.75f;
    case SL_PROBE_MAP_MOMENTS_STEP_Y: return 2 * y < SL_PROBE_MAP_SIZE ? 0.25f : 0.75f;
    default: return 0.5f;
    }
}

float sl_probe_layer_depth(sl_probe_map map, int layer, int x, int y) {
    (void)map;
    switch (layer) {
    case 0: return sl_probe_map_depth(SL_PROBE_MAP_STEP, x, y);
    case 2: return sl_probe_map_depth(SL_PROBE_MAP_OCCLUDED, x, y);
    case 3: return 0.6f;
    default: return 1.0f;
    }
}

float sl_probe_cube_depth(sl_probe_map map, int face, int x, int y) {
    /* The direction through texel (x, y) of the face: GL's table of cube map
     * faces read backwards (s, t in [-1, 1]; row 0 is t = -1). */
    float s = 2.0f * ((float)x + 0.5f) / SL_PROBE_MAP_SIZE - 1.0f;
    float t = 2.0f * ((float)y + 0.5f) / SL_PROBE_MAP_SIZE - 1.0f;
    float d[6][3] = {{1, -t, -s}, {-1, -t, s}, {s, 1, t}, {s, -1, -t}, {s, -t, 1}, {-s, -t, -1}};
    const float *v = d[face < 0 || face > 5 ? 0 : face];
    switch (map) {
    case SL_PROBE_MAP_CUBE_OCCLUDED: return 0.25f;
    case SL_PROBE_MAP_CUBE_ROOM: {
        float largest = fmaxf(fabsf(v[0]), fmaxf(fabsf(v[1]), fabsf(v[2])));
        return 2.0f * sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / largest / 10.0f;
    }
    case SL_PROBE_MAP_CUBE_POSITIVE: return face % 2 == 0 ? 0.1f : 1.0f;
    default: return 1.0f;
    }
}
