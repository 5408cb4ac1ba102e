/* sl_lab1_4_viewer: what the viewer shows of labs 1-4's shadow-map frame (their title and overlay
 * texts), and labs 2-4's descriptors: they add their steps to lab 1's frame, so they have no frame
 * hooks of their own, only these texts and their functions' probes (sl_probe_calls.c). Lab 1's
 * descriptor (sl_lab1_4_shadow_map.c) lists these. */
#ifndef SL_LAB1_4_VIEWER_H
#define SL_LAB1_4_VIEWER_H

#include "sl_technique.h"

void sl_lab1_settings_text(const sl_view_context *c, char *out, size_t n);
void sl_lab1_drawing_text(const sl_view_context *c, char *out, size_t n);

#endif
