/* sl_case_types: what a grading case is, as data: its checks, their kinds,
 * probe tables and the symptoms a failed check shows. The types alone, so
 * that the modules which read a case's parts (sl_case_probe.c) and sl_case.c
 * which reads the whole both stand on it; sl_case.h has the functions. */
#ifndef SL_CASE_TYPES_H
#define SL_CASE_TYPES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "sl_params.h"
#include "sl_protocol.h"
#include "sl_scene.h"

#define SL_CASE_MAX_CHECKS 8
#define SL_CASE_MAX_FRAMES SL_JOB_MAX_FRAMES

typedef enum sl_check_kind {
    SL_CHECK_FBO,        /* the shadow map's framebuffer and texture (no reference) */
    SL_CHECK_DEPTH_MAP,  /* the depth texture vs reference (EXR) */
    SL_CHECK_MATRICES,   /* lab 2's view, projection, shadow matrix vs reference (JSON) */
    SL_CHECK_VISIBILITY, /* the visibility term vs reference (PNG) */
    SL_CHECK_IMAGE,      /* the shaded image vs reference (PNG) */
    SL_CHECK_PENUMBRA,   /* penumbra widths along probe lines, vs the reference visibility */
    SL_CHECK_PROBE,      /* a student function called on a table of inputs, vs the solution's outputs */
    /* lab 5 */
    SL_CHECK_MOMENTS,         /* the moments before the blur vs reference (2-channel EXR, per channel), and their format */
    SL_CHECK_MOMENTS_BLURRED, /* the moments after the blur, likewise; blur widths along x and y */
    SL_CHECK_BLEEDING,        /* light bleeding in the reference's umbra, with and without the reduction */
    SL_CHECK_CASCADE_INDEX, /* lab 6: the cascade each pixel used vs reference (EXR) */
    SL_CHECK_FLICKER,    /* lab 6: visibility changes on world-fixed pixels along a camera path */
    SL_CHECK_CUBE_FACE,  /* lab 7: one face of the cube map (distance / far) vs reference (EXR) */
    SL_CHECK_KIND_COUNT
} sl_check_kind;

#define SL_CHECK_MAX_PROBES 4

/* What a failed check's capture shows, as the grader measures it; a case's
 * hint names the symptoms it is about ("hint_when"), and is shown only then. */
typedef enum sl_symptom {
    SL_SYMPTOM_NO_SHADOWS,     /* nothing shadowed where the reference has shadows */
    SL_SYMPTOM_MISSING_SHADOW, /* part of the reference's shadow is lit here */
    SL_SYMPTOM_EXTRA_SHADOW,   /* part of the reference's lit area is shadowed here */
    SL_SYMPTOM_ACNE,           /* lit surfaces shadow themselves in a fine pattern */
    SL_SYMPTOM_DETACHED,       /* shadows start away from their casters (Peter Panning) */
    SL_SYMPTOM_SWAPPED,        /* lit and shadowed exchanged */
    SL_SYMPTOM_HARD_EDGES,     /* hard edges where the reference's are soft */
    SL_SYMPTOM_STALE_DEPTH,    /* a depth map with depths nearer than the scene's */
    /* Measured on every failed capture the same way (grader/diagnose/visibility.c): the
     * evidence a function's probe must predict before a message may blame it. */
    SL_SYMPTOM_TOO_DARK,        /* darker than the reference somewhere (a depth map: nearer) */
    SL_SYMPTOM_TOO_LIGHT,       /* lighter than the reference somewhere (a depth map: farther) */
    SL_SYMPTOM_NARROW_PENUMBRA, /* less soft area than the reference's */
    SL_SYMPTOM_WIDE_PENUMBRA,   /* more soft area than the reference's */
    SL_SYMPTOM_GROSS,           /* most of the shadow or of the lit area wrong: no small mistake explains it */
    SL_SYMPTOM_COUNT
} sl_symptom;
/* Every symptom: what a mistake of unknown effect may show. */
#define SL_SYMPTOMS_ANY ((1u << SL_SYMPTOM_COUNT) - 1u)

/* A line across a shadow edge, in pixels of the camera image (x right, y down). */
typedef struct sl_probe {
    char name[32];
    float from[2], to[2];
} sl_probe;

/* How one parameter of a probe's rows varies under --hidden --seed (grader/sl_hidden.c): one
 * draw per check and group, the same for every row, so rows keep their relations. */
typedef enum sl_vary_kind { SL_VARY_NONE, SL_VARY_SCALE, SL_VARY_ADD, SL_VARY_PICK, SL_VARY_TURN } sl_vary_kind;
#define SL_VARY_MAX_PICKS 8
typedef struct sl_probe_vary {
    sl_vary_kind kind;
    float range[4];        /* scale: lo, hi; add: the amplitude of each component (+-); turn: degrees about +y */
    bool homogeneous;      /* add: to the divided coordinate xyz / w (the offset times w) */
    int pick_count;
    float picks[SL_VARY_MAX_PICKS][4]; /* pick: one of these values */
    char group[32];        /* parameters of one group share the draw; default: the parameter's name */
} sl_probe_vary;

typedef struct sl_check {
    char name[64];
    sl_check_kind kind;
    double points;
    bool bonus;           /* extra credit: its points add to the score, not to the maximum */
    double threshold;     /* per pixel (images) */
    double fail_fraction; /* of pixels (images) */
    double epsilon;       /* per matrix element, relative to the largest (matrices) */
    double mean_tolerance; /* of the mean per-pixel difference: systematic errors (images) */
    double binarise;      /* visibility: > 0, both images read as lit (1) at or above it, shadowed (0) below */
    char hint[320];       /* added to the message when the check fails with one of hint_when's symptoms */
    uint32_t hint_when;   /* 1 << sl_symptom; 0: only when no more specific diagnosis was found */
    sl_probe probes[SL_CHECK_MAX_PROBES]; /* penumbra: the first is nearest to the contact */
    int probe_count;
    /* probe: the function (sl_probe_at), its rows of inputs, and what each row tests */
    int function;
    int rows;
    float inputs[SL_PROBE_MAX_ROWS][SL_PROBE_MAX_INPUTS];
    char about[SL_PROBE_MAX_ROWS][256];
    float row_tolerance[SL_PROBE_MAX_ROWS]; /* a row's own tolerance (0: the check's) */
    /* the last generic_rows of the rows are drawn from a seed and judged by the contract's formula
     * (grader/sl_probe_generic.h), not read from the case file or its reference */
    int generic_rows;
    sl_probe_vary vary[SL_PROBE_MAX_PARAMS]; /* by parameter: how hidden variants change it ("vary") */
    uint32_t row_keep[SL_PROBE_MAX_ROWS];    /* 1 << parameter: the row keeps it as written ("keep") */
    double tolerance, relative; /* an output passes within tolerance + relative * |expected| */
    /* by output: how far above the expected value it may also be ("above"), where the README lets a
     * value be rounded up (lab 6's sphere radius) */
    float above[SL_PROBE_MAX_OUTPUTS];
    int face;             /* cube_face: 0..5, GL's order (+x, -x, +y, -y, +z, -z) */
} sl_check;

typedef struct sl_case {
    char name[96];
    char path[1024];
    int lab;
    char title[160];
    sl_scene scene;
    sl_light frame_lights[SL_CASE_MAX_FRAMES]; /* the light of each frame; the last one is captured */
    int frame_count;
    /* lab 6's "camera_path": the camera the cascades are fitted to, per frame */
    bool camera_path;
    sl_camera frame_cameras[SL_CASE_MAX_FRAMES];
    sl_render_params params;
    int width, height;
    double timeout_seconds;
    double memory_mb;     /* the runner's address space (default 4096) */
    double reference_cpu_seconds; /* the solutions' runner's CPU time for the case (references' manifest); 0: unknown */
    sl_check checks[SL_CASE_MAX_CHECKS];
    int check_count;
} sl_case;

#endif
