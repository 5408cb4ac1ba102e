#define _POSIX_C_SOURCE 200809L
#include "sl_case.h"

#include "sl_json.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_case_probe.h"
#include "sl_params.h"

/* Default tolerances, from the renderer noise measured on the solutions
 * (scripts/measure-renderer-noise.sh; grader/cases/README.md has the table):
 * under the neighbourhood compare, other CPU features and softpipe move at
 * most 0.006% of pixels by more than 0.02, and the mean by 1e-5. */
static const struct {
    const char *name;
    const char *reference;
    double threshold, fail_fraction, epsilon, mean;
} _sl_kinds[SL_CHECK_KIND_COUNT] = {
    [SL_CHECK_FBO] = {"fbo", NULL, 0, 0, 0, 0},
    /* depth in [0,1]; renderer noise moves silhouettes by a texel, absorbed by the neighbourhood */
    [SL_CHECK_DEPTH_MAP] = {"depth_map", "depth_map.exr", 0.002, 0.005, 0, 0.0005},
    [SL_CHECK_MATRICES] = {"matrices", "matrices.json", 0, 0, 1e-3, 0},
    [SL_CHECK_VISIBILITY] = {"visibility", "visibility.exr", 0.05, 0.0025, 0, 0.002},
    [SL_CHECK_IMAGE] = {"image", "image.png", 0.1, 0.01, 0, 0.005},
    /* threshold here: the allowed width difference, as a fraction of the reference's (at least 2 px) */
    [SL_CHECK_PENUMBRA] = {"penumbra", "visibility.exr", 0.35, 0, 0, 0},
    [SL_CHECK_PROBE] = {"probe", ".probe.json", 0, 0, 0, 0},
    /* moments: the same rasterised depths on every renderer; 1e-4 is far above float noise. The
     * format's precision is checked by rule (the neighbourhood compare forgives quantisation). */
    [SL_CHECK_MOMENTS] = {"moments", "moments.exr", 1e-4, 0.005, 0, 2e-5},
    [SL_CHECK_MOMENTS_BLURRED] = {"moments_blurred", "moments_blurred.exr", 1e-4, 0.005, 0, 2e-5},
    /* threshold: visibility above it in the reference's umbra is light bleeding */
    [SL_CHECK_BLEEDING] = {"bleeding", "visibility.exr", 0.1, 0, 0, 0},
    /* cascade indices are whole numbers: a pixel differs when its index does */
    [SL_CHECK_CASCADE_INDEX] = {"cascade_index", "cascade_index.exr", 0.5, 0.01, 0, 0.02},
    /* threshold here: the largest flicker score, of world-fixed receiver pixels changing per frame */
    [SL_CHECK_FLICKER] = {"flicker", "flicker.exr", 0.002, 0, 0, 0},
    /* distance / far in [0,1], as a depth map: silhouettes may move by a texel */
    [SL_CHECK_CUBE_FACE] = {"cube_face", ".exr", 0.002, 0.005, 0, 0.0005},
};

const char *sl_check_kind_name(sl_check_kind kind) { return _sl_kinds[kind].name; }

void sl_check_kind_defaults(sl_check_kind kind, double *threshold, double *fail_fraction, double *epsilon,
                            double *mean_tolerance) {
    *threshold = _sl_kinds[kind].threshold;
    *fail_fraction = _sl_kinds[kind].fail_fraction;
    *epsilon = _sl_kinds[kind].epsilon;
    *mean_tolerance = _sl_kinds[kind].mean;
}

static const char *const _sl_symptom_names[SL_SYMPTOM_COUNT] = {
    [SL_SYMPTOM_NO_SHADOWS] = "no_shadows",         [SL_SYMPTOM_MISSING_SHADOW] = "missing_shadow",
    [SL_SYMPTOM_EXTRA_SHADOW] = "extra_shadow",     [SL_SYMPTOM_ACNE] = "acne",
    [SL_SYMPTOM_DETACHED] = "detached",             [SL_SYMPTOM_SWAPPED] = "swapped",
    [SL_SYMPTOM_HARD_EDGES] = "hard_edges",         [SL_SYMPTOM_STALE_DEPTH] = "stale_depth",
    [SL_SYMPTOM_TOO_DARK] = "too_dark",             [SL_SYMPTOM_TOO_LIGHT] = "too_light",
    [SL_SYMPTOM_NARROW_PENUMBRA] = "narrow_penumbra", [SL_SYMPTOM_WIDE_PENUMBRA] = "wide_penumbra",
    [SL_SYMPTOM_GROSS] = "gross",
};

const char *sl_symptom_name(sl_symptom symptom) {
    return (unsigned)symptom < SL_SYMPTOM_COUNT ? _sl_symptom_names[symptom] : "?";
}

/* "hint_when": one symptom's name, or an array of them. */
static bool _sl_hint_when(const sl_case *c, sl_check *k, const cJSON *json, char *err, size_t n) {
    const cJSON *when = cJSON_GetObjectItemCaseSensitive(json, "hint_when"), *item;
    if (!when) return true;
    bool ok = cJSON_IsString(when) || (cJSON_IsArray(when) && cJSON_GetArraySize(when) > 0);
    if (cJSON_IsString(when)) {
        ok = false;
        for (int s = 0; s < SL_SYMPTOM_COUNT; s++)
            if (strcmp(when->valuestring, _sl_symptom_names[s]) == 0) {
                k->hint_when |= 1u << s;
                ok = true;
            }
    } else {
        cJSON_ArrayForEach(item, when) {
            bool known = false;
            for (int s = 0; cJSON_IsString(item) && s < SL_SYMPTOM_COUNT; s++)
                if (strcmp(item->valuestring, _sl_symptom_names[s]) == 0) {
                    k->hint_when |= 1u << s;
                    known = true;
                }
            ok &= known;
        }
    }
    if (!ok) {
        char names[400] = "";
        for (int s = 0; s < SL_SYMPTOM_COUNT; s++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", s ? ", " : "", _sl_symptom_names[s]);
        snprintf(err, n, "%s: checks \"%s\": \"hint_when\" must name symptoms: %s", c->path, k->name, names);
    }
    return ok;
}

bool sl_check_reference_file(const sl_check *k, char *out, size_t n) {
    const char *file = _sl_kinds[k->kind].reference;
    if (!file) return false;
    if (k->kind == SL_CHECK_PROBE || k->kind == SL_CHECK_CUBE_FACE)
        snprintf(out, n, "%s%s", k->name, file); /* one file per probe check, per face */
    else snprintf(out, n, "%s", file);
    return true;
}
const char *sl_check_capture_name(const sl_case *c, const sl_check *k) {
    if (k->kind == SL_CHECK_PROBE) return sl_capture_name(SL_CAPTURE_PROBE + (int)(k - c->checks));
    if (k->kind == SL_CHECK_CUBE_FACE) return sl_capture_name(SL_CAPTURE_CUBE_FACE + k->face);
    return k->kind == SL_CHECK_PENUMBRA || k->kind == SL_CHECK_BLEEDING ? "visibility" : _sl_kinds[k->kind].name;
}

static uint32_t _sl_check_captures_of_kind(const sl_case *c, const sl_check *k);

uint32_t sl_check_captures(const sl_case *c, const sl_check *k) {
    /* lab 7: which way the cube map was drawn (six passes or one layered pass), for the messages */
    if (c->lab == 7 && k->kind != SL_CHECK_PROBE) return _sl_check_captures_of_kind(c, k) | 1u << SL_CAPTURE_PATH;
    return _sl_check_captures_of_kind(c, k);
}

static uint32_t _sl_check_captures_of_kind(const sl_case *c, const sl_check *k) {
    switch (k->kind) {
    case SL_CHECK_PROBE: return 1u << (SL_CAPTURE_PROBE + (int)(k - c->checks));
    case SL_CHECK_FBO: return 1u << SL_CAPTURE_FBO;
    case SL_CHECK_DEPTH_MAP: return 1u << SL_CAPTURE_DEPTH_MAP;
    case SL_CHECK_MATRICES: return 1u << SL_CAPTURE_MATRICES;
    case SL_CHECK_VISIBILITY:
        /* from lab 2 on, acne is told from shadow on the surfaces that face the light */
        /* lab 5: the moments target's format too, the first suspect of a VSM picture that is off */
        /* and the blurred moments, where a target cleared to (0, 0) shows */
        /* and what each of its passes drew, so a message can say which pass departs first */
        return (1u << SL_CAPTURE_VISIBILITY) | (c->lab >= 2 ? 1u << SL_CAPTURE_LIT_MASK : 0) |
               (c->lab == 5 ? (1u << SL_CAPTURE_MOMENTS_TARGET) | (1u << SL_CAPTURE_MOMENTS_BLURRED) |
                                  (1u << SL_CAPTURE_MOMENTS_PASSES)
                            : 0);
    case SL_CHECK_IMAGE: return 1u << SL_CAPTURE_IMAGE;
    case SL_CHECK_PENUMBRA: return 1u << SL_CAPTURE_VISIBILITY;
    case SL_CHECK_MOMENTS: return (1u << SL_CAPTURE_MOMENTS) | (1u << SL_CAPTURE_MOMENTS_TARGET);
    case SL_CHECK_MOMENTS_BLURRED:
        return (1u << SL_CAPTURE_MOMENTS_BLURRED) | (1u << SL_CAPTURE_MOMENTS_TARGET) | (1u << SL_CAPTURE_MOMENTS_PASSES);
    case SL_CHECK_BLEEDING:
        return (1u << SL_CAPTURE_VISIBILITY) | (1u << SL_CAPTURE_VISIBILITY_UNREDUCED) | (1u << SL_CAPTURE_LIT_MASK) |
               (1u << SL_CAPTURE_MOMENTS_TARGET) | (1u << SL_CAPTURE_MOMENTS_BLURRED);
    case SL_CHECK_CASCADE_INDEX: return 1u << SL_CAPTURE_CASCADE_INDEX;
    case SL_CHECK_FLICKER: return (1u << SL_CAPTURE_FLICKER) | (1u << SL_CAPTURE_LIT_MASK);
    case SL_CHECK_CUBE_FACE: return 1u << (SL_CAPTURE_CUBE_FACE + k->face);
    default: return 0;
    }
}

const char *sl_criterion_percent(double fraction, char *out, size_t n) {
    snprintf(out, n, "%.4g", 100 * fraction); /* four digits: 100 * 0.0025 is 0.25 give or take 1e-17 */
    return out;
}

bool sl_case_name_valid(const char *name) {
    if (!*name) return false;
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') || *p == '_' || *p == '-'))
            return false;
    return true;
}

static bool _sl_params(sl_case *c, const cJSON *json, char *err, size_t n) {
    sl_render_params_defaults(&c->params);
    c->params.lab = c->lab;
    c->params.output = SL_OUTPUT_VISIBILITY;
    if (c->lab < 3) c->params.bias.mode = SL_BIAS_CONSTANT;
    if (c->lab < 4) c->params.filter.mode = SL_FILTER_NONE;
    c->params.vsm.map_size = 0; /* lab 5's moments: the case's shadow_map_size */
    if (!json) return true;
    if (!cJSON_IsObject(json)) {
        snprintf(err, n, "%s: \"params\" must be an object", c->path);
        return false;
    }
    sl_bias_settings *b = &c->params.bias;
    sl_filter_settings *f = &c->params.filter;
    double size = c->params.shadow_map_size, constant = b->constant, slope = b->slope, max_bias = b->max_bias;
    double factor = b->polygon_offset_factor, units = b->polygon_offset_units, offset = b->normal_offset;
    double radius = f->grid_radius, poisson = f->poisson_radius;
    sl_vsm_settings *v = &c->params.vsm;
    double blur = v->blur_radius, min_variance = v->min_variance, bleeding = v->bleeding;
    if (!sl_json_number(json, "shadow_map_size", &size, 16, 4096, c->path, err, n) ||
        !sl_json_number(json, "depth_bias", &constant, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "slope_bias", &slope, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "max_bias", &max_bias, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "polygon_offset_factor", &factor, -100, 100, c->path, err, n) ||
        !sl_json_number(json, "polygon_offset_units", &units, -10000, 10000, c->path, err, n) ||
        !sl_json_number(json, "normal_offset", &offset, 0, 100, c->path, err, n) ||
        !sl_json_number(json, "grid_radius", &radius, 0, 16, c->path, err, n) ||
        !sl_json_number(json, "poisson_radius", &poisson, 0, 256, c->path, err, n) ||
        !sl_json_number(json, "blur_radius", &blur, 0, 32, c->path, err, n) ||
        !sl_json_number(json, "min_variance", &min_variance, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "bleeding", &bleeding, 0, 0.99, c->path, err, n))
        return false;
    v->blur_radius = (int)blur;
    v->min_variance = (float)min_variance;
    v->bleeding = (float)bleeding;
    c->params.shadow_map_size = (int)size;
    b->constant = (float)constant;
    b->slope = (float)slope;
    b->max_bias = (float)max_bias;
    b->polygon_offset_factor = (float)factor;
    b->polygon_offset_units = (float)units;
    b->normal_offset = (float)offset;
    f->grid_radius = (int)radius;
    f->poisson_radius = (float)poisson;
    const char *mode = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "bias_mode"));
    if (mode && !sl_bias_mode_parse(mode, &b->mode)) {
        snprintf(err, n, "%s: \"bias_mode\" must be none, constant, slope, polygon-offset, front-culling, normal-offset or midpoint", c->path);
        return false;
    }
    if (!mode && c->lab < 3) b->mode = SL_BIAS_CONSTANT; /* labs 1-2: lab 2's constant bias */
    mode = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "filter"));
    if (mode && !sl_filter_mode_parse(mode, &f->mode)) {
        snprintf(err, n, "%s: \"filter\" must be none, hardware, grid, poisson or pcss", c->path);
        return false;
    }
    if (!mode && c->lab < 4) f->mode = SL_FILTER_NONE;
    /* lab 6: "cascades": {"count", "lambda", "max_distance", "caster_margin"} */
    const cJSON *cascades = cJSON_GetObjectItemCaseSensitive(json, "cascades");
    if (cascades) {
        sl_cascade_params *cp = &c->params.cascades;
        double count = cp->count, lambda = cp->lambda, max_distance = cp->max_distance, margin = cp->caster_margin;
        double band = cp->blend_band;
        if (!cJSON_IsObject(cascades) ||
            !sl_json_number(cascades, "count", &count, 1, SL_MAX_CASCADES, c->path, err, n) ||
            !sl_json_number(cascades, "lambda", &lambda, 0, 1, c->path, err, n) ||
            !sl_json_number(cascades, "max_distance", &max_distance, 0, 1e6, c->path, err, n) ||
            !sl_json_number(cascades, "caster_margin", &margin, 0, 1e6, c->path, err, n) ||
            !sl_json_number(cascades, "blend_band", &band, 0, 1, c->path, err, n)) {
            if (!cJSON_IsObject(cascades)) snprintf(err, n, "%s: \"cascades\" must be an object", c->path);
            return false;
        }
        cp->count = (int)count;
        cp->lambda = (float)lambda;
        cp->max_distance = (float)max_distance;
        cp->caster_margin = (float)margin;
        cp->blend_band = (float)band;
    }
    /* lab 7 */
    sl_cube_settings *cube = &c->params.cube;
    double cube_size = cube->map_size, cube_bias = cube->bias, soft_radius = cube->soft_radius;
    if (!sl_json_number(json, "cube_map_size", &cube_size, 16, 2048, c->path, err, n) ||
        !sl_json_number(json, "cube_bias", &cube_bias, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "soft_radius", &soft_radius, 0, 100, c->path, err, n))
        return false;
    cube->map_size = (int)cube_size;
    cube->bias = (float)cube_bias;
    cube->soft_radius = (float)soft_radius;
    const cJSON *soft = cJSON_GetObjectItemCaseSensitive(json, "soft");
    if (soft) cube->soft = cJSON_IsTrue(soft);
    mode = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "cube_pass"));
    if (mode && !sl_cube_pass_parse(mode, &cube->pass)) {
        snprintf(err, n, "%s: \"cube_pass\" must be auto, six or layered", c->path);
        return false;
    }
    const cJSON *compare = cJSON_GetObjectItemCaseSensitive(json, "compare");
    if (compare) {
        const char *s = cJSON_GetStringValue(compare);
        if (s && strcmp(s, "manual") == 0) c->params.compare = SL_COMPARE_MANUAL;
        else if (s && strcmp(s, "hardware") == 0) c->params.compare = SL_COMPARE_HARDWARE;
        else {
            snprintf(err, n, "%s: \"compare\" must be \"manual\" or \"hardware\"", c->path);
            return false;
        }
    }
    return true;
}

static bool _sl_check(sl_case *c, sl_check *k, const cJSON *json, int index, char *err, size_t n) {
    memset(k, 0, sizeof *k);
    const char *kind = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "kind"));
    int found = -1;
    for (int i = 0; kind && i < SL_CHECK_KIND_COUNT; i++)
        if (strcmp(kind, _sl_kinds[i].name) == 0) found = i;
    if (found < 0) {
        snprintf(err, n, "%s: checks[%d]: \"kind\" must be fbo, depth_map, matrices, visibility, image, penumbra, probe, "
                    "moments, moments_blurred, bleeding, cascade_index, flicker or cube_face",
                 c->path, index);
        return false;
    }
    k->kind = (sl_check_kind)found;
    k->threshold = _sl_kinds[found].threshold;
    k->fail_fraction = _sl_kinds[found].fail_fraction;
    k->epsilon = _sl_kinds[found].epsilon;
    k->mean_tolerance = _sl_kinds[found].mean;
    const char *name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "name"));
    snprintf(k->name, sizeof k->name, "%s", name ? name : kind);
    if (!sl_case_name_valid(k->name)) {
        snprintf(err, n, "%s: checks[%d]: \"name\" must be letters, digits, '_' and '-': it names a reference file",
                 c->path, index);
        return false;
    }
    for (int i = 0; i < index; i++)
        if (strcmp(c->checks[i].name, k->name) == 0) {
            snprintf(err, n, "%s: checks[%d]: two checks are named \"%s\"", c->path, index, k->name);
            return false;
        }
    k->bonus = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(json, "bonus"));
    const char *hint = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "hint"));
    if (hint) snprintf(k->hint, sizeof k->hint, "%s", hint);
    if (!_sl_hint_when(c, k, json, err, n)) return false;
    k->points = -1;
    double percent = k->fail_fraction * 100;
    if (!sl_json_number(json, "points", &k->points, 0, 1000, c->path, err, n) ||
        !sl_json_number(json, "threshold", &k->threshold, 0, 1e9, c->path, err, n) ||
        !sl_json_number(json, "fail_percent", &percent, 0, 100, c->path, err, n) ||
        !sl_json_number(json, "epsilon", &k->epsilon, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "mean_tolerance", &k->mean_tolerance, 0, 1, c->path, err, n) ||
        !sl_json_number(json, "binarise", &k->binarise, 0, 1, c->path, err, n))
        return false;
    k->fail_fraction = percent / 100;
    if (k->points < 0) {
        snprintf(err, n, "%s: checks[%d] (%s) has no \"points\"", c->path, index, k->name);
        return false;
    }
    const cJSON *probes = cJSON_GetObjectItemCaseSensitive(json, "probes"), *p;
    if (k->kind == SL_CHECK_PENUMBRA &&
        (!cJSON_IsArray(probes) || cJSON_GetArraySize(probes) < 1 || cJSON_GetArraySize(probes) > SL_CHECK_MAX_PROBES)) {
        snprintf(err, n, "%s: checks[%d] (%s) needs \"probes\": 1..%d lines {\"name\", \"from\": [x, y], \"to\": [x, y]}",
                 c->path, index, k->name, SL_CHECK_MAX_PROBES);
        return false;
    }
    if (k->kind == SL_CHECK_PROBE && !sl_case_probe_check(c, k, json, err, n)) return false;
    if (k->kind == SL_CHECK_CUBE_FACE) {
        const char *face = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "face"));
        k->face = face ? sl_cube_face_parse(face) : -1;
        if (k->face < 0) {
            snprintf(err, n, "%s: checks[%d] (%s) needs \"face\": \"+x\", \"-x\", \"+y\", \"-y\", \"+z\" or \"-z\"",
                     c->path, index, k->name);
            return false;
        }
    }
    const cJSON *probe_list = k->kind == SL_CHECK_PENUMBRA ? probes : NULL;
    cJSON_ArrayForEach(p, probe_list) {
        sl_probe *probe = &k->probes[k->probe_count];
        const char *pname = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(p, "name"));
        snprintf(probe->name, sizeof probe->name, "%s", pname ? pname : "probe");
        const cJSON *from = cJSON_GetObjectItemCaseSensitive(p, "from"), *to = cJSON_GetObjectItemCaseSensitive(p, "to");
        bool ok = cJSON_GetArraySize(from) == 2 && cJSON_GetArraySize(to) == 2;
        for (int i = 0; ok && i < 2; i++) {
            ok = cJSON_IsNumber(cJSON_GetArrayItem(from, i)) && cJSON_IsNumber(cJSON_GetArrayItem(to, i));
            if (ok) {
                probe->from[i] = (float)cJSON_GetArrayItem(from, i)->valuedouble;
                probe->to[i] = (float)cJSON_GetArrayItem(to, i)->valuedouble;
            }
        }
        if (!ok) {
            snprintf(err, n, "%s: checks[%d] (%s): probes[%d] needs \"from\": [x, y] and \"to\": [x, y]", c->path, index,
                     k->name, k->probe_count);
            return false;
        }
        k->probe_count++;
    }
    return true;
}

bool sl_case_load(sl_case *c, const char *path, char *err, size_t n) {
    memset(c, 0, sizeof *c);
    snprintf(c->path, sizeof c->path, "%s", path);
    cJSON *json = sl_json_load_file(path, "case", err, n);
    if (!json) return false;
    bool ok = false;
    const char *name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "name"));
    const char *title = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "title"));
    const char *scene = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "scene"));
    const cJSON *lab = cJSON_GetObjectItemCaseSensitive(json, "lab");
    const cJSON *checks = cJSON_GetObjectItemCaseSensitive(json, "checks");
    double width = 256, height = 256, timeout = 20, memory = 4096;
    if (!name || !*name) {
        snprintf(err, n, "%s: missing \"name\"", path);
    } else if (!sl_case_name_valid(name) || strlen(name) >= sizeof c->name) {
        snprintf(err, n, "%s: \"name\" must be letters, digits, '_' and '-' (at most %zu): it names folders and files",
                 path, sizeof c->name - 1);
    } else if (!cJSON_IsNumber(lab) || lab->valueint < 0 || lab->valueint > SL_LAB_COUNT) {
        /* 0: the technique a build adds (its runner's slot 0, docs/adding-a-technique.md) */
        snprintf(err, n, "%s: \"lab\" must be a number 1..%d (0: the technique a build adds)", path, SL_LAB_COUNT);
    } else if (!cJSON_IsArray(checks) || cJSON_GetArraySize(checks) < 1 ||
               cJSON_GetArraySize(checks) > SL_CASE_MAX_CHECKS) {
        snprintf(err, n, "%s: \"checks\" must be an array of 1..%d checks", path, SL_CASE_MAX_CHECKS);
    } else if (sl_json_number(json, "width", &width, 16, 2048, path, err, n) &&
               sl_json_number(json, "height", &height, 16, 2048, path, err, n) &&
               sl_json_number(json, "timeout", &timeout, 1, 3600, path, err, n) &&
               sl_json_number(json, "memory_mb", &memory, 256, 65536, path, err, n)) {
        snprintf(c->name, sizeof c->name, "%s", name);
        snprintf(c->title, sizeof c->title, "%s", title ? title : name);
        c->lab = lab->valueint;
        c->width = (int)width;
        c->height = (int)height;
        c->timeout_seconds = timeout;
        c->memory_mb = memory;
        char scene_err[1024];
        ok = true;
        if (scene) ok = sl_scene_load(&c->scene, scene, scene_err, sizeof scene_err);
        if (!ok) snprintf(err, n, "%s: scene %s", path, scene_err);
        const cJSON *light = cJSON_GetObjectItemCaseSensitive(json, "light");
        if (ok && light) ok = sl_light_from_json(&c->scene.light, light, path, err, n);
        const cJSON *camera = cJSON_GetObjectItemCaseSensitive(json, "camera");
        if (ok && camera) ok = sl_camera_from_json(&c->scene.camera, camera, path, err, n);
        if (ok) ok = _sl_params(c, cJSON_GetObjectItemCaseSensitive(json, "params"), err, n);
        /* "light_path": per-frame changes to the light; the last frame is the one captured. */
        const cJSON *frames = cJSON_GetObjectItemCaseSensitive(json, "light_path");
        c->frame_lights[0] = c->scene.light;
        c->frame_count = scene ? 1 : 0; /* without a scene: probes only, no frame */
        if (ok && frames) {
            if (!cJSON_IsArray(frames) || cJSON_GetArraySize(frames) < 1 ||
                cJSON_GetArraySize(frames) > SL_CASE_MAX_FRAMES) {
                snprintf(err, n, "%s: \"light_path\" must be an array of 1..%d lights", path, SL_CASE_MAX_FRAMES);
                ok = false;
            } else {
                c->frame_count = 0;
                const cJSON *f;
                cJSON_ArrayForEach(f, frames) {
                    sl_light l = c->scene.light;
                    if (!(ok = sl_light_from_json(&l, f, path, err, n))) break;
                    c->frame_lights[c->frame_count++] = l;
                }
            }
        }
        /* lab 6's "camera_path": per-frame changes to the camera the cascades are
         * fitted to; the picture is drawn from "camera", so its pixels stay put. */
        const cJSON *cameras = cJSON_GetObjectItemCaseSensitive(json, "camera_path");
        if (ok && cameras) {
            if (!cJSON_IsArray(cameras) || cJSON_GetArraySize(cameras) < 2 ||
                cJSON_GetArraySize(cameras) > SL_CASE_MAX_FRAMES || (frames && cJSON_GetArraySize(frames) != cJSON_GetArraySize(cameras))) {
                snprintf(err, n, "%s: \"camera_path\" must be an array of 2..%d cameras (as many as \"light_path\" has lights)",
                         path, SL_CASE_MAX_FRAMES);
                ok = false;
            } else {
                int count = 0;
                const cJSON *f;
                cJSON_ArrayForEach(f, cameras) {
                    sl_camera cam = c->scene.camera;
                    if (!(ok = sl_camera_from_json(&cam, f, path, err, n))) break;
                    c->frame_cameras[count] = cam;
                    if (!frames) c->frame_lights[count] = c->scene.light;
                    count++;
                }
                c->frame_count = count;
                c->camera_path = true;
            }
        }
        const cJSON *item;
        cJSON_ArrayForEach(item, checks) {
            if (!ok) break;
            ok = _sl_check(c, &c->checks[c->check_count], item, c->check_count, err, n);
            c->check_count += ok;
        }
        for (int i = 0; ok && !scene && i < c->check_count; i++)
            if (c->checks[i].kind != SL_CHECK_PROBE) {
                snprintf(err, n, "%s: missing \"scene\" (only a case of probe checks goes without one)", path);
                ok = false;
            }
    }
    cJSON_Delete(json);
    return ok;
}
