/* sl_viewer_overlay: what the viewer says (private to the viewer's modules): the window's title,
 * what draws instead of the asked lab and why, the overlay's panels, labels and pass times. */
#ifndef SL_VIEWER_OVERLAY_H
#define SL_VIEWER_OVERLAY_H

#include "sl_viewer_state.h"

/* The window's title: the lab, the scene, the settings of what draws. */
void _sl_viewer_update_title(_sl_viewer *v);
/* The pass times of renderer r's last frame, smoothed when `smooth`. */
void _sl_viewer_update_timing(_sl_viewer *v, sl_renderer *r, double frame_seconds, bool smooth);
/* Why the asked lab's technique is not what draws, and what does ("" when it draws). */
void _sl_viewer_status(_sl_viewer *v, const sl_frame_info *info, char *out, size_t n);
/* The light's frustum as lines. */
void _sl_viewer_add_frustum(sl_overlay *ov, const sl_frame_info *info);
/* The labels of what is drawn, and the frozen frustum's lines. */
void _sl_viewer_labels(_sl_viewer *v, const sl_frame_info *info, int width, int height, bool labels);
/* The overlay's panels; the key panel too when `windowed`. */
void _sl_viewer_overlay_fill(_sl_viewer *v, const sl_renderer *r, int width, int height, bool windowed);

#endif
