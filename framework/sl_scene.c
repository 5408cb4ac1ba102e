#define _POSIX_C_SOURCE 200809L
#include "sl_scene.h"

#include <sys/stat.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_json.h"

#ifndef SL_SCENES_DIR
#define SL_SCENES_DIR "framework/scenes"
#endif

const char *sl_scenes_dir(void) {
    const char *env = getenv("SHADOWLAB_SCENES");
    return env && *env ? env : SL_SCENES_DIR;
}

const char *sl_light_type_name(sl_light_type type) {
    switch (type) {
    case SL_LIGHT_DIRECTIONAL: return "directional";
    case SL_LIGHT_SPOT: return "spot";
    case SL_LIGHT_POINT: return "point";
    }
    return "unknown";
}

/* Reads an array of n numbers; absent keeps `out`, wrong type is an error. */
static bool _sl_json_vec(const cJSON *obj, const char *key, float *out, int n, const char *origin, char *err,
                         size_t err_size) {
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item) return true;
    if (cJSON_IsNumber(item) && n == 1) {
        out[0] = (float)item->valuedouble;
        return true;
    }
    if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n) {
        snprintf(err, err_size, "%s: \"%s\" must be %s of %d numbers", origin, key, n == 1 ? "a number, not an array" : "an array", n);
        return false;
    }
    for (int i = 0; i < n; i++) {
        const cJSON *v = cJSON_GetArrayItem(item, i);
        if (!cJSON_IsNumber(v)) {
            snprintf(err, err_size, "%s: \"%s\"[%d] is not a number", origin, key, i);
            return false;
        }
        out[i] = (float)v->valuedouble;
    }
    return true;
}

static bool _sl_json_float(const cJSON *obj, const char *key, float *out, const char *origin, char *err, size_t n) {
    return _sl_json_vec(obj, key, out, 1, origin, err, n);
}

bool sl_light_from_json(sl_light *light, const cJSON *json, const char *origin, char *err, size_t err_size) {
    if (!cJSON_IsObject(json)) {
        snprintf(err, err_size, "%s: \"light\" must be an object", origin);
        return false;
    }
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(json, "type");
    if (type) {
        const char *t = cJSON_GetStringValue(type);
        if (t && strcmp(t, "directional") == 0) light->type = SL_LIGHT_DIRECTIONAL;
        else if (t && strcmp(t, "spot") == 0) light->type = SL_LIGHT_SPOT;
        else if (t && strcmp(t, "point") == 0) light->type = SL_LIGHT_POINT;
        else {
            snprintf(err, err_size, "%s: light \"type\" must be \"directional\", \"spot\" or \"point\"", origin);
            return false;
        }
    }
    bool ok = _sl_json_vec(json, "position", light->position, 3, origin, err, err_size) &&
              _sl_json_vec(json, "direction", light->direction, 3, origin, err, err_size) &&
              _sl_json_vec(json, "color", light->color, 3, origin, err, err_size) &&
              _sl_json_float(json, "intensity", &light->intensity, origin, err, err_size) &&
              _sl_json_float(json, "spot_angle", &light->spot_angle_deg, origin, err, err_size) &&
              _sl_json_float(json, "near", &light->near, origin, err, err_size) &&
              _sl_json_float(json, "far", &light->far, origin, err, err_size) &&
              _sl_json_float(json, "size", &light->size, origin, err, err_size);
    if (!ok) return false;
    /* A light may be aimed at a point instead of given a direction. */
    vec3 target;
    const cJSON *tgt = cJSON_GetObjectItemCaseSensitive(json, "target");
    if (tgt) {
        if (!_sl_json_vec(json, "target", target, 3, origin, err, err_size)) return false;
        glm_vec3_sub(target, light->position, light->direction);
    }
    if (glm_vec3_norm(light->direction) < 1e-6f) {
        snprintf(err, err_size, "%s: light direction is zero", origin);
        return false;
    }
    glm_vec3_normalize(light->direction);
    return true;
}

bool sl_camera_from_json(sl_camera *camera, const cJSON *json, const char *origin, char *err, size_t err_size) {
    if (!cJSON_IsObject(json)) {
        snprintf(err, err_size, "%s: \"camera\" must be an object", origin);
        return false;
    }
    return _sl_json_vec(json, "position", camera->position, 3, origin, err, err_size) &&
           _sl_json_vec(json, "target", camera->target, 3, origin, err, err_size) &&
           _sl_json_float(json, "fov", &camera->fov_deg, origin, err, err_size) &&
           _sl_json_float(json, "near", &camera->near, origin, err, err_size) &&
           _sl_json_float(json, "far", &camera->far, origin, err, err_size);
}

static bool _sl_object_from_json(sl_object *o, const cJSON *json, const char *origin, int index, char *err,
                                 size_t err_size) {
    static const struct { const char *name; sl_shape shape; } shapes[] = {
        {"plane", SL_SHAPE_PLANE}, {"box", SL_SHAPE_BOX}, {"sphere", SL_SHAPE_SPHERE},
        {"cylinder", SL_SHAPE_CYLINDER}, {"torus", SL_SHAPE_TORUS},
    };
    char where[300];
    snprintf(where, sizeof where, "%s: objects[%d]", origin, index);
    const char *shape = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "shape"));
    if (!shape) {
        snprintf(err, err_size, "%s: missing \"shape\"", where);
        return false;
    }
    size_t k = 0;
    while (k < sizeof shapes / sizeof shapes[0] && strcmp(shapes[k].name, shape) != 0) k++;
    if (k == sizeof shapes / sizeof shapes[0]) {
        snprintf(err, err_size, "%s: unknown shape \"%s\" (plane, box, sphere, cylinder, torus)", where, shape);
        return false;
    }
    memset(o, 0, sizeof *o);
    o->shape = shapes[k].shape;
    glm_vec3_copy((vec3){1, 1, 1}, o->size);
    glm_vec3_copy((vec3){0.8f, 0.8f, 0.8f}, o->color);
    bool ok = _sl_json_vec(json, "position", o->position, 3, where, err, err_size) &&
              _sl_json_vec(json, "rotation", o->rotation_deg, 3, where, err, err_size) &&
              _sl_json_vec(json, "color", o->color, 3, where, err, err_size);
    if (!ok) return false;
    switch (o->shape) {
    case SL_SHAPE_PLANE: {
        float subdivisions = 8;
        ok = _sl_json_vec(json, "size", o->size, 2, where, err, err_size) &&
             _sl_json_float(json, "subdivisions", &subdivisions, where, err, err_size);
        if (ok && (subdivisions < 1 || subdivisions > 256)) {
            snprintf(err, err_size, "%s: \"subdivisions\" must be 1..256", where);
            return false;
        }
        o->subdivisions = (int)subdivisions;
        break;
    }
    case SL_SHAPE_BOX: ok = _sl_json_vec(json, "size", o->size, 3, where, err, err_size); break;
    case SL_SHAPE_SPHERE: ok = _sl_json_float(json, "radius", &o->size[0], where, err, err_size); break;
    case SL_SHAPE_CYLINDER:
        ok = _sl_json_float(json, "radius", &o->size[0], where, err, err_size) &&
             _sl_json_float(json, "height", &o->size[1], where, err, err_size);
        break;
    case SL_SHAPE_TORUS:
        o->size[1] = 0.25f;
        ok = _sl_json_float(json, "radius", &o->size[0], where, err, err_size) &&
             _sl_json_float(json, "tube", &o->size[1], where, err, err_size);
        break;
    }
    if (ok && (o->size[0] <= 0 || o->size[1] <= 0 || o->size[2] <= 0)) {
        snprintf(err, err_size, "%s: sizes must be positive", where);
        return false;
    }
    return ok;
}

static void _sl_object_local_bounds(const sl_object *o, vec3 lo, vec3 hi) {
    const float *s = o->size;
    glm_vec3_zero(hi);
    switch (o->shape) {
    case SL_SHAPE_PLANE: glm_vec3_copy((vec3){s[0] / 2, 0, s[1] / 2}, hi); break;
    case SL_SHAPE_BOX: glm_vec3_copy((vec3){s[0] / 2, s[1] / 2, s[2] / 2}, hi); break;
    case SL_SHAPE_SPHERE: glm_vec3_copy((vec3){s[0], s[0], s[0]}, hi); break;
    case SL_SHAPE_CYLINDER: glm_vec3_copy((vec3){s[0], s[1] / 2, s[0]}, hi); break;
    case SL_SHAPE_TORUS: glm_vec3_copy((vec3){s[0] + s[1], s[1], s[0] + s[1]}, hi); break;
    }
    glm_vec3_negate_to(hi, lo);
}

void sl_scene_update(sl_scene *scene) {
    glm_vec3_copy((vec3){1e30f, 1e30f, 1e30f}, scene->bounds.min);
    glm_vec3_copy((vec3){-1e30f, -1e30f, -1e30f}, scene->bounds.max);
    for (int i = 0; i < scene->object_count; i++) {
        sl_object *o = &scene->objects[i];
        glm_mat4_identity(o->model);
        glm_translate(o->model, o->position);
        glm_rotate_y(o->model, glm_rad(o->rotation_deg[1]), o->model);
        glm_rotate_x(o->model, glm_rad(o->rotation_deg[0]), o->model);
        glm_rotate_z(o->model, glm_rad(o->rotation_deg[2]), o->model);
        vec3 lo, hi;
        _sl_object_local_bounds(o, lo, hi);
        for (int c = 0; c < 8; c++) {
            vec4 p = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2], 1}, w;
            glm_mat4_mulv(o->model, p, w);
            glm_vec3_minv(scene->bounds.min, w, scene->bounds.min);
            glm_vec3_maxv(scene->bounds.max, w, scene->bounds.max);
        }
    }
    if (scene->object_count == 0) {
        glm_vec3_zero(scene->bounds.min);
        glm_vec3_zero(scene->bounds.max);
    }
}

bool sl_scene_from_json(sl_scene *scene, const cJSON *json, const char *origin, char *err, size_t err_size) {
    memset(scene, 0, sizeof *scene);
    if (!cJSON_IsObject(json)) {
        snprintf(err, err_size, "%s: a scene must be a JSON object", origin);
        return false;
    }
    const char *name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "name"));
    snprintf(scene->name, sizeof scene->name, "%s", name ? name : "unnamed");
    const cJSON *objects = cJSON_GetObjectItemCaseSensitive(json, "objects");
    if (!cJSON_IsArray(objects) || cJSON_GetArraySize(objects) == 0) {
        snprintf(err, err_size, "%s: \"objects\" must be a non-empty array", origin);
        return false;
    }
    if (cJSON_GetArraySize(objects) > SL_SCENE_MAX_OBJECTS) {
        snprintf(err, err_size, "%s: too many objects (at most %d)", origin, SL_SCENE_MAX_OBJECTS);
        return false;
    }
    const cJSON *item;
    cJSON_ArrayForEach(item, objects) {
        if (!_sl_object_from_json(&scene->objects[scene->object_count], item, origin, scene->object_count, err,
                                  err_size))
            return false;
        scene->object_count++;
    }
    scene->light = (sl_light){
        .type = SL_LIGHT_DIRECTIONAL,
        .direction = {-0.4f, -1.0f, -0.3f},
        .color = {1, 1, 1},
        .intensity = 1,
        .spot_angle_deg = 30,
        .near = 0.5f,
        .far = 50,
        .size = 0.5f,
    };
    glm_vec3_normalize(scene->light.direction);
    const cJSON *light = cJSON_GetObjectItemCaseSensitive(json, "light");
    if (light && !sl_light_from_json(&scene->light, light, origin, err, err_size)) return false;
    sl_scene_update(scene);
    /* Default camera: looking at the scene's centre from the front-right. */
    vec3 centre;
    glm_vec3_center(scene->bounds.min, scene->bounds.max, centre);
    float radius = glm_vec3_distance(scene->bounds.min, scene->bounds.max) / 2;
    scene->camera = (sl_camera){.fov_deg = 45, .near = 0.1f, .far = 4 * radius + 10};
    glm_vec3_copy(centre, scene->camera.target);
    glm_vec3_add(centre, (vec3){radius, radius * 0.8f, radius * 1.2f}, scene->camera.position);
    const cJSON *camera = cJSON_GetObjectItemCaseSensitive(json, "camera");
    if (camera && !sl_camera_from_json(&scene->camera, camera, origin, err, err_size)) return false;
    return true;
}

bool sl_scene_load(sl_scene *scene, const char *name_or_path, char *err, size_t err_size) {
    char path[1024];
    size_t len = strlen(name_or_path);
    if (strchr(name_or_path, '/') || (len > 5 && strcmp(name_or_path + len - 5, ".json") == 0))
        snprintf(path, sizeof path, "%s", name_or_path);
    else
        snprintf(path, sizeof path, "%s/%s.json", sl_scenes_dir(), name_or_path);
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(err, err_size, "%s: cannot open scene file (built-in scenes are in %s)", path, sl_scenes_dir());
        return false;
    }
    cJSON *json = sl_json_load_file(path, "scene", err, err_size);
    if (!json) return false;
    bool ok = sl_scene_from_json(scene, json, path, err, err_size);
    cJSON_Delete(json);
    return ok;
}

void sl_camera_view(const sl_camera *camera, mat4 dest) {
    vec3 eye, target;
    glm_vec3_copy((float *)camera->position, eye);
    glm_vec3_copy((float *)camera->target, target);
    glm_lookat(eye, target, (vec3){0, 1, 0}, dest);
}

void sl_camera_projection(const sl_camera *camera, float aspect, mat4 dest) {
    glm_perspective(glm_rad(camera->fov_deg), aspect, camera->near, camera->far, dest);
}

void sl_camera_orbit(sl_camera *camera, float delta_yaw, float delta_pitch, float zoom) {
    vec3 offset;
    glm_vec3_sub(camera->position, camera->target, offset);
    float r = glm_vec3_norm(offset) * zoom;
    float yaw = atan2f(offset[0], offset[2]) + delta_yaw;
    float pitch = asinf(glm_clamp(offset[1] / glm_vec3_norm(offset), -1, 1)) + delta_pitch;
    pitch = glm_clamp(pitch, glm_rad(-85), glm_rad(85));
    r = glm_clamp(r, 0.5f, camera->far * 0.9f);
    offset[0] = r * cosf(pitch) * sinf(yaw);
    offset[1] = r * sinf(pitch);
    offset[2] = r * cosf(pitch) * cosf(yaw);
    glm_vec3_add(camera->target, offset, camera->position);
}

/* ---- the light camera before lab 2 ----
 * Lab 1 draws its depth map before lab 2 exists, so the framework needs a
 * light camera of its own. For a spot light that camera is lab 2's answer
 * (and for a sun its view is), so the students' handout does not compute
 * it. Every build reads the matrices of the lights its scenes and lab 1's
 * cases use from a table (sl_light_cameras.inc, printed by the staff
 * build's shadowlab-light-table). Staff programs compute any other light's
 * with solutions/framework/sl_light_camera.c, given through
 * sl_light_camera_compute_with (the grader, for hidden variants, and sends
 * the matrices in the job; a staff viewer, for a light it moved); no runner
 * links that code. Without it, another light is drawn from straight above. */
typedef struct _sl_light_camera {
    sl_light_type type;
    float position[3], direction[3], spot_angle_deg, near, far; /* a sun: direction alone */
    float bounds_min[3], bounds_max[3];                         /* a sun's only: its box fits them */
    float view[16], projection[16];
} _sl_light_camera;

#include "sl_light_cameras.inc"

static sl_light_camera_fn _sl_light_camera_computation;

void sl_light_camera_compute_with(sl_light_camera_fn compute) { _sl_light_camera_computation = compute; }

static bool _sl_same(const float *a, const float *b, size_t n) { return memcmp(a, b, n * sizeof(float)) == 0; }

static bool _sl_light_camera_fits(const _sl_light_camera *t, const sl_light *light, const sl_aabb *bounds) {
    if (t->type != light->type || !_sl_same(t->direction, light->direction, 3)) return false;
    if (light->type == SL_LIGHT_DIRECTIONAL)
        return _sl_same(t->bounds_min, bounds->min, 3) && _sl_same(t->bounds_max, bounds->max, 3);
    return _sl_same(t->position, light->position, 3) && _sl_same(&t->spot_angle_deg, &light->spot_angle_deg, 1) &&
           _sl_same(&t->near, &light->near, 1) && _sl_same(&t->far, &light->far, 1);
}

/* A camera straight above the scene's bounding sphere, looking down (-y, image up -z), orthographic. */
static void _sl_overview_matrices(const sl_aabb *bounds, mat4 view, mat4 projection) {
    vec3 centre;
    glm_vec3_center((float *)bounds->min, (float *)bounds->max, centre);
    float radius = glm_vec3_distance((float *)bounds->min, (float *)bounds->max) / 2;
    if (!(radius > 0)) radius = 1;
    vec3 eye = {centre[0], centre[1] + 2 * radius, centre[2]};
    glm_mat4_identity(view);
    view[1][1] = 0, view[2][1] = -1, view[1][2] = 1, view[2][2] = 0;
    view[3][0] = -eye[0], view[3][1] = eye[2], view[3][2] = -eye[1];
    glm_ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f, projection);
}

bool sl_light_default_matrices(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection) {
    for (size_t i = 0; i < sizeof _sl_light_cameras / sizeof _sl_light_cameras[0]; i++) {
        const _sl_light_camera *t = &_sl_light_cameras[i];
        if (!_sl_light_camera_fits(t, light, bounds)) continue;
        memcpy(view, t->view, sizeof t->view);
        memcpy(projection, t->projection, sizeof t->projection);
        return true;
    }
    if (_sl_light_camera_computation && _sl_light_camera_computation(light, bounds, view, projection)) return true;
    _sl_overview_matrices(bounds, view, projection);
    return false;
}

void sl_light_camera_table_entry(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection, FILE *out) {
    const float *numbers[6] = {light->position, light->direction, bounds->min, bounds->max, (const float *)view,
                               (const float *)projection};
    static const int counts[6] = {3, 3, 3, 3, 16, 16};
    fprintf(out, "    {%d, ", (int)light->type);
    for (int g = 0; g < 6; g++) {
        fputc('{', out);
        for (int i = 0; i < counts[g]; i++) {
            char text[32];
            snprintf(text, sizeof text, "%.9g", (double)numbers[g][i]);
            fprintf(out, "%s%s%sf", i ? ", " : "", text, strpbrk(text, ".en") ? "" : ".0");
        }
        fputs("}, ", out);
        if (g == 1) {
            const float single[3] = {light->spot_angle_deg, light->near, light->far};
            for (int i = 0; i < 3; i++) {
                char text[32];
                snprintf(text, sizeof text, "%.9g", (double)single[i]);
                fprintf(out, "%s%sf, ", text, strpbrk(text, ".en") ? "" : ".0");
            }
        }
    }
    fputs("},\n", out);
}
