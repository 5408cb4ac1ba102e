/* sl_lab1_4_programs: the programs labs 1-4's shadow-map frame draws with (sl_lab1_4_shadow_map.c), held
 * by lab 1's technique in the renderer's technique_state[1].
 *
 * Each program is built the first time a frame needs it, then kept. The camera
 * pass has one program per lab and per setting that changes its code (compare
 * type, bias mode, filter, grid radius): those settings reach the GLSL as
 * preprocessor defines, so a program holds only the code of its own technique.
 * A software rasteriser runs every branch a pixel might take, and loops with
 * constant bounds unroll. Uniform locations are looked up once per build. */
#ifndef SL_LAB1_4_PROGRAMS_H
#define SL_LAB1_4_PROGRAMS_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_renderer.h"

/* Every uniform the framework sets, as u_<name> in the GLSL. */
#define SL_LAB1_4_UNIFORMS(X)                                                                             \
    X(model) X(normal_matrix) X(albedo) X(view) X(projection) X(shadow_matrix) X(light_view_projection)   \
    X(light_position) X(light_direction) X(light_radiance) X(spot_cos) X(shadows) X(output) X(depth_bias) \
    X(second_map) X(slope_bias) X(max_bias) X(normal_offset) X(texel_size) X(poisson_radius)              \
    X(light_size_uv) X(light_near) X(light_far) X(shadow_map) X(texture) X(perspective) X(near) X(far)    \
    X(moments) X(min_variance) X(bleeding)

typedef struct sl_lab1_4_uniforms {
#define SL_LAB1_4_UNIFORM_FIELD(name) GLint name;
    SL_LAB1_4_UNIFORMS(SL_LAB1_4_UNIFORM_FIELD)
#undef SL_LAB1_4_UNIFORM_FIELD
} sl_lab1_4_uniforms;

typedef struct sl_lab1_4_slot {
    sl_program program;
    sl_lab1_4_uniforms u;
    GLuint located; /* the program id u belongs to: a rebuild changes the id */
    bool attempted;
    bool compiles;  /* the latest build succeeded (after a failed rebuild, the program is the one before) */
} sl_lab1_4_slot;

/* What a camera-pass program is built for: each field is a compile-time constant in its GLSL. */
typedef struct sl_lab1_4_variant_key {
    int lab;         /* 0: no shadows (plain.frag); 2, 3 or 4: scene.frag, scene_bias.frag, scene_filter.frag */
    int light_type;  /* SL_LIGHT_TYPE */
    bool hardware;   /* sampler2DShadow */
    int bias_mode;   /* labs 3-4: SL_BIAS_MODE */
    int filter_mode; /* lab 4: SL_FILTER_MODE */
    int grid_radius; /* lab 4's grid: SL_GRID_RADIUS */
} sl_lab1_4_variant_key;

/* The programs made (on the first frame); false when out of memory. */
bool sl_lab1_4_programs_ready(sl_renderer *r);
/* Lab 1's depth program, the debug view's, the camera pass's for `key`: each built on first use, NULL
 * if it does not compile (the error in the renderer's shader_errors[lab]). */
sl_lab1_4_slot *sl_lab1_4_depth_program(sl_renderer *r);
sl_lab1_4_slot *sl_lab1_4_debug_program(sl_renderer *r);
sl_lab1_4_slot *sl_lab1_4_variant_program(sl_renderer *r, const sl_lab1_4_variant_key *key);
/* Whether lab `lab` (0..SL_RENDERER_MAX_LAB) has camera-pass shaders of its own (labs 2-5; 0: no shadows). */
bool sl_lab1_4_has_camera_pass(int lab);
/* The slot's uniform locations, looked up once per build. */
const sl_lab1_4_uniforms *sl_lab1_4_uniforms_of(sl_lab1_4_slot *s);
/* Lab 1's technique's hooks (sl_technique.h): the programs' builds and count, hot reload, clean-up. */
void sl_lab1_4_program_stats(const sl_renderer *r, sl_program_stats *out);
bool sl_lab1_4_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size);
void sl_lab1_4_programs_destroy(sl_renderer *r);

#endif
