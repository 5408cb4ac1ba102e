/* sl_protocol: what passes between the grader and its runner, the process
 * that runs lab code for one case.
 *
 *   grader -> runner  fd 0: one sl_job; then the grader keeps the pipe open
 *                     until it has checked the runner's DONE, and closes it
 *                     to let the runner exit (the runner waits for that).
 *   runner -> grader  fd 3: messages [sl_message_header][name][payload].
 *                     stdout and stderr: lab code's own output, kept apart.
 *
 * The grader treats every byte from the runner as hostile: lab code shares
 * the runner's process and can write anything to fd 3. So every length is
 * bounded, every capture must be one the job asked for and come once, and
 * nothing after DONE is allowed (grader/sl_run.c enforces it). The job holds
 * only what the runner needs to render: never a reference, and of lab
 * code's answers only lab 1's light camera, in lab 1's cases (below). */
#ifndef SL_PROTOCOL_H
#define SL_PROTOCOL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "sl_params.h"
#include "sl_probe.h"
#include "sl_scene.h"

#define SL_JOB_MAGIC 0x424a4c53u /* "SLJB" */
#define SL_PROTOCOL_VERSION 5 /* 3: probe tables name their function (sl_probe_table); 4: lab 5's passes;
                                * 5: GL_ERROR */
#define SL_JOB_MAX_FRAMES 16
#define SL_JOB_MAX_PROBES 8   /* a case's checks: each may be a probe */
#define SL_CHANNEL_FD 3
/* Where, in the job's labs tree, the technique a build adds (lab 0) finds its files (its shaders/):
 * the namespaces sandbox copies them there from the grader's --technique-dir. */
#define SL_TECHNIQUE_FOLDER "technique"

/* What a case can ask the runner to capture after its last frame. */
typedef enum sl_capture_kind {
    SL_CAPTURE_FBO,        /* numbers: lab 1's framebuffer and texture, as glGet* reports them */
    SL_CAPTURE_DEPTH_MAP,  /* image, 1 channel: the shadow map's texels */
    SL_CAPTURE_MATRICES,   /* numbers: light view, projection, shadow matrix (48) */
    SL_CAPTURE_VISIBILITY, /* image, 1 channel: the visibility term, camera size */
    SL_CAPTURE_LIT_MASK,   /* image, 1 channel: surfaces facing the light, camera size */
    SL_CAPTURE_IMAGE,      /* image, 3 channels: the shaded picture, camera size */
    /* lab 5 */
    SL_CAPTURE_MOMENTS,         /* image, 2 channels: the moments before the blur (a frame with radius 0), map size */
    SL_CAPTURE_MOMENTS_BLURRED, /* image, 2 channels: the moments the camera pass reads, map size */
    SL_CAPTURE_MOMENTS_TARGET,  /* numbers: lab 5's target, as glGet* reports it */
    SL_CAPTURE_VISIBILITY_UNREDUCED, /* image, 1 channel: the visibility without light-bleeding reduction */
    /* image, 2 channels, map size x 3 map sizes: what each pass of the blurred frame drew, read back from the
     * framebuffer it drew into right after its draw, stacked top to bottom: the moments pass, the blur's
     * first (horizontal) pass, its second (vertical) pass; NaN where a pass did not run or drew into no
     * framebuffer object */
    SL_CAPTURE_MOMENTS_PASSES,
    SL_CAPTURE_CASCADE_INDEX, /* lab 6: image, 1 channel: the cascade each pixel used (-1: none), camera size */
    SL_CAPTURE_FLICKER,    /* lab 6: image, 1 channel: every frame's visibility, stacked: camera width x height * frames */
    /* lab 7: image, 1 channel: one face of the cube map (face f = SL_CAPTURE_CUBE_FACE + f), face size */
    SL_CAPTURE_CUBE_FACE,
    SL_CAPTURE_CUBE_FACE_LAST = SL_CAPTURE_CUBE_FACE + 5,
    SL_CAPTURE_PATH,       /* numbers: the path the framework took (SL_PATH_NUMBERS, see sl_runner.c) */
    SL_CAPTURE_KIND_COUNT,
    /* numbers: the outputs of probe table k, "probe_k"; rows x outputs */
    SL_CAPTURE_PROBE = SL_CAPTURE_KIND_COUNT,
    SL_CAPTURE_END = SL_CAPTURE_PROBE + SL_JOB_MAX_PROBES
} sl_capture_kind;

/* "fbo", "depth_map", ..., "probe_3": the names captures travel under. */
const char *sl_capture_name(int capture);
/* -1 when the name is no capture's. */
int sl_capture_parse(const char *name);

#define SL_FBO_NUMBERS 10     /* see sl_runner.c: status, attachment type, ..., requested size */
#define SL_MATRICES_NUMBERS 48
#define SL_MOMENTS_TARGET_NUMBERS 19 /* see sl_vsm_describe_target */
/* the highest lab whose code drew the last frame; lab 7's cube map drawn layered (1; 2: after an SL_OK that
 * attached no layered cube) */
#define SL_PATH_NUMBERS 2

typedef struct sl_job {
    uint32_t magic, version, size; /* SL_JOB_MAGIC, SL_PROTOCOL_VERSION, sizeof(sl_job) */
    int lab;                       /* the lab the case grades */
    int width, height;             /* the camera image */
    int backend;                   /* sl_backend: the headless GL to render with */
    sl_scene scene;
    sl_light frame_lights[SL_JOB_MAX_FRAMES]; /* the light of each frame; the last frame is captured */
    /* A lab 1 case's: lab 1's light camera for each frame's light (view, projection), the one its depth
     * map is drawn with. It is lab 2's answer for that light, so the grader computes it, no runner can
     * (framework/sl_scene.h), and only lab 1's cases get it: lab 2's code, run in a later lab's case,
     * must not find its own answer in the job. Without it a frame takes sl_light_default_matrices. */
    bool light_cameras_given;
    float frame_light_cameras[SL_JOB_MAX_FRAMES][2][16];
    int frame_count;
    /* lab 6: the camera the cascades are fitted to in each frame (the picture keeps the scene's camera) */
    bool camera_path;
    sl_camera frame_cameras[SL_JOB_MAX_FRAMES];
    sl_render_params params;
    uint32_t captures;             /* bit (1 << capture) per capture wanted; probe k: SL_CAPTURE_PROBE + k */
    sl_probe_table probes[SL_JOB_MAX_PROBES]; /* function "": none */
    char labs_dir[512];            /* the labs tree's shaders, as the runner sees the file system */
    char framework_dir[512];       /* framework/ (its shaders/), likewise */
} sl_job;

typedef enum sl_message_type {
    SL_MSG_HELLO = 1,       /* payload: "backend\nrenderer" once the GL context exists */
    SL_MSG_STAGE,           /* name: the lab function about to run ("" after it returned) */
    SL_MSG_NOT_IMPLEMENTED, /* name: a stub that returned SL_NOT_IMPLEMENTED */
    SL_MSG_FAILED,          /* name: a lab function that returned SL_FAILED */
    SL_MSG_ERROR,           /* payload: why the case could not run (set-up, shader compile error) */
    SL_MSG_CAPTURE_ERROR,   /* name: a capture; payload: why it could not be taken */
    SL_MSG_IMAGE,           /* name: a capture; payload: int32 width, height, channels, then floats */
    SL_MSG_NUMBERS,         /* name: a capture; payload: doubles */
    SL_MSG_RENDER_TIME,     /* payload: one double, the CPU seconds the case's frames took */
    SL_MSG_DONE,            /* every capture was sent */
    SL_MSG_GL_ERROR,        /* name: a lab function; payload: the first error GL reported while it ran */
    SL_MSG_TYPE_END
} sl_message_type;

typedef struct sl_message_header {
    uint32_t type;
    uint32_t name_length;    /* at most SL_MSG_NAME_MAX, no terminator */
    uint64_t payload_length;
} sl_message_header;

#define SL_MSG_NAME_MAX 63
#define SL_MSG_TEXT_MAX 16384      /* ERROR, CAPTURE_ERROR and HELLO payloads */
#define SL_MSG_GL_ERROR_MAX 400    /* a GL_ERROR's text */
#define SL_MSG_GL_ERRORS 8         /* GL_ERROR messages a runner sends at most, one per function */
#define SL_MSG_NUMBERS_MAX (SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS)
#define SL_IMAGE_SIDE_MAX 4096     /* shadow maps and camera images */
#define SL_IMAGE_HEADER_BYTES 12   /* int32 width, height, channels */

#endif
