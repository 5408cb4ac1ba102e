/* sl_lab6_viewer: what the viewer shows of lab 6 (its descriptor, sl_lab6_cascades.c, lists these):
 * its keys, its title and overlay texts, the frozen frustum (the camera above it, its slices and
 * light boxes) and the camera the cascades are fitted to. */
#ifndef SL_LAB6_VIEWER_H
#define SL_LAB6_VIEWER_H

#include "sl_technique.h"

extern const sl_technique_key sl_lab6_keys[];
void sl_lab6_key_pressed(sl_view_context *c, const sl_technique_key *k, int code, bool raise);
void sl_lab6_key_state(const sl_view_context *c, const sl_technique_key *k, char *out, size_t n);
void sl_lab6_settings_text(const sl_view_context *c, char *out, size_t n);
bool sl_lab6_maps_text(const sl_view_context *c, char *out, size_t n);
void sl_lab6_overlay_lines(struct sl_overlay *ov, const sl_view_context *c);
void sl_lab6_frozen_lines(struct sl_overlay *ov, const sl_view_context *c, int width, int height);
void sl_lab6_freeze(sl_render_params *p, const sl_camera *walking, bool on, sl_camera *view);
sl_camera *sl_lab6_fit_camera(sl_render_params *p, const sl_camera *camera);

#endif
