/* sl_case_view_state: the state of the viewer's --case (sl_case_view.c), shared with its drawing
 * (sl_case_view_draw.c). Private to them. */
#ifndef SL_CASE_VIEW_STATE_H
#define SL_CASE_VIEW_STATE_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_compare.h"
#include "sl_context.h"
#include "sl_overlay.h"
#include "sl_renderer.h"

enum { _SL_STUDENT, _SL_REFERENCE, _SL_DIFF, _SL_PANELS };

#define _SL_MAX_SHOWN 16

typedef struct _sl_case_view {
    sl_case c;
    const sl_check *check;        /* the check shown */
    const sl_check *shown[_SL_MAX_SHOWN]; /* every check with a picture, in the case's order (C cycles) */
    int shown_count, shown_index;
    const char *references_dir;
    sl_image reference;
    int panel_size[_SL_PANELS][2]; /* each panel's picture size, drawn with its aspect kept */
    sl_image lit_mask;             /* flicker: the receivers, as the solutions drew them (the grader's lit_mask.exr) */
    sl_flicker reference_flicker;  /* flicker: the reference's, measured as the grader measures it */
    sl_context *ctx;
    sl_renderer renderer;
    sl_program panel_program;
    GLuint textures[_SL_PANELS], vao, target_fbo, target_texture, target_depth;
    bool side_by_side, show_reference, show_diff;
    int scale;
    char summary[320];   /* what this render scores, as the grader counts it */
    char criterion[400]; /* how the grader decides the check, from the case and the compare code */
    /* depth and distance pictures are stretched to their own range: each panel's, for its label */
    bool stretched[_SL_PANELS];
    float range[_SL_PANELS][2];
    sl_overlay *overlay;   /* the panels' labels and the summary */
    int band;              /* pixels below the panels for the summary */
    int text_scale;
} _sl_case_view;

#define _SL_BAND_LINES 4

#endif
