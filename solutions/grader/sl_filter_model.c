#define _POSIX_C_SOURCE 200809L
#include "sl_filter_model.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "diagnose/verdict_filter.h"
#include "diagnose/verdict_rows.h"

/* The 16 points of lab 4's given Poisson disk (labs/lab4_pcf/shaders/pcf.glsl, "Given"). */
static const float _sl_disk[16][2] = {
    {-0.0552f, -0.8003f}, {-0.0288f, 0.2479f}, {-0.2544f, 0.6151f}, {-0.8666f, 0.0488f},
    {0.5174f, -0.0053f},  {-0.5927f, -0.6601f}, {0.1417f, -0.3470f}, {0.4121f, 0.6630f},
    {-0.6696f, 0.6331f},  {0.4826f, -0.8500f},  {0.9683f, -0.1818f}, {-0.4203f, -0.0849f},
    {0.0948f, 0.9732f},   {0.6713f, -0.4826f},  {0.9246f, 0.2683f},  {-0.8898f, -0.3631f}};

/* One slip: a term of the contract's three steps written another way, as a student might. */
typedef enum {
    _SL_PCSS_CONTRACT,
    _SL_PCSS_LINEAR_NEAR_FAR_SWAPPED, /* pcf_linear_depth(d, far, near) */
    _SL_PCSS_RECEIVER_NEAR_FAR_SWAPPED, /* the receiver's alone */
    _SL_PCSS_BLOCKER_NEAR_FAR_SWAPPED,  /* the blockers' alone */
    _SL_PCSS_LINEAR_DEPTH_AS_NDC,       /* the depth d put in as clip z, without z = 2 d - 1 */
    _SL_PCSS_RECEIVER_RAW,            /* receiver = p.z */
    _SL_PCSS_BLOCKER_RAW,             /* the blockers' raw depths averaged */
    _SL_PCSS_LINEARISE_AVERAGE,       /* pcf_linear_depth of the raw depths' average */
    _SL_PCSS_ALL_RAW,                 /* no pcf_linear_depth at all */
    _SL_PCSS_WIDTH_OVER_RECEIVER,     /* (receiver - blocker) * L / receiver */
    _SL_PCSS_WIDTH_NAMES_SWAPPED,     /* (blocker - receiver) * L / receiver */
    _SL_PCSS_WIDTH_NO_LIGHT_SIZE,     /* (receiver - blocker) / blocker * near / receiver */
    _SL_PCSS_WIDTH_NO_NEAR,           /* ... / blocker / receiver */
    _SL_PCSS_WIDTH_NOT_PROJECTED,     /* no * near / receiver */
    _SL_PCSS_WIDTH_PROJECTED_INVERSE, /* * receiver / near */
    _SL_PCSS_WIDTH_OVER_BLOCKER_NEAR, /* / (blocker * near) */
    _SL_PCSS_WIDTH_NEGATED,           /* (blocker - receiver) */
    _SL_PCSS_SEARCH_FULL,             /* search_uv = L */
    _SL_PCSS_SEARCH_NOT_DIVIDED,      /* L * (receiver - near) */
    _SL_PCSS_SEARCH_OVER_NEAR,        /* L * (receiver - near) / near */
    _SL_PCSS_FILTER_SEARCH_WIDTH,     /* the PCF over the search's width */
    _SL_PCSS_FILTER_LIGHT_SIZE,       /* the PCF over light_size_uv */
    _SL_PCSS_BLOCKER_OVER_ALL,        /* blocker_sum / 16 */
    _SL_PCSS_BLOCKER_NO_BIAS,         /* d < p.z */
    _SL_PCSS_FILTER_NO_BIAS,          /* p.z compared unbiased in the PCF */
    _SL_PCSS_NO_ROTATION,             /* the disk unrotated */
    _SL_PCSS_XY_NOT_DIVIDED,          /* the map read at shadow_coord.xy */
    _SL_PCSS_Z_NOT_DIVIDED,           /* shadow_coord.z as the receiver's depth */
    _SL_PCSS_BLOCKER_IS_RECEIVER,     /* the receiver's depth summed for each blocker: d_blocker = d_receiver */
    _SL_PCSS_PROJECTED_BY_BLOCKER,    /* * near / d_blocker: projected from the blocker, not the receiver */
    _SL_PCSS_SLIP_COUNT
} _sl_pcss_slip;

static const struct {
    const char *slip, *contract;
} _sl_pcss_text[_SL_PCSS_SLIP_COUNT] = {
    [_SL_PCSS_LINEAR_NEAR_FAR_SWAPPED] = {"pcf_linear_depth(d, far, near): near and far swapped",
                                          "pcf_linear_depth(d, near, far)"},
    [_SL_PCSS_RECEIVER_NEAR_FAR_SWAPPED] = {"the receiver's distance as pcf_linear_depth(p.z, far, near): near and far "
                                            "swapped",
                                            "d_receiver = pcf_linear_depth(p.z, near, far)"},
    [_SL_PCSS_BLOCKER_NEAR_FAR_SWAPPED] = {"the blockers' distances as pcf_linear_depth(d, far, near): near and far "
                                           "swapped",
                                           "pcf_linear_depth(d, near, far) for each blocker"},
    [_SL_PCSS_LINEAR_DEPTH_AS_NDC] = {"distances as 2 near far / (far + near - d (far - near)): the depth d taken as "
                                      "the normalised device z",
                                      "pcf_linear_depth(d, near, far): the depth buffer's d is z * 0.5 + 0.5, so z = "
                                      "2 d - 1"},
    [_SL_PCSS_RECEIVER_RAW] = {"the receiver's distance as its raw depth p.z",
                               "d_receiver = pcf_linear_depth(p.z, near, far)"},
    [_SL_PCSS_BLOCKER_RAW] = {"the blockers' raw depths averaged, not their distances",
                              "d_blocker = the average of pcf_linear_depth(d, near, far) over the blockers"},
    [_SL_PCSS_LINEARISE_AVERAGE] = {"the blockers' raw depths averaged first and the average made a distance "
                                    "(pcf_linear_depth of the mean depth): depth is not linear in distance, so that "
                                    "is not the blockers' mean distance",
                                    "the average of pcf_linear_depth(d, near, far) over the blockers: each depth made "
                                    "a distance, then averaged"},
    [_SL_PCSS_ALL_RAW] = {"every distance as a raw depth (no pcf_linear_depth)",
                          "distances from pcf_linear_depth(d, near, far), for the receiver and the blockers"},
    [_SL_PCSS_WIDTH_OVER_RECEIVER] = {"the width divided by d_receiver, (d_receiver - d_blocker) * light_size_uv / "
                                      "d_receiver",
                                      "(d_receiver - d_blocker) * light_size_uv / d_blocker (similar triangles: over "
                                      "the blocker's distance)"},
    [_SL_PCSS_WIDTH_NAMES_SWAPPED] = {"d_blocker and d_receiver swapped in step 2, (d_blocker - d_receiver) * "
                                      "light_size_uv / d_receiver",
                                      "(d_receiver - d_blocker) * light_size_uv / d_blocker: d_blocker below the line, "
                                      "not d_receiver"},
    [_SL_PCSS_WIDTH_NO_LIGHT_SIZE] = {"the width without light_size_uv, (d_receiver - d_blocker) / d_blocker * near / "
                                      "d_receiver",
                                      "(d_receiver - d_blocker) * light_size_uv / d_blocker * near / d_receiver: a "
                                      "larger light, a wider penumbra"},
    [_SL_PCSS_WIDTH_NO_NEAR] = {"the width projected with / d_receiver alone (near left out)",
                                "(d_receiver - d_blocker) * light_size_uv / d_blocker * near / d_receiver"},
    [_SL_PCSS_WIDTH_NOT_PROJECTED] = {"the width on the receiver, not projected onto the map (no * near / d_receiver)",
                                      "(d_receiver - d_blocker) * light_size_uv / d_blocker * near / d_receiver"},
    [_SL_PCSS_WIDTH_PROJECTED_INVERSE] = {"the width projected with * d_receiver / near (the ratio inverted)",
                                          "* near / d_receiver: the map lies at the near plane"},
    [_SL_PCSS_WIDTH_OVER_BLOCKER_NEAR] = {"the width divided by (d_blocker * near)",
                                          "/ d_blocker * near / d_receiver"},
    [_SL_PCSS_WIDTH_NEGATED] = {"the width as (d_blocker - d_receiver) * ...: negative, the disk turned over",
                                "(d_receiver - d_blocker) * ..., positive behind a blocker"},
    [_SL_PCSS_SEARCH_FULL] = {"the blocker search over light_size_uv itself",
                              "a search region of light_size_uv * (d_receiver - near) / d_receiver"},
    [_SL_PCSS_SEARCH_NOT_DIVIDED] = {"the search region light_size_uv * (d_receiver - near), not divided by "
                                     "d_receiver",
                                     "light_size_uv * (d_receiver - near) / d_receiver"},
    [_SL_PCSS_SEARCH_OVER_NEAR] = {"the search region light_size_uv * (d_receiver - near) / near",
                                   "light_size_uv * (d_receiver - near) / d_receiver"},
    [_SL_PCSS_FILTER_SEARCH_WIDTH] = {"the filter as wide as the blocker search",
                                      "the filter as wide as the penumbra of step 2"},
    [_SL_PCSS_FILTER_LIGHT_SIZE] = {"the filter light_size_uv wide", "the filter as wide as the penumbra of step 2"},
    [_SL_PCSS_BLOCKER_OVER_ALL] = {"the blockers' sum divided by all 16 samples",
                                   "divided by the number of blockers found"},
    [_SL_PCSS_BLOCKER_NO_BIAS] = {"a blocker test without the bias, d < p.z: the blocker search counts the "
                                  "receiver's own surface as a blocker",
                                  "d < p.z - bias: the bias belongs in the blocker search too"},
    [_SL_PCSS_FILTER_NO_BIAS] = {"the filter's comparisons without the bias", "p.z - bias compared at every sample"},
    [_SL_PCSS_XY_NOT_DIVIDED] = {"x and y not divided by w (the map read around shadow_coord.xy)",
                                 "p = shadow_coord.xyz / shadow_coord.w (pcf_project), then read around p.xy"},
    [_SL_PCSS_Z_NOT_DIVIDED] = {"z not divided by w (shadow_coord.z as the receiver's depth)",
                                "p.z = shadow_coord.z / shadow_coord.w: a spot light's coordinate is homogeneous"},
    [_SL_PCSS_BLOCKER_IS_RECEIVER] = {"the blockers' distance equal to the receiver's (p.z summed for each blocker "
                                      "found, where the blocker's stored depth d belongs): the width (d_receiver - "
                                      "d_blocker) is 0, so every sample reads the point itself, a hard shadow",
                                      "d_blocker = the average of pcf_linear_depth(d, near, far) over the blockers, d "
                                      "the depth stored at each sample"},
    [_SL_PCSS_PROJECTED_BY_BLOCKER] = {"the width projected onto the map with * near / d_blocker: from the "
                                       "blocker's distance, not the receiver's",
                                       "* near / d_receiver: the penumbra lies on the receiver, so the receiver's "
                                       "distance projects it"},
    [_SL_PCSS_NO_ROTATION] = {"the disk unrotated (or turned by a rotation that is not the pixel's)",
                              "each offset turned by pcf_rotation(gl_FragCoord.xy)"},
};

int sl_pcss_slip_count(void) { return _SL_PCSS_SLIP_COUNT - 1; }

/* pcf_linear_depth(d, near, far), or its slip (the receiver's or a blocker's, as `receiver` says) */
static float _sl_linear(float d, float near, float far, int slip, bool receiver) {
    if (slip == _SL_PCSS_LINEAR_NEAR_FAR_SWAPPED || (receiver && slip == _SL_PCSS_RECEIVER_NEAR_FAR_SWAPPED) ||
        (!receiver && slip == _SL_PCSS_BLOCKER_NEAR_FAR_SWAPPED)) {
        float t = near;
        near = far;
        far = t;
    }
    float z = slip == _SL_PCSS_LINEAR_DEPTH_AS_NDC ? d : d * 2.0f - 1.0f;
    return 2.0f * near * far / (far + near - z * (far - near));
}

/* A nearest-filtered lookup of the 64-texel synthetic map, its border 1.0 (nothing there). */
static float _sl_lookup(sl_probe_map map, float u, float v) {
    if (!(u >= 0 && u < 1 && v >= 0 && v < 1)) return 1.0f;
    return sl_probe_map_depth(map, (int)floorf(u * SL_PROBE_MAP_SIZE), (int)floorf(v * SL_PROBE_MAP_SIZE));
}

/* lab 4's given pcf_rotation(pixel): an integer hash of the pixel, an angle in 1024 steps */
static void _sl_rotation(float px, float py, float m[4]) {
    uint32_t qx = (uint32_t)px, qy = (uint32_t)py;
    uint32_t h = (qx * 73856093u) ^ (qy * 19349663u);
    h = (h ^ (h >> 13u)) * 1274126177u;
    float angle = (float)(h >> 22u) * (6.28318530718f / 1024.0f);
    /* mat2(c, s, -s, c): columns (c, s) and (-s, c) */
    m[0] = cosf(angle), m[1] = sinf(angle), m[2] = -m[1], m[3] = m[0];
}

double sl_pcss_model(const sl_probe_function *f, const float *in, int row, int slip) {
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias"), *size = _sl_param(f, in, "light_size_uv");
    const float *near_p = _sl_param(f, in, "near"), *far_p = _sl_param(f, in, "far");
    if (!map || !coord || !bias || !size || !near_p || !far_p) return NAN;
    sl_probe_map m = (sl_probe_map)(int)*map;
    if (sl_probe_map_type(m) != SL_PROBE_MAP) return NAN;
    float w = coord[3], p[3] = {coord[0] / w, coord[1] / w, coord[2] / w};
    if (slip == _SL_PCSS_XY_NOT_DIVIDED) p[0] = coord[0], p[1] = coord[1];
    if (slip == _SL_PCSS_Z_NOT_DIVIDED) p[2] = coord[2];
    if (!(w > 0) || p[0] < 0 || p[1] < 0 || p[2] < 0 || p[0] > 1 || p[1] > 1 || p[2] > 1) return 1.0;
    float near = *near_p, far = *far_p, light = *size;
    bool raw_receiver = slip == _SL_PCSS_RECEIVER_RAW || slip == _SL_PCSS_ALL_RAW;
    bool raw_blocker = slip == _SL_PCSS_BLOCKER_RAW || slip == _SL_PCSS_ALL_RAW || slip == _SL_PCSS_LINEARISE_AVERAGE;
    float receiver = raw_receiver ? p[2] : _sl_linear(p[2], near, far, slip, true);
    float rot[4] = {1, 0, 0, 1};
    if (slip != _SL_PCSS_NO_ROTATION) _sl_rotation(0.5f, 2.0f * (float)row + 0.5f, rot);

    float search = light * (receiver - near) / receiver;
    if (slip == _SL_PCSS_SEARCH_FULL) search = light;
    if (slip == _SL_PCSS_SEARCH_NOT_DIVIDED) search = light * (receiver - near);
    if (slip == _SL_PCSS_SEARCH_OVER_NEAR) search = light * (receiver - near) / near;
    float blocker_bias = slip == _SL_PCSS_BLOCKER_NO_BIAS ? 0.0f : *bias;
    float sum = 0;
    int blockers = 0;
    for (int i = 0; i < 16; i++) {
        float ox = rot[0] * _sl_disk[i][0] + rot[2] * _sl_disk[i][1], oy = rot[1] * _sl_disk[i][0] + rot[3] * _sl_disk[i][1];
        float d = _sl_lookup(m, p[0] + ox * search, p[1] + oy * search);
        if (d < p[2] - blocker_bias) {
            sum += raw_blocker ? d : _sl_linear(d, near, far, slip, false);
            blockers++;
        }
    }
    if (blockers == 0) return 1.0;
    float blocker = sum / (float)(slip == _SL_PCSS_BLOCKER_OVER_ALL ? 16 : blockers);
    if (slip == _SL_PCSS_LINEARISE_AVERAGE) blocker = _sl_linear(blocker, near, far, slip, false);
    if (slip == _SL_PCSS_BLOCKER_IS_RECEIVER) blocker = receiver;
    float width;
    switch (slip) {
    case _SL_PCSS_WIDTH_OVER_RECEIVER: width = (receiver - blocker) * light / receiver * near / receiver; break;
    case _SL_PCSS_WIDTH_NAMES_SWAPPED: width = (blocker - receiver) * light / receiver * near / receiver; break;
    case _SL_PCSS_WIDTH_NO_LIGHT_SIZE: width = (receiver - blocker) / blocker * near / receiver; break;
    case _SL_PCSS_WIDTH_NO_NEAR: width = (receiver - blocker) * light / blocker / receiver; break;
    case _SL_PCSS_WIDTH_NOT_PROJECTED: width = (receiver - blocker) * light / blocker; break;
    case _SL_PCSS_WIDTH_PROJECTED_INVERSE: width = (receiver - blocker) * light / blocker * receiver / near; break;
    case _SL_PCSS_WIDTH_OVER_BLOCKER_NEAR: width = (receiver - blocker) * light / (blocker * near) / receiver; break;
    case _SL_PCSS_WIDTH_NEGATED: width = (blocker - receiver) * light / blocker * near / receiver; break;
    case _SL_PCSS_PROJECTED_BY_BLOCKER: width = (receiver - blocker) * light / blocker * near / blocker; break;
    case _SL_PCSS_FILTER_SEARCH_WIDTH: width = search; break;
    case _SL_PCSS_FILTER_LIGHT_SIZE: width = light; break;
    default: width = (receiver - blocker) * light / blocker * near / receiver; break;
    }
    float filter_bias = slip == _SL_PCSS_FILTER_NO_BIAS ? 0.0f : *bias;
    float lit = 0;
    for (int i = 0; i < 16; i++) {
        float ox = rot[0] * _sl_disk[i][0] + rot[2] * _sl_disk[i][1], oy = rot[1] * _sl_disk[i][0] + rot[3] * _sl_disk[i][1];
        float d = _sl_lookup(m, p[0] + ox * width, p[1] + oy * width);
        lit += p[2] - filter_bias > d ? 0.0f : 1.0f;
    }
    return lit / 16.0;
}

static double _sl_row_tolerance(const sl_verdict_rows *v, int r) {
    return v->k->row_tolerance[r] > 0 ? v->k->row_tolerance[r] : v->k->tolerance;
}

/* Whether a row is exact: its tolerance is below one sample of 16, so no sample lies near a texel's edge
 * (rows chosen so) and every GL answers it as the model does. */
static bool _sl_row_exact(const sl_verdict_rows *v, int r) { return _sl_row_tolerance(v, r) < 1.0 / 16; }

/* Does slip s give every row what the student's gave? With `slack`, one row that is not exact may be one
 * sample of 16 off: a sample on a texel's edge falls on either side of it, in float, on another GL. */
static bool _sl_slip_fits(const sl_verdict_rows *v, int s, bool slack) {
    int off = 0;
    for (int r = 0; r < v->k->rows; r++) {
        double model = sl_pcss_model(v->f, v->k->inputs[r], r, s), d = fabs(_sl_got(v, r, 0) - model);
        if (isnan(model) || d > 1.0 / 16 + 1e-4 || (d > 1e-3 && _sl_row_exact(v, r))) return false;
        off += d > 1e-3;
    }
    return off <= (slack ? 1 : 0);
}

int sl_pcss_slip_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    if (strcmp(v->f->name, "pcss") != 0) return -1;
    /* the model must be the contract first: on these rows, as the solution answers every one */
    int first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        double model = sl_pcss_model(v->f, v->k->inputs[r], r, _SL_PCSS_CONTRACT);
        if (isnan(model) || fabs(_sl_want(v, r, 0) - model) > _sl_row_tolerance(v, r) + 1e-4) return -1;
        if (first < 0 && _sl_failed(v, r)) first = r;
    }
    if (first < 0 || _sl_slip_fits(v, _SL_PCSS_CONTRACT, true)) return -1;
    int fits[_SL_PCSS_SLIP_COUNT], count = 0;
    for (int slack = 0; slack <= 1 && count == 0; slack++)
        for (int s = 1; s < _SL_PCSS_SLIP_COUNT; s++)
            if (_sl_slip_fits(v, s, slack)) fits[count++] = s;
    if (count == 0 || count > 2) return -1;
    if (count == 1)
        snprintf(text, n, "on every row it answers as if it computed %s, where the contract says %s",
                 _sl_pcss_text[fits[0]].slip, _sl_pcss_text[fits[0]].contract);
    else
        snprintf(text, n, "on every row it answers as if it computed %s, or %s (these rows answer both alike), "
                          "where the contract says %s, and %s",
                 _sl_pcss_text[fits[0]].slip, _sl_pcss_text[fits[1]].slip, _sl_pcss_text[fits[0]].contract,
                 _sl_pcss_text[fits[1]].contract);
    /* what the rows show of it in a picture: darker or lighter, a penumbra wider or narrower (farther from
     * or nearer to one comparison's 0 or 1 at the point) */
    uint32_t symptoms = 1u << SL_SYMPTOM_GROSS;
    for (int r = 0; r < v->k->rows; r++) {
        if (!_sl_failed(v, r)) continue;
        double got = _sl_got(v, r, 0), want = _sl_want(v, r, 0), centre = _sl_filter_row_of(v->f, v->k->inputs[r]).centre;
        symptoms |= 1u << (got < want ? SL_SYMPTOM_TOO_DARK : SL_SYMPTOM_TOO_LIGHT);
        symptoms |= 1u << (fabs(got - centre) > fabs(want - centre) ? SL_SYMPTOM_WIDE_PENUMBRA : SL_SYMPTOM_NARROW_PENUMBRA);
    }
    sl_verdict_predicts(v, symptoms);
    return first;
}

/* ---- pcf_poisson: the rotated disk, and its slips ---- */

typedef enum {
    _SL_POISSON_CONTRACT,
    _SL_POISSON_TRANSPOSED,     /* PCF_POISSON_DISK[i] * rotation: the transpose, turned the other way */
    _SL_POISSON_UNROTATED,      /* no rotation, or pcf_rotation of a uv (which hashes every uv to angle 0) */
    _SL_POISSON_TEXEL_HASH,     /* pcf_rotation(p.xy * textureSize): the map's texel, not the pixel */
    _SL_POISSON_FRAG_COORD,     /* pcf_rotation(gl_FragCoord.xy): right in a picture, not a slip (below) */
    _SL_POISSON_OFFSET_IN_UV,   /* radius_texels * disk in uv, not divided by textureSize */
    _SL_POISSON_HALF_RADIUS,    /* the radius taken as a diameter */
    _SL_POISSON_NO_BIAS,        /* p.z compared unbiased */
    _SL_POISSON_BIAS_ADDED,     /* p.z + bias */
    _SL_POISSON_XY_NOT_DIVIDED, /* read around shadow_coord.xy */
    _SL_POISSON_Z_NOT_DIVIDED,  /* shadow_coord.z compared */
    _SL_POISSON_SLIP_COUNT
} _sl_poisson_slip;

static const struct {
    const char *slip, *contract;
} _sl_poisson_text[_SL_POISSON_SLIP_COUNT] = {
    [_SL_POISSON_TRANSPOSED] = {"the disk turned the other way: PCF_POISSON_DISK[i] * rotation multiplies by the "
                                "rotation's transpose, its inverse",
                                "rotation * PCF_POISSON_DISK[i] (in GLSL a matrix times a vector, in that order)"},
    [_SL_POISSON_UNROTATED] = {"the disk unrotated (no rotation, or pcf_rotation of a coordinate in [0, 1), whose "
                               "integer hash is the same, angle 0, everywhere)",
                               "each offset turned by pcf_rotation(pixel), the pixel's own angle: the pattern "
                               "changes from pixel to pixel, so banding becomes fine noise"},
    [_SL_POISSON_TEXEL_HASH] = {"the disk turned by the map's texel, pcf_rotation(p.xy * textureSize)",
                                "pcf_rotation(pixel): an angle per screen pixel, not per shadow-map texel (several "
                                "pixels share a texel, and their noise would be one)"},
    [_SL_POISSON_OFFSET_IN_UV] = {"offsets of radius_texels in uv (not divided by textureSize): the disk hundreds of "
                                  "texels wide",
                                  "PCF_POISSON_DISK[i] * radius_texels / textureSize(shadow_map, 0)"},
    [_SL_POISSON_HALF_RADIUS] = {"a disk half as wide (radius_texels taken as the diameter)",
                                 "offsets up to radius_texels texels from the centre"},
    [_SL_POISSON_NO_BIAS] = {"comparisons without the bias", "p.z - bias compared at every sample"},
    [_SL_POISSON_BIAS_ADDED] = {"comparisons of p.z + bias: the bias added", "p.z - bias compared at every sample"},
    [_SL_POISSON_XY_NOT_DIVIDED] = {"x and y not divided by w (the map read around shadow_coord.xy)",
                                    "p = shadow_coord.xyz / shadow_coord.w (pcf_project), then read around p.xy"},
    [_SL_POISSON_Z_NOT_DIVIDED] = {"z not divided by w (shadow_coord.z compared)",
                                   "p.z = shadow_coord.z / shadow_coord.w"},
};

double sl_poisson_model(const sl_probe_function *f, const float *in, int row, int slip) {
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias"), *radius = _sl_param(f, in, "radius_texels");
    const float *pixel = _sl_param(f, in, "pixel");
    if (!map || !coord || !bias || !radius || !pixel) return NAN;
    sl_probe_map m = (sl_probe_map)(int)*map;
    if (sl_probe_map_type(m) != SL_PROBE_MAP) return NAN;
    float w = coord[3], p[3] = {coord[0] / w, coord[1] / w, coord[2] / w};
    if (slip == _SL_POISSON_XY_NOT_DIVIDED) p[0] = coord[0], p[1] = coord[1];
    if (slip == _SL_POISSON_Z_NOT_DIVIDED) p[2] = coord[2];
    if (!(w > 0) || p[0] < 0 || p[1] < 0 || p[2] < 0 || p[0] > 1 || p[1] > 1 || p[2] > 1) return 1.0;
    float rot[4] = {1, 0, 0, 1};
    switch (slip) {
    case _SL_POISSON_UNROTATED: break;
    case _SL_POISSON_TEXEL_HASH: _sl_rotation(p[0] * SL_PROBE_MAP_SIZE, p[1] * SL_PROBE_MAP_SIZE, rot); break;
    case _SL_POISSON_FRAG_COORD: _sl_rotation(0.5f, 2.0f * (float)row + 0.5f, rot); break;
    default: _sl_rotation(pixel[0], pixel[1], rot); break;
    }
    if (slip == _SL_POISSON_TRANSPOSED) {
        float t = rot[1];
        rot[1] = rot[2], rot[2] = t;
    }
    float scale = *radius / SL_PROBE_MAP_SIZE;
    if (slip == _SL_POISSON_OFFSET_IN_UV) scale = *radius;
    if (slip == _SL_POISSON_HALF_RADIUS) scale *= 0.5f;
    float z = p[2] - (slip == _SL_POISSON_NO_BIAS ? 0.0f : slip == _SL_POISSON_BIAS_ADDED ? -*bias : *bias);
    float lit = 0;
    for (int i = 0; i < 16; i++) {
        float ox = rot[0] * _sl_disk[i][0] + rot[2] * _sl_disk[i][1], oy = rot[1] * _sl_disk[i][0] + rot[3] * _sl_disk[i][1];
        lit += z > _sl_lookup(m, p[0] + ox * scale, p[1] + oy * scale) ? 0.0f : 1.0f;
    }
    return lit / 16.0;
}

int sl_poisson_slip_count(void) { return _SL_POISSON_SLIP_COUNT - 1; }

/* Does the Poisson slip s give every row what the student's gave (one row may be one sample off)? */
static bool _sl_poisson_fits(const sl_verdict_rows *v, int s, bool slack) {
    int off = 0;
    for (int r = 0; r < v->k->rows; r++) {
        double model = sl_poisson_model(v->f, v->k->inputs[r], r, s), d = fabs(_sl_got(v, r, 0) - model);
        if (isnan(model) || d > 1.0 / 16 + 1e-4 || (d > 1e-3 && _sl_row_exact(v, r))) return false;
        off += d > 1e-3;
    }
    return off <= (slack ? 1 : 0);
}

int sl_poisson_slip_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    if (strcmp(v->f->name, "pcf_poisson") != 0) return -1;
    int first = -1;
    for (int r = 0; r < v->k->rows; r++) {
        double model = sl_poisson_model(v->f, v->k->inputs[r], r, _SL_POISSON_CONTRACT);
        if (isnan(model) || fabs(_sl_want(v, r, 0) - model) > _sl_row_tolerance(v, r) + 1e-4) return -1;
        if (first < 0 && _sl_failed(v, r)) first = r;
    }
    /* the contract's answers, or the same disk turned by gl_FragCoord (the pixel a picture passes): no slip */
    if (first < 0 || _sl_poisson_fits(v, _SL_POISSON_CONTRACT, true) || _sl_poisson_fits(v, _SL_POISSON_FRAG_COORD, true))
        return -1;
    int fits[_SL_POISSON_SLIP_COUNT], count = 0;
    for (int slack = 0; slack <= 1 && count == 0; slack++)
        for (int s = 1; s < _SL_POISSON_SLIP_COUNT; s++)
            if (s != _SL_POISSON_FRAG_COORD && _sl_poisson_fits(v, s, slack)) fits[count++] = s;
    if (count != 1) return -1;
    snprintf(text, n, "on every row it answers as if it computed %s, where the contract says %s",
             _sl_poisson_text[fits[0]].slip, _sl_poisson_text[fits[0]].contract);
    bool rotation = fits[0] == _SL_POISSON_TRANSPOSED || fits[0] == _SL_POISSON_UNROTATED ||
                    fits[0] == _SL_POISSON_TEXEL_HASH;
    uint32_t symptoms = 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT;
    if (!rotation) symptoms |= 1u << SL_SYMPTOM_GROSS | 1u << SL_SYMPTOM_WIDE_PENUMBRA | 1u << SL_SYMPTOM_NARROW_PENUMBRA;
    sl_verdict_predicts(v, symptoms);
    return first;
}

/* ---- pcf_grid: a grid of another spacing ---- */

/* A (2r+1)^2 grid whose samples are `spacing` texels apart, on a synthetic map (nearest texels, the
 * border's depth 1.0 off the map): what pcf_grid gives for a row with that spacing. */
static double _sl_grid_with_spacing(const sl_probe_function *f, const float *in, double spacing) {
    const float *map = _sl_param(f, in, "shadow_map"), *coord = _sl_param(f, in, "shadow_coord");
    const float *bias = _sl_param(f, in, "bias"), *radius = _sl_param(f, in, "radius");
    if (!map || !coord || !bias || !radius || coord[3] <= 0) return NAN;
    double x = coord[0] / coord[3], y = coord[1] / coord[3], z = coord[2] / coord[3] - *bias;
    int r = (int)*radius, lit = 0, all = 0;
    for (int j = -r; j <= r; j++)
        for (int i = -r; i <= r; i++) {
            double u = x + i * spacing / SL_PROBE_MAP_SIZE, w = y + j * spacing / SL_PROBE_MAP_SIZE;
            double stored = u < 0 || u >= 1 || w < 0 || w >= 1
                                ? 1.0
                                : sl_probe_map_depth((sl_probe_map)(int)*map, (int)floor(u * SL_PROBE_MAP_SIZE),
                                                     (int)floor(w * SL_PROBE_MAP_SIZE));
            lit += !(z > stored);
            all++;
        }
    return (double)lit / all;
}

/* The grid's samples another distance apart than one texel (a scale of 1.5, as some published
 * kernels take, or a fixed step in uv): the spacings, in texels of the 64-texel map, at which a grid
 * gives every failing row what the student's gives. One map size cannot tell a scale from a uv
 * step, so the message names both. */
int sl_grid_spacing_verdict(const sl_verdict_rows *v, char *text, size_t n) {
    if (strcmp(v->f->name, "pcf_grid") != 0) return -1;
    /* samples `radius` texels apart, on every row (right at radius 1 alone): the offsets scaled by the radius too,
     * as if it were a spread like the Poisson disk's radius_texels */
    int by_radius = -1, wider = 0;
    bool every = true;
    for (int r = 0; r < v->k->rows && every; r++) {
        const float *radius = _sl_param(v->f, v->k->inputs[r], "radius");
        if (!radius) return -1;
        /* a row the model does not give as the contract does (outside the frustum) says nothing */
        double tolerance = _sl_row_tolerance(v, r) + 1e-4, contract = _sl_grid_with_spacing(v->f, v->k->inputs[r], 1);
        if (isnan(contract) || !_sl_near(_sl_want(v, r, 0), contract, tolerance)) continue;
        double model = _sl_grid_with_spacing(v->f, v->k->inputs[r], *radius);
        every = !isnan(model) && _sl_near(_sl_got(v, r, 0), model, tolerance);
        if (_sl_failed(v, r)) {
            wider += *radius >= 2;
            if (by_radius < 0) by_radius = r;
        }
    }
    if (every && by_radius >= 0 && wider > 0) {
        snprintf(text, n, "the grid's samples are radius texels apart, not one: on every row it answers as a grid whose "
                          "offsets are multiplied by the radius as well as by the texel (right at radius 1 alone) — "
                          "the loops run from -radius to radius, and each offset is (x, y) * texel, the radius only "
                          "bounding the loops");
        sl_verdict_predicts(v, 1u << SL_SYMPTOM_WIDE_PENUMBRA | 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT |
                                   1u << SL_SYMPTOM_GROSS | SL_PREDICTS_EVERY_SETTING);
        return by_radius;
    }
    double lo = INFINITY, hi = -INFINITY;
    int first = -1;
    for (int step = 25; step <= 400; step++) {
        double spacing = step / 100.0;
        if (step == 100) continue;
        bool all = true;
        int failing = 0;
        for (int r = 0; r < v->k->rows && all; r++) {
            if (!_sl_failed(v, r)) continue;
            failing++;
            double tolerance = v->k->row_tolerance[r] > 0 ? v->k->row_tolerance[r] : v->k->tolerance;
            double model = _sl_grid_with_spacing(v->f, v->k->inputs[r], spacing);
            all = !isnan(model) && _sl_near(_sl_got(v, r, 0), model, tolerance + 1e-4);
            if (all && first < 0) first = r;
        }
        if (all && failing > 0) {
            lo = fmin(lo, spacing);
            hi = fmax(hi, spacing);
        }
    }
    if (first < 0 || !(lo <= hi) || (lo < 1 && hi > 1)) return -1;
    bool wide = lo > 1;
    char spacing[64];
    if (hi - lo < 0.05) snprintf(spacing, sizeof spacing, "%.2g", lo);
    else snprintf(spacing, sizeof spacing, "%.2g to %.2g", lo, hi);
    snprintf(text, n, "the kernel is too %s: its samples are %s texels apart on this 64-texel map, not one — offset "
                      "(x, y) times the texel, 1.0 / textureSize(map, 0), and nothing else: no scale (some published "
                      "kernels spread a 3x3 grid 1.5 texels apart) and no fixed step in uv",
             wide ? "wide" : "narrow", spacing);
    sl_verdict_predicts(v, (wide ? 1u << SL_SYMPTOM_WIDE_PENUMBRA : 1u << SL_SYMPTOM_NARROW_PENUMBRA) |
                               1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT | 1u << SL_SYMPTOM_GROSS |
                               SL_PREDICTS_EVERY_SETTING);
    return first;
}
