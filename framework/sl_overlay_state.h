/* sl_overlay_state: what a frame's overlay holds, private to the overlay's modules (sl_overlay.c
 * draws it, sl_overlay_layout.c places its panels). */
#ifndef SL_OVERLAY_STATE_H
#define SL_OVERLAY_STATE_H

#include <stdbool.h>
#include <stddef.h>

#include <cglm/cglm.h>

#include "sl_gl.h"
#include "sl_overlay_types.h"
#include "sl_shader.h"
#include "sl_ttf.h"

#define _SL_MAX_PANELS 16
#define _SL_MAX_LINES 96
#define _SL_MAX_LABELS 32
#define _SL_MAX_BOXES 16
#define _SL_MAX_MARKERS 4
#define _SL_LINE_CHARS 121

typedef struct _sl_text_line {
    char text[_SL_LINE_CHARS];
    float rgb[3];
    int panel; /* index into panels, or -1 for a label */
    int x, y;  /* a label's position */
} _sl_text_line;

typedef struct _sl_panel {
    sl_overlay_corner corner;
} _sl_panel;

typedef struct _sl_marker {
    vec3 position;
    float rgb[3];
    char text[32];
} _sl_marker;

/* A TrueType face rasterised at one size, with its texture (sl_ttf.h). */
typedef struct _sl_face {
    sl_ttf_atlas atlas;
    GLuint texture;
} _sl_face;

struct sl_overlay {
    sl_program text_program, line_program;
    GLuint font_texture, text_vao, text_vbo, line_vao, line_vbo;
    int scale;
    bool lecture;
    /* A lecture's TrueType text: the proportional face for the status line, the monospaced one for
     * panels and labels (their columns line up as the bitmap font's do). Made when first drawn; when a
     * font cannot be read the bitmap font stands in, said once. */
    char font_path[SL_PATH_MAX];
    _sl_face sans, mono;
    bool font_failed;
    char status_line[2 * _SL_LINE_CHARS]; /* a lecture's one line (empty: none) */
    _sl_panel panels[_SL_MAX_PANELS];
    int panel_count;
    _sl_text_line lines[_SL_MAX_LINES + _SL_MAX_LABELS + _SL_MAX_MARKERS];
    int line_count, label_count;
    mat4 boxes[_SL_MAX_BOXES];
    float box_rgb[_SL_MAX_BOXES][3];
    bool box_on_top[_SL_MAX_BOXES];
    int box_count;
    _sl_marker markers[_SL_MAX_MARKERS];
    int marker_count;
    float *vertices; /* text quads: x, y, u, v, r, g, b, a */
    size_t vertex_capacity;
    float *line_vertices; /* line quads: clip x, y, z, w, r, g, b, a */
    size_t line_capacity;
};

#endif
