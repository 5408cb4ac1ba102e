/* sl_renderer: one frame of the shadow pipeline, built from the labs' code.
 *
 * Each lab's technique is one descriptor in the table of sl_technique.h, and
 * the renderer names none of them: a frame is drawn by the technique that
 * takes it (lab 6's cascades, lab 7's cube map for a point light), else by
 * lab 1's shadow-map frame (sl_lab1_4_shadow_map.c), which labs 2-5 add to:
 *
 *   1. lab 2 builds the light's view, projection and shadow matrix
 *      (lab 1 alone uses the light camera its job gives, else sl_light_default_matrices)
 *   2. lab 1 creates the shadow map (once per size) and begins the depth pass,
 *      lab 3 adds its depth-pass state (polygon offset, culling); the
 *      framework draws every object with lab 1's depth shaders
 *   3. lab 4 sets the map's filtering; the camera pass shades each pixel with
 *      the highest lab's lookup: lab 2 (scene.frag), lab 3's bias
 *      (scene_bias.frag) or lab 4's filters (scene_filter.frag)
 *
 * A lab function that returns SL_NOT_IMPLEMENTED switches its step off (no
 * shadows) and is listed in sl_frame_info, which the grader turns into
 * "not implemented". The viewer and the grader both draw through this module. */
#ifndef SL_RENDERER_H
#define SL_RENDERER_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"
#include "sl_labs.h"
#include "sl_mesh.h"
#include "sl_params.h"
#include "sl_scene.h"
#include "sl_shader.h"
#include "shadowlab.h"

#define SL_RENDERER_MAX_LAB SL_LAB_COUNT

#define SL_MAX_NOT_IMPLEMENTED 16

/* Why a frame drew less than its lab asks for: each step of the asked
 * technique that did not run, noted where the renderer stepped down, so
 * the viewer can say what is really drawing ("lab 5 VSM is off: lab 3's
 * depth_pass_state is not implemented; drawing lab 2's hard shadows"). */
typedef enum sl_stop_reason {
    SL_STOP_NOT_IMPLEMENTED, /* `function` returned SL_NOT_IMPLEMENTED */
    SL_STOP_FAILED,          /* `function` returned SL_FAILED */
    SL_STOP_SHADERS,         /* lab `lab`'s shaders do not compile */
    SL_STOP_SWITCHED_OFF,    /* a setting switched the technique off (lab 5's vsm_off) */
    SL_STOP_NO_POINT_LIGHT,  /* lab 7 casts from a point light only: the scene has none */
} sl_stop_reason;

typedef struct sl_frame_stop {
    int lab;              /* the lab whose step stopped */
    const char *function; /* its function (not implemented, failed), else NULL */
    sl_stop_reason reason;
} sl_frame_stop;

#define SL_MAX_FRAME_STOPS 4

/* What the labs did in the last frame. */
typedef struct sl_frame_info {
    const char *not_implemented[SL_MAX_NOT_IMPLEMENTED]; /* names of stubs that returned SL_NOT_IMPLEMENTED */
    int not_implemented_count;
    const char *failed;          /* a lab function that returned SL_FAILED, or NULL */
    const char *shader_error;    /* compile error of a lab's shaders in use, or NULL */
    int shader_error_lab;        /* whose shaders those are */
    bool shadow_map_ready;       /* lab 1 created a map and ran the depth pass */
    bool second_map_ready;       /* lab 3's extension: the second surface's map too */
    bool lab2_ready;             /* lab 2's matrices are in use */
    int lab_in_use;              /* the highest lab whose code this frame used (0: no shadows) */
    int lab_asked;               /* the lab the frame was drawn for (params.lab) */
    sl_frame_stop stops[SL_MAX_FRAME_STOPS]; /* why lab_asked's technique did not draw, in the order met */
    int stop_count;
    mat4 light_view, light_projection, shadow_matrix; /* the matrices used */
    sl_shadow_map shadow_map;    /* lab 1's map, for inspection */
    bool moments_ready;          /* lab 5: moments drawn, blurred and filtered this frame */
    sl_moments_target moments_target; /* lab 5's targets, for inspection */
    /* lab 5: which moments texture (0, 1; -1 another, -2 none) each blur pass read on unit 0, and which
     * framebuffer it drew into; with keep_pass_outputs, what each pass drew (SL_CAPTURE_MOMENTS_PASSES) */
    int vsm_blur_read[2], vsm_blur_drew[2];
    const sl_image *vsm_passes;
    /* lab 6 (sl_lab6_cascades.c): the cascades of this frame */
    bool cascades_ready;         /* lab 6's functions and lab 2's shadow matrix ran, the layers are drawn */
    int cascade_count;
    float cascade_splits[SL_MAX_CASCADES + 1];
    vec4 cascade_spheres[SL_MAX_CASCADES];
    mat4 cascade_view[SL_MAX_CASCADES], cascade_projection[SL_MAX_CASCADES], cascade_shadow_matrix[SL_MAX_CASCADES];
    mat4 cascade_fit_view;       /* the view of the camera they were fitted to */
    GLuint cascade_texture;      /* the depth texture array */
    /* lab 7 (sl_lab7_cube.c) */
    bool cube_frame;             /* this frame was lab 7's (a point light) */
    bool cube_matrices_ready;    /* lab 7's face views and projection are in use */
    bool cube_map_ready;         /* lab 7 created the cube map and its depth passes ran */
    bool cube_layered;           /* the faces were rendered in one layered pass (else six) */
    bool cube_layered_attached;  /* in that pass, the whole cube map was attached (a layered attachment) */
    mat4 cube_views[6], cube_projection;
    sl_cube_map cube_map;        /* lab 7's map, for inspection */
} sl_frame_info;

/* Per-pass times of one frame, from GL timer queries (glQueryCounter, GL 3.3).
 * On a GPU they are GPU time. On llvmpipe a timestamp is taken when the
 * rasteriser threads reach it, so a pass's time is the rasteriser's CPU time
 * for that pass (vertex work and draw calls on the calling thread overlap it). */
#define SL_MAX_PASSES 8
typedef struct sl_pass_time {
    const char *name; /* "depth", "second depth", "camera", "debug view" */
    double ms;
} sl_pass_time;

typedef struct sl_frame_timing {
    sl_pass_time passes[SL_MAX_PASSES]; /* in the order they ran */
    int pass_count;
} sl_frame_timing;

typedef struct sl_renderer_desc {
    const char *labs_dir;      /* labs/ or solutions/ (default: the build's) */
    const char *framework_dir; /* default: the source tree's framework/ */
} sl_renderer_desc;

/* How many GLSL programs a renderer has built (compiled and linked), and the
 * time that took: a frame builds only the programs it uses, once each. */
typedef struct sl_program_stats {
    int builds;      /* builds and rebuilds (hot reload), failed ones included */
    double build_ms; /* wall-clock time spent in them */
    int cached;      /* programs held now */
} sl_program_stats;


typedef struct sl_renderer {
    const sl_lab_functions *fns[SL_LAB_COUNT + 1]; /* whose code runs for each lab (this build's) */
    char labs_dir[SL_PATH_MAX];
    char shaders_dir[SL_PATH_MAX];
    unsigned long frame_count; /* frames drawn (a program not used by the last one is rebuilt when next used) */
    char shader_errors[SL_RENDERER_MAX_LAB + 1][8192]; /* per lab: why its shaders do not compile (0: framework) */
    GLint lab1_min_filter, lab1_mag_filter; /* lab 1's choice, restored when lab 4 is off */
    GLuint empty_vao;
    sl_mesh meshes[SL_SCENE_MAX_OBJECTS];
    int mesh_count;
    sl_shadow_map shadow_map;
    sl_status shadow_map_status;
    bool shadow_map_attempted;
    sl_shadow_map second_map; /* lab 3's extension (midpoint shadow maps) */
    sl_status second_map_status;
    bool second_map_attempted;
    sl_frame_info info;
    /* timing (sl_renderer_set_timing): one timestamp before the frame and one after each pass */
    bool timing;
    GLuint timer_queries[SL_MAX_PASSES + 1];
    const char *timer_names[SL_MAX_PASSES];
    int timer_count;
    /* Per lab, what its technique's module keeps between frames (its targets and programs), made by
     * its first frame and freed by its destroy hook (sl_technique.h). */
    void *technique_state[SL_LAB_COUNT + 1];
    /* lab 1's light camera, where the grader gave it (sl_renderer_set_light_camera) */
    bool light_camera_given;
    mat4 light_camera_view, light_camera_projection;
    /* read back each pass's output right after its draw (lab 5's passes: the grader's runner asks) */
    bool keep_pass_outputs;
} sl_renderer;

/* Called before each call into lab code with the function's name, so a crash
 * can be pinned on it (the grader sets this). */
extern void (*sl_lab_call_hook)(const char *function);

/* Folder of the lab sources this binary was built with, and what they are
 * ("student", "solutions" or a variant's name). Defined per build. */
extern const char sl_build_labs_dir[];
extern const char sl_build_labs_kind[];
/* The framework folder (its shaders/): compiled in; SHADOWLAB_FRAMEWORK
 * overrides it in the viewer. The grader's runner never reads the environment. */
const char *sl_framework_dir(void);

/* Prepares a renderer; programs are built by the first frame that uses them.
 * False (message in err) when the framework's shaders cannot be found. A
 * lab's broken shaders switch its step off and show up as
 * sl_frame_info.shader_error, so the rest still runs. */
bool sl_renderer_init(sl_renderer *r, const sl_renderer_desc *desc, char *err, size_t err_size);
void sl_renderer_destroy(sl_renderer *r);
bool sl_renderer_set_scene(sl_renderer *r, const sl_scene *scene, char *err, size_t err_size);
/* Rebuilds the programs the last frame used whose files changed; false with
 * err set if one failed (a program that compiled before stays in use). Other
 * programs whose files changed are rebuilt when a frame next uses them. */
bool sl_renderer_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size);

/* The light camera the next frames draw lab 1's depth map with when lab 2's
 * matrices are not in use (the runner: the one its job gives), instead of
 * sl_light_default_matrices; NULL, NULL: back to that. */
void sl_renderer_set_light_camera(sl_renderer *r, const float *view, const float *projection);

/* Draws one frame into framebuffer `target` (0 = the window or OSMesa buffer). */
void sl_renderer_draw(sl_renderer *r, const sl_scene *scene, const sl_render_params *params, GLuint target,
                      int width, int height);
const sl_frame_info *sl_renderer_info(const sl_renderer *r);

void sl_renderer_program_stats(const sl_renderer *r, sl_program_stats *out);

/* Times the passes of every frame from now on (or stops). Off by default. */
void sl_renderer_set_timing(sl_renderer *r, bool enabled);
/* The pass times of the last frame drawn with timing on; waits until the GL
 * has finished that frame. False if no such frame was drawn. */
bool sl_renderer_frame_timing(sl_renderer *r, sl_frame_timing *out);

/* For the techniques' modules (sl_technique.h): a call into lab
 * code is announced, then its result recorded, as the renderer does with its own (the result is true when
 * the step may go on); a pass's end is timed. */
void sl_renderer_lab_enter(const char *function);
bool sl_renderer_lab_result(sl_renderer *r, const char *function, sl_status status);
void sl_renderer_timer_mark(sl_renderer *r, const char *finished_pass);
/* Where a pass module steps down: lab `lab`'s step stopped this frame. The
 * reason is what the frame recorded: the lab's first function that was not
 * implemented or failed, else its shaders' error. False (nothing noted)
 * when the frame recorded nothing of that lab. */
bool sl_renderer_note_stop(sl_renderer *r, int lab);
/* A technique switched off by a setting or the scene, not by lab code. */
void sl_renderer_note_off(sl_renderer *r, int lab, sl_stop_reason reason);
/* Draws every object of the scene with the bound program (u_model, and with
 * colours also u_normal_matrix and u_albedo, at these locations; -1: not set). */
void sl_renderer_draw_objects(sl_renderer *r, const sl_scene *scene, GLint model, GLint normal_matrix, GLint albedo);
/* Binds `target` with its viewport and puts back the GL state a lab may have
 * changed (depth test and writes, culling, polygon offset, blending, scissor),
 * so one pass cannot leak into the next. */
void sl_renderer_reset_state(GLuint target, int width, int height);

/* Read-backs, as top-down images: sl_capture.h. */
#include "sl_capture.h"

#endif
