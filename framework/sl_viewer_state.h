/* sl_viewer_state: the viewer's state, shared by its modules (sl_viewer.c the main loop,
 * sl_viewer_options.c the command line, sl_viewer_keys.c the keys and the mouse,
 * sl_viewer_camera.c the camera and the light, sl_viewer_overlay.c what the overlay and the title
 * say, sl_viewer_capture.c screenshots, animations and marked changes). Private to them. */
#ifndef SL_VIEWER_STATE_H
#define SL_VIEWER_STATE_H

#include <stdbool.h>

#include "sl_capture.h"
#include "sl_context.h"
#include "sl_overlay.h"
#include "sl_renderer.h"
#include "sl_serve.h"
#include "sl_technique.h"

/* --split A,B (sl_viewer_split.c): one half of the frame, and what it sets apart from the other half. */
typedef struct _sl_split_side {
    int lab;    /* 0: the viewer's lab */
    int filter; /* -1: the viewer's filter; else an sl_filter_mode */
    int code;   /* -1: the viewer's code (key U); 0: this build's; 1: the second lab code */
} _sl_split_side;

typedef struct _sl_split {
    bool given, on;          /* --split was given; the halves show now (key Y) */
    _sl_split_side sides[2]; /* left, right */
    /* The right half draws with a renderer of its own (its own maps, programs and per-lab state) over the
     * whole frame first; its right half waits in `framebuffer` while the left half draws, then goes back:
     * each half is the single view's picture. */
    sl_renderer right;
    bool right_ready, right_second; /* made; with the second lab code */
    GLuint framebuffer, color;
    int width, height;
} _sl_split;

typedef struct _sl_viewer {
    sl_context *ctx;
    sl_renderer renderer;
    sl_scene scene;
    sl_render_params params;
    bool dragging;
    double last_x, last_y;
    bool dirty_title;
    /* lab 6: the frozen camera's frustum seen from above; the camera to return to */
    bool frozen;
    sl_camera walking_camera;
    double last_frame_time;
    /* Lecture aids: the overlay, the light's frustum, light animation, screenshots on a key. */
    sl_overlay *overlay;
    bool show_overlay, show_frustum, animate_light, screenshot_requested;
    const char *caption; /* --caption: a line at the bottom, overlay or not (figures) */
    const char *frame_dir; /* --frame-dir: every frame saved there (animations for slides) */
    sl_animation *animation; /* --screenshot FILE.gif: every frame into one animated GIF */
    /* --camera-path: the camera moves back and forth by itself (lab 6's shimmer demo). What
     * it added last frame is taken away first, so flying and orbiting still work. */
    int camera_path;       /* _SL_PATH_NONE, _SL_PATH_SLIDE, _SL_PATH_TURN */
    vec3 path_shift;       /* slide: added to the camera's position and target */
    float path_yaw;        /* turn: radians the target is turned about the camera's position */
    bool path_fit_only;    /* --path-fits-cascades: the path moves only the camera lab 6 fits to */
    /* --mark-changes: the first frame, and where a later one differed from it */
    bool mark_changes;
    sl_image first_frame;
    unsigned char *changed;
    const char *keys;      /* --keys: keys pressed before the first frame */
    char status[512];      /* what is drawing instead of the asked lab, as last said ("" when it draws) */
    bool lecture;          /* --lecture: TrueType text, one status line, thin translucent lines */
    bool show_panels;      /* the overlay's panels (I); off: its status line alone (a lecture's default) */
    const char *font;      /* --font: the lecture's TrueType font; NULL: DejaVu Sans */
    int changed_lab, changed_key; /* the last key that changed a setting, and the lab it was pressed in */
    bool labels;           /* --labels: the cascade legend, cube-face labels, the light's marker */
    int text_scale;        /* --text-scale: the overlay's font size; 0: from the frame's size */
    int screenshot_count;
    const char *screenshot_dir; /* where X saves (--screenshot-dir; --serve: shadowlab-screenshots); NULL: here */
    double pass_ms[SL_MAX_PASSES], frame_ms; /* smoothed, for reading */
    const char *pass_names[SL_MAX_PASSES];
    int pass_count;
    /* Student vs solutions (U key): the second renderer draws with the second lab code. */
    sl_renderer second;
    bool second_ready, show_second;
    sl_serve *serve; /* --serve: frames to a browser, its keys and mouse back */
    /* The second lab code (sl_viewer_set_second_labs): NULL in builds without one. */
    const sl_lab_functions *second_functions;
    const char *second_dir, *second_kind;
    unsigned long keys_acted; /* key presses a binding took (--serve's page counts them) */
    _sl_split split; /* --split: two settings side by side */
} _sl_viewer;

enum { _SL_PATH_NONE = 0, _SL_PATH_SLIDE, _SL_PATH_TURN };
/* One period of the path: a GIF of --frames K frames loops without a jump. */
#define _SL_PATH_SECONDS 6.0
#define _SL_PATH_SLIDE_METRES 0.25f /* half the sideways travel */
#define _SL_PATH_TURN_DEGREES 3.0f  /* half the turn */

/* The camera path's name, as --camera-path takes it: "none", "slide", "turn". */
static inline const char *_sl_viewer_path_name(int path) {
    static const char *const names[] = {"none", "slide", "turn"};
    return path >= 0 && path <= _SL_PATH_TURN ? names[path] : "none";
}

/* What a technique's key or text is given of the viewer (sl_technique.h): `info`, the frame last drawn. */
static inline sl_view_context _sl_viewer_context(_sl_viewer *v, const sl_frame_info *info) {
    return (sl_view_context){.params = &v->params, .scene = &v->scene, .info = info, .frozen = v->frozen,
                             .camera_path = v->camera_path ? _sl_viewer_path_name(v->camera_path) : NULL};
}

#endif
