/* sl_case_view_draw: the viewer's --case on screen: its panels (yours, the reference, their
 * difference), their labels, the summary and criterion under them, the window's title. */
#ifndef SL_CASE_VIEW_DRAW_H
#define SL_CASE_VIEW_DRAW_H

#include "sl_case_view_state.h"

/* The panels and their words into the default framebuffer (width x height). */
void _sl_case_view_draw(_sl_case_view *v, int width, int height);
/* Whether the summary and the criterion fit the band under the panels, as drawn at width x height. */
bool _sl_case_view_band_fits(_sl_case_view *v, int width, int height);
/* The window's title: the summary, the layout, the legend. */
void _sl_case_view_title(_sl_case_view *v);

#endif
