/* sl_probe: function probes. Each function a student writes, GLSL or C, is
 * also called directly on a table of inputs that covers its domain and its
 * edges (a case file's "probe" check), and its outputs are compared with the
 * solution's. This module is the table of those functions: their
 * parameters, what their stubs return, where their TODO is. No GL here: the
 * grader reads it too; the runner calls the functions (sl_probe_pass.h). */
#ifndef SL_PROBE_H
#define SL_PROBE_H

#include <stdbool.h>

#define SL_PROBE_MAX_ROWS 32
#define SL_PROBE_MAX_INPUTS 40  /* floats per row (a vertex stage takes a vec3 and two mat4) */
#define SL_PROBE_MAX_OUTPUTS 16 /* numbers per row */
#define SL_PROBE_MAX_PARAMS 12

typedef enum sl_probe_type {
    SL_PROBE_FLOAT,
    SL_PROBE_INT,
    SL_PROBE_VEC2,
    SL_PROBE_VEC3,
    SL_PROBE_VEC4,
    SL_PROBE_MAT4,
    SL_PROBE_MAP,        /* GLSL sampler2D over a synthetic depth map (sl_probe_map) */
    SL_PROBE_SHADOW_MAP, /* GLSL sampler2DShadow over one (compare mode on, GL_LEQUAL) */
    SL_PROBE_CUBE_MAP,   /* GLSL samplerCube over a synthetic depth cube map (lab 7; the cube_* maps) */
    SL_PROBE_ARRAY_MAP,  /* GLSL sampler2DArray over a synthetic depth texture array (lab 6; "cascades") */
    SL_PROBE_MOMENTS_MAP, /* GLSL sampler2D over synthetic moments, GL_RG32F as lab 5's targets (the moments_* maps) */
} sl_probe_type;
/* A parameter that names a synthetic map (its one float is the sl_probe_map). */
#define SL_PROBE_IS_MAP(type)                                                                                          \
    ((type) == SL_PROBE_MAP || (type) == SL_PROBE_SHADOW_MAP || (type) == SL_PROBE_CUBE_MAP ||                         \
     (type) == SL_PROBE_ARRAY_MAP || (type) == SL_PROBE_MOMENTS_MAP)

/* Synthetic depth maps, 64 x 64 texels, for the functions that read one. */
typedef enum sl_probe_map {
    SL_PROBE_MAP_LIT,      /* 1.0 everywhere: nothing in front of anything */
    SL_PROBE_MAP_OCCLUDED, /* 0.25 everywhere: an occluder in front of everything */
    SL_PROBE_MAP_STEP,     /* 0.25 where u < 0.5, 1.0 where u >= 0.5: one occluder's edge */
    SL_PROBE_MAP_RAMP,     /* depth = u: a surface tilted away from the light */
    /* lab 7's cube maps, distance / far for a light at the centre and far = 10 */
    SL_PROBE_MAP_CUBE_LIT,      /* 1.0 everywhere: nothing around the light */
    SL_PROBE_MAP_CUBE_OCCLUDED, /* 0.25 everywhere: a closed shell 2.5 units around the light */
    SL_PROBE_MAP_CUBE_ROOM,     /* the walls of a cube room of half-size 2: 2 |d| / max|d_i| / 10, seamless */
    SL_PROBE_MAP_CUBE_POSITIVE, /* 0.1 on the +X, +Y, +Z faces (an occluder 1 unit away), 1.0 on the others */
    /* 2D again (after the cube maps, so the others keep their numbers) */
    SL_PROBE_MAP_STEP_FLOOR,    /* 0.25 where u < 0.5, 0.9 where u >= 0.5: an occluder's edge over a floor */
    /* lab 6's cascades: a depth texture array of SL_PROBE_LAYERS layers, each its own content
     * (0: "step", 1: "lit", 2: "occluded", 3: a surface at 0.6), so a lookup in another layer shows */
    SL_PROBE_MAP_CASCADES,
    /* lab 5's moments, (depth, depth^2) per texel, GL_RG32F, linear, clamped to the edge as lab 5's targets */
    SL_PROBE_MAP_MOMENTS_FLAT,   /* depth 0.5 everywhere */
    SL_PROBE_MAP_MOMENTS_STEP_X, /* depth 0.25 where u < 0.5, 0.75 where u >= 0.5: an edge across x */
    SL_PROBE_MAP_MOMENTS_STEP_Y, /* depth 0.25 where v < 0.5, 0.75 where v >= 0.5: an edge across y */
    /* 2D again (last, so the others keep their numbers) */
    SL_PROBE_MAP_STEP_V, /* 0.25 where v < 0.5, 1.0 where v >= 0.5: an occluder's edge across t */
    SL_PROBE_MAP_CORNER, /* 0.25 where u < 0.5 and v < 0.5, 1.0 elsewhere: an occluder's corner, edges across s and t */
    SL_PROBE_MAP_COUNT
} sl_probe_map;
#define SL_PROBE_MAP_SIZE 64
/* The viewport a pass's probe sets before calling the function (no size a pass asks for): found after the
 * call, the function never set its own. */
#define SL_PROBE_STALE_VIEWPORT_WIDTH 7
#define SL_PROBE_STALE_VIEWPORT_HEIGHT 5
#define SL_PROBE_LAYERS 4

typedef struct sl_probe_param {
    const char *name;
    sl_probe_type type;
} sl_probe_param;

/* What a GLSL probe calls: a function of a lab file, or the main() of a whole shader stage, whose
 * parameters are then its inputs by name (attributes a_*, uniforms u_*, the rest the varyings of
 * stage_inputs' block) and whose outputs are what the stage writes (gl_Position, gl_FragDepth). */
typedef enum sl_probe_stage {
    SL_PROBE_FUNCTION,      /* a function of a lab file, called in a full-screen pass */
    SL_PROBE_VERTEX_MAIN,   /* a vertex shader: one point a row, its gl_Position by transform feedback */
    SL_PROBE_FRAGMENT_MAIN, /* a fragment shader: one fragment a row, its gl_FragDepth (the last
                             * parameter is gl_FragCoord.z as the probe draws the fragment) */
} sl_probe_stage;

typedef struct sl_probe_function {
    const char *name;   /* as students write it: "slope_scaled_bias", or a stage's file ("depth.vert") */
    int lab;
    bool glsl;          /* GLSL (called in a full-screen pass) or C (called in the runner) */
    const char *file;   /* GLSL: the include path under the labs tree; C: the lab's .c file */
    const char *todo;   /* "lab3.2" */
    const char *outputs; /* names of the outputs, comma-separated ("bias", "x,y,z") */
    int output_count;
    sl_probe_param params[SL_PROBE_MAX_PARAMS];
    int param_count;
    bool linear_maps;   /* shadow maps filtered with GL_LINEAR (2x2 PCF) */
    /* What the stub returns, so a stub reads as "not implemented": a
     * constant for every output, or (stub_param >= 0) that parameter. */
    double stub_value;
    int stub_param;
    bool bonus;         /* an extension's function */
    sl_probe_stage stage;
    const char *stage_inputs; /* SL_PROBE_FRAGMENT_MAIN: the interface block its varyings arrive in */
    const double *stub_outputs; /* a stub that returns a vector of constants: one for each output */
    /* A C function whose last output is whether it returned SL_OK: a row where it returned SL_FAILED
     * keeps what it made (the framebuffer's status, say), so the failure can be read, not only seen.
     * SL_NOT_IMPLEMENTED still empties the row. */
    bool reports_status;
} sl_probe_function;

/* What follows a probed name where it is said as a call: "()" for a function, "" for a whole stage
 * ("depth.vert", a file). */
const char *sl_probe_parens(const char *name);
/* The GLSL function a probe of f calls: "main" for a whole stage, else f's name. */
const char *sl_probe_entry(const sl_probe_function *f);

/* The function of that name, or NULL: the course's (this file's table) or one described since. */
const sl_probe_function *sl_probe_find(const char *name);
/* Adds the description of a function outside the course's table (a technique a build adds, slot 0:
 * its case describes it to the grader, its descriptor to the runner, sl_technique.h), so that
 * sl_probe_find, sl_probe_at and sl_probe_index know it; the description is copied, its strings are
 * not. A name described before keeps its first description. Returns it, or NULL when the name is the
 * course's or SL_PROBE_MAX_DESCRIBED are described already. */
#define SL_PROBE_MAX_DESCRIBED 8
const sl_probe_function *sl_probe_describe(const sl_probe_function *f);
const sl_probe_function *sl_probe_at(int index);
int sl_probe_index(const sl_probe_function *f);
/* Floats one input row takes (a map counts one: its sl_probe_map). */
int sl_probe_input_count(const sl_probe_function *f);
/* The inputs of one parameter in an input row, or NULL if the function has none of that name. */
const float *sl_probe_row_param(const sl_probe_function *f, const float *row, const char *name);
int sl_probe_type_size(sl_probe_type type);
const char *sl_probe_map_name(sl_probe_map map);
/* -1 when the name is no map's. */
int sl_probe_map_parse(const char *name);
/* The depth of a synthetic map at texel (x, y). */
float sl_probe_map_depth(sl_probe_map map, int x, int y);
/* A cube map's stored value on face 0..5 at texel (x, y), GL's face orientations. */
float sl_probe_cube_depth(sl_probe_map map, int face, int x, int y);
/* Whether a map is one of the cube maps (for samplerCube parameters) or a 2D one. */
bool sl_probe_map_is_cube(sl_probe_map map);
/* The parameter type that takes a map: SL_PROBE_CUBE_MAP, SL_PROBE_ARRAY_MAP, or SL_PROBE_MAP for the 2D ones. */
sl_probe_type sl_probe_map_type(sl_probe_map map);
/* A moments map's first moment (the depth) at texel (x, y); the second is its square. */
float sl_probe_moments_depth(sl_probe_map map, int x, int y);
/* A texture array's depth in layer `layer` at texel (x, y). */
float sl_probe_layer_depth(sl_probe_map map, int layer, int x, int y);

/* A table of inputs as the runner receives it. The function travels by name, so a runner finds it in
 * its own build (the course's table, or a technique's described probe) whatever the grader's indices;
 * with the counts the grader read the case's rows by, which the runner's function must have. */
#define SL_PROBE_NAME_MAX 48
typedef struct sl_probe_table {
    char function[SL_PROBE_NAME_MAX]; /* "": none */
    int input_count, output_count;
    int rows;
    float inputs[SL_PROBE_MAX_ROWS][SL_PROBE_MAX_INPUTS];
} sl_probe_table;

#endif
