/* sl_params: what a frame is rendered with (lab, map size, bias, filter,
 * output), the names the command line and case files give those settings,
 * and the labs' folders and titles. No GL here: the grader, which runs no lab
 * code and opens no GL context, shares this module with the renderer. */
#ifndef SL_PARAMS_H
#define SL_PARAMS_H

#include <stdbool.h>

#include "shadowlab.h"
#include "sl_scene.h"

#define SL_LAB_COUNT 7  /* the highest lab with code in this project (a lab in between may be absent: sl_lab_folder) */
#define SL_LAB_MAX 7    /* labs the course plans: case files may name 1..7 */

typedef enum sl_compare_mode { SL_COMPARE_MANUAL = 0, SL_COMPARE_HARDWARE = 1 } sl_compare_mode;
/* SL_OUTPUT_LIT_MASK: white where a surface faces the light (the grader's "lit surfaces"). */
/* SL_OUTPUT_CASCADE_INDEX (lab 6): the cascade each pixel used, as a number (-1: none, background). */
typedef enum sl_output {
    SL_OUTPUT_SHADED = 0,
    SL_OUTPUT_VISIBILITY = 1,
    SL_OUTPUT_LIT_MASK = 2,
    SL_OUTPUT_CASCADE_INDEX = 3,
} sl_output;

/* Lab 6: the cascades. The camera they are fitted to (and whose view depth
 * picks one) is the scene's, unless use_camera: then `camera`, which the
 * viewer's frozen frustum and the grader's camera paths use while the
 * picture is drawn from the scene's camera. */
typedef struct sl_cascade_params {
    int count;           /* 1..SL_MAX_CASCADES */
    float lambda;        /* practical split scheme: 0 uniform, 1 logarithmic */
    float max_distance;  /* view depth the last cascade ends at (0: the camera's far plane) */
    float caster_margin; /* world units the light's depth range reaches beyond the slice's sphere */
    float blend_band;    /* bonus: the last fraction of each cascade's range blended with the next (0: off) */
    bool show_cascades;  /* shaded output tinted by cascade (viewer) */
    bool show_frustum;   /* with use_camera: the slices of `camera`'s frustum and their light boxes, as lines */
    /* viewer (the shimmer demo): each light box recentred on its sphere after lab6_cascade_matrices,
     * which undoes texel snapping however the lab code did it */
    bool unsnapped;
    bool use_camera;
    sl_camera camera;
} sl_cascade_params;

/* Lab 7: how the six faces of the cube map are rendered. */
typedef enum sl_cube_pass {
    SL_CUBE_PASS_AUTO = 0, /* one layered pass if lab7_begin_cube_pass does SL_CUBE_ALL_FACES, else six */
    SL_CUBE_PASS_SIX,      /* six passes, one per face */
    SL_CUBE_PASS_LAYERED,  /* one layered pass (geometry shader); six if the lab does not do it */
    SL_CUBE_PASS_COUNT
} sl_cube_pass;

/* The biases the viewer uses: the soft lookup's samples off the centre direction land on the
 * same surface, nearer the light where it is tilted, so it needs a larger one. */
#define SL_CUBE_HARD_BIAS 0.004f
#define SL_CUBE_SOFT_BIAS 0.01f

typedef struct sl_cube_settings {
    int map_size;        /* texels per face side; default 512 */
    float bias;          /* in units of distance / far (the soft lookup needs more: SL_CUBE_SOFT_BIAS) */
    bool soft;           /* point_shadow_soft: 20 samples around the direction */
    float soft_radius;   /* the disk's radius in world units at distance far (grows with distance) */
    sl_cube_pass pass;
} sl_cube_settings;

typedef struct sl_render_params {
    int lab;                 /* labs in use, 1..SL_LAB_COUNT: 1 = depth pass only */
    int shadow_map_size;     /* texels; default 1024 */
    sl_compare_mode compare; /* labs 2-3: sampler2D + manual compare, or sampler2DShadow */
    sl_bias_settings bias;   /* lab 2 uses bias.constant; lab 3 all of it */
    sl_filter_settings filter; /* lab 4 */
    sl_vsm_settings vsm;     /* lab 5 */
    bool vsm_off;            /* lab 5 in use, but lab 4's filter instead (the viewer's VSM vs PCF key) */
    sl_output output;
    bool show_shadow_map;    /* debug view of the depth map in a corner (lab 7: the six faces as a cross) */
    sl_cascade_params cascades; /* lab 6 */
    sl_cube_settings cube;   /* lab 7 */
} sl_render_params;

void sl_render_params_defaults(sl_render_params *params);

/* Names as the command line and case files spell them ("slope", "pcss"). */
const char *sl_bias_mode_name(sl_bias_mode mode);
bool sl_bias_mode_parse(const char *name, sl_bias_mode *mode);
const char *sl_filter_mode_name(sl_filter_mode mode);
bool sl_filter_mode_parse(const char *name, sl_filter_mode *mode);

const char *sl_cube_pass_name(sl_cube_pass pass);
bool sl_cube_pass_parse(const char *name, sl_cube_pass *pass);
/* "+x", "-x", "+y", "-y", "+z", "-z" for faces 0..5; "?" otherwise. */
const char *sl_cube_face_name(int face);
int sl_cube_face_parse(const char *name); /* -1 when no face's */

/* Folder of lab N under a labs tree ("lab1_depth_fbo"), N = 1..SL_LAB_COUNT; NULL otherwise,
 * and NULL for a lab this tree does not have (labs are numbered for the course). */
const char *sl_lab_folder(int lab);
/* "depth FBO", ..., N = 1..SL_LAB_MAX; "?" otherwise. */
const char *sl_lab_title(int lab);
/* Which labs a lab builds on (framework/lab_dependencies.cmake, the one place
 * it is said): the earlier labs whose code the framework calls when it draws
 * lab `lab`'s cases (its per-lab runner takes them from the solutions, every
 * other lab from the stubs); and those of them whose results show in its
 * pictures (a mistake there is named in it: "needs lab K first"). */
bool sl_lab_builds_on(int lab, int earlier);
bool sl_lab_shows(int lab, int earlier);
/* Whether lab `lab`'s frames draw their shadow map from a light camera the grader gives in the job
 * (sl_protocol.h's light_cameras_given): lab 1's, whose runner has no light camera of its own (lab 2's
 * code computes it). No other lab gets it: lab 2's code, run in a later lab's case, must not find its
 * own answer in the job. */
bool sl_lab_given_light_camera(int lab);

/* The colour a cascade is shown in (the viewer's K key and frusta, --case,
 * the grader's report): 0 red, 1 green, 2 blue, 3 yellow; grey for none (-1)
 * or a number out of range. Its name ("red", ..., "grey") for legends. */
const char *sl_cascade_colour(int cascade, float rgb[3]);
/* The same four colours as a table (the lab 6 shader's tint takes them as a uniform). */
extern const float sl_cascade_colours[SL_MAX_CASCADES][3];

#endif
