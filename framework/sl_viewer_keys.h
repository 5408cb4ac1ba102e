/* sl_viewer_keys: the viewer's keys and mouse (private to the viewer's modules). The key table is
 * the union of the viewer's common keys and each technique's own (sl_technique.keys), read by
 * the dispatch, --help, --list-keys, the --serve page's table and the overlay's key panel. */
#ifndef SL_VIEWER_KEYS_H
#define SL_VIEWER_KEYS_H

#include <stdio.h>

#include "sl_viewer_state.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* The viewer that keys pressed without a window (--keys, the --serve page) act on. */
void _sl_viewer_keys_attach(_sl_viewer *v);
/* A key pressed in window `w` (GLFW's key callback), or with w NULL for the attached viewer. */
void _sl_viewer_key(GLFWwindow *w, int key, int scancode, int action, int mods);
/* W A S D Q E held (in the window `w`, or on the --serve page when w is NULL) move the camera, in every lab
 * but where the lab takes a letter for a key of its own (lab 7's S). */
void _sl_viewer_fly(_sl_viewer *v, GLFWwindow *w, double now);
/* The window's key, button, cursor and wheel callbacks. */
void _sl_viewer_input_callbacks(GLFWwindow *window);
/* The --serve page's keys, button, pointer and wheel since the last frame. */
void _sl_viewer_serve_events(_sl_viewer *v);
/* --help's keys; --list-keys' lines (LAB<tab>KEYS<tab>WHAT); the page's key table and the
 * lab `lab` it starts in (JSON, cJSON_free it). */
void _sl_viewer_print_keys(FILE *f);
void _sl_viewer_list_keys(FILE *f);
char *_sl_viewer_keys_json(int lab);
/* The setting the last key pressed in this lab changed, as it is now ("filter: grid"); false when none. */
bool _sl_viewer_last_change(_sl_viewer *v, const sl_frame_info *info, char *out, size_t n);
/* The overlay's key panel (bottom left): the lab's keys with what they set now, then the general ones. */
void _sl_viewer_key_panel(_sl_viewer *v, const sl_frame_info *info);

#endif
