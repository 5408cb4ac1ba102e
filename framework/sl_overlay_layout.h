/* sl_overlay_layout: where the overlay's panels go in a frame of a given size, and how their lines
 * break into rows. Private to the overlay (sl_overlay.c draws what this places).
 * Each corner's panels stack away from it; a line too long for the frame wraps at a space (its rest
 * indented by two); a panel at the bottom moves up above a label it would cover (the names of what a lab
 * draws there: lab 6's layers, lab 7's faces); a right-hand panel too wide to sit beside the left ones
 * starts below (or above) them. */
#ifndef SL_OVERLAY_LAYOUT_H
#define SL_OVERLAY_LAYOUT_H

#include "sl_overlay_state.h"

#define _SL_MAX_ROWS (2 * _SL_MAX_LINES)
typedef struct _sl_row {
    int line, start, length; /* the part of lines[line] this row shows */
    bool indent;
} _sl_row;
typedef struct _sl_layout {
    _sl_row rows[_SL_MAX_ROWS];
    int row_count;
    float panel_x[_SL_MAX_PANELS], panel_y[_SL_MAX_PANELS], panel_w[_SL_MAX_PANELS], panel_h[_SL_MAX_PANELS];
    bool fits; /* no panel covers another or a label, and all are inside the frame */
} _sl_layout;

/* Lays out `ov`'s panels at font scale `s` in a width x height frame; `labels` of its labels are the
 * frame's own (the rest are markers' texts, which panels may cover). L->fits says whether all fit. */
void _sl_overlay_lay_out(const sl_overlay *ov, int s, int width, int height, int labels, _sl_layout *L);

#endif
