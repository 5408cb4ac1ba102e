#include "sl_probe_generic.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_probe.h"
#include "sl_probe_formula.h"

/* GL's numbers for the state lab 1's map must have (the grader links no GL). */
#define _SL_GL_NEAREST 0x2600
#define _SL_GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define _SL_GL_CLAMP_TO_BORDER 0x812D

/* ---- splitmix64, one stream per case and check ---- */

typedef struct _sl_rng {
    uint64_t state;
} _sl_rng;

static uint64_t _sl_next(_sl_rng *r) {
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* In [lo, hi). */
static double _sl_uniform(_sl_rng *r, double lo, double hi) {
    return lo + (hi - lo) * ((double)(_sl_next(r) >> 11) * 0x1.0p-53);
}

/* In lo..hi, both included. */
static int _sl_integer(_sl_rng *r, int lo, int hi) { return lo + (int)(_sl_next(r) % (uint64_t)(hi - lo + 1)); }

static _sl_rng _sl_stream(uint64_t seed, const sl_case *c, const sl_check *k) {
    char key[256];
    snprintf(key, sizeof key, "generic/%s/%s", c->name, k->name);
    uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char *p = (const unsigned char *)key; *p; p++) h = (h ^ *p) * 0x100000001b3ull;
    _sl_rng r = {seed ^ h};
    _sl_next(&r);
    return r;
}

/* ---- a row's parameters by name ---- */

static void _sl_set(const sl_probe_function *f, float *row, const char *name, const double *v) {
    int offset = 0;
    for (int i = 0; i < f->param_count; offset += sl_probe_type_size(f->params[i].type), i++)
        if (strcmp(f->params[i].name, name) == 0)
            for (int j = 0; j < sl_probe_type_size(f->params[i].type); j++) row[offset + j] = (float)v[j];
}

static void _sl_set1(const sl_probe_function *f, float *row, const char *name, double v) { _sl_set(f, row, name, &v); }

static double _sl_get(const sl_probe_function *f, const float *row, const char *name, int j) {
    const float *p = sl_probe_row_param(f, row, name);
    return p ? (double)p[j] : NAN;
}

/* ---- the synthetic maps, read as the probe pass's textures are (64 texels, nearest) ---- */

/* The texel a coordinate reads with GL_NEAREST, clamped to the edge. */
static int _sl_texel(double u) {
    int i = (int)floor(u * SL_PROBE_MAP_SIZE);
    return i < 0 ? 0 : i >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : i;
}

/* The synthetic map as the probe binds it: past its edge, the border's depth 1.0 (GL_CLAMP_TO_BORDER) */
static double _sl_map_at(sl_probe_map map, double u, double v) {
    if (u < 0 || u >= 1 || v < 0 || v >= 1) return 1.0;
    return (double)sl_probe_map_depth(map, _sl_texel(u), _sl_texel(v));
}

/* A coordinate inside texel i, away from its edges (so a lookup reads that texel on every renderer). */
static double _sl_in_texel(_sl_rng *r, int i) { return (i + 0.5 + _sl_uniform(r, -0.3, 0.3)) / SL_PROBE_MAP_SIZE; }

/* A shadow coordinate (p * w, w) for a projected point p and a w that is not 1. */
static void _sl_homogeneous(_sl_rng *r, bool below_one, const double p[3], double out[4]) {
    double w = below_one ? _sl_uniform(r, 0.35, 0.8) : _sl_uniform(r, 1.4, 3.0);
    for (int j = 0; j < 3; j++) out[j] = p[j] * w;
    out[3] = w;
}

/* ---- each function: its generic rows and its contract ---- */

typedef struct _sl_generic {
    const char *function;
    /* fills row (all parameters) and its about; may use the row's index to cover cases in turn */
    void (*draw)(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n);
    /* the contract's outputs for row (slip 0), or the outputs of the formula with slip `slip` (1..) made */
    void (*expect)(const sl_probe_function *f, const float *row, int slip, double *out);
    /* slip i (from 1) as "what the formula then computes", "what the contract says"; NULL-ended */
    const char *const (*slips)[2];
    /* the contract's formula in sl_probe_formula's language (NULL: a loop or a texture the language does
     * not hold); its one-edit variants are slips no catalogue has to list */
    const char *formula;
    /* catalogued slips (bit i: slip i) no written-row verdict names: they lead, as an edit of the formula does */
    uint64_t leading;
} _sl_generic;

/* lab 1: a map of any size (never one a scene uses), with the lab's filtering and border */
static void _sl_draw_create_shadow_map(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                       size_t n) {
    (void)index;
    int size = _sl_integer(r, 40, 700);
    if ((size & (size - 1)) == 0) size += 3; /* no power of two: a constant size of its own shows */
    _sl_set1(f, row, "size", size);
    snprintf(about, n, "generic size %d (drawn, no scene's): a %dx%d map, GL_NEAREST, GL_CLAMP_TO_BORDER with border "
                       "depth 1.0",
             size, size, size);
}

static void _sl_expect_create_shadow_map(const sl_probe_function *f, const float *row, int slip, double *out) {
    (void)slip;
    double size = _sl_get(f, row, "size", 0);
    /* then the framebuffer: complete (GL_FRAMEBUFFER_COMPLETE), no stencil attachment, its status asked, SL_OK */
    double want[12] = {_SL_GL_NEAREST, _SL_GL_NEAREST, _SL_GL_CLAMP_TO_BORDER, _SL_GL_CLAMP_TO_BORDER, 1.0, size, size,
                       size, _SL_GL_FRAMEBUFFER_COMPLETE, 0, 1, 1};
    memcpy(out, want, sizeof want);
}

/* lab 1: depth.vert's gl_Position = u_light_view_projection * u_model * (a_position, 1), with a model that
 * turns, scales unevenly and moves, and a projective light matrix (w != 1), so every product shows */
static void _sl_draw_depth_vert(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double p[3], model[16] = {0}, light[16], axis[3], length = 0;
    for (int j = 0; j < 3; j++) p[j] = _sl_uniform(r, -2, 2), axis[j] = _sl_uniform(r, -1, 1);
    for (int j = 0; j < 3; j++) length += axis[j] * axis[j];
    length = sqrt(length) + 1e-9;
    for (int j = 0; j < 3; j++) axis[j] /= length;
    double angle = _sl_uniform(r, 0.4, 2.6), c = cos(angle), s = sin(angle), scale[3];
    for (int j = 0; j < 3; j++) scale[j] = _sl_uniform(r, 0.5, 2.0);
    /* column-major: column j is the rotated axis j, scaled (Rodrigues' rotation), then the translation */
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            double rot = (i == j ? c : 0) + (1 - c) * axis[i] * axis[j];
            int k = 3 - i - j; /* the third axis, for the cross-product term */
            if (i != j) rot += ((i + 1) % 3 == j ? -1 : 1) * s * axis[k];
            model[j * 4 + i] = rot * scale[j];
        }
    for (int i = 0; i < 3; i++) model[12 + i] = _sl_uniform(r, -4, 4);
    model[15] = 1;
    for (int i = 0; i < 16; i++) light[i] = _sl_uniform(r, -1.5, 1.5);
    _sl_set(f, row, "a_position", p);
    _sl_set(f, row, "u_model", model);
    _sl_set(f, row, "u_light_view_projection", light);
    snprintf(about, n, "generic: a model that turns, scales unevenly and moves, and a projective light matrix (its w "
                       "is not 1)");
}

static const char *const _sl_depth_vert_slips[][2] = {
    {"", ""},
    {"u_light_view_projection * (a_position, 1): u_model left out", "u_light_view_projection * u_model * (a_position, 1)"},
    {"u_model * u_light_view_projection * (a_position, 1): the matrices in the other order",
     "u_light_view_projection * u_model * (a_position, 1): the model first, then the light"},
    {"the matrices times (a_position, 0): a direction, whose translations are lost",
     "(a_position, 1): a vertex is a point, w = 1"},
    {"u_model * (a_position, 1): u_light_view_projection left out", "u_light_view_projection * u_model * (a_position, 1)"},
    {"(a_position, 1) * u_model * u_light_view_projection: a row vector, the matrices transposed",
     "u_light_view_projection * u_model * (a_position, 1): GLSL's matrices multiply column vectors"},
    {"gl_Position divided by its w", "gl_Position as the product gives it: the GPU divides by w after the vertex shader"},
    {"the product with its w set to 1 (a perspective's divide lost)", "gl_Position as the product gives it, its w "
                                                                       "included: the GPU divides by w"},
    {"x and y moved to [0, 1] (0.5 * v + 0.5): texture space", "clip space: the rasterizer maps x and y in [-w, w] "
                                                               "onto the viewport itself"},
    {"u_model without its translation (mat3(u_model) * a_position, then w = 1): each object's own move is lost",
     "u_model * (a_position, 1): the whole model matrix, its translation included"},
    {NULL, NULL},
};

static void _sl_times(const float *m, bool transposed, const double *v, double *out) {
    for (int i = 0; i < 4; i++) {
        out[i] = 0;
        for (int j = 0; j < 4; j++) out[i] += (double)(transposed ? m[i * 4 + j] : m[j * 4 + i]) * v[j];
    }
}

static void _sl_expect_depth_vert(const sl_probe_function *f, const float *row, int slip, double *out) {
    const float *p = sl_probe_row_param(f, row, "a_position"), *model = sl_probe_row_param(f, row, "u_model"),
                *light = sl_probe_row_param(f, row, "u_light_view_projection");
    double v[4] = {p[0], p[1], p[2], slip == 3 ? 0.0 : 1.0}, m[4];
    if (slip == 2) { /* the light first, then the model */
        _sl_times(light, false, v, m);
        _sl_times(model, false, m, out);
        return;
    }
    if (slip == 5) { /* v * M * L = L^T (M^T v) */
        _sl_times(model, true, v, m);
        _sl_times(light, true, m, out);
        return;
    }
    if (slip == 1) memcpy(m, v, sizeof m);
    else if (slip == 9) { /* the model's upper 3x3 alone, then w = 1 */
        double direction[4] = {v[0], v[1], v[2], 0};
        _sl_times(model, false, direction, m);
        m[3] = 1;
    } else _sl_times(model, false, v, m);
    if (slip == 4) memcpy(out, m, sizeof m);
    else _sl_times(light, false, m, out);
    if (slip == 6 && out[3] != 0) {
        for (int i = 0; i < 3; i++) out[i] /= out[3];
        out[3] = 1;
    }
    if (slip == 7) out[3] = 1;
    if (slip == 8)
        for (int i = 0; i < 2; i++) out[i] = 0.5 * out[i] + 0.5;
}

/* lab 7: cube_depth.frag's gl_FragDepth = length(world_position - u_light_position) / u_light_far, for a
 * light off the origin, a far plane other than the scenes' and a fragment drawn at the depth its face's
 * perspective camera gives it (what gl_FragCoord.z holds in the depth pass) */
static double _sl_face_depth(const double d[3], double near, double far) {
    double axis = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    double ndc = (far + near) / (far - near) - 2 * far * near / ((far - near) * axis);
    return ndc * 0.5 + 0.5;
}

static void _sl_draw_cube_depth(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double light[3], d[3], far = _sl_uniform(r, 8, 60), near = _sl_uniform(r, 0.05, 0.5), length = 0;
    for (int j = 0; j < 3; j++) light[j] = _sl_uniform(r, -3, 3), d[j] = _sl_uniform(r, -1, 1);
    for (int j = 0; j < 3; j++) length += d[j] * d[j];
    length = sqrt(length) + 1e-9;
    /* one row in three within a unit of the light, where a distance left undivided is still below 1 */
    double distance = index % 3 == 0 ? _sl_uniform(r, 0.3, 0.95) : _sl_uniform(r, 0.15, 0.85) * far, world[3];
    for (int j = 0; j < 3; j++) d[j] *= distance / length, world[j] = light[j] + d[j];
    /* the face camera's near plane in front of the fragment, or the fragment is clipped and writes nothing */
    double axis = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    near = fmin(near, 0.5 * axis);
    _sl_set(f, row, "world_position", world);
    _sl_set(f, row, "u_light_position", light);
    _sl_set1(f, row, "u_light_far", far);
    _sl_set1(f, row, "gl_FragCoord.z", _sl_face_depth(d, near, far));
    snprintf(about, n, "generic: a light off the origin, far %.3g, the fragment %.3g of the way to it, off its face's "
                       "axis",
             far, distance / far);
}

static const char *const _sl_cube_depth_slips[][2] = {
    {"", ""},
    {"the distance from the origin, length(world_position) / u_light_far", "the distance from the light, "
                                                                           "length(world_position - u_light_position)"},
    {"the distance along the face's axis (the largest |component|) / u_light_far", "the length of the light-to-fragment "
                                                                                   "vector / u_light_far"},
    {"the squared distance / u_light_far^2", "the distance itself / u_light_far: linear in the distance"},
    {"gl_FragCoord.z: the face camera's non-linear depth", "length(world_position - u_light_position) / u_light_far: "
                                                           "the lookup has only a direction and a distance"},
    {"the distance not divided by u_light_far (the depth buffer keeps at most 1.0)", "the distance / u_light_far, in "
                                                                                     "[0, 1]"},
    {"the distance times u_light_far", "the distance divided by u_light_far"},
    {"distance / u_light_far moved again from [-1, 1] to [0, 1] (* 0.5 + 0.5)", "distance / u_light_far: already in "
                                                                                "[0, 1], stored as it is"},
    {"the difference of the two positions' distances from the origin, length(world_position) - "
     "length(u_light_position): not the distance between them",
     "length(world_position - u_light_position): the length of the difference"},
    {"the length of the sum, length(world_position + u_light_position)",
     "length(world_position - u_light_position): from the light to the fragment"},
    {NULL, NULL},
};

static void _sl_expect_cube_depth(const sl_probe_function *f, const float *row, int slip, double *out) {
    double d[3], length = 0, axis = 0, far = _sl_get(f, row, "u_light_far", 0);
    for (int j = 0; j < 3; j++) {
        d[j] = _sl_get(f, row, "world_position", j) - (slip == 1 ? 0 : _sl_get(f, row, "u_light_position", j));
        length += d[j] * d[j];
        axis = fmax(axis, fabs(d[j]));
    }
    double depth = slip == 2 ? axis / far : slip == 3 ? length / (far * far) : slip == 5 ? sqrt(length)
                   : slip == 6 ? sqrt(length) * far : sqrt(length) / far;
    if (slip == 4) depth = _sl_get(f, row, "gl_FragCoord.z", 0);
    if (slip == 7) depth = depth * 0.5 + 0.5;
    if (slip == 8 || slip == 9) {
        double world = 0, light = 0, sum = 0;
        for (int j = 0; j < 3; j++) {
            double w = _sl_get(f, row, "world_position", j), l = _sl_get(f, row, "u_light_position", j);
            world += w * w, light += l * l, sum += (w + l) * (w + l);
        }
        depth = (slip == 8 ? sqrt(world) - sqrt(light) : sqrt(sum)) / far;
    }
    out[0] = fmin(fmax(depth, 0), 1); /* the depth buffer keeps [0, 1] */
}

/* lab 2: shadow_matrix * world_position, with a projective matrix and w != 1 */
static void _sl_draw_shadow_coord(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                  size_t n) {
    (void)index;
    double m[16], p[4];
    for (int i = 0; i < 16; i++) m[i] = _sl_uniform(r, -1.5, 1.5);
    for (int i = 0; i < 3; i++) p[i] = _sl_uniform(r, -4, 4);
    p[3] = _sl_uniform(r, 0.5, 2.0);
    _sl_set(f, row, "shadow_matrix", m);
    _sl_set(f, row, "world_position", p);
    snprintf(about, n, "generic: a full projective matrix (no zero in its last row) and world_position.w = %.3g", p[3]);
}

static const char *const _sl_shadow_coord_slips[][2] = {
    {"", ""},
    {"world_position * shadow_matrix (the matrix transposed)", "shadow_matrix * world_position"},
    {"the matrix times (world_position.xyz, 1): its w taken as 1", "shadow_matrix * world_position, w as given"},
    {"the product divided by its w", "shadow_matrix * world_position, undivided (the lookup divides)"},
    {NULL, NULL},
};

static void _sl_expect_shadow_coord(const sl_probe_function *f, const float *row, int slip, double *out) {
    const float *m = sl_probe_row_param(f, row, "shadow_matrix"), *p = sl_probe_row_param(f, row, "world_position");
    for (int i = 0; i < 4; i++) {
        out[i] = 0;
        for (int j = 0; j < 4; j++) {
            double pj = slip == 2 && j == 3 ? 1.0 : (double)p[j];
            out[i] += (slip == 1 ? (double)m[i * 4 + j] : (double)m[j * 4 + i]) * pj;
        }
    }
    if (slip == 3 && out[3] != 0)
        for (int i = 0; i < 4; i++) out[i] /= i == 3 ? 1 : out[3];
    if (slip == 3) out[3] = 1;
}

/* lab 2 and 4: a lookup on the "step" (or "step_floor") map with w != 1, where dividing x and y by w
 * or not reads different sides of the edge about half the time */
static void _sl_draw_lookup(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n,
                            int radius) {
    sl_probe_map map = index % 2 ? SL_PROBE_MAP_STEP_FLOOR : SL_PROBE_MAP_STEP;
    int half = SL_PROBE_MAP_SIZE / 2;
    int i = radius > 0 ? _sl_integer(r, half - radius - 1, half + radius) : _sl_integer(r, 4, SL_PROBE_MAP_SIZE - 5);
    double p[3] = {_sl_in_texel(r, i), _sl_in_texel(r, _sl_integer(r, 4, SL_PROBE_MAP_SIZE - 5)),
                   _sl_uniform(r, 0.32, 0.82)};
    double bias = _sl_uniform(r, 0.001, 0.02), coord[4];
    _sl_homogeneous(r, (index / 2) % 2 == 0, p, coord);
    _sl_set1(f, row, "shadow_map", map);
    _sl_set(f, row, "shadow_coord", coord);
    _sl_set1(f, row, "bias", bias);
    if (radius > 0) _sl_set1(f, row, "radius", radius);
    size_t used = (size_t)snprintf(about, n, "generic: w = %.3g, the point (%.3g, %.3g, %.3g) after the divide of x, "
                                             "y and z by w, bias %.3g",
                                   coord[3], p[0], p[1], p[2], bias);
    if (radius > 0 && used < n)
        snprintf(about + used, n - used, ", radius %d: a %dx%d grid one texel apart across the edge", radius,
                 2 * radius + 1, 2 * radius + 1);
}

static void _sl_draw_compare(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    _sl_draw_lookup(f, r, index, row, about, n, 0);
    if (index < 4) return;
    /* half the rows sit within 0.0015 of the occluder's depth plus the bias, in front or behind: a bias
     * of one's own, or a comparison that adds it, turns these */
    int half = SL_PROBE_MAP_SIZE / 2;
    double coord[4], bias = _sl_get(f, row, "bias", 0), delta = _sl_uniform(r, 0.0004, 0.0015) * (index % 2 ? 1 : -1);
    for (int j = 0; j < 4; j++) coord[j] = _sl_get(f, row, "shadow_coord", j);
    double w = coord[3], u = _sl_in_texel(r, _sl_integer(r, 4, half - 5));
    double depth = _sl_map_at(SL_PROBE_MAP_STEP, u, 0.5) + bias + delta;
    coord[0] = u * w;
    coord[2] = depth * w;
    _sl_set1(f, row, "shadow_map", SL_PROBE_MAP_STEP);
    _sl_set(f, row, "shadow_coord", coord);
    snprintf(about, n, "generic: w = %.3g, on the occluder (depth 0.25), the point %.2g %s it beyond the bias %.3g",
             w, fabs(delta), delta > 0 ? "behind" : "in front of", bias);
}

static void _sl_draw_pcf_grid(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    /* radii 1 to 5 in turn: past the 3 a loop of constant bounds stops at */
    int radius = 1 + index % 5;
    _sl_draw_lookup(f, r, index, row, about, n, radius);
    if (index % 4 != 3) return;
    /* one row in four by an occluder's corner, the kernel across both of its edges: a kernel that covers
     * one line of the grid (a row, a column, a diagonal) answers as the full one only where the map varies
     * along one axis */
    int half = SL_PROBE_MAP_SIZE / 2;
    double p[3] = {_sl_in_texel(r, _sl_integer(r, half - radius, half + radius - 1)),
                   _sl_in_texel(r, _sl_integer(r, half - radius, half + radius - 1)), _sl_uniform(r, 0.32, 0.82)};
    double coord[4];
    _sl_homogeneous(r, (index / 4) % 2 == 0, p, coord);
    _sl_set1(f, row, "shadow_map", SL_PROBE_MAP_CORNER);
    _sl_set(f, row, "shadow_coord", coord);
    snprintf(about, n, "generic: w = %.3g, the point (%.3g, %.3g, %.3g) after the divide, by an occluder's corner "
                       "(the quarter u, v < 0.5), radius %d: a %dx%d grid across both of its edges",
             coord[3], p[0], p[1], p[2], radius, 2 * radius + 1, 2 * radius + 1);
}

/* How a grid lookup departs from the contract (one slip at a time). */
typedef enum _sl_grid_slip {
    _SL_GRID_CONTRACT,
    _SL_GRID_REVERSED,
    _SL_GRID_XY_NOT_DIVIDED,
    _SL_GRID_Z_NOT_DIVIDED,
    _SL_GRID_NO_FRUSTUM_TEST,
    _SL_GRID_ONE_ROW,
    _SL_GRID_ONE_SHORT,
    _SL_GRID_ONE_SHORT_FULL_COUNT,
    _SL_GRID_DIVIDED_BY_SIDE,
    _SL_GRID_UV_STEPS,
    _SL_GRID_TWO_TEXEL_STEPS,
    _SL_GRID_BIAS_OVER_W,  /* textureProj(map, vec4(xy, z - bias, w)): the divide takes the bias too */
    _SL_GRID_BIAS_TIMES_W, /* the bias scaled by w after the divide */
    _SL_GRID_BIAS_ON_XY,   /* vec3(p.xy, p.z) - bias: the lookup moved as well */
    _SL_GRID_NO_BIAS,
    _SL_GRID_BIAS_ADDED,
    _SL_GRID_CENTRE_DRIFTS, /* p.xy += offset in the loop: each sample from where the last one was */
    _SL_GRID_V_FLIPPED,     /* the map read at (p.x, 1 - p.y): Direct3D's v, running downwards */
    _SL_GRID_DIAGONAL,      /* offsets (x, x): each row of the loop samples the same diagonal */
    _SL_GRID_UV_REMAPPED,   /* the map read at p.xy * 0.5 + 0.5: texture space taken for NDC */
    _SL_GRID_FRUSTUM_UNDIVIDED, /* the frustum test on shadow_coord.xyz, before the divide by w */
    _SL_GRID_ALL_REMAPPED,      /* p * 0.5 + 0.5, z as well: a tutorial's remap where the matrix holds no W */
    _SL_GRID_TEXEL_INDEX,       /* texelFetch(map, ivec2(p.xy), 0): uv taken for a texel's index, texel (0, 0) */
} _sl_grid_slip;

/* The bias's slips, in _sl_grid_slip's order from _SL_GRID_BIAS_OVER_W. */
#define _SL_BIAS_SLIPS                                                                                              \
    {"the bias divided by w (z - bias inside the divide, as textureProj(map, vec4(xy, z - bias, w)) does)",        \
     "p.z - bias after the divide (inside textureProj: z - bias * w)"},                                            \
        {"the bias multiplied by w", "p.z - bias after the divide"},                                              \
        {"the bias subtracted from x and y too (vec3(p.xy, p.z) - bias): the lookup moves",                        \
         "the map read at p.xy, compared with p.z - bias"},                                                       \
        {"no bias", "p.z - bias compared"}, {"the bias added", "p.z - bias compared"}

static const char *const _sl_compare_slips[][2] = {
    {"", ""},
    {"the comparison reversed: lit where the point lies behind the stored depth", "p.z - bias > closest: shadowed"},
    {"x and y not divided by w (the map read at shadow_coord.xy)", "p = shadow_coord.xyz / shadow_coord.w, then read at p.xy"},
    {"z not divided by w (shadow_coord.z compared)", "p.z = shadow_coord.z / shadow_coord.w compared"},
    {"no test for points outside the light's frustum (w <= 0, or p outside [0, 1]): they read the map", "outside the light's frustum: lit (1.0)"},
    _SL_BIAS_SLIPS,
    {"t flipped: the map read at (p.x, 1 - p.y), Direct3D's v running downwards",
     "the map read at p.xy: GL's t runs upwards, as the bias matrix maps y"},
    {"the map read at p.xy * 0.5 + 0.5: p moved from [-1, 1] to [0, 1] again",
     "the map read at p.xy: the shadow matrix's bias already took it to [0, 1]"},
    {"the frustum test on the undivided coordinate (shadow_coord.xyz in [0, 1], before the divide by w): where w is "
     "not 1, points inside the frustum count as outside and the other way round",
     "the test on p = shadow_coord.xyz / shadow_coord.w: w <= 0, or p outside [0, 1]"},
    {"p moved to [0, 1] again, p * 0.5 + 0.5 (z as well), as a tutorial whose matrix holds no bias matrix does",
     "p as the divide gives it: lab 2's shadow matrix already holds W, which takes x, y and z to [0, 1]"},
    {"the map read at texel (int(p.x), int(p.y)), texel (0, 0) for every point inside: texelFetch given the uv "
     "coordinate as a texel's index",
     "texture(shadow_map, p.xy) with p.xy in [0, 1], or texelFetch at ivec2(p.xy * textureSize(shadow_map, 0))"},
    {NULL, NULL},
};

/* The compare catalogue's slips as the grid's (the grid's own kernel slips have no meaning for one lookup). */
static const _sl_grid_slip _sl_compare_as_grid[] = {
    _SL_GRID_CONTRACT,    _SL_GRID_REVERSED,     _SL_GRID_XY_NOT_DIVIDED, _SL_GRID_Z_NOT_DIVIDED,
    _SL_GRID_NO_FRUSTUM_TEST, _SL_GRID_BIAS_OVER_W, _SL_GRID_BIAS_TIMES_W, _SL_GRID_BIAS_ON_XY,
    _SL_GRID_NO_BIAS,     _SL_GRID_BIAS_ADDED,   _SL_GRID_V_FLIPPED, _SL_GRID_UV_REMAPPED,
    _SL_GRID_FRUSTUM_UNDIVIDED, _SL_GRID_ALL_REMAPPED, _SL_GRID_TEXEL_INDEX};

static const char *const _sl_grid_slips[][2] = {
    {"", ""},
    {"the comparison reversed: lit where the point lies behind the stored depth", "p.z - bias > closest: shadowed"},
    {"x and y not divided by w (the map read around shadow_coord.xy)", "p = shadow_coord.xyz / shadow_coord.w"},
    {"z not divided by w (shadow_coord.z compared)", "p.z = shadow_coord.z / shadow_coord.w compared"},
    {"no test for points outside the light's frustum: they read the map", "outside the light's frustum: lit (1.0)"},
    {"one row of the grid (y fixed at 0), averaged over (2r+1)^2", "a (2r+1) x (2r+1) grid: y from -radius to radius too"},
    {"loops from -radius to radius - 1 (one short), averaged over the taps taken", "x and y from -radius to radius, both included"},
    {"loops from -radius to radius - 1 (one short), divided by (2r+1)^2", "x and y from -radius to radius, both included"},
    {"the sum divided by 2r+1, not by (2r+1)^2 taps", "the sum divided by (2r+1)^2, the number of taps"},
    {"offsets in whole uv units (x, y), not in texels", "offsets (x, y) * texel, texel = 1.0 / textureSize(shadow_map, 0)"},
    {"offsets two texels apart", "offsets one texel apart"},
    _SL_BIAS_SLIPS,
    {"the centre moved by each offset in the loop (p.xy += offset): the samples wander along a running sum",
     "every sample at p.xy + (x, y) * texel, around the same centre"},
    {"t flipped: the map read around (p.x, 1 - p.y), Direct3D's v running downwards",
     "the map read around p.xy: GL's t runs upwards, as the bias matrix maps y"},
    {"offsets (x, x) or (y, y): one loop variable for both axes, so every row of the loop samples the same "
     "diagonal", "offsets (x, y) * texel: x across, y up, every texel of the (2r+1) x (2r+1) grid once"},
    {"the map read around p.xy * 0.5 + 0.5: p moved from [-1, 1] to [0, 1] again",
     "the map read around p.xy: the shadow matrix's bias already took it to [0, 1]"},
    {"the frustum test on the undivided coordinate (shadow_coord.xyz in [0, 1], before the divide by w): where w is "
     "not 1, points inside the frustum count as outside and the other way round",
     "the test on p = shadow_coord.xyz / shadow_coord.w: w <= 0, or p outside [0, 1]"},
    {"p moved to [0, 1] again, p * 0.5 + 0.5 (z as well), as a tutorial whose matrix holds no bias matrix does",
     "p as the divide gives it: lab 2's shadow matrix already holds W, which takes x, y and z to [0, 1]"},
    {"the map read at texel (int(p.x), int(p.y)), texel (0, 0) for every point inside: texelFetch given the uv "
     "coordinate as a texel's index",
     "texture(shadow_map, p.xy) with p.xy in [0, 1], or texelFetch at ivec2(p.xy * textureSize(shadow_map, 0))"},
    {NULL, NULL},
};

/* The fraction of a (2r+1)^2 grid of nearest lookups, one texel apart, that are lit (radius 0: one); outside
 * the light's frustum (w <= 0, or p outside [0, 1]) lit. */
static double _sl_grid(const sl_probe_function *f, const float *row, int radius, _sl_grid_slip slip) {
    sl_probe_map map = (sl_probe_map)(int)_sl_get(f, row, "shadow_map", 0);
    double w = _sl_get(f, row, "shadow_coord", 3), bias = _sl_get(f, row, "bias", 0);
    double xy_w = slip == _SL_GRID_XY_NOT_DIVIDED ? 1 : w, z_w = slip == _SL_GRID_Z_NOT_DIVIDED ? 1 : w;
    double u = _sl_get(f, row, "shadow_coord", 0) / xy_w, v = _sl_get(f, row, "shadow_coord", 1) / xy_w;
    double z = _sl_get(f, row, "shadow_coord", 2) / z_w;
    if (slip == _SL_GRID_BIAS_OVER_W) bias /= w;
    if (slip == _SL_GRID_BIAS_TIMES_W) bias *= w;
    if (slip == _SL_GRID_BIAS_ON_XY) u -= bias, v -= bias;
    if (slip == _SL_GRID_V_FLIPPED) v = 1 - v;
    if (slip == _SL_GRID_UV_REMAPPED || slip == _SL_GRID_ALL_REMAPPED) u = u * 0.5 + 0.5, v = v * 0.5 + 0.5;
    if (slip == _SL_GRID_ALL_REMAPPED) z = z * 0.5 + 0.5;
    if (slip == _SL_GRID_TEXEL_INDEX) u = (floor(u) + 0.5) / SL_PROBE_MAP_SIZE, v = (floor(v) + 0.5) / SL_PROBE_MAP_SIZE;
    if (slip == _SL_GRID_NO_BIAS) bias = 0;
    if (slip == _SL_GRID_BIAS_ADDED) bias = -bias;
    double px = _sl_get(f, row, "shadow_coord", 0) / w, py = _sl_get(f, row, "shadow_coord", 1) / w;
    double pz = _sl_get(f, row, "shadow_coord", 2) / w;
    if (slip == _SL_GRID_FRUSTUM_UNDIVIDED)
        px = _sl_get(f, row, "shadow_coord", 0), py = _sl_get(f, row, "shadow_coord", 1),
        pz = _sl_get(f, row, "shadow_coord", 2);
    if (slip == _SL_GRID_ALL_REMAPPED) /* p remapped where it is made: the frustum test reads it so too */
        px = px * 0.5 + 0.5, py = py * 0.5 + 0.5, pz = pz * 0.5 + 0.5;
    bool outside = w <= 0 || px < 0 || px > 1 || py < 0 || py > 1 || pz < 0 || pz > 1;
    if (outside && slip != _SL_GRID_NO_FRUSTUM_TEST) return 1;
    double texel = slip == _SL_GRID_UV_STEPS ? 1.0 : slip == _SL_GRID_TWO_TEXEL_STEPS ? 2.0 / SL_PROBE_MAP_SIZE
                                                                                    : 1.0 / SL_PROBE_MAP_SIZE;
    int hi = slip == _SL_GRID_ONE_SHORT || slip == _SL_GRID_ONE_SHORT_FULL_COUNT ? radius - 1 : radius;
    int y0 = slip == _SL_GRID_ONE_ROW ? 0 : -radius, y1 = slip == _SL_GRID_ONE_ROW ? 0 : hi;
    if (radius == 0) hi = y1 = 0;
    double lit = 0, taps = 0, drift_u = 0, drift_v = 0;
    for (int y = y0; y <= y1; y++)
        for (int x = -radius; x <= hi; x++, taps++) {
            double su = u + x * texel, sv = v + (slip == _SL_GRID_DIAGONAL ? x : y) * texel;
            if (slip == _SL_GRID_CENTRE_DRIFTS) {
                drift_u += x * texel, drift_v += y * texel;
                su = u + drift_u, sv = v + drift_v;
            }
            bool behind = z - bias > _sl_map_at(map, su, sv);
            lit += behind == (slip == _SL_GRID_REVERSED) ? 1 : 0;
        }
    double side = 2 * radius + 1;
    return slip == _SL_GRID_ONE_SHORT && taps > 0 ? lit / taps : slip == _SL_GRID_DIVIDED_BY_SIDE ? lit / side
                                                                                               : lit / (side * side);
}

static void _sl_expect_compare(const sl_probe_function *f, const float *row, int slip, double *out) {
    out[0] = _sl_grid(f, row, 0, _sl_compare_as_grid[slip]);
}

static void _sl_expect_pcf_grid(const sl_probe_function *f, const float *row, int slip, double *out) {
    out[0] = _sl_grid(f, row, (int)_sl_get(f, row, "radius", 0), (_sl_grid_slip)slip);
}

/* lab 3 (bonus): the midpoint of two maps, with w != 1 and a second surface near enough that the two
 * depths' sum lies below 1 (a sum where the half belongs then shadows where it should not, and the
 * first or the second depth alone each turn rows of their own) */
static void _sl_draw_midpoint(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    double u = _sl_in_texel(r, _sl_integer(r, 20, 44)), v = _sl_in_texel(r, _sl_integer(r, 4, SL_PROBE_MAP_SIZE - 5));
    double first = _sl_map_at(SL_PROBE_MAP_OCCLUDED, u, v), second = _sl_map_at(SL_PROBE_MAP_RAMP, u, v);
    double middle = 0.5 * (first + second), z;
    const char *where;
    switch (index % 4) {
    case 0: z = _sl_uniform(r, middle + 0.25 * (second - middle), second - 0.25 * (second - middle)), where = "past the midpoint, before the second surface: shadowed"; break;
    case 1: z = _sl_uniform(r, first + 0.25 * (middle - first), middle - 0.25 * (middle - first)), where = "past the first surface, before the midpoint: lit"; break;
    case 2: z = _sl_uniform(r, second + 0.02, fmin(first + second + 0.05, 0.98)), where = "past the second surface: shadowed"; break;
    default: z = _sl_uniform(r, 0.05, first - 0.03), where = "in front of both surfaces: lit"; break;
    }
    double p[3] = {u, v, z}, coord[4];
    _sl_homogeneous(r, index % 2 == 0, p, coord);
    _sl_set1(f, row, "first_depth", SL_PROBE_MAP_OCCLUDED);
    _sl_set1(f, row, "second_depth", SL_PROBE_MAP_RAMP);
    _sl_set(f, row, "shadow_coord", coord);
    snprintf(about, n, "generic: w = %.3g, the surfaces at %.3g and %.3g (midpoint %.3g), the point at depth %.3g, %s",
             coord[3], first, second, middle, z, where);
}

static const char *const _sl_midpoint_slips[][2] = {
    {"", ""},
    {"the two depths added, not averaged", "midpoint = 0.5 * (first + second)"},
    {"the first map's depth alone", "the midpoint of both maps' depths"},
    {"the second map's depth alone", "the midpoint of both maps' depths"},
    {"xyz not divided by w", "p = shadow_coord.xyz / shadow_coord.w"},
    {"lit and shadowed swapped", "p.z > midpoint: shadowed (0), else lit (1)"},
    {"0.5 * first + second: the half on the first depth alone (the parentheses left out)", "0.5 * (first + second)"},
    {"first + 0.5 * second: the half on the second depth alone (the parentheses left out)", "0.5 * (first + second)"},
    {"half the difference, 0.5 * (second - first): half the gap between the surfaces, a distance, not a depth",
     "0.5 * (first + second): the depth half way between them"},
    {"half the difference added to the second depth, second + 0.5 * (second - first): past the second surface",
     "first + 0.5 * (second - first) = 0.5 * (first + second)"},
    {"a midpoint of 0, as 1 / 2 * (first + second) gives (1 / 2 divides integers: 0): every point lies behind it",
     "0.5 * (first + second), the half a float"},
    {NULL, NULL},
};

static void _sl_expect_midpoint(const sl_probe_function *f, const float *row, int slip, double *out) {
    double c[4];
    for (int j = 0; j < 4; j++) c[j] = _sl_get(f, row, "shadow_coord", j);
    double w = slip == 4 ? 1 : c[3], p[3] = {c[0] / w, c[1] / w, c[2] / w};
    if (c[3] <= 0 || p[0] < 0 || p[1] < 0 || p[2] < 0 || p[0] > 1 || p[1] > 1 || p[2] > 1) {
        out[0] = 1;
        return;
    }
    sl_probe_map a = (sl_probe_map)(int)_sl_get(f, row, "first_depth", 0);
    sl_probe_map b = (sl_probe_map)(int)_sl_get(f, row, "second_depth", 0);
    double first = _sl_map_at(a, p[0], p[1]), second = _sl_map_at(b, p[0], p[1]);
    double middle = slip == 1 ? first + second : slip == 2 ? first : slip == 3 ? second
                  : slip == 6 ? 0.5 * first + second : slip == 7 ? first + 0.5 * second
                  : slip == 8 ? 0.5 * (second - first) : slip == 9 ? second + 0.5 * (second - first)
                  : slip == 10 ? 0
                              : 0.5 * (first + second);
    bool shadowed = p[2] > middle;
    out[0] = (slip == 5 ? shadowed : !shadowed) ? 1 : 0;
}

/* lab 3: min(constant + slope * tan(theta), max_bias), cos(theta) = n_dot_l, every term non-zero */
static void _sl_draw_slope_bias(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    /* one row in four near grazing (below 0.1) and still under max_bias, where a floor on cos of its own shows */
    double n_dot_l = index % 4 == 0 ? _sl_uniform(r, 0.03, 0.1) : _sl_uniform(r, 0.1, 0.97);
    double constant = _sl_uniform(r, 2e-4, 3e-3);
    double slope = _sl_uniform(r, 5e-4, 6e-3), tan_theta = sqrt(1 - n_dot_l * n_dot_l) / n_dot_l;
    double unclamped = constant + slope * tan_theta;
    /* most rows below the clamp (every term shows), one in four above it */
    double max_bias = index % 4 == 3 ? unclamped * _sl_uniform(r, 0.5, 0.85) : unclamped * _sl_uniform(r, 1.2, 3.0);
    _sl_set1(f, row, "n_dot_l", n_dot_l);
    _sl_set1(f, row, "constant_bias", constant);
    _sl_set1(f, row, "slope", slope);
    _sl_set1(f, row, "max_bias", max_bias);
    snprintf(about, n, "generic: n_dot_l %.3g (tan = %.3g), constant, slope and max_bias all non-zero, %s", n_dot_l,
             tan_theta, index % 4 == 3 ? "the clamp to max_bias applies" : "below max_bias");
}

static const char *const _sl_slope_bias_slips[][2] = {
    {"", ""},
    {"sin(theta) in place of tan(theta)", "tan(theta) = sqrt(1 - n_dot_l^2) / n_dot_l"},
    {"1 / n_dot_l in place of tan(theta)", "tan(theta) = sqrt(1 - n_dot_l^2) / n_dot_l"},
    {"the angle theta itself (radians) in place of tan(theta)", "tan(theta), theta = acos(n_dot_l)"},
    {"tan(n_dot_l) in place of tan(acos(n_dot_l))", "tan(theta), theta = acos(n_dot_l)"},
    {"n_dot_l (cos theta) in place of tan(theta)", "tan(theta) = sqrt(1 - n_dot_l^2) / n_dot_l"},
    {"the clamp on the slope term alone: constant + min(slope * tan(theta), max_bias)",
     "min(constant + slope * tan(theta), max_bias): the sum clamped"},
    {"max in place of min: max_bias as a floor", "min(constant + slope * tan(theta), max_bias): max_bias a ceiling"},
    {"no clamp to max_bias", "min(constant + slope * tan(theta), max_bias)"},
    {NULL, NULL},
};

static void _sl_expect_slope_bias(const sl_probe_function *f, const float *row, int slip, double *out) {
    double c = fmax(_sl_get(f, row, "n_dot_l", 0), 1e-4), s = sqrt(fmax(1 - c * c, 0));
    double term = slip == 1 ? s : slip == 2 ? 1 / c : slip == 3 ? acos(c) : slip == 4 ? tan(c) : slip == 5 ? c : s / c;
    double constant = _sl_get(f, row, "constant_bias", 0), slope = _sl_get(f, row, "slope", 0);
    double max_bias = _sl_get(f, row, "max_bias", 0);
    out[0] = slip == 6 ? constant + fmin(slope * term, max_bias)
           : slip == 7 ? fmax(constant + slope * term, max_bias)
           : slip == 8 ? constant + slope * term
                       : fmin(constant + slope * term, max_bias);
}

/* lab 3: world_position + normal * texels * texel_world_size * (1 - n_dot_l) */
static void _sl_draw_normal_offset(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                   size_t n) {
    (void)index;
    double p[3], normal[3], length = 0;
    for (int j = 0; j < 3; j++) p[j] = _sl_uniform(r, -5, 5), normal[j] = _sl_uniform(r, -1, 1);
    for (int j = 0; j < 3; j++) length += normal[j] * normal[j];
    length = sqrt(length) + 1e-9;
    for (int j = 0; j < 3; j++) normal[j] /= length;
    double n_dot_l = _sl_uniform(r, 0.1, 0.9), texel = _sl_uniform(r, 0.01, 0.2), texels = _sl_uniform(r, 0.5, 3);
    _sl_set(f, row, "world_position", p);
    _sl_set(f, row, "normal", normal);
    _sl_set1(f, row, "n_dot_l", n_dot_l);
    _sl_set1(f, row, "texel_world_size", texel);
    _sl_set1(f, row, "texels", texels);
    snprintf(about, n, "generic: a slanted normal, n_dot_l %.3g, texel %.3g world units, %.3g texels", n_dot_l, texel,
             texels);
}

/* The angle's factor written as another function of it: published normal offsets scale by 1 - N.L, by sin
 * or by tan of the angle; the contract's is 1 - N.L. (Slips of one input, n_dot_l as 1 - it or 0, or the
 * normal negated, are found without a catalogue.) */
static const char *const _sl_normal_offset_slips[][2] = {
    {"", ""},
    {"sin(theta) = sqrt(1 - n_dot_l^2) in place of 1 - n_dot_l", "the offset scaled by 1 - n_dot_l"},
    {"tan(theta) = sqrt(1 - n_dot_l^2) / n_dot_l in place of 1 - n_dot_l", "the offset scaled by 1 - n_dot_l"},
    {"the angle theta = acos(n_dot_l) itself (radians, up to pi/2) in place of 1 - n_dot_l",
     "the offset scaled by 1 - n_dot_l (0 facing the light, 1 edge-on)"},
    {NULL, NULL},
};

static void _sl_expect_normal_offset(const sl_probe_function *f, const float *row, int slip, double *out) {
    double n_dot_l = _sl_get(f, row, "n_dot_l", 0), sin_theta = sqrt(fmax(0, 1 - n_dot_l * n_dot_l));
    double angle = slip == 1   ? sin_theta
                 : slip == 2 ? sin_theta / n_dot_l
                 : slip == 3 ? acos(fmin(fmax(n_dot_l, -1), 1))
                             : 1 - n_dot_l;
    double k = _sl_get(f, row, "texels", 0) * _sl_get(f, row, "texel_world_size", 0) * angle;
    for (int j = 0; j < 3; j++) out[j] = _sl_get(f, row, "world_position", j) + _sl_get(f, row, "normal", j) * k;
}

/* lab 5: (depth, depth^2) */
static void _sl_draw_moments(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double depth = _sl_uniform(r, 0.05, 0.95);
    _sl_set1(f, row, "depth", depth);
    snprintf(about, n, "generic depth %.3g: (depth, depth^2)", depth);
}

static const char *const _sl_moments_slips[][2] = {
    {"", ""},
    {"(depth, depth): the second moment not squared", "(depth, depth * depth)"},
    {"(depth * depth, depth): the moments swapped", "(depth, depth * depth)"},
    {"the moments of 2 * depth - 1 (NDC depth)", "the moments of the window depth in [0, 1], as given"},
    {NULL, NULL},
};

static void _sl_expect_moments(const sl_probe_function *f, const float *row, int slip, double *out) {
    double d = _sl_get(f, row, "depth", 0);
    if (slip == 3) d = 2 * d - 1;
    out[0] = slip == 2 ? d * d : d;
    out[1] = slip == 1 || slip == 2 ? d : d * d;
}

/* lab 5: 2r+1 Gaussian taps one texel apart along direction, sigma = max(r/2, 0.5), normalised */
static void _sl_draw_blur(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    bool along_x = index % 2 == 0;
    sl_probe_map map = _sl_integer(r, 0, 1) ? SL_PROBE_MAP_MOMENTS_STEP_X : SL_PROBE_MAP_MOMENTS_STEP_Y;
    int radius = _sl_integer(r, 2, 6), half = SL_PROBE_MAP_SIZE / 2;
    /* the tap across the edge: within the radius of it along the direction the map changes */
    int i = _sl_integer(r, half - radius, half + radius - 1), other = _sl_integer(r, 4, SL_PROBE_MAP_SIZE - 5);
    bool edge_x = map == SL_PROBE_MAP_MOMENTS_STEP_X;
    double uv[2] = {(edge_x ? i : other) + 0.5, (edge_x ? other : i) + 0.5};
    uv[0] /= SL_PROBE_MAP_SIZE;
    uv[1] /= SL_PROBE_MAP_SIZE;
    double direction[2] = {along_x ? 1 : 0, along_x ? 0 : 1};
    _sl_set1(f, row, "moments", map);
    _sl_set(f, row, "uv", uv);
    _sl_set(f, row, "direction", direction);
    _sl_set1(f, row, "radius", radius);
    snprintf(about, n, "generic: radius %d along %s, %s the edge of the \"%s\" map (uv %.4g, %.4g)", radius,
             along_x ? "x" : "y", along_x == edge_x ? "across" : "beside", sl_probe_map_name(map), uv[0], uv[1]);
}

static const char *const _sl_blur_slips[][2] = {
    {"", ""},
    {"weights not normalised: the sum not divided by the weights' total", "the weighted sum divided by the sum of the weights"},
    {"equal weights (a box filter)", "Gaussian weights exp(-i^2 / (2 sigma^2))"},
    {"sigma = radius", "sigma = max(radius / 2, 0.5)"},
    {"taps from -radius to radius - 1 (one short)", "taps from -radius to radius, both included"},
    {"taps two texels apart", "taps one texel apart along direction"},
    {"taps a whole uv unit apart, not a texel", "taps one texel (1.0 / textureSize) apart along direction"},
    {"only the first moment blurred (the second as read at uv)", "both moments blurred alike"},
    {"always along x, whatever direction is", "taps along direction"},
    {"always along y, whatever direction is", "taps along direction"},
    {"Gaussian weights exp(-i^2 / (2 sigma)): sigma not squared", "exp(-i^2 / (2 sigma^2))"},
    {NULL, NULL},
};

static void _sl_expect_blur(const sl_probe_function *f, const float *row, int slip, double *out) {
    sl_probe_map map = (sl_probe_map)(int)_sl_get(f, row, "moments", 0);
    int radius = (int)_sl_get(f, row, "radius", 0);
    int x0 = (int)floor(_sl_get(f, row, "uv", 0) * SL_PROBE_MAP_SIZE);
    int y0 = (int)floor(_sl_get(f, row, "uv", 1) * SL_PROBE_MAP_SIZE);
    int dx = (int)_sl_get(f, row, "direction", 0), dy = (int)_sl_get(f, row, "direction", 1);
    if (slip == 8) dx = 1, dy = 0;
    if (slip == 9) dx = 0, dy = 1;
    int step = slip == 5 ? 2 : slip == 6 ? SL_PROBE_MAP_SIZE : 1;
    double sigma = slip == 3 ? fmax(radius, 0.5) : fmax(radius * 0.5, 0.5), sum[2] = {0, 0}, weights = 0;
    for (int i = -radius; i <= (slip == 4 ? radius - 1 : radius); i++) {
        double w = slip == 2 ? 1.0 : exp(-(double)(i * i) / (2 * sigma * (slip == 10 ? 1 : sigma)));
        int x = x0 + i * dx * step, y = y0 + i * dy * step;
        x = x < 0 ? 0 : x >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : x;
        y = y < 0 ? 0 : y >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : y;
        double d = (double)sl_probe_moments_depth(map, x, y);
        sum[0] += w * d;
        sum[1] += w * d * d;
        weights += w;
    }
    if (slip == 1) weights = 1;
    out[0] = sum[0] / weights;
    out[1] = sum[1] / weights;
    if (slip == 7) {
        double d = (double)sl_probe_moments_depth(map, x0, y0);
        out[1] = d * d;
    }
}

/* lab 5: Chebyshev's one-tailed bound, variance clamped below by min_variance */
static void _sl_draw_chebyshev(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    double mu = _sl_uniform(r, 0.15, 0.7), variance = _sl_uniform(r, 4e-4, 0.02);
    double t = index % 4 == 3 ? mu - _sl_uniform(r, 0.02, 0.1) : mu + _sl_uniform(r, 0.02, 0.25);
    double min_variance = index % 4 == 2 ? variance * _sl_uniform(r, 1.5, 4) : variance * _sl_uniform(r, 0.05, 0.5);
    double moments[2] = {mu, mu * mu + variance};
    _sl_set(f, row, "moments", moments);
    _sl_set1(f, row, "t", t);
    _sl_set1(f, row, "min_variance", min_variance);
    snprintf(about, n, "generic: mean %.3g, variance %.3g, t %.3g (%s), min_variance %.3g (%s)", mu, variance, t,
             t <= mu ? "in front of the mean: lit" : "behind the mean", min_variance,
             min_variance > variance ? "above the variance: it applies" : "below the variance");
}

static const char *const _sl_chebyshev_slips[][2] = {
    {"", ""},
    {"the variance as E[x^2] - mu, not E[x^2] - mu^2", "variance = moments.y - mu * mu"},
    {"the variance not clamped below by min_variance", "variance = max(moments.y - mu * mu, min_variance)"},
    {"min in place of max: min_variance as a ceiling on the variance", "variance = max(moments.y - mu * mu, min_variance)"},
    {"min_variance added to the variance", "variance = max(moments.y - mu * mu, min_variance)"},
    {"d not squared: variance / (variance + d)", "variance / (variance + d * d), d = t - mu"},
    {"no lit test for t <= mu: the bound used in front of the mean too", "t <= mu: fully lit (1.0)"},
    {"1 - p_max returned", "p_max = variance / (variance + d * d)"},
    {"min_variance added to the variance clamped at 0: max(variance, 0) + min_variance", "variance = max(moments.y - mu * mu, min_variance)"},
    {"sigma = sqrt(variance) where the bound takes the variance itself: sigma / (sigma + d * d)",
     "p_max = sigma^2 / (sigma^2 + d^2): the variance, not the standard deviation"},
    {NULL, NULL},
};

static void _sl_expect_chebyshev(const sl_probe_function *f, const float *row, int slip, double *out) {
    double mu = _sl_get(f, row, "moments", 0), m2 = _sl_get(f, row, "moments", 1), t = _sl_get(f, row, "t", 0);
    double min_variance = _sl_get(f, row, "min_variance", 0);
    if (t <= mu && slip != 6) {
        out[0] = 1;
        return;
    }
    double raw = slip == 1 ? m2 - mu : m2 - mu * mu;
    double variance = slip == 2 ? raw : slip == 3 ? fmin(raw, min_variance) : slip == 4 ? raw + min_variance
                    : slip == 8 ? fmax(raw, 0) + min_variance : fmax(raw, min_variance);
    if (slip == 9) variance = sqrt(variance);
    double d = t - mu, p = variance / (variance + (slip == 5 ? d : d * d));
    out[0] = slip == 7 ? 1 - p : p;
}

/* lab 5: linstep(amount, 1, p_max) */
static void _sl_draw_bleeding(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double amount = _sl_uniform(r, 0.1, 0.6), p_max = _sl_uniform(r, 0.0, 1.0);
    _sl_set1(f, row, "p_max", p_max);
    _sl_set1(f, row, "amount", amount);
    snprintf(about, n, "generic: p_max %.3g, amount %.3g: (p_max - amount) / (1 - amount), clamped to [0, 1]", p_max,
             amount);
}

static const char *const _sl_bleeding_slips[][2] = {
    {"", ""},
    {"linstep(0, amount, p_max): p_max / amount", "linstep(amount, 1, p_max) = (p_max - amount) / (1 - amount)"},
    {"no clamp to [0, 1]", "(p_max - amount) / (1 - amount), clamped to [0, 1]"},
    {"p_max - amount, not rescaled by 1 / (1 - amount)", "(p_max - amount) / (1 - amount)"},
    {"(p_max - amount) / amount", "(p_max - amount) / (1 - amount)"},
    {"smoothstep(amount, 1, p_max) in place of the linear ramp", "linstep(amount, 1, p_max) = (p_max - amount) / (1 - amount)"},
    {"mix(amount, 1, p_max) = amount + (1 - amount) * p_max, the ramp's inverse: full shadow raised to amount",
     "linstep(amount, 1, p_max) = (p_max - amount) / (1 - amount): p_max below amount cut to 0"},
    {NULL, NULL},
};

static void _sl_expect_bleeding(const sl_probe_function *f, const float *row, int slip, double *out) {
    double amount = _sl_get(f, row, "amount", 0), p = _sl_get(f, row, "p_max", 0);
    double v = slip == 1 ? p / amount : slip == 3 ? p - amount : slip == 4 ? (p - amount) / amount
                                      : slip == 6 ? amount + (1 - amount) * p
                                                  : (p - amount) / (1 - amount);
    if (slip != 2) v = fmin(fmax(v, 0), 1);
    if (slip == 5) v = v * v * (3 - 2 * v);
    out[0] = v;
}

/* lab 5 (bonus): EVSM's two warps, exp(c+ d) and -exp(-c- d), with c+ and c- apart (one read for the other
 * shows) and each product c d between 0.5 and 4, so both warps' sizes are alike (a slip in either shows at
 * the same tolerance) */
static void _sl_draw_evsm(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double depth = _sl_uniform(r, 0.1, 0.95);
    double positive = _sl_uniform(r, 1, 4) / depth, negative = _sl_uniform(r, 0.5, 3) / depth;
    if (fabs(positive - negative) < 1) negative = positive * 0.5;
    double exponents[2] = {positive, negative};
    _sl_set1(f, row, "depth", depth);
    _sl_set(f, row, "exponents", exponents);
    snprintf(about, n, "generic: depth %.3g, c+ %.3g, c- %.3g", depth, positive, negative);
}

static void _sl_expect_evsm(const sl_probe_function *f, const float *row, int slip, double *out) {
    (void)slip;
    double d = _sl_get(f, row, "depth", 0);
    out[0] = exp(_sl_get(f, row, "exponents", 0) * d);
    out[1] = -exp(-_sl_get(f, row, "exponents", 1) * d);
}

/* lab 5 (bonus): exponential shadow maps, exp(c * d) stored, the point in front of the occluder (where only
 * the clamp keeps the answer at 1) or behind it */
static void _sl_draw_esm(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    double c = _sl_uniform(r, 15, 60), d = _sl_uniform(r, 0.2, 0.8);
    double t = index % 2 ? d + _sl_uniform(r, 0.002, 0.08) : d - _sl_uniform(r, 0.02, 0.15);
    _sl_set1(f, row, "moment", exp(c * d));
    _sl_set1(f, row, "t", t);
    _sl_set1(f, row, "c", c);
    snprintf(about, n, "generic: c = %.3g, the occluder at depth %.3g (moment exp(c * %.3g)), the point at %.3g, %s", c,
             d, d, t, t < d ? "in front of it: lit, clamped to 1" : "behind it: exp(-c * (t - d))");
}

static const char *const _sl_esm_slips[][2] = {{"", ""}, {NULL, NULL}};

static void _sl_expect_esm(const sl_probe_function *f, const float *row, int slip, double *out) {
    (void)slip;
    double v = _sl_get(f, row, "moment", 0) * exp(-_sl_get(f, row, "c", 0) * _sl_get(f, row, "t", 0));
    out[0] = fmin(fmax(v, 0), 1);
}

/* lab 6: lambda * near * (far/near)^(i/count) + (1 - lambda) * (near + (far - near) * i/count), unused 0 */
static void _sl_draw_splits(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    (void)index;
    double near = _sl_uniform(r, 0.2, 4.0), far = _sl_uniform(r, 30, 400), lambda = _sl_uniform(r, 0.15, 0.95);
    int count = _sl_integer(r, 2, 4);
    _sl_set1(f, row, "near", near);
    _sl_set1(f, row, "far", far);
    _sl_set1(f, row, "count", count);
    _sl_set1(f, row, "lambda", lambda);
    snprintf(about, n, "generic: near %.3g (not 1), far %.4g, %d cascades, lambda %.3g: both schemes count", near, far,
             count, lambda);
}

static const char *const _sl_splits_slips[][2] = {
    {"", ""},
    {"lambda on the linear scheme and 1 - lambda on the logarithmic one", "lambda * logarithmic + (1 - lambda) * linear"},
    {"t = i / (count + 1)", "t = i / count"},
    {"t = i / (count - 1)", "t = i / count"},
    {"the linear scheme as near + far * t", "near + (far - near) * t"},
    {"the logarithmic scheme as (far / near)^t, without the factor near", "near * (far / near)^t"},
    {"the logarithmic scheme as near + (far - near)^t", "near * (far / near)^t"},
    {NULL, NULL},
};

static void _sl_expect_splits(const sl_probe_function *f, const float *row, int slip, double *out) {
    double near = _sl_get(f, row, "near", 0), far = _sl_get(f, row, "far", 0), lambda = _sl_get(f, row, "lambda", 0);
    int count = (int)_sl_get(f, row, "count", 0);
    double parts = slip == 2 ? count + 1 : slip == 3 ? count - 1 : count;
    for (int i = 0; i < 5; i++) {
        double t = parts > 0 ? i / parts : 0;
        double logarithmic = slip == 5 ? pow(far / near, t) : slip == 6 ? near + pow(far - near, t) : near * pow(far / near, t);
        double linear = slip == 4 ? near + far * t : near + (far - near) * t;
        double l = slip == 1 ? 1 - lambda : lambda;
        out[i] = i > count ? 0 : l * logarithmic + (1 - l) * linear;
    }
    /* the ends are near and far exactly (a slip in between still pins them, as the lab's code does) */
    out[0] = near;
    if (count >= 0 && count < 5) out[count] = far;
}

/* lab 6: the sphere around a slice of a camera's frustum (the mean of its 8 corners, the farthest corner), for
 * a camera looking anywhere from anywhere, at other fields of view, aspects and planes, and a slice that is
 * not the first */
static void _sl_draw_slice(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    double eye[3], target[3];
    for (int j = 0; j < 3; j++) eye[j] = _sl_uniform(r, -20, 20), target[j] = eye[j] + _sl_uniform(r, -10, 10);
    target[1] = eye[1] + _sl_uniform(r, -3, 1); /* never straight up or down: lookat's up is the world's */
    double fov = _sl_uniform(r, 35, 80), aspect = _sl_uniform(r, 1.0, 2.2), near = _sl_uniform(r, 0.1, 1.0);
    double far = _sl_uniform(r, 40, 200);
    /* a slice drawn in turn: the first, one in the middle, the last */
    double a = index % 3 == 0 ? near : near + (far - near) * _sl_uniform(r, 0.02, 0.3);
    double b = index % 3 == 2 ? far : a + (far - a) * _sl_uniform(r, 0.1, 0.5);
    _sl_set(f, row, "eye", eye);
    _sl_set(f, row, "target", target);
    _sl_set1(f, row, "fov_deg", fov);
    _sl_set1(f, row, "aspect", aspect);
    _sl_set1(f, row, "near", near);
    _sl_set1(f, row, "far", far);
    _sl_set1(f, row, "split_near", a);
    _sl_set1(f, row, "split_far", b);
    snprintf(about, n, "generic: a camera at (%.3g, %.3g, %.3g), fov %.3g, aspect %.3g, near %.3g, far %.4g; the slice "
                       "from %.4g to %.4g",
             eye[0], eye[1], eye[2], fov, aspect, near, far, a, b);
}

enum {
    _SL_SLICE_FROM_FAR = 1,
    _SL_SLICE_NEAR_PLUS_FAR,
    _SL_SLICE_T_OVER_FAR,
    _SL_SLICE_T_NEAR_KEPT,
    _SL_SLICE_T_SPLIT_OVER_RANGE,
    _SL_SLICE_DISTANCE_ALONG_EDGE,
    _SL_SLICE_NDC_LERP,
    _SL_SLICE_NEAR_AT_NDC_ZERO,
    _SL_SLICE_NO_W_DIVIDE,
    _SL_SLICE_WHOLE_FRUSTUM,
    _SL_SLICE_RADIUS_FIRST_CORNER,
    _SL_SLICE_CENTRE_OVER_FOUR,
    _SL_SLICE_NEAR_BY_FAR_W,
    _SL_SLICE_FAR_BY_NEAR_W,
    _SL_SLICE_RADIUS_SEVEN_CORNERS,
    _SL_SLICE_CENTRE_NEAR_CORNERS,
    _SL_SLICE_CENTRE_SEVEN_OVER_EIGHT,
};

static const char *const _sl_slice_slips[][2] = {
    {"", ""},
    [_SL_SLICE_FROM_FAR] = {"the corners lerped from the far corner towards the near one, cf + (cn - cf) * t: the "
                            "fraction measured from the far plane (or t with near and far in each other's place)",
                            "cn + (cf - cn) * t, t = (split - near) / (far - near), measured from the near corner"},
    [_SL_SLICE_NEAR_PLUS_FAR] = {"the corners as cn + cf * t: t times the far corner itself, not the edge cf - cn",
                                 "cn + (cf - cn) * t: along the edge from the near corner to the far one"},
    [_SL_SLICE_T_OVER_FAR] = {"t = split / far", "t = (split - near) / (far - near)"},
    [_SL_SLICE_T_NEAR_KEPT] = {"t = (split - near) / far", "t = (split - near) / (far - near)"},
    [_SL_SLICE_T_SPLIT_OVER_RANGE] = {"t = split / (far - near)", "t = (split - near) / (far - near)"},
    [_SL_SLICE_DISTANCE_ALONG_EDGE] = {"each corner split - near along the unit edge from the near corner: a distance "
                                       "along the edge, where the split is a view depth",
                                       "cn + (cf - cn) * t, t = (split - near) / (far - near): the edge is longer than "
                                       "the depth it spans"},
    [_SL_SLICE_NDC_LERP] = {"the corners unprojected at NDC z = -1 + 2 t: depth is not linear in NDC z, so the slice "
                            "lies much farther away",
                            "the near and far corners unprojected (NDC z -1 and +1), then lerped in world space"},
    [_SL_SLICE_NEAR_AT_NDC_ZERO] = {"the near corners at NDC z = 0 (Direct3D's depth range), not -1",
                                    "NDC z = -1 on the near plane and +1 on the far one (GL's range)"},
    [_SL_SLICE_NO_W_DIVIDE] = {"the corners without the divide by w: inv_view_projection * (x, y, z, 1) is homogeneous",
                               "each unprojected corner's xyz divided by its w"},
    [_SL_SLICE_WHOLE_FRUSTUM] = {"the sphere around the whole frustum, near to far: split_near and split_far unused",
                                 "the corners at split_near and split_far"},
    [_SL_SLICE_RADIUS_FIRST_CORNER] = {"the radius as the distance to the corners at split_near alone (the first "
                                       "corner, or a loop over 4 where 8 belong: the 4 near corners lie equally far "
                                       "from the centre), so the slice's wider far end is left out",
                                       "the largest distance from the centre to any of the 8 corners"},
    [_SL_SLICE_CENTRE_OVER_FOUR] = {"the centre as the corners' sum divided by 4", "the mean of the 8 corners, sum / 8"},
    [_SL_SLICE_NEAR_BY_FAR_W] = {"the near corner divided by the far corner's w (wn.xyz / wf.w)",
                                 "each unprojected corner divided by its own w: wn.xyz / wn.w, wf.xyz / wf.w"},
    [_SL_SLICE_FAR_BY_NEAR_W] = {"the far corner divided by the near corner's w (wf.xyz / wn.w)",
                                 "each unprojected corner divided by its own w: wn.xyz / wn.w, wf.xyz / wf.w"},
    [_SL_SLICE_RADIUS_SEVEN_CORNERS] = {"the radius over the first 7 corners (a loop one short)",
                                        "the largest distance from the centre to any of the 8 corners"},
    [_SL_SLICE_CENTRE_NEAR_CORNERS] = {"the centre as the mean of the 4 corners at split_near only",
                                       "the mean of all 8 corners"},
    [_SL_SLICE_CENTRE_SEVEN_OVER_EIGHT] = {"the centre as the first 7 corners' sum over 8 (a loop one short)",
                                           "the mean of all 8 corners, their sum over 8"},
    {NULL, NULL},
};

/* a corner of the slice's plane at `split` (x, y = -1 or 1 in NDC), as the contract or a slip finds it */
static void _sl_slice_corner(const double eye[3], const double ray[3], double near, double far, double split,
                             int slip, double out[3]) {
    double cn[3], cf[3];
    double d_near = near;
    if (slip == _SL_SLICE_NEAR_AT_NDC_ZERO) d_near = 2 * near * far / (far + near);
    for (int j = 0; j < 3; j++) cn[j] = eye[j] + d_near * ray[j], cf[j] = eye[j] + far * ray[j];
    /* inv_view_projection * (x, y, -1 or 1, 1) has w = 1 / (the view depth): near's or far's */
    if (slip == _SL_SLICE_NO_W_DIVIDE)
        for (int j = 0; j < 3; j++) cn[j] /= near, cf[j] /= far;
    if (slip == _SL_SLICE_NEAR_BY_FAR_W)
        for (int j = 0; j < 3; j++) cn[j] *= far / near;
    if (slip == _SL_SLICE_FAR_BY_NEAR_W)
        for (int j = 0; j < 3; j++) cf[j] *= near / far;
    double t = (split - near) / (far - near);
    switch (slip) {
    case _SL_SLICE_FROM_FAR: t = 1 - t; break;
    case _SL_SLICE_T_OVER_FAR: t = split / far; break;
    case _SL_SLICE_T_NEAR_KEPT: t = (split - near) / far; break;
    case _SL_SLICE_T_SPLIT_OVER_RANGE: t = split / (far - near); break;
    case _SL_SLICE_NDC_LERP: {
        double z = -1 + 2 * t, depth = 2 * near * far / (far + near - z * (far - near));
        t = (depth - near) / (far - near);
        break;
    }
    default: break;
    }
    if (slip == _SL_SLICE_DISTANCE_ALONG_EDGE) {
        double edge[3], length = 0;
        for (int j = 0; j < 3; j++) edge[j] = cf[j] - cn[j], length += edge[j] * edge[j];
        length = sqrt(length);
        for (int j = 0; j < 3; j++) out[j] = cn[j] + edge[j] / length * (split - near);
        return;
    }
    for (int j = 0; j < 3; j++)
        out[j] = slip == _SL_SLICE_FROM_FAR ? cf[j] + (cn[j] - cf[j]) * (1 - t)
               : slip == _SL_SLICE_NEAR_PLUS_FAR ? cn[j] + cf[j] * t
                                                 : cn[j] + (cf[j] - cn[j]) * t;
}

static void _sl_expect_slice(const sl_probe_function *f, const float *row, int slip, double *out) {
    double eye[3], target[3], forward[3], right[3], up[3], length = 0;
    for (int j = 0; j < 3; j++) eye[j] = _sl_get(f, row, "eye", j), target[j] = _sl_get(f, row, "target", j);
    for (int j = 0; j < 3; j++) forward[j] = target[j] - eye[j], length += forward[j] * forward[j];
    for (int j = 0; j < 3; j++) forward[j] /= sqrt(length);
    /* lookat with the world's up (0, 1, 0): right = forward x up, up' = right x forward */
    right[0] = -forward[2], right[1] = 0, right[2] = forward[0];
    length = sqrt(right[0] * right[0] + right[2] * right[2]);
    for (int j = 0; j < 3; j++) right[j] /= length;
    up[0] = right[1] * forward[2] - right[2] * forward[1];
    up[1] = right[2] * forward[0] - right[0] * forward[2];
    up[2] = right[0] * forward[1] - right[1] * forward[0];
    double half = tan(_sl_get(f, row, "fov_deg", 0) * 3.14159265358979323846 / 360.0), aspect = _sl_get(f, row, "aspect", 0);
    double near = _sl_get(f, row, "near", 0), far = _sl_get(f, row, "far", 0);
    double splits[2] = {_sl_get(f, row, "split_near", 0), _sl_get(f, row, "split_far", 0)};
    if (slip == _SL_SLICE_WHOLE_FRUSTUM) splits[0] = near, splits[1] = far;
    double corners[8][3], centre[3] = {0, 0, 0};
    for (int i = 0; i < 8; i++) {
        double x = (i & 1) ? 1 : -1, y = (i & 2) ? 1 : -1, ray[3];
        for (int j = 0; j < 3; j++) ray[j] = forward[j] + x * half * aspect * right[j] + y * half * up[j];
        _sl_slice_corner(eye, ray, near, far, splits[i / 4], slip, corners[i]);
        for (int j = 0; j < 3; j++) centre[j] += corners[i][j];
    }
    for (int j = 0; j < 3; j++) centre[j] /= slip == _SL_SLICE_CENTRE_OVER_FOUR ? 4 : 8;
    if (slip == _SL_SLICE_CENTRE_NEAR_CORNERS || slip == _SL_SLICE_CENTRE_SEVEN_OVER_EIGHT) {
        int count = slip == _SL_SLICE_CENTRE_NEAR_CORNERS ? 4 : 7;
        for (int j = 0; j < 3; j++) {
            centre[j] = 0;
            for (int i = 0; i < count; i++) centre[j] += corners[i][j];
            centre[j] /= slip == _SL_SLICE_CENTRE_NEAR_CORNERS ? 4 : 8;
        }
    }
    double radius = 0;
    int from = 0;
    int to = slip == _SL_SLICE_RADIUS_FIRST_CORNER ? 1 : slip == _SL_SLICE_RADIUS_SEVEN_CORNERS ? 7 : 8;
    for (int i = from; i < to; i++) {
        double d = 0;
        for (int j = 0; j < 3; j++) d += (corners[i][j] - centre[j]) * (corners[i][j] - centre[j]);
        radius = fmax(radius, sqrt(d));
    }
    for (int j = 0; j < 3; j++) out[j] = centre[j];
    out[3] = radius;
}

/* lab 6: the first cascade whose far split lies beyond the point's view depth (-z), the last one past them */
static void _sl_draw_cascade_index(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                   size_t n) {
    int count = 2 + index % 3;
    double split[4] = {0, 0, 0, 0}, at = _sl_uniform(r, 0.3, 3);
    for (int i = 0; i < count; i++) split[i] = at += _sl_uniform(r, 2, 40);
    /* a depth inside a cascade drawn in turn, away from its ends */
    int cascade = index % count;
    double lo = cascade ? split[cascade - 1] : 0.2, hi = split[cascade];
    double depth = lo + (hi - lo) * _sl_uniform(r, 0.1, 0.9);
    double position[3] = {_sl_uniform(r, -0.8, 0.8) * depth, _sl_uniform(r, -0.6, 0.6) * depth, -depth};
    _sl_set(f, row, "view_position", position);
    _sl_set(f, row, "split_far", split);
    _sl_set1(f, row, "count", count);
    snprintf(about, n, "generic: %d cascades ending at %.4g, %.4g, %.4g, %.4g; a point %.4g in front of the camera, off "
                       "its axis (x %.3g, y %.3g): cascade %d",
             count, split[0], split[1], split[2], split[3], depth, position[0], position[1], cascade);
}

static const char *const _sl_cascade_index_slips[][2] = {
    {"", ""},
    {"the distance length(view_position) in place of the view depth -z", "the view depth -view_position.z"},
    {"count (one past the last cascade) for a point beyond every split", "count - 1, the last cascade"},
    {"the comparison reversed: the first cascade whose far split lies in front of the point (depth > split)",
     "the first cascade whose far split lies beyond the point (depth < split_far[i])"},
    {"the last cascade before count - 1 whose far split lies beyond the point (the loop goes on after a match: no "
     "break)", "the first cascade whose far split lies beyond the point: stop at the first match"},
    {NULL, NULL},
};

static void _sl_expect_cascade_index(const sl_probe_function *f, const float *row, int slip, double *out) {
    double x = _sl_get(f, row, "view_position", 0), y = _sl_get(f, row, "view_position", 1);
    double z = _sl_get(f, row, "view_position", 2);
    double depth = slip == 1 ? sqrt(x * x + y * y + z * z) : -z;
    int count = (int)_sl_get(f, row, "count", 0);
    out[0] = slip == 2 ? count : count - 1;
    for (int i = 0; i < count - 1; i++)
        if (slip == 3 ? depth > _sl_get(f, row, "split_far", i) : depth < _sl_get(f, row, "split_far", i)) {
            out[0] = i;
            if (slip != 4) break;
        }
}

/* lab 6 (bonus): the weight of the next cascade across the last `band` of the slice */
static void _sl_draw_blend(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about, size_t n) {
    double split_near = _sl_uniform(r, 0.5, 20), split_far = split_near + _sl_uniform(r, 5, 60);
    double band = _sl_uniform(r, 0.1, 0.4), start = split_far - band * (split_far - split_near);
    double depth = _sl_uniform(r, 0, 1) < 0.75 ? _sl_uniform(r, start, split_far) : _sl_uniform(r, split_near, split_far);
    /* one row in four within `band` metres of the split: a band taken in metres blends there, and only there */
    if (index % 4 == 1) depth = split_far - _sl_uniform(r, 0.2, 0.8) * band;
    _sl_set1(f, row, "view_depth", depth);
    _sl_set1(f, row, "split_near", split_near);
    _sl_set1(f, row, "split_far", split_far);
    _sl_set1(f, row, "band", band);
    snprintf(about, n, "generic: the slice %.4g..%.4g (its near end not 0), band %.3g of it, view depth %.4g",
             split_near, split_far, band, depth);
}

static const char *const _sl_blend_slips[][2] = {
    {"", ""},
    {"the weight reversed (1 at the band's start, 0 at the split)", "0 at the band's start, rising to 1 at split_far"},
    {"band in metres of view depth, not a fraction of the slice", "the band's start split_far - band * (split_far - split_near)"},
    {"the band measured from split_near: start = split_near + band * (split_far - split_near)",
     "start = split_far - band * (split_far - split_near)"},
    {"no clamp to [0, 1]", "clamped to [0, 1]"},
    {"divided by band, the fraction, where the band's width in view depth is split_far - start = band * (split_far - "
     "split_near)", "(view_depth - start) / (split_far - start)"},
    {NULL, NULL},
};

static void _sl_expect_blend(const sl_probe_function *f, const float *row, int slip, double *out) {
    double band = _sl_get(f, row, "band", 0), sn = _sl_get(f, row, "split_near", 0), sf = _sl_get(f, row, "split_far", 0);
    if (band <= 0) {
        out[0] = 0;
        return;
    }
    double start = slip == 2 ? sf - band : slip == 3 ? sn + band * (sf - sn) : sf - band * (sf - sn);
    double w = (_sl_get(f, row, "view_depth", 0) - start) / (slip == 5 ? band : sf - start);
    if (slip != 4) w = fmin(fmax(w, 0), 1);
    out[0] = slip == 1 ? 1 - w : w;
}

/* lab 7: a 90-degree square perspective, GL's depth range, any near and far */
static void _sl_draw_face_projection(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                     size_t n) {
    (void)index;
    double near = _sl_uniform(r, 0.03, 2.0), far = _sl_uniform(r, 4, 120);
    _sl_set1(f, row, "near", near);
    _sl_set1(f, row, "far", far);
    snprintf(about, n, "generic: near %.3g, far %.4g (a far plane other than the scenes')", near, far);
}

static const char *const _sl_face_projection_slips[][2] = {
    {"", ""},
    {"depth mapped to [0, 1] (m22 = far / (near - far), m32 = near * far / (near - far))",
     "GL's depth range [-1, 1]: m22 = (far + near) / (near - far), m32 = 2 * far * near / (near - far)"},
    {"the matrix transposed (-1 in m32, the depth term in m23)", "-1 in m23, 2 * far * near / (near - far) in m32"},
    {"a 45-degree field of view", "90 degrees: each face covers a quarter turn"},
    {NULL, NULL},
};

static void _sl_expect_face_projection(const sl_probe_function *f, const float *row, int slip, double *out) {
    double near = _sl_get(f, row, "near", 0), far = _sl_get(f, row, "far", 0);
    for (int i = 0; i < 16; i++) out[i] = 0;
    out[0] = out[5] = slip == 3 ? 1 / tan(22.5 * 3.14159265358979323846 / 180) : 1; /* 1 / tan(fov / 2), aspect 1 */
    out[10] = slip == 1 ? far / (near - far) : (far + near) / (near - far);
    out[11] = -1;
    out[14] = slip == 1 ? far * near / (near - far) : 2 * far * near / (near - far);
    if (slip == 2) {
        double t = out[11];
        out[11] = out[14];
        out[14] = t;
    }
}

/* lab 7: length(light_to_fragment) / far_plane - bias against the "cube_positive" map, a far plane
 * other than the map's 10 */
static void _sl_draw_point_shadow(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                  size_t n) {
    double d[3];
    int axis = _sl_integer(r, 0, 2);
    /* one row in three just behind the occluder, far off the face's axis: there the distance must be the
     * vector's length (at least 1.18 times its largest component), or the point comes out lit */
    bool off_axis = index % 3 == 0;
    for (int j = 0; j < 3; j++)
        d[j] = off_axis ? (_sl_uniform(r, 0, 1) < 0.5 ? -1 : 1) * _sl_uniform(r, 0.45, 0.6) : _sl_uniform(r, -0.6, 0.6);
    d[axis] = _sl_uniform(r, 0, 1) < 0.5 ? -1 : 1; /* well inside one face */
    if (off_axis) d[axis] = 1; /* a face the occluder covers */
    /* one row in three on the axis, behind the occluder by less than bias * far_plane: the bias is subtracted
     * in the map's units, so the point is shadowed; taken for metres (times far) it would come out lit */
    bool behind_by_bias = index % 3 == 1;
    /* every other row of the third kind just in front of the occluder, by less than the bias: lit, and
     * shadowed where the bias is added to the point's distance (or taken from the stored one) */
    bool front_by_bias = index % 3 == 2 && (index / 3) % 2 == 0;
    /* the others of the third kind far behind the occluder (0.4 to 0.9 of far): shadowed, and still shadowed
     * by a squared distance over far^2, where a slip of sign (far or the distance negated) lights them */
    bool deep_behind = index % 3 == 2 && (index / 3) % 2 == 1;
    if (behind_by_bias || front_by_bias || deep_behind) d[axis] = 1;
    /* a near far plane in front of the occluder: there a squared distance over far stays below the occluder's
     * 0.1 (lit, as the contract), so only a bias on the wrong side shadows it */
    double far = front_by_bias || _sl_uniform(r, 0, 1) < 0.5 ? _sl_uniform(r, 3, 8) : _sl_uniform(r, 14, 40);
    double bias = behind_by_bias ? _sl_uniform(r, 0.01, 0.02) : _sl_uniform(r, 0.002, 0.02);
    /* the point's stored-scale depth away from the occluder's 0.1 and the far wall's 1.0 */
    double current = off_axis         ? _sl_uniform(r, 0.105, 0.115)
                   : behind_by_bias ? 0.1 + _sl_uniform(r, 0.3, 0.8) * fmin(bias * (far - 1), 0.5)
                   : front_by_bias  ? 0.1 - (1 + _sl_uniform(r, 0.25, 0.75)) * bias
                   : deep_behind    ? _sl_uniform(r, 0.4, 0.9)
                   : _sl_uniform(r, 0, 1) < 0.5 ? _sl_uniform(r, 0.03, 0.07)
                                                : _sl_uniform(r, 0.14, 0.9);
    double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), distance = (current + bias) * far;
    for (int j = 0; j < 3; j++) d[j] *= distance / length;
    _sl_set1(f, row, "cube_map", SL_PROBE_MAP_CUBE_POSITIVE);
    _sl_set(f, row, "light_to_fragment", d);
    _sl_set1(f, row, "far_plane", far);
    _sl_set1(f, row, "bias", bias);
    snprintf(about, n, "generic: far_plane %.3g (not the map's 10), the point %.3g from the light towards the %s%c "
                       "face%s, bias %.3g",
             far, distance, d[axis] > 0 ? "+" : "-", "xyz"[axis],
             off_axis         ? ", far off its axis, just behind the occluder (the distance is the length, not a component)"
             : behind_by_bias ? ", behind the occluder by less than bias * far_plane (the bias is in the map's units)"
             : front_by_bias  ? ", in front of the occluder by less than the bias: lit (the bias moves the point towards "
                                "the light, never away)"
             : deep_behind    ? ", far behind the occluder: shadowed"
                              : "",
             bias);
}

static const char *const _sl_point_shadow_slips[][2] = {
    {"", ""},
    {"the distance not divided by far_plane", "length(light_to_fragment) / far_plane, the stored scale"},
    {"the squared distance (dot) in place of its length", "length(light_to_fragment) / far_plane"},
    {"the largest component of light_to_fragment in place of its length", "length(light_to_fragment) / far_plane"},
    {"the comparison reversed: lit where the point lies behind the stored distance", "current - bias > closest: shadowed"},
    {"the bias multiplied by far_plane (taken for metres)", "bias in the map's units (distance / far), subtracted as given"},
    {NULL, NULL},
};

static void _sl_expect_point_shadow(const sl_probe_function *f, const float *row, int slip, double *out) {
    double d[3], length = 0;
    int axis = 0;
    for (int j = 0; j < 3; j++) {
        d[j] = _sl_get(f, row, "light_to_fragment", j);
        length += d[j] * d[j];
        if (fabs(d[j]) > fabs(d[axis])) axis = j;
    }
    /* the model knows the "cube_positive" map alone (0.1 on +X, +Y, +Z): a written row on another map is
     * not modelled, or its walls would be taken for that map's */
    if ((sl_probe_map)(int)_sl_get(f, row, "cube_map", 0) != SL_PROBE_MAP_CUBE_POSITIVE) {
        out[0] = NAN;
        return;
    }
    double closest = d[axis] > 0 ? 0.1 : 1.0;
    double distance = slip == 2 ? length : slip == 3 ? fabs(d[axis]) : sqrt(length);
    double far = _sl_get(f, row, "far_plane", 0);
    double current = distance / (slip == 1 ? 1 : far) - _sl_get(f, row, "bias", 0) * (slip == 5 ? far : 1);
    out[0] = (current > closest) == (slip == 4) ? 1 : 0;
}

/* lab 4: pcf_hardware, texture() on a sampler2DShadow with GL_LINEAR: four comparisons blended by the
 * point's bilinear weights. The point lies on eighths of a texel (weights every GL computes exactly, in
 * whatever fixed point it filters), both weights fractional, near the "corner" map's occluder so that
 * both axes blend, with w a power of two (an exact divide). */
typedef enum {
    _SL_HW_CONTRACT,
    _SL_HW_HALF_TEXEL_UP,   /* p.xy + 0.5 / textureSize */
    _SL_HW_HALF_TEXEL_DOWN, /* p.xy - 0.5 / textureSize */
    _SL_HW_TEXEL_CENTRE,    /* (floor(p.xy * size) + 0.5) / size: one comparison */
    _SL_HW_XY_NOT_DIVIDED,  /* shadow_coord.xy */
    _SL_HW_Z_NOT_DIVIDED,   /* shadow_coord.z - bias */
    _SL_HW_BIAS_BEFORE_DIVIDE, /* (shadow_coord.z - bias) / w: the bias scaled by 1 / w */
    _SL_HW_T_FLIPPED,       /* 1 - p.y */
} _sl_hw_slip;

static double _sl_hw_compare(sl_probe_map map, int i, int j, double z) {
    i = i < 0 ? 0 : i >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : i;
    j = j < 0 ? 0 : j >= SL_PROBE_MAP_SIZE ? SL_PROBE_MAP_SIZE - 1 : j;
    return z <= sl_probe_map_depth(map, i, j) ? 1.0 : 0.0; /* GL_LEQUAL: lit when the reference is not beyond */
}

static void _sl_draw_pcf_hardware(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                  size_t n) {
    int half = SL_PROBE_MAP_SIZE / 2;
    /* texel coordinates (the sample point minus half a texel) between the last occluded texel's centre and
     * the first lit one's, in eighths, never whole (a whole weight hides the blend): across the corner's
     * vertical edge, its horizontal one, or both */
    double tx = half - 1 + _sl_integer(r, 1, 7) / 8.0, ty = half - 1 + _sl_integer(r, 1, 7) / 8.0;
    if (index % 3 == 1) tx = half - 3 + _sl_integer(r, 0, 15) / 8.0; /* inside the occluder in x: the blend in y */
    if (index % 3 == 2) ty = half - 3 + _sl_integer(r, 0, 15) / 8.0; /* and in x */
    double u = (tx + 0.5) / SL_PROBE_MAP_SIZE, v = (ty + 0.5) / SL_PROBE_MAP_SIZE;
    /* behind the occluder (0.25) or, one row in four, just in front of it by less than the bias */
    double bias = _sl_integer(r, 2, 8) / 1024.0;
    double z = index % 4 == 3 ? 0.25 + bias / 2 : 0.25 + _sl_integer(r, 16, 160) / 256.0;
    static const double ws[4] = {0.5, 2.0, 0.25, 4.0};
    double w = index % 4 == 0 ? 1.0 : ws[_sl_integer(r, 0, 3)];
    double coord[4] = {u * w, v * w, z * w, w};
    _sl_set1(f, row, "shadow_map", SL_PROBE_MAP_CORNER);
    _sl_set(f, row, "shadow_coord", coord);
    _sl_set1(f, row, "bias", bias);
    snprintf(about, n, "generic: the occluder's corner, the point at texel (%.3g, %.3g) of the 64-texel map (both "
                       "bilinear weights fractional), depth %.4g, bias %.4g, w = %g%s",
             tx + 0.5, ty + 0.5, z, bias, w, index % 4 == 3 ? ": just in front of the occluder by less than the bias, lit" : "");
}

static void _sl_expect_pcf_hardware(const sl_probe_function *f, const float *row, int slip, double *out) {
    double c[4];
    for (int j = 0; j < 4; j++) c[j] = _sl_get(f, row, "shadow_coord", j);
    double bias = _sl_get(f, row, "bias", 0), w = c[3];
    sl_probe_map map = (sl_probe_map)(int)_sl_get(f, row, "shadow_map", 0);
    double x = c[0] / w, y = c[1] / w, z = c[2] / w - bias;
    if (slip == _SL_HW_XY_NOT_DIVIDED) x = c[0], y = c[1];
    if (slip == _SL_HW_Z_NOT_DIVIDED) z = c[2] - bias;
    if (slip == _SL_HW_BIAS_BEFORE_DIVIDE) z = (c[2] - bias) / w;
    if (slip == _SL_HW_T_FLIPPED) y = 1 - y;
    if (!(w > 0) || x < 0 || y < 0 || x > 1 || y > 1 || c[2] / w > 1 || c[2] / w < 0) {
        out[0] = 1;
        return;
    }
    double shift = slip == _SL_HW_HALF_TEXEL_UP ? 0.5 : slip == _SL_HW_HALF_TEXEL_DOWN ? -0.5 : 0;
    double sx = x * SL_PROBE_MAP_SIZE + shift - 0.5, sy = y * SL_PROBE_MAP_SIZE + shift - 0.5;
    if (slip == _SL_HW_TEXEL_CENTRE) sx = floor(x * SL_PROBE_MAP_SIZE), sy = floor(y * SL_PROBE_MAP_SIZE);
    int i = (int)floor(sx), j = (int)floor(sy);
    double a = sx - i, b = sy - j;
    out[0] = (1 - a) * (1 - b) * _sl_hw_compare(map, i, j, z) + a * (1 - b) * _sl_hw_compare(map, i + 1, j, z) +
             (1 - a) * b * _sl_hw_compare(map, i, j + 1, z) + a * b * _sl_hw_compare(map, i + 1, j + 1, z);
}

static const char *const _sl_hw_slips[][2] = {
    {"", ""},
    {"the lookup moved half a texel up and right (p.xy + 0.5 / textureSize): the four texels blended are not the "
     "four around the point",
     "texture(shadow_map, vec3(p.xy, p.z - bias)): GL_LINEAR already blends the four texels whose centres surround "
     "p.xy, so no offset of any kind"},
    {"the lookup moved half a texel down and left (p.xy - 0.5 / textureSize): the four texels blended are not the "
     "four around the point",
     "texture(shadow_map, vec3(p.xy, p.z - bias)): GL_LINEAR already blends the four texels whose centres surround "
     "p.xy, so no offset of any kind"},
    {"one comparison at the point's texel centre ((floor(p.xy * size) + 0.5) / size): the blend between texels lost",
     "texture(shadow_map, vec3(p.xy, p.z - bias)) at p.xy itself: the hardware's blend is the filter"},
    {"x and y not divided by w (the map read at shadow_coord.xy)",
     "p = shadow_coord.xyz / shadow_coord.w (pcf_project), then the lookup at p.xy"},
    {"z not divided by w (shadow_coord.z - bias compared)", "p.z = shadow_coord.z / shadow_coord.w, then p.z - bias"},
    {"the bias subtracted before the divide, (shadow_coord.z - bias) / w: the bias scaled by 1 / w",
     "p.z - bias, after the divide (the bias is in the map's depth units)"},
    {"t flipped (1 - p.y): the map's rows read upside down", "p.y as it is: the map's t runs upwards, as y does"},
    {NULL, NULL},
};

/* lab 7 (bonus): point_shadow_soft on the "cube_positive" map (0.1 on +X, +Y, +Z, 1.0 on the others), a
 * point near an edge between an occluded face and a lit one, so that a fraction of the 20 directions lands
 * on each; far plane, distance, radius and bias drawn; every direction kept clear of a face's edge (each
 * sample's face is the one every GL picks) for the contract and for each slip. */
static const double _sl_soft_offsets[20][3] = {
    {1, 1, 1},   {1, -1, 1},  {-1, -1, 1},  {-1, 1, 1},  {1, 1, -1},  {1, -1, -1}, {-1, -1, -1},
    {-1, 1, -1}, {1, 1, 0},   {1, -1, 0},   {-1, -1, 0}, {-1, 1, 0},  {1, 0, 1},   {-1, 0, 1},
    {1, 0, -1},  {-1, 0, -1}, {0, 1, 1},    {0, -1, 1},  {0, -1, -1}, {0, 1, -1}};

typedef enum {
    _SL_SOFT_CONTRACT,
    _SL_SOFT_UNIT_DIRECTION,  /* normalize(light_to_fragment) + offset * disk */
    _SL_SOFT_DISK_FIXED,      /* disk = radius */
    _SL_SOFT_DISK_NO_FAR,     /* disk = radius * distance */
    _SL_SOFT_DISK_OVER_FAR,   /* disk = radius / far_plane */
    _SL_SOFT_OFFSETS_UNIT,    /* normalize(offset) * disk */
    _SL_SOFT_NO_DISK,         /* light_to_fragment + offset */
    _SL_SOFT_FIRST_16,        /* 16 of the 20 directions, over 16 */
    _SL_SOFT_NOT_OVER_FAR,    /* current = distance - bias */
    _SL_SOFT_NO_BIAS,         /* current = distance / far */
    _SL_SOFT_BIAS_ADDED,      /* current = distance / far + bias */
    _SL_SOFT_DISK_INVERTED,   /* disk = radius * far_plane / distance */
    _SL_SOFT_SLIP_COUNT
} _sl_soft_slip;

/* Whether direction d picks its face clearly: its largest component ahead of the next by a margin. */
static bool _sl_face_clear(const double d[3]) {
    double a[3] = {fabs(d[0]), fabs(d[1]), fabs(d[2])};
    double top = fmax(a[0], fmax(a[1], a[2])), second = 0;
    int axis = a[0] == top ? 0 : a[1] == top ? 1 : 2;
    for (int j = 0; j < 3; j++)
        if (j != axis) second = fmax(second, a[j]);
    return top - second > 2e-3 * top;
}

/* The soft lookup with slip `slip`; *clear says whether every sample picked its face clearly. */
static double _sl_soft(const double l[3], double far, double bias, double radius, int slip, bool *clear) {
    double distance = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    double current = slip == _SL_SOFT_NOT_OVER_FAR ? distance - bias
                   : slip == _SL_SOFT_NO_BIAS      ? distance / far
                   : slip == _SL_SOFT_BIAS_ADDED   ? distance / far + bias
                                                   : distance / far - bias;
    double disk = slip == _SL_SOFT_DISK_FIXED    ? radius
                : slip == _SL_SOFT_DISK_NO_FAR   ? radius * distance
                : slip == _SL_SOFT_DISK_OVER_FAR ? radius / far
                : slip == _SL_SOFT_NO_DISK       ? 1.0
                : slip == _SL_SOFT_DISK_INVERTED ? radius * far / distance
                                                 : radius * distance / far;
    int count = slip == _SL_SOFT_FIRST_16 ? 16 : 20;
    double lit = 0;
    if (clear) *clear = true;
    for (int i = 0; i < count; i++) {
        const double *o = _sl_soft_offsets[i];
        double scale = slip == _SL_SOFT_OFFSETS_UNIT ? 1 / sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) : 1;
        double d[3];
        for (int j = 0; j < 3; j++) d[j] = (slip == _SL_SOFT_UNIT_DIRECTION ? l[j] / distance : l[j]) + o[j] * scale * disk;
        if (clear && !_sl_face_clear(d)) *clear = false;
        int axis = fabs(d[0]) >= fabs(d[1]) && fabs(d[0]) >= fabs(d[2]) ? 0 : fabs(d[1]) >= fabs(d[2]) ? 1 : 2;
        double closest = d[axis] > 0 ? 0.1 : 1.0;
        lit += current > closest ? 0 : 1;
    }
    return lit / count;
}

static void _sl_draw_point_shadow_soft(const sl_probe_function *f, _sl_rng *r, int index, float *row, char *about,
                                       size_t n) {
    (void)index;
    double l[3], far = 0, bias = 0, radius = 0, distance = 0;
    for (int tries = 0; tries < 2000; tries++) {
        /* towards the edge between an occluded face (+axis) and a lit one (-other) */
        int axis = _sl_integer(r, 0, 2), other = (axis + _sl_integer(r, 1, 2)) % 3, third = 3 - axis - other;
        double dir[3];
        dir[axis] = 1;
        dir[other] = -_sl_uniform(r, 0.7, 1.3);
        dir[third] = _sl_uniform(r, -0.5, 0.5);
        far = _sl_uniform(r, 4, 40);
        bias = _sl_uniform(r, 0.002, 0.02);
        double current = _sl_uniform(r, 0.15, 0.85);
        distance = (current + bias) * far;
        double length = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        for (int j = 0; j < 3; j++) l[j] = dir[j] * distance / length;
        /* the disk's angle at the far plane, radius / far, from 0.05 to 0.4 */
        radius = far * _sl_uniform(r, 0.05, 0.4);
        bool clear, all_clear = true;
        double want = _sl_soft(l, far, bias, radius, 0, &clear);
        all_clear = clear;
        for (int s = 1; s < _SL_SOFT_SLIP_COUNT && all_clear; s++) {
            _sl_soft(l, far, bias, radius, s, &clear);
            all_clear = clear;
        }
        /* a fraction, with lit and shadowed samples both several */
        if (all_clear && want >= 0.15 && want <= 0.85) break;
    }
    _sl_set1(f, row, "cube_map", SL_PROBE_MAP_CUBE_POSITIVE);
    _sl_set(f, row, "light_to_fragment", l);
    _sl_set1(f, row, "far_plane", far);
    _sl_set1(f, row, "bias", bias);
    _sl_set1(f, row, "radius", radius);
    snprintf(about, n, "generic: far_plane %.3g, the point %.3g from the light near an edge of an occluded face and a "
                       "lit one, radius %.3g (the disk %.3g wide there), bias %.3g: a fraction of the 20 samples lit",
             far, distance, radius, radius * distance / far, bias);
}

static void _sl_expect_point_shadow_soft(const sl_probe_function *f, const float *row, int slip, double *out) {
    if ((sl_probe_map)(int)_sl_get(f, row, "cube_map", 0) != SL_PROBE_MAP_CUBE_POSITIVE) {
        out[0] = NAN;
        return;
    }
    double l[3];
    for (int j = 0; j < 3; j++) l[j] = _sl_get(f, row, "light_to_fragment", j);
    out[0] = _sl_soft(l, _sl_get(f, row, "far_plane", 0), _sl_get(f, row, "bias", 0), _sl_get(f, row, "radius", 0), slip,
                      NULL);
}

static const char *const _sl_soft_slips[][2] = {
    {"", ""},
    {"the offsets added to the unit direction, normalize(light_to_fragment) + offset * disk: the disk's angle "
     "grows with the distance (length(light_to_fragment) times too wide)",
     "light_to_fragment + offset * disk, with disk = radius * length(light_to_fragment) / far_plane: the same "
     "angle at any distance"},
    {"a disk of radius alone, not grown with the distance", "disk = radius * length(light_to_fragment) / far_plane"},
    {"the disk radius * distance, not divided by far_plane", "disk = radius * length(light_to_fragment) / far_plane"},
    {"the disk radius / far_plane, not grown with the distance",
     "disk = radius * length(light_to_fragment) / far_plane"},
    {"each offset made unit length (normalize(POINT_SHADOW_OFFSETS[i]) * disk): the given offsets are longer than "
     "one (sqrt 2, sqrt 3), so the disk shrinks",
     "POINT_SHADOW_OFFSETS[i] * disk, the offsets as given"},
    {"the offsets added unscaled, light_to_fragment + POINT_SHADOW_OFFSETS[i]: no disk",
     "light_to_fragment + POINT_SHADOW_OFFSETS[i] * disk, disk = radius * length(light_to_fragment) / far_plane"},
    {"16 of the 20 directions, averaged over 16", "all 20 directions, the sum over 20.0"},
    {"the distance not divided by far_plane", "current = length(light_to_fragment) / far_plane - bias"},
    {"comparisons without the bias", "current = length(light_to_fragment) / far_plane - bias"},
    {"the bias added to the distance", "current = length(light_to_fragment) / far_plane - bias"},
    {"the disk radius * far_plane / distance (the ratio inverted): it shrinks with the distance",
     "disk = radius * length(light_to_fragment) / far_plane: it grows with the distance, the same angle everywhere"},
    {NULL, NULL},
};

static const _sl_generic _sl_generics[] = {
    {"lab1_create_shadow_map", _sl_draw_create_shadow_map, _sl_expect_create_shadow_map, NULL, NULL, 0},
    {"depth.vert", _sl_draw_depth_vert, _sl_expect_depth_vert, _sl_depth_vert_slips, NULL, 0},
    {"shadow_coord", _sl_draw_shadow_coord, _sl_expect_shadow_coord, _sl_shadow_coord_slips, NULL, 0},
    /* x and y, or z, not divided: sharper than the written rows' "no divide by w" */
    {"shadow_compare_manual", _sl_draw_compare, _sl_expect_compare, _sl_compare_slips, NULL, 1ull << 2 | 1ull << 3},
    {"shadow_compare_hardware", _sl_draw_compare, _sl_expect_compare, _sl_compare_slips, NULL, 1ull << 2 | 1ull << 3},
    {"slope_scaled_bias", _sl_draw_slope_bias, _sl_expect_slope_bias, _sl_slope_bias_slips,
     "tan_theta = sqrt(1 - n_dot_l * n_dot_l) / n_dot_l; min(constant_bias + slope * tan_theta, max_bias)", 0},
    {"normal_offset_position", _sl_draw_normal_offset, _sl_expect_normal_offset, _sl_normal_offset_slips,
     "world_position[i] + normal[i] * texels * texel_world_size * (1 - n_dot_l)", 0},
    {"midpoint_compare", _sl_draw_midpoint, _sl_expect_midpoint, _sl_midpoint_slips, NULL, 0},
    {"pcf_grid", _sl_draw_pcf_grid, _sl_expect_pcf_grid, _sl_grid_slips, NULL, 1ull << _SL_GRID_CENTRE_DRIFTS},
    {"compute_moments", _sl_draw_moments, _sl_expect_moments, _sl_moments_slips, "if(i == 0, depth, depth * depth)", 0},
    /* a box, a tap short, taps two texels apart: sharper than "too wide" (a sigma of another size has a written
     * verdict of its own, which says by how much) */
    {"blur_moments", _sl_draw_blur, _sl_expect_blur, _sl_blur_slips, NULL, 1ull << 2 | 1ull << 4 | 1ull << 5},
    {"chebyshev_upper_bound", _sl_draw_chebyshev, _sl_expect_chebyshev, _sl_chebyshev_slips,
     "mu = moments[0]; variance = max(moments[1] - mu * mu, min_variance); d = t - mu; "
     "if(t <= mu, 1, variance / (variance + d * d))", 0},
    {"reduce_light_bleeding", _sl_draw_bleeding, _sl_expect_bleeding, _sl_bleeding_slips,
     "clamp((p_max - amount) / (1 - amount), 0, 1)", 0},
    {"esm_visibility", _sl_draw_esm, _sl_expect_esm, _sl_esm_slips, "clamp(moment * exp(-c * t), 0, 1)", 0},
    {"evsm_warp", _sl_draw_evsm, _sl_expect_evsm, NULL,
     "if(i == 0, exp(exponents[0] * depth), -exp(-exponents[1] * depth))", 0},
    {"lab6_split_distances", _sl_draw_splits, _sl_expect_splits, _sl_splits_slips,
     "t = i / count; logarithmic = near * pow(far / near, t); linear = near + (far - near) * t; "
     "if(i > count, 0, if(i == 0, near, if(i == count, far, lambda * logarithmic + (1 - lambda) * linear)))", 0},
    /* the slips the written rows' verdicts do not name lead (t without the near plane, no divide by w, the
     * whole frustum and a centre over 4 have messages of their own) */
    {"lab6_slice_sphere", _sl_draw_slice, _sl_expect_slice, _sl_slice_slips, NULL,
     1ull << _SL_SLICE_FROM_FAR | 1ull << _SL_SLICE_NEAR_PLUS_FAR | 1ull << _SL_SLICE_DISTANCE_ALONG_EDGE |
         1ull << _SL_SLICE_NDC_LERP | 1ull << _SL_SLICE_NEAR_AT_NDC_ZERO | 1ull << _SL_SLICE_RADIUS_FIRST_CORNER |
         1ull << _SL_SLICE_NEAR_BY_FAR_W | 1ull << _SL_SLICE_FAR_BY_NEAR_W |
         1ull << _SL_SLICE_RADIUS_SEVEN_CORNERS |
         1ull << _SL_SLICE_CENTRE_NEAR_CORNERS | 1ull << _SL_SLICE_CENTRE_SEVEN_OVER_EIGHT},
    {"cascade_index", _sl_draw_cascade_index, _sl_expect_cascade_index, _sl_cascade_index_slips, NULL, 0},
    {"cascade_blend", _sl_draw_blend, _sl_expect_blend, _sl_blend_slips,
     "start = split_far - band * (split_far - split_near); "
     "if(band <= 0, 0, clamp((view_depth - start) / (split_far - start), 0, 1))", 0},
    {"lab7_face_projection", _sl_draw_face_projection, _sl_expect_face_projection, _sl_face_projection_slips, NULL, 0},
    {"cube_depth.frag", _sl_draw_cube_depth, _sl_expect_cube_depth, _sl_cube_depth_slips, NULL, 0},
    {"point_shadow", _sl_draw_point_shadow, _sl_expect_point_shadow, _sl_point_shadow_slips,
     "current = length(light_to_fragment) / far_plane - bias; closest = if(major_positive(light_to_fragment), 0.1, 1); "
     "if(current > closest, 0, 1)", 0},
    {"pcf_hardware", _sl_draw_pcf_hardware, _sl_expect_pcf_hardware, _sl_hw_slips, NULL, 0xfeull},
    {"point_shadow_soft", _sl_draw_point_shadow_soft, _sl_expect_point_shadow_soft, _sl_soft_slips, NULL, 0xffeull},
};

static const _sl_generic *_sl_find(const char *function) {
    for (size_t i = 0; i < sizeof _sl_generics / sizeof _sl_generics[0]; i++)
        if (strcmp(_sl_generics[i].function, function) == 0) return &_sl_generics[i];
    return NULL;
}

bool sl_probe_generic_known(const char *function) { return _sl_find(function) != NULL; }

int sl_probe_generic_add(sl_case *c, uint64_t seed) {
    int added = 0;
    for (int ki = 0; ki < c->check_count; ki++) {
        sl_check *k = &c->checks[ki];
        const sl_probe_function *f = k->kind == SL_CHECK_PROBE ? sl_probe_at(k->function) : NULL;
        const _sl_generic *g = f ? _sl_find(f->name) : NULL;
        if (!g || k->generic_rows > 0) continue;
        int room = SL_PROBE_MAX_ROWS - k->rows, count = room < SL_PROBE_GENERIC_ROWS ? room : SL_PROBE_GENERIC_ROWS;
        _sl_rng r = _sl_stream(seed, c, k);
        for (int i = 0; i < count; i++) {
            int row = k->rows + i;
            memset(k->inputs[row], 0, sizeof k->inputs[row]);
            k->row_tolerance[row] = 0;
            k->row_keep[row] = 0;
            g->draw(f, &r, i, k->inputs[row], k->about[row], sizeof k->about[row]);
        }
        k->rows += count;
        k->generic_rows = count;
        added += count;
    }
    return added;
}

bool sl_probe_generic_expected(const sl_check *k, int row, double *out) {
    const sl_probe_function *f = sl_probe_at(k->function);
    const _sl_generic *g = f ? _sl_find(f->name) : NULL;
    if (!g || row < k->rows - k->generic_rows || row >= k->rows) return false;
    g->expect(f, k->inputs[row], 0, out);
    return true;
}

/* ---- a slip of one input: the contract's formula with that input changed ---- */

typedef enum _sl_slip_kind {
    _SL_SLIP_NEGATED,
    _SL_SLIP_COMPONENT_NEGATED,
    _SL_SLIP_COMPONENT_ZERO,
    _SL_SLIP_XY_SWAPPED,
    _SL_SLIP_DOUBLED,
    _SL_SLIP_HALVED,
    _SL_SLIP_ONE_MINUS,
    _SL_SLIP_ZERO,
    _SL_SLIP_ONE,
    _SL_SLIP_PLUS_ONE,
    _SL_SLIP_MINUS_ONE,
    _SL_SLIP_SWAPPED_WITH,
    _SL_SLIP_CONSTANT, /* the value it has on most written rows, whatever it is (a 4 for count) */
    _SL_SLIP_KINDS
} _sl_slip_kind;

/* Applies slip `kind` to parameter p (offset, size) of row; `component` and `other` (offset) as the kind needs.
 * False when the slip does not apply to a parameter of that type. */
static bool _sl_slip_apply(const sl_probe_function *f, int p, int offset, int size, _sl_slip_kind kind, int component,
                           int other, float constant, float *row) {
    bool is_int = f->params[p].type == SL_PROBE_INT;
    float *v = row + offset;
    switch (kind) {
    case _SL_SLIP_NEGATED:
        for (int j = 0; j < size; j++) v[j] = -v[j];
        return !is_int;
    case _SL_SLIP_COMPONENT_NEGATED:
        if (size < 2 || component >= size) return false;
        v[component] = -v[component];
        return true;
    case _SL_SLIP_COMPONENT_ZERO:
        if (size < 2 || component >= size) return false;
        v[component] = 0.0f;
        return true;
    case _SL_SLIP_XY_SWAPPED: {
        if (size < 2) return false;
        float t = v[0];
        v[0] = v[1];
        v[1] = t;
        return true;
    }
    case _SL_SLIP_DOUBLED:
    case _SL_SLIP_HALVED:
        for (int j = 0; j < size; j++) v[j] *= kind == _SL_SLIP_DOUBLED ? 2.0f : 0.5f;
        return !is_int;
    case _SL_SLIP_ONE_MINUS:
        if (size != 1 || is_int) return false;
        v[0] = 1.0f - v[0];
        return true;
    case _SL_SLIP_ZERO:
    case _SL_SLIP_ONE:
        if (size != 1) return false;
        v[0] = kind == _SL_SLIP_ZERO ? 0.0f : 1.0f;
        return true;
    case _SL_SLIP_PLUS_ONE:
    case _SL_SLIP_MINUS_ONE:
        if (!is_int) return false;
        v[0] += kind == _SL_SLIP_PLUS_ONE ? 1.0f : -1.0f;
        return true;
    case _SL_SLIP_CONSTANT:
        if (size != 1) return false;
        v[0] = constant;
        return true;
    case _SL_SLIP_SWAPPED_WITH:
        if (other < 0) return false;
        for (int j = 0; j < size; j++) {
            float t = v[j];
            v[j] = row[other + j];
            row[other + j] = t;
        }
        return true;
    default:
        return false;
    }
}

static void _sl_slip_words(const sl_probe_function *f, int p, _sl_slip_kind kind, int component, int q, float constant,
                           char *out, size_t n) {
    const char *name = f->params[p].name, *axis = "xyzw";
    switch (kind) {
    case _SL_SLIP_NEGATED: snprintf(out, n, "%s negated", name); break;
    case _SL_SLIP_COMPONENT_NEGATED: snprintf(out, n, "the %c of %s negated", axis[component], name); break;
    case _SL_SLIP_COMPONENT_ZERO: snprintf(out, n, "the %c of %s left out (0)", axis[component], name); break;
    case _SL_SLIP_XY_SWAPPED: snprintf(out, n, "the x and y of %s swapped", name); break;
    case _SL_SLIP_DOUBLED: snprintf(out, n, "%s doubled", name); break;
    case _SL_SLIP_HALVED: snprintf(out, n, "%s halved", name); break;
    case _SL_SLIP_ONE_MINUS: snprintf(out, n, "1 - %s in place of %s", name, name); break;
    case _SL_SLIP_ZERO: snprintf(out, n, "%s left out (0)", name); break;
    case _SL_SLIP_ONE: snprintf(out, n, "1 in place of %s", name); break;
    case _SL_SLIP_PLUS_ONE: snprintf(out, n, "%s + 1 in place of %s", name, name); break;
    case _SL_SLIP_MINUS_ONE: snprintf(out, n, "%s - 1 in place of %s", name, name); break;
    case _SL_SLIP_SWAPPED_WITH: snprintf(out, n, "%s and %s swapped", name, f->params[q].name); break;
    case _SL_SLIP_CONSTANT: snprintf(out, n, "%s taken as %g, whatever it is (a constant where the input belongs)", name, constant); break;
    default: out[0] = '\0';
    }
}

/* Whether two answers agree: within a ten-thousandth of the size the function's answers have on this check
 * (`scale`: the largest contract answer of that output) and a thousandth of the answer. Where answers are
 * small (a bias of 0.003), a fixed tolerance would take tan and cot for one another. */
static bool _sl_slip_close(double student, double expected, double scale) {
    return isfinite(student) && isfinite(expected) && fabs(student - expected) <= 1e-4 * scale + 1e-3 * fabs(expected);
}

/* A candidate explanation of the student's outputs: the contract with one input slipped (formula_slip 0,
 * edit 0), the formula with one of its catalogued slips (formula_slip > 0), or the formula one edit away
 * (edit > 0). */
typedef struct _sl_slip_candidate {
    int p, kind, component, q, other, formula_slip, edit;
    float constant; /* an input slip's constant (_SL_SLIP_CONSTANT) */
} _sl_slip_candidate;

/* What the formula's names mean on one row: the function's parameters. */
typedef struct _sl_row_inputs {
    const sl_probe_function *f;
    const float *row;
} _sl_row_inputs;

static int _sl_param(const sl_probe_function *f, const char *name, int *offset) {
    int at = 0;
    for (int p = 0; p < f->param_count; at += sl_probe_type_size(f->params[p].type), p++)
        if (strcmp(f->params[p].name, name) == 0) {
            *offset = at;
            return p;
        }
    return -1;
}

static bool _sl_row_value(const void *context, const char *name, int component, double *out) {
    const _sl_row_inputs *in = context;
    int offset, p = _sl_param(in->f, name, &offset);
    if (p < 0 || component < 0 || component >= sl_probe_type_size(in->f->params[p].type)) return false;
    *out = in->row[offset + component];
    return true;
}

static int _sl_row_size(const void *context, const char *name) {
    const _sl_row_inputs *in = context;
    int offset, p = _sl_param(in->f, name, &offset);
    return p < 0 ? 0 : sl_probe_type_size(in->f->params[p].type);
}

static void _sl_formula_outputs(const sl_formula *formula, const sl_probe_function *f, const float *row, double *out) {
    _sl_row_inputs context = {f, row};
    sl_formula_inputs in = {&context, _sl_row_value, _sl_row_size};
    for (int o = 0; o < f->output_count; o++) out[o] = sl_formula_eval(formula, &in, o);
}

/* The candidate's outputs on `count` rows (out[row * output_count + o]); false where it does not apply. */
static bool _sl_candidate_outputs(const _sl_generic *g, const sl_probe_function *f, const int *offsets,
                                  const sl_formula *formula, const _sl_slip_candidate *c,
                                  const float (*rows)[SL_PROBE_MAX_INPUTS], int count, double *out) {
    static sl_formula edited;
    if (c->edit > 0 && !sl_formula_edited(formula, c->edit, &edited)) return false;
    int inputs = sl_probe_input_count(f);
    for (int row = 0; row < count; row++) {
        double *at = out + row * f->output_count;
        if (c->edit > 0) {
            _sl_formula_outputs(&edited, f, rows[row], at);
            continue;
        }
        float slipped[SL_PROBE_MAX_INPUTS];
        memcpy(slipped, rows[row], sizeof(float) * (size_t)inputs);
        if (c->formula_slip == 0 &&
            !_sl_slip_apply(f, c->p, offsets[c->p], sl_probe_type_size(f->params[c->p].type), (_sl_slip_kind)c->kind,
                            c->component, c->other, c->constant, slipped))
            return false;
        g->expect(f, slipped, c->formula_slip, at);
    }
    return true;
}

/* Whether every modelled row of k follows the candidate, and at least one differs from the contract
 * (contract: the contract's outputs on every row of k). */
/* How many modelled rows a slip may fail to fit (0, or 1 on a second look: a slip the student made, and a
 * written edge case answered some other way besides), and the last row that did not. */
static int _sl_misfits_allowed, _sl_misfit_row;

static bool _sl_slip_fits(const _sl_generic *g, const sl_probe_function *f, const sl_check *k, const double *student,
                          const double *contract, const double *scale, const bool *modelled, const int *offsets,
                          const sl_formula *formula, const _sl_slip_candidate *c) {
    static double slipped[SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS];
    if (!_sl_candidate_outputs(g, f, offsets, formula, c, (const float (*)[SL_PROBE_MAX_INPUTS])k->inputs, k->rows,
                               slipped))
        return false;
    int explained = 0, misfits = 0;
    for (int row = 0; row < k->rows; row++) {
        if (!modelled[row]) continue;
        bool fits = true, differs = false;
        /* a row's outputs that are one vector (a centre, a matrix) carry rounding in proportion to the whole
         * vector: a slip that makes them large leaves a small component as uncertain as the others */
        double largest = 0;
        for (int o = 0; o < f->output_count; o++)
            if (isfinite(slipped[row * f->output_count + o]))
                largest = fmax(largest, fabs(slipped[row * f->output_count + o]));
        for (int o = 0; o < f->output_count; o++) {
            int at = row * f->output_count + o;
            fits &= _sl_slip_close(student[at], slipped[at], fmax(scale[o], 0.1 * largest));
            differs |= !_sl_slip_close(student[at], contract[at], scale[o]);
        }
        if (!fits) {
            /* a row let off must be wrong itself: a right row the slip does not give says the slip is not made */
            if (++misfits > _sl_misfits_allowed || !differs) return false;
            _sl_misfit_row = row;
        } else {
            explained += differs;
        }
    }
    /* with a row let off, the slip must explain several rows on its own: one or two are a coincidence */
    return misfits == 0 ? explained > 0 : explained >= 3;
}

/* Rows of the function's own kind that the check never saw: two slips that give the same outputs on them
 * are one formula written two ways (a catalogue entry and the edit it is), not two explanations. */
enum { _SL_FRESH_ROWS = 24 };

static bool _sl_same_formula(const double *a, const double *b, int count) {
    for (int i = 0; i < count; i++) {
        if (isnan(a[i]) && isnan(b[i])) continue;
        if (!(fabs(a[i] - b[i]) <= 1e-6 + 1e-6 * fabs(b[i])) && !(isinf(a[i]) && a[i] == b[i])) return false;
    }
    return true;
}

static void _sl_candidate_words(const _sl_generic *g, const sl_probe_function *f, const sl_formula *formula,
                                const _sl_slip_candidate *c, char *out, size_t n) {
    if (c->formula_slip > 0) {
        snprintf(out, n, "%s, where the contract says %s", g->slips[c->formula_slip][0], g->slips[c->formula_slip][1]);
    } else if (c->edit > 0) {
        char computed[300], contract[300];
        sl_formula_edit_words(formula, c->edit, computed, contract, sizeof computed);
        snprintf(out, n, "%s, where the contract says %s", computed, contract);
    } else {
        _sl_slip_words(f, c->p, (_sl_slip_kind)c->kind, c->component, c->q, c->constant, out, n);
    }
}

/* Collects c into the groups of fitting candidates (one per distinct formula); false once there are more
 * than `most` groups. */
typedef struct _sl_slip_groups {
    _sl_slip_candidate first[4];
    double fresh[4][_SL_FRESH_ROWS * SL_PROBE_MAX_OUTPUTS];
    int count;
} _sl_slip_groups;

static void _sl_group(_sl_slip_groups *groups, const _sl_generic *g, const sl_probe_function *f, const int *offsets,
                      const sl_formula *formula, const float (*fresh)[SL_PROBE_MAX_INPUTS],
                      const _sl_slip_candidate *c) {
    static double outputs[_SL_FRESH_ROWS * SL_PROBE_MAX_OUTPUTS];
    int size = _SL_FRESH_ROWS * f->output_count;
    if (!_sl_candidate_outputs(g, f, offsets, formula, c, fresh, _SL_FRESH_ROWS, outputs)) return;
    for (int i = 0; i < groups->count && i < 4; i++)
        if (_sl_same_formula(outputs, groups->fresh[i], size)) {
            /* one formula: its catalogue or input words stand; among edits, the likeliest names it */
            const _sl_slip_candidate *first = &groups->first[i];
            if (first->edit > 0 && c->edit > 0 && sl_formula_edit_rank(c->edit) < sl_formula_edit_rank(first->edit))
                groups->first[i] = *c;
            return;
        }
    if (groups->count < 4) {
        groups->first[groups->count] = *c;
        memcpy(groups->fresh[groups->count], outputs, sizeof(double) * (size_t)size);
    }
    groups->count++;
}

/* The value most of k's written rows give the input at `offset` (a constant someone might have written
 * in its place: the value the examples they tried had); NaN when no value is shared by two rows. */
static float _sl_common_value(const sl_check *k, int offset) {
    int written = k->rows - k->generic_rows, best = 1;
    float value = NAN;
    for (int a = 0; a < written; a++) {
        int same = 0;
        for (int b = 0; b < written; b++) same += k->inputs[b][offset] == k->inputs[a][offset];
        if (same > best) best = same, value = k->inputs[a][offset];
    }
    return value;
}

sl_probe_slip sl_probe_generic_slip(const sl_check *k, const double *student, const double *expected, char *out,
                                    size_t n) {
    const sl_probe_function *f = sl_probe_at(k->function);
    const _sl_generic *g = f ? _sl_find(f->name) : NULL;
    out[0] = '\0';
    if (!g || k->rows < 1 || f->output_count > SL_PROBE_MAX_OUTPUTS) return SL_PROBE_SLIP_NONE;
    int offsets[SL_PROBE_MAX_PARAMS];
    for (int p = 0, offset = 0; p < f->param_count; offset += sl_probe_type_size(f->params[p].type), p++)
        offsets[p] = offset;
    /* the rows the formula models: every generic row, and each written row where the contract's formula
     * gives the reference's answer (a written edge case the formula leaves out says nothing of a slip) */
    static double contract[SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS];
    double scale[SL_PROBE_MAX_OUTPUTS] = {0};
    /* a check that compares relative to the answer (exponentials: 1 and 2e17 on one check) sizes each output
     * by its smallest answer, the rest of the tolerance being relative as well */
    bool relative = k->relative > 0;
    for (int o = 0; relative && o < f->output_count; o++) scale[o] = INFINITY;
    for (int row = 0; row < k->rows; row++) {
        g->expect(f, k->inputs[row], 0, contract + row * f->output_count);
        for (int o = 0; o < f->output_count; o++) {
            double size = fabs(contract[row * f->output_count + o]);
            if (isfinite(size) && (relative ? size > 0 && size < scale[o] : size > scale[o])) scale[o] = size;
        }
    }
    for (int o = 0; relative && o < f->output_count; o++)
        if (!isfinite(scale[o])) scale[o] = 0;
    for (int o = 0; o < f->output_count; o++)
        if (scale[o] < 1e-6) scale[o] = 1; /* an output the contract keeps at 0: its size is the unit's */
    bool modelled[SL_PROBE_MAX_ROWS];
    int modelled_rows = 0;
    for (int row = 0; row < k->rows; row++) {
        const double *as_given = contract + row * f->output_count;
        bool agrees = true;
        for (int o = 0; expected && o < f->output_count; o++)
            agrees &= _sl_slip_close(expected[row * f->output_count + o], as_given[o], scale[o]);
        modelled[row] = agrees;
        modelled_rows += agrees;
    }
    if (modelled_rows < 3) return SL_PROBE_SLIP_NONE;
    /* the formula's edits, where the formula gives the contract's outputs on every modelled row */
    static sl_formula formula;
    char err[160];
    bool edits = g->formula && sl_formula_parse(&formula, g->formula, err, sizeof err);
    for (int row = 0; edits && row < k->rows; row++) {
        double as_written[SL_PROBE_MAX_OUTPUTS];
        _sl_formula_outputs(&formula, f, k->inputs[row], as_written);
        for (int o = 0; modelled[row] && o < f->output_count; o++)
            edits &= _sl_slip_close(as_written[o], contract[row * f->output_count + o], scale[o]);
    }
    /* fresh rows of the function's kind, to tell one formula written two ways from two formulas */
    static float fresh[_SL_FRESH_ROWS][SL_PROBE_MAX_INPUTS];
    _sl_rng r = {0x5eed5eedu};
    for (int i = 0; i < _SL_FRESH_ROWS; i++) {
        char about[200];
        memset(fresh[i], 0, sizeof fresh[i]);
        g->draw(f, &r, i, fresh[i], about, sizeof about);
    }
    /* every slip that fits, grouped by the formula it is; a few groups that fit alike are listed (the rows
     * cannot tell them apart), more are a coincidence of the rows (a clamp all reach, an input all zero
     * out) and none is named. Catalogued slips first, then slips of one input, then edits: where one
     * formula is all three, its catalogue words are the ones shown. */
    static _sl_slip_groups groups;
    groups.count = 0;
    bool let_off = false;
    for (int look = 0; look < 2 && groups.count == 0; look++) {
    _sl_misfits_allowed = look;
    let_off = look > 0;
    for (int s = 1; g->slips && g->slips[s][0]; s++) {
        _sl_slip_candidate c = {0, 0, 0, 0, -1, s, 0, 0};
        if (_sl_slip_fits(g, f, k, student, contract, scale, modelled, offsets, &formula, &c))
            _sl_group(&groups, g, f, offsets, &formula, (const float (*)[SL_PROBE_MAX_INPUTS])fresh, &c);
    }
    for (int p = 0; p < f->param_count; p++) {
        sl_probe_type type = f->params[p].type;
        if (SL_PROBE_IS_MAP(type) || type == SL_PROBE_MAT4) continue;
        int size = sl_probe_type_size(type);
        for (int kind = 0; kind < _SL_SLIP_KINDS; kind++)
            for (int variant = 0; variant < f->param_count || variant < 4; variant++) {
                /* the component a component slip takes, or the parameter a swap takes */
                int component = variant, q = variant;
                if (kind == _SL_SLIP_COMPONENT_NEGATED || kind == _SL_SLIP_COMPONENT_ZERO ? variant >= size
                    : kind == _SL_SLIP_SWAPPED_WITH    ? variant >= f->param_count || q <= p ||
                                                          f->params[q].type != type
                                                       : variant > 0)
                    continue;
                _sl_slip_candidate c = {p, kind, component, q, kind == _SL_SLIP_SWAPPED_WITH ? offsets[q] : -1, 0, 0,
                                        _sl_common_value(k, offsets[p])};
                /* a constant that is 0 or 1 is the slips above; one that no written row shares is no slip */
                if (kind == _SL_SLIP_CONSTANT && (size != 1 || c.constant == 0 || c.constant == 1 || isnan(c.constant)))
                    continue;
                if (_sl_slip_fits(g, f, k, student, contract, scale, modelled, offsets, &formula, &c))
                    _sl_group(&groups, g, f, offsets, &formula, (const float (*)[SL_PROBE_MAX_INPUTS])fresh, &c);
            }
    }
    for (int e = 1; edits && e <= sl_formula_edit_count(&formula); e++) {
        _sl_slip_candidate c = {0, 0, 0, 0, -1, 0, e, 0};
        if (_sl_slip_fits(g, f, k, student, contract, scale, modelled, offsets, &formula, &c))
            _sl_group(&groups, g, f, offsets, &formula, (const float (*)[SL_PROBE_MAX_INPUTS])fresh, &c);
    }
    }
    _sl_misfits_allowed = 0;
    if (groups.count < 1 || groups.count > (let_off ? 2 : 4)) return SL_PROBE_SLIP_NONE;
    char words[4][640];
    for (int i = 0; i < groups.count; i++)
        _sl_candidate_words(g, f, &formula, &groups.first[i], words[i], sizeof words[i]);
    if (let_off) {
        /* the row the slip leaves out, found again */
        _sl_misfits_allowed = 1;
        _sl_misfit_row = -1;
        _sl_slip_fits(g, f, k, student, contract, scale, modelled, offsets, &formula, &groups.first[0]);
        _sl_misfits_allowed = 0;
        int row = _sl_misfit_row;
        bool formula_slip = groups.first[0].formula_slip > 0 || groups.first[0].edit > 0;
        char also[700] = "";
        if (groups.count == 2)
            snprintf(also, sizeof also, " (or, as these rows cannot tell apart, %s)", words[1]);
        snprintf(out, n, "on every row but one it answers %s %s%s; the row it does not fit%s%s%s is wrong another way "
                         "too",
                 formula_slip ? "as if it computed" : "as the contract does with", words[0], also,
                 row >= 0 && k->about[row][0] ? " (" : "", row >= 0 ? k->about[row] : "",
                 row >= 0 && k->about[row][0] ? ")" : "");
        return SL_PROBE_SLIP_OF_FORMULA;
    }
    if (groups.count == 1) {
        bool formula_slip = groups.first[0].formula_slip > 0 || groups.first[0].edit > 0;
        snprintf(out, n, formula_slip ? "on every row it answers as if it computed %s"
                                      : "on every row it answers as the contract does with %s",
                 words[0]);
        bool leads = groups.first[0].formula_slip > 0 && groups.first[0].formula_slip < 64 &&
                     ((g->leading >> groups.first[0].formula_slip) & 1u);
        return groups.first[0].edit > 0 || leads ? SL_PROBE_SLIP_EDIT
             : formula_slip              ? SL_PROBE_SLIP_OF_FORMULA
                                         : SL_PROBE_SLIP_OF_INPUT;
    }
    size_t used = (size_t)snprintf(out, n, "on every row its answers fit each of %d slips, which these rows cannot tell "
                                           "apart: ",
                                   groups.count);
    for (int i = 0; i < groups.count && used < n; i++)
        used += (size_t)snprintf(out + used, n - used, "%s%s", i ? "; or " : "", words[i]);
    return SL_PROBE_SLIP_LIST;
}

bool sl_probe_generic_formulas_agree(char *err, size_t n) {
    static sl_formula formula;
    err[0] = '\0';
    for (size_t i = 0; i < sizeof _sl_generics / sizeof _sl_generics[0]; i++) {
        const _sl_generic *g = &_sl_generics[i];
        const sl_probe_function *f = g->formula ? sl_probe_find(g->function) : NULL;
        if (!g->formula) continue;
        if (!f) {
            snprintf(err, n, "%s: no such probed function", g->function);
            return false;
        }
        char parse_err[160];
        if (!sl_formula_parse(&formula, g->formula, parse_err, sizeof parse_err)) {
            snprintf(err, n, "%s: %s", g->function, parse_err);
            return false;
        }
        _sl_rng r = {0xa9ee5u + i};
        for (int row = 0; row < 64; row++) {
            float inputs[SL_PROBE_MAX_INPUTS] = {0};
            char about[200];
            double written[SL_PROBE_MAX_OUTPUTS], contract[SL_PROBE_MAX_OUTPUTS];
            g->draw(f, &r, row, inputs, about, sizeof about);
            _sl_formula_outputs(&formula, f, inputs, written);
            g->expect(f, inputs, 0, contract);
            for (int o = 0; o < f->output_count; o++)
                if (!_sl_slip_close(written[o], contract[o], fmax(fabs(contract[o]), 1e-3))) {
                    snprintf(err, n, "%s: output %d is %.6g by the formula, %.6g by the contract, on %s", g->function, o,
                             written[o], contract[o], about);
                    return false;
                }
        }
    }
    return true;
}
