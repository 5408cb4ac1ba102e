#define _GNU_SOURCE
#include "sl_hidden.h"

#include <errno.h>
#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sl_grade.h"
#include "sl_manifest.h"
#include "sl_sandbox.h"
#include "sl_probe.h"
#include "sl_scene.h"

/* ---- the bounds of every change (degrees, world units, factors) ---- */

#define _SL_LIGHT_TURN 20.0f      /* about the vertical */
#define _SL_LIGHT_TILT 3.0f       /* elevation: small, so a grazing light stays grazing */
#define _SL_LIGHT_ELEVATION_MIN 5.0f
#define _SL_LIGHT_ELEVATION_MAX 85.0f
#define _SL_POINT_LIGHT_MOVE 0.3f
#define _SL_CAMERA_TURN 15.0f
#define _SL_CAMERA_TILT 5.0f
#define _SL_CAMERA_ELEVATION_MIN 10.0f
#define _SL_CAMERA_ELEVATION_MAX 80.0f
#define _SL_CAMERA_ZOOM 0.08f     /* distance x [1 - z, 1 + z] */
#define _SL_OBJECTS_MOVE 0.4f
#define _SL_OBJECTS_TURN 15.0f
#define _SL_PROBE_MARGIN 4.0f     /* carried probe lines stay this far inside the image (pixels) */
#define _SL_CAMERA_TRIES 16
static const float _sl_map_factors[] = {0.75f, 1.0f, 1.25f, 1.5f};
#define _SL_MAP_FACTOR_COUNT ((int)(sizeof _sl_map_factors / sizeof _sl_map_factors[0]))

bool sl_hidden_parse_seed(const char *text, uint64_t *seed) {
    if (!text || !*text || strlen(text) > 20) return false;
    uint64_t v = 0;
    for (const char *p = text; *p; p++) {
        if (*p < '0' || *p > '9') return false;
        uint64_t digit = (uint64_t)(*p - '0');
        if (v > (UINT64_MAX - digit) / 10) return false;
        v = v * 10 + digit;
    }
    *seed = v;
    return true;
}

/* ---- splitmix64: one stream per case ---- */

typedef struct _sl_stream {
    uint64_t state;
} _sl_stream;

static uint64_t _sl_next(_sl_stream *s) {
    uint64_t z = (s->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* In [-1, 1]. */
static float _sl_signed(_sl_stream *s) { return (float)((double)(_sl_next(s) >> 11) * 0x1.0p-53 * 2.0 - 1.0); }

/* The case's stream: the seed and the case's name (FNV-1a), so a case's
 * variant does not depend on which other cases are graded with it. */
static _sl_stream _sl_case_stream(uint64_t seed, const char *name) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char *p = (const unsigned char *)name; *p; p++) h = (h ^ *p) * 0x100000001b3ull;
    _sl_stream s = {seed ^ h};
    _sl_next(&s);
    return s;
}

/* ---- geometry ---- */

static float _sl_clampf(float v, float lo, float hi) { return v < lo ? lo : v > hi ? hi : v; }

/* About the vertical axis through `centre`, as glm_rotate_y turns a model. */
static void _sl_turn_point(vec3 p, const vec3 centre, float degrees) {
    float a = glm_rad(degrees), c = cosf(a), s = sinf(a);
    float x = p[0] - centre[0], z = p[2] - centre[2];
    p[0] = centre[0] + x * c + z * s;
    p[2] = centre[2] - x * s + z * c;
}

/* A direction turned about the vertical and tilted in elevation; the
 * elevation stays in [lo, hi] degrees, or where it was if it started outside. */
static void _sl_turn_direction(vec3 d, float turn, float tilt, float lo, float hi) {
    float length = glm_vec3_norm(d);
    if (length <= 0) return;
    float elevation = asinf(_sl_clampf(-d[1] / length, -1, 1)), azimuth = atan2f(d[0], d[2]);
    float e0 = glm_deg(elevation);
    float e = _sl_clampf(e0 + tilt, fminf(lo, e0), fmaxf(hi, e0));
    elevation = glm_rad(e);
    float turned = azimuth + glm_rad(turn);
    d[0] = length * cosf(elevation) * sinf(turned);
    d[1] = -length * sinf(elevation);
    d[2] = length * cosf(elevation) * cosf(turned);
}

/* The ground: the largest level plane. Objects stand on it; probe lines lie on it. */
static int _sl_ground(const sl_scene *scene) {
    int ground = -1;
    float area = 0;
    for (int i = 0; i < scene->object_count; i++) {
        const sl_object *o = &scene->objects[i];
        bool level = o->rotation_deg[0] == 0 && o->rotation_deg[2] == 0;
        if (o->shape == SL_SHAPE_PLANE && level && o->size[0] * o->size[1] > area) {
            area = o->size[0] * o->size[1];
            ground = i;
        }
    }
    return ground;
}

/* Where a spot light's axis meets the ground (or the middle of its range). */
static void _sl_spot_aim(const sl_light *l, float ground_y, bool have_ground, vec3 aim) {
    float t = (l->near + l->far) * 0.5f;
    if (have_ground && l->direction[1] < -0.05f) t = (ground_y - l->position[1]) / l->direction[1];
    glm_vec3_scale((float *)l->direction, t, aim);
    glm_vec3_add(aim, (float *)l->position, aim);
}

static void _sl_change_light(sl_light *l, float turn, float tilt, const vec3 move, float ground_y, bool have_ground) {
    switch (l->type) {
    case SL_LIGHT_DIRECTIONAL:
        _sl_turn_direction(l->direction, turn, tilt, _SL_LIGHT_ELEVATION_MIN, _SL_LIGHT_ELEVATION_MAX);
        break;
    case SL_LIGHT_SPOT: {
        /* about the spot it lights: the cone covers the same ground, at the same distances */
        vec3 aim, origin = {0, 0, 0};
        _sl_spot_aim(l, ground_y, have_ground, aim);
        _sl_turn_point(l->position, aim, turn);
        _sl_turn_point(l->direction, origin, turn);
        break;
    }
    default: /* a point light: moved a little, level */
        l->position[0] += move[0];
        l->position[2] += move[2];
        break;
    }
}

/* Orbits the camera about its target. */
static void _sl_orbit(sl_camera *cam, float turn, float tilt, float zoom) {
    vec3 offset;
    glm_vec3_sub(cam->position, cam->target, offset);
    float r = glm_vec3_norm(offset);
    if (r <= 0) return;
    /* an offset is the reverse of a viewing direction: its elevation is that of -offset */
    vec3 view = {-offset[0], -offset[1], -offset[2]};
    _sl_turn_direction(view, turn, tilt, _SL_CAMERA_ELEVATION_MIN, _SL_CAMERA_ELEVATION_MAX);
    glm_vec3_scale(view, -zoom, offset);
    glm_vec3_add(cam->target, offset, cam->position);
}

/* A pixel (x right, y down, row 0 at the top) to the point of the ground it shows. */
static bool _sl_pixel_to_ground(const sl_camera *cam, int w, int h, const float pixel[2], float ground_y, vec3 out) {
    mat4 view, projection, clip, inverse;
    sl_camera_view(cam, view);
    sl_camera_projection(cam, (float)w / (float)h, projection);
    glm_mat4_mul(projection, view, clip);
    glm_mat4_inv(clip, inverse);
    float nx = (pixel[0] + 0.5f) / (float)w * 2 - 1, ny = 1 - (pixel[1] + 0.5f) / (float)h * 2;
    vec4 near_point = {nx, ny, -1, 1}, far_point = {nx, ny, 1, 1}, a, b;
    glm_mat4_mulv(inverse, near_point, a);
    glm_mat4_mulv(inverse, far_point, b);
    if (a[3] == 0 || b[3] == 0) return false;
    vec3 p = {a[0] / a[3], a[1] / a[3], a[2] / a[3]}, q = {b[0] / b[3], b[1] / b[3], b[2] / b[3]};
    float dy = q[1] - p[1];
    if (fabsf(dy) < 1e-6f) return false;
    float t = (ground_y - p[1]) / dy;
    if (t <= 0) return false;
    out[0] = p[0] + (q[0] - p[0]) * t;
    out[1] = ground_y;
    out[2] = p[2] + (q[2] - p[2]) * t;
    return true;
}

static bool _sl_ground_to_pixel(const sl_camera *cam, int w, int h, const vec3 point, float pixel[2]) {
    mat4 view, projection, clip;
    sl_camera_view(cam, view);
    sl_camera_projection(cam, (float)w / (float)h, projection);
    glm_mat4_mul(projection, view, clip);
    vec4 p = {point[0], point[1], point[2], 1}, c;
    glm_mat4_mulv(clip, p, c);
    if (c[3] <= 0) return false;
    pixel[0] = (c[0] / c[3] + 1) * 0.5f * (float)w - 0.5f;
    pixel[1] = (1 - c[1] / c[3]) * 0.5f * (float)h - 0.5f;
    return true;
}

static bool _sl_has_penumbra_check(const sl_case *c) {
    for (int k = 0; k < c->check_count; k++)
        if (c->checks[k].kind == SL_CHECK_PENUMBRA) return true;
    return false;
}

/* Carries every penumbra probe line from the old camera's image into the new
 * one's, through the ground; false if a line would leave the image. */
static bool _sl_carry_probe_lines(sl_case *c, const sl_camera *before, const sl_camera *after, float ground_y) {
    sl_check moved[SL_CASE_MAX_CHECKS];
    memcpy(moved, c->checks, sizeof moved);
    float lo = _SL_PROBE_MARGIN, hi_x = (float)c->width - 1 - _SL_PROBE_MARGIN, hi_y = (float)c->height - 1 - _SL_PROBE_MARGIN;
    for (int k = 0; k < c->check_count; k++) {
        if (moved[k].kind != SL_CHECK_PENUMBRA) continue;
        for (int i = 0; i < moved[k].probe_count; i++) {
            float *ends[2] = {moved[k].probes[i].from, moved[k].probes[i].to};
            for (int e = 0; e < 2; e++) {
                vec3 ground;
                if (!_sl_pixel_to_ground(before, c->width, c->height, ends[e], ground_y, ground) ||
                    !_sl_ground_to_pixel(after, c->width, c->height, ground, ends[e]))
                    return false;
                if (ends[e][0] < lo || ends[e][0] > hi_x || ends[e][1] < lo || ends[e][1] > hi_y) return false;
            }
        }
    }
    memcpy(c->checks, moved, sizeof moved);
    return true;
}

static int _sl_map_size(int original, int choice, const sl_case *c) {
    for (int i = 0; i < _SL_MAP_FACTOR_COUNT; i++) {
        float f = _sl_map_factors[(choice + i) % _SL_MAP_FACTOR_COUNT];
        int size = (int)lroundf((float)original * f / 8.0f) * 8;
        size = size < 16 ? 16 : size > 4096 ? 4096 : size;
        /* a map the size of the image would hide a viewport left at the image's size */
        if (size != c->width && size != c->height) return size;
    }
    return original;
}

/* ---- function probes: their rows' inputs, as each check's "vary" allows ---- */

/* One draw per case, check and group: every row of the check moves alike. */
static _sl_stream _sl_group_stream(uint64_t seed, const sl_case *c, const sl_check *k, const char *group) {
    char key[256];
    snprintf(key, sizeof key, "%s/%s/%s", c->name, k->name, group);
    return _sl_case_stream(seed, key);
}

/* Varies the rows of every probe check of c that says how; the number of checks varied. */
static int _sl_vary_probes(sl_case *c, uint64_t seed) {
    int varied = 0;
    for (int ki = 0; ki < c->check_count; ki++) {
        sl_check *k = &c->checks[ki];
        const sl_probe_function *f = k->kind == SL_CHECK_PROBE ? sl_probe_at(k->function) : NULL;
        if (!f) continue;
        bool any = false;
        int offset = 0;
        for (int p = 0; p < f->param_count; offset += sl_probe_type_size(f->params[p].type), p++) {
            const sl_probe_vary *v = &k->vary[p];
            if (v->kind == SL_VARY_NONE) continue;
            int size = sl_probe_type_size(f->params[p].type);
            bool integer = f->params[p].type == SL_PROBE_INT;
            _sl_stream s = _sl_group_stream(seed, c, k, v->group);
            /* the draw, before any row: the same for every row */
            float u = (_sl_signed(&s) + 1) * 0.5f, d[4];
            for (int j = 0; j < 4; j++) d[j] = _sl_signed(&s);
            int pick = v->pick_count ? (int)(_sl_next(&s) % (uint64_t)v->pick_count) : 0;
            for (int r = 0; r < k->rows; r++) {
                if ((k->row_keep[r] >> p) & 1u) continue;
                float *x = &k->inputs[r][offset];
                switch (v->kind) {
                case SL_VARY_SCALE: {
                    float factor = v->range[0] + (v->range[1] - v->range[0]) * u;
                    for (int j = 0; j < size; j++) x[j] *= factor;
                    break;
                }
                case SL_VARY_ADD:
                    for (int j = 0; j < size; j++) {
                        if (v->homogeneous && j == 3) continue;
                        x[j] += d[j] * v->range[j] * (v->homogeneous ? x[3] : 1.0f);
                    }
                    break;
                case SL_VARY_PICK:
                    for (int j = 0; j < size; j++) x[j] = v->picks[pick][j];
                    break;
                case SL_VARY_TURN: {
                    vec3 origin = {0, 0, 0};
                    _sl_turn_point(x, origin, d[0] * v->range[0]);
                    break;
                }
                default: break;
                }
                if (integer)
                    for (int j = 0; j < size; j++) x[j] = roundf(x[j]);
                any = true;
            }
        }
        varied += any;
    }
    return varied;
}

void sl_hidden_derive(sl_case *c, uint64_t seed, char *note, size_t n) {
    note[0] = '\0';
    int varied = _sl_vary_probes(c, seed);
    if (c->frame_count == 0) {
        snprintf(note, n, "%s", varied ? "function tables varied" : "function tables kept");
        return;
    }
    if (c->camera_path) { /* lab 6: a path measured in texels of the cascades it was written for */
        snprintf(note, n, "camera path kept");
        return;
    }
    _sl_stream s = _sl_case_stream(seed, c->name);
    /* Every number is drawn, in this order, whatever the case uses. */
    float light_turn = _sl_signed(&s) * _SL_LIGHT_TURN, light_tilt = _sl_signed(&s) * _SL_LIGHT_TILT;
    vec3 light_move = {_sl_signed(&s) * _SL_POINT_LIGHT_MOVE, 0, _sl_signed(&s) * _SL_POINT_LIGHT_MOVE};
    float camera_turn = _sl_signed(&s) * _SL_CAMERA_TURN, camera_tilt = _sl_signed(&s) * _SL_CAMERA_TILT;
    float camera_zoom = 1 + _sl_signed(&s) * _SL_CAMERA_ZOOM;
    float objects_dx = _sl_signed(&s) * _SL_OBJECTS_MOVE, objects_dz = _sl_signed(&s) * _SL_OBJECTS_MOVE;
    float objects_turn = _sl_signed(&s) * _SL_OBJECTS_TURN;
    int map_choice = (int)(_sl_next(&s) % (uint64_t)_SL_MAP_FACTOR_COUNT);

    sl_scene *scene = &c->scene;
    int ground = _sl_ground(scene);
    float ground_y = ground >= 0 ? scene->objects[ground].position[1] : 0;
    bool keep_geometry = _sl_has_penumbra_check(c);
    size_t used = 0;
#define _SL_NOTE(...)                                                          \
    do {                                                                       \
        if (used < n) used += (size_t)snprintf(note + used, n - used, __VA_ARGS__); \
    } while (0)

    if (keep_geometry) {
        _SL_NOTE("light and objects kept (penumbra probe lines)");
    } else {
        for (int f = 0; f < c->frame_count; f++)
            _sl_change_light(&c->frame_lights[f], light_turn, light_tilt, light_move, ground_y, ground >= 0);
        _sl_change_light(&scene->light, light_turn, light_tilt, light_move, ground_y, ground >= 0);
        if (scene->light.type == SL_LIGHT_DIRECTIONAL) _SL_NOTE("light turned %+.1f, tilted %+.1f deg", light_turn, light_tilt);
        else if (scene->light.type == SL_LIGHT_SPOT) _SL_NOTE("spot light turned %+.1f deg about its aim", light_turn);
        else _SL_NOTE("light moved (%+.2f, %+.2f)", light_move[0], light_move[2]);
        if (ground >= 0) {
            vec3 centre = {0, 0, 0};
            int moving = 0;
            for (int i = 0; i < scene->object_count; i++)
                if (i != ground) {
                    glm_vec3_add(centre, scene->objects[i].position, centre);
                    moving++;
                }
            if (moving > 0) {
                glm_vec3_scale(centre, 1.0f / (float)moving, centre);
                for (int i = 0; i < scene->object_count; i++) {
                    if (i == ground) continue;
                    sl_object *o = &scene->objects[i];
                    _sl_turn_point(o->position, centre, objects_turn);
                    o->position[0] += objects_dx;
                    o->position[2] += objects_dz;
                    o->rotation_deg[1] += objects_turn;
                }
                sl_scene_update(scene);
                _SL_NOTE("; objects moved (%+.2f, %+.2f), turned %+.1f deg", objects_dx, objects_dz, objects_turn);
            }
        } else {
            _SL_NOTE("; objects kept (no ground plane)");
        }
    }

    sl_camera before = scene->camera;
    _sl_orbit(&scene->camera, camera_turn, camera_tilt, camera_zoom);
    if (keep_geometry) {
        /* the lines must stay in the image: other draws of the same stream until they do */
        bool carried = ground >= 0 && _sl_carry_probe_lines(c, &before, &scene->camera, ground_y);
        for (int t = 1; !carried && ground >= 0 && t < _SL_CAMERA_TRIES; t++) {
            camera_turn = _sl_signed(&s) * _SL_CAMERA_TURN;
            camera_tilt = _sl_signed(&s) * _SL_CAMERA_TILT;
            camera_zoom = 1 + _sl_signed(&s) * _SL_CAMERA_ZOOM;
            scene->camera = before;
            _sl_orbit(&scene->camera, camera_turn, camera_tilt, camera_zoom);
            carried = _sl_carry_probe_lines(c, &before, &scene->camera, ground_y);
        }
        if (!carried) scene->camera = before;
        if (carried) _SL_NOTE("; camera turned %+.1f, tilted %+.1f deg, distance x%.2f, probe lines carried", camera_turn,
                              camera_tilt, camera_zoom);
        else _SL_NOTE("; camera kept");
    } else {
        _SL_NOTE("; camera turned %+.1f, tilted %+.1f deg, distance x%.2f", camera_turn, camera_tilt, camera_zoom);
    }
    int size = _sl_map_size(c->params.shadow_map_size, map_choice, c);
    if (size != c->params.shadow_map_size) _SL_NOTE("; shadow map %d (was %d)", size, c->params.shadow_map_size);
    else _SL_NOTE("; shadow map %d", size);
    c->params.shadow_map_size = size;
#undef _SL_NOTE
}

/* ---- the references ---- */

bool sl_hidden_open(sl_hidden *h, uint64_t seed, char *err, size_t n) {
    memset(h, 0, sizeof *h);
    h->seed = seed;
    snprintf(h->references_dir, sizeof h->references_dir, "/tmp/shadowlab-hidden-XXXXXX");
    if (!mkdtemp(h->references_dir)) { /* mode 0700 */
        snprintf(err, n, "cannot create a folder under /tmp for the hidden references: %s", strerror(errno));
        h->references_dir[0] = '\0';
        return false;
    }
    return true;
}

bool sl_hidden_render_references(const sl_hidden *h, const sl_case *cases, int count, const sl_run_options *base,
                                 volatile int *stop, char *err, size_t n) {
    /* The solutions are staff code: they render in the basic sandbox, as the
     * grader's user, so they need not be readable by the runners' uid. */
    sl_sandbox trusted;
    char why[512];
    if (!sl_sandbox_open(&trusted, SL_SANDBOX_BASIC, base->setups[0].runner, why, sizeof why)) {
        snprintf(err, n, "cannot start the solutions' runner: %s", why);
        return false;
    }
    sl_run_options run = *base;
    run.sandbox = &trusted;
    sl_case_result *results = calloc((size_t)count, sizeof *results);
    sl_manifest *manifest = sl_manifest_load(h->references_dir, true, why, sizeof why);
    bool ok = results && manifest;
    if (!ok) snprintf(err, n, "%s", results ? why : "out of memory");
    if (ok && !sl_run_cases(cases, count, &run, results, stop)) {
        snprintf(err, n, "stopped while rendering the hidden references: nothing was graded");
        ok = false;
    }
    for (int i = 0; ok && i < count; i++) {
        const sl_case_result *r = &results[i];
        if (!r->finished) {
            snprintf(err, n, "the solutions did not finish the hidden variant of %s: %s", cases[i].name,
                     r->staff_error[0] ? r->staff_error : r->error[0] ? r->error : r->protocol_error[0] ? r->protocol_error
                                          : r->timed_out           ? "timed out (raise --timeout)"
                                                                   : "crashed");
            ok = false;
            break;
        }
        if (r->renderer[0]) sl_manifest_set_renderer(manifest, r->renderer);
        for (int k = 0; ok && k < cases[i].check_count; k++)
            ok = sl_reference_write(h->references_dir, manifest, &cases[i], &cases[i].checks[k], r, err, n);
    }
    if (ok) ok = sl_manifest_save(manifest, h->references_dir, err, n);
    if (manifest) sl_manifest_free(manifest);
    for (int i = 0; results && i < count; i++) sl_case_result_free(&results[i]);
    free(results);
    sl_sandbox_close(&trusted);
    return ok;
}

static int _sl_remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw) {
    (void)st;
    (void)ftw;
    if (type == FTW_DP) rmdir(path);
    else unlink(path);
    return 0;
}

void sl_hidden_close(sl_hidden *h) {
    if (h->references_dir[0]) nftw(h->references_dir, _sl_remove_entry, 16, FTW_DEPTH | FTW_PHYS);
    h->references_dir[0] = '\0';
}
