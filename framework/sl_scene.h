/* sl_scene: scenes as JSON data (objects, one light, a camera), the built-in
 * scenes, and the cameras. See framework/scenes/README.md for the format. */
#ifndef SL_SCENE_H
#define SL_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include <cjson/cJSON.h>

#include "shadowlab.h"

#define SL_SCENE_MAX_OBJECTS 64

typedef enum sl_shape { SL_SHAPE_PLANE, SL_SHAPE_BOX, SL_SHAPE_SPHERE, SL_SHAPE_CYLINDER, SL_SHAPE_TORUS } sl_shape;

typedef struct sl_object {
    sl_shape shape;
    vec3 size;       /* plane: x, z; box: x, y, z; sphere: radius; cylinder: radius, height; torus: radius, tube */
    int subdivisions; /* plane: quads per side (default 8); 1 makes big triangles */
    vec3 position;
    vec3 rotation_deg; /* applied as Y, then X, then Z */
    vec3 color;
    mat4 model;      /* derived */
} sl_object;

typedef struct sl_camera {
    vec3 position, target;
    float fov_deg, near, far;
} sl_camera;

typedef struct sl_scene {
    char name[64];
    sl_object objects[SL_SCENE_MAX_OBJECTS];
    int object_count;
    sl_light light;
    sl_camera camera;
    sl_aabb bounds; /* derived: world bounds of every object */
} sl_scene;

/* Folder of the built-in scenes (compiled in; SHADOWLAB_SCENES overrides). */
const char *sl_scenes_dir(void);
/* `name_or_path`: a built-in's name ("boxes_on_floor") or a .json path. */
bool sl_scene_load(sl_scene *scene, const char *name_or_path, char *err, size_t err_size);
bool sl_scene_from_json(sl_scene *scene, const cJSON *json, const char *origin, char *err, size_t err_size);
/* Overrides the fields present in `json` (a "light" object of a case file). */
bool sl_light_from_json(sl_light *light, const cJSON *json, const char *origin, char *err, size_t err_size);
bool sl_camera_from_json(sl_camera *camera, const cJSON *json, const char *origin, char *err, size_t err_size);
/* Recomputes models and bounds after objects changed. */
void sl_scene_update(sl_scene *scene);

void sl_camera_view(const sl_camera *camera, mat4 dest);
void sl_camera_projection(const sl_camera *camera, float aspect, mat4 dest);
/* Orbit around the target: yaw/pitch deltas in radians, zoom as a factor. */
void sl_camera_orbit(sl_camera *camera, float delta_yaw, float delta_pitch, float zoom);

/* The light camera used when lab 2's matrices are not in use (lab 1, and
 * before lab 2 is done): a loose box around the scene's bounding sphere for a
 * directional light, the cone for a spot light. It is lab 2's answer, so it is
 * computed by staff programs only (the grader, which sends it to its runners
 * in the job; a staff build's viewer): each gives its computation with
 * sl_light_camera_compute_with. Everywhere else (the runners, the students'
 * handout) it is known for the lights of the scenes and lab 1's cases (a
 * table); for another light this gives a camera straight above the scene
 * instead and returns false. */
bool sl_light_default_matrices(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection);
typedef bool (*sl_light_camera_fn)(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection);
/* The computation sl_light_default_matrices uses for a light its table lacks (NULL: none, the default). */
void sl_light_camera_compute_with(sl_light_camera_fn compute);
/* One entry of that table (sl_light_cameras.inc): `light` and its camera, as C. */
void sl_light_camera_table_entry(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection, FILE *out);

const char *sl_light_type_name(sl_light_type type);

#endif
