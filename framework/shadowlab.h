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

/* ---- Lab 3: bias & culling (labs/lab3_bias/lab3.c) ---------------------- */
typedef enum sl_bias_mode {
    SL_BIAS_NONE = 0,          /* no bias at all: acne everywhere, for comparison */
    SL_BIAS_CONSTANT,          /* p.z - constant */
    SL_BIAS_SLOPE_SCALED,      /* constant + slope * tan(angle between N and L), clamped */
    SL_BIAS_POLYGON_OFFSET,    /* glPolygonOffset in the depth pass, no bias in the lookup */
    SL_BIAS_FRONT_FACE_CULLING,/* only back faces reach the map (closed meshes only) */
    SL_BIAS_NORMAL_OFFSET,     /* lookup moved along the normal by texels * (1 - N.L), plus constant */
    SL_BIAS_MIDPOINT,          /* extension: compare with the midpoint of the first and second surface */
    SL_BIAS_MODE_COUNT
} sl_bias_mode;

typedef struct sl_bias_settings {
    sl_bias_mode mode;
    float constant;              /* depth units, [0,1] */
    float slope;                 /* times tan(angle) */
    float max_bias;              /* clamp of the slope-scaled bias */
    float polygon_offset_factor; /* glPolygonOffset(factor, units) */
    float polygon_offset_units;
    float normal_offset;         /* in shadow-map texels */
} sl_bias_settings;

/* Called right after lab1_begin_depth_pass (the map's framebuffer is bound). */
sl_status lab3_depth_pass_state(const sl_bias_settings *bias);
/* Extension (optional): in SL_BIAS_MIDPOINT mode the framework runs a second
 * depth pass into a second map; this sets that pass's state so the map keeps
 * the SECOND surface along each light ray (Wang & Molnar 1994). */
sl_status lab3_second_depth_state(void);

/* ---- Lab 4: PCF & PCSS (labs/lab4_pcf/lab4.c) --------------------------- */
typedef enum sl_filter_mode {
    SL_FILTER_NONE = 0,     /* one comparison (lab 2) */
    SL_FILTER_HARDWARE,     /* 2x2 PCF by the texture unit: sampler2DShadow + GL_LINEAR */
    SL_FILTER_GRID,         /* (2r+1) x (2r+1) comparisons */
    SL_FILTER_POISSON,      /* 16 comparisons on a rotated Poisson disk */
    SL_FILTER_PCSS,         /* percentage-closer soft shadows (Fernando 2005) */
    SL_FILTER_MODE_COUNT
} sl_filter_mode;

typedef struct sl_filter_settings {
    sl_filter_mode mode;
    int grid_radius;        /* grid: r, in texels */
    float poisson_radius;   /* Poisson: disk radius in texels */
} sl_filter_settings;       /* PCSS takes the light's width from sl_light.size */

/* Sets the depth texture's filtering for `mode` (the texture is bound to
 * GL_TEXTURE_2D on texture unit 0 when this is called). */
sl_status lab4_configure_shadow_texture(GLuint depth_texture, sl_filter_mode mode);

/* ---- Lab 5: variance shadow maps (labs/lab5_vsm/lab5.c) ----------------- */
/* Two moments targets of the same size: the moments pass draws into [0] (with
 * a depth buffer for its own depth test), the horizontal blur reads [0] and
 * writes [1], the vertical blur reads [1] and writes [0]: the camera pass
 * reads moments[0]. */
typedef struct sl_moments_target {
    GLuint framebuffer[2];
    GLuint moments[2]; /* GL_RG32F textures: (depth, depth^2) per texel */
    GLuint depth;      /* a depth renderbuffer, attached to framebuffer[0] */
    int size;          /* width = height, in texels */
} sl_moments_target;

typedef struct sl_vsm_settings {
    int blur_radius;     /* of the separable Gaussian, in texels; 0: no blur */
    float min_variance;  /* the variance never goes below this (precision, acne) */
    float bleeding;      /* light-bleeding reduction: linstep(bleeding, 1, p_max); 0: off */
    int map_size;        /* the moments targets' size in texels; 0: the shadow map's */
} sl_vsm_settings;

sl_status lab5_create_moments_target(int size, sl_moments_target *target);
/* The moments pass: target->framebuffer[0] bound, cleared, depth test on. */
sl_status lab5_begin_moments_pass(const sl_moments_target *target);
/* One blur pass: direction 0 reads moments[0] and writes framebuffer[1]
 * (horizontal), direction 1 reads moments[1] and writes framebuffer[0]
 * (vertical). Binds the texture to read on texture unit 0. */
sl_status lab5_begin_blur_pass(const sl_moments_target *target, int direction);
/* After the blur: mipmaps of moments[0] and trilinear filtering. */
sl_status lab5_filter_moments(const sl_moments_target *target);
void lab5_destroy_moments_target(sl_moments_target *target);
/* ---- Lab 6: cascaded shadow maps (labs/lab6_cascades/lab6.c) ------------ */
#define SL_MAX_CASCADES 4

/* Where the cascades begin and end, as view depths (distance along the
 * camera's view direction): splits[0] = near, splits[count] = far, between
 * them the practical split scheme with weight lambda (Zhang et al. 2006). */
sl_status lab6_split_distances(float near, float far, int count, float lambda, float splits[SL_MAX_CASCADES + 1]);
/* The bounding sphere (dest: centre x, y, z and radius) of the slice of the
 * camera's frustum between view depths split_near and split_far. The frustum
 * is given by the inverse of the camera's projection * view and its own
 * near and far planes. */
sl_status lab6_slice_sphere(mat4 inv_view_projection, float near, float far, float split_near, float split_far,
                            vec4 dest);
/* One cascade's light camera: a view along light->direction and an
 * orthographic projection around `sphere`, whose depth range reaches
 * caster_margin further towards the light, moved so the world stays on the
 * texel grid of a map_size x map_size map (texel snapping). */
sl_status lab6_cascade_matrices(const sl_light *light, vec4 sphere, float caster_margin, int map_size, mat4 light_view,
                                mat4 light_projection);
/* ---- Lab 7: cube-map shadows (labs/lab7_cube/lab7.c) -------------------- */
/* A point light's shadow map: a depth cube map (six square faces) and a
 * framebuffer to render into it. Each texel stores the distance from the
 * light to the nearest surface divided by the light's far plane. */
typedef struct sl_cube_map {
    GLuint framebuffer;
    GLuint depth_cube; /* GL_TEXTURE_CUBE_MAP, depth format */
    int size;          /* each face is size x size texels */
} sl_cube_map;

/* The faces in GL's order: face f is GL_TEXTURE_CUBE_MAP_POSITIVE_X + f. */
typedef enum sl_cube_face {
    SL_CUBE_POSITIVE_X = 0,
    SL_CUBE_NEGATIVE_X,
    SL_CUBE_POSITIVE_Y,
    SL_CUBE_NEGATIVE_Y,
    SL_CUBE_POSITIVE_Z,
    SL_CUBE_NEGATIVE_Z,
    SL_CUBE_FACE_COUNT
} sl_cube_face;
/* lab7_begin_cube_pass's face for one layered pass (a geometry shader picks gl_Layer). */
#define SL_CUBE_ALL_FACES (-1)

sl_status lab7_create_cube_map(int size, sl_cube_map *map);
/* Binds the map's framebuffer for face 0..5 (six passes), or the whole cube
 * for SL_CUBE_ALL_FACES (one layered pass; return SL_NOT_IMPLEMENTED there if
 * you render six passes, and the framework does). Viewport, depth state, clear. */
sl_status lab7_begin_cube_pass(const sl_cube_map *map, int face);
void lab7_destroy_cube_map(sl_cube_map *map);
/* The view matrix of one face: the eye at the light, looking down the face's axis. */
sl_status lab7_face_view(vec3 light_position, int face, mat4 dest);
/* The projection every face shares: 90 degrees, aspect 1. */
sl_status lab7_face_projection(float near, float far, mat4 dest);

#endif
