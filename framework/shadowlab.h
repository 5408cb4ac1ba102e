/* shadowlab.h: what lab code sees. Include this one header in a lab's .c file.
 *
 * Conventions (cglm's): matrices are column-major mat4, the destination
 * argument comes last, angles are in radians unless a name says _deg. */
#ifndef SHADOWLAB_H
#define SHADOWLAB_H

#include <stdbool.h>

#include <cglm/cglm.h>

#include "sl_gl.h"

/* What a lab function returns. Stubs return SL_NOT_IMPLEMENTED: the framework
 * then renders without that step and the grader reports "not implemented". */
typedef enum sl_status {
    SL_OK = 0,
    SL_NOT_IMPLEMENTED = 1,
    SL_FAILED = 2,
} sl_status;

typedef struct sl_aabb {
    vec3 min, max;
} sl_aabb;

typedef enum sl_light_type {
    SL_LIGHT_DIRECTIONAL = 0, /* sun: parallel rays along `direction` */
    SL_LIGHT_SPOT = 1,        /* at `position`, cone around `direction` */
    SL_LIGHT_POINT = 2,       /* at `position`, all directions */
} sl_light_type;

typedef struct sl_light {
    sl_light_type type;
    vec3 position;        /* spot, point */
    vec3 direction;       /* directional, spot: the way the light travels (unit length) */
    vec3 color;
    float intensity;
    float spot_angle_deg; /* spot: half-angle of the cone, degrees */
    float near, far;      /* spot, point: depth range of the light's camera */
    float size;           /* light size in world units (soft shadows, lab 4) */
} sl_light;

/* Lab 1: a depth texture attached to a framebuffer with no colour buffer. */
typedef struct sl_shadow_map {
    GLuint framebuffer;
    GLuint depth_texture;
    int size; /* width = height, in texels */
} sl_shadow_map;

/* ---- Lab 1: depth FBO (labs/lab1_depth_fbo/lab1.c) ---------------------- */
sl_status lab1_create_shadow_map(int size, sl_shadow_map *map);
sl_status lab1_begin_depth_pass(const sl_shadow_map *map);
void lab1_destroy_shadow_map(sl_shadow_map *map);

/* ---- Lab 2: projective lookup (labs/lab2_projective/lab2.c) ------------- */
sl_status lab2_light_view(const sl_light *light, const sl_aabb *scene_bounds, mat4 dest);
sl_status lab2_light_projection(const sl_light *light, const sl_aabb *scene_bounds, mat4 light_view, mat4 dest);
sl_status lab2_shadow_matrix(mat4 light_projection, mat4 light_view, mat4 dest);

#endif
