/* sl_viewer_capture: what the viewer saves (private to the viewer's modules): screenshots, the
 * frames of an animated GIF, and --mark-changes' first frame with what later frames changed. */
#ifndef SL_VIEWER_CAPTURE_H
#define SL_VIEWER_CAPTURE_H

#include "sl_viewer_state.h"

/* Whether `path` names a GIF (--screenshot FILE.gif: every frame into one animation). */
bool _sl_viewer_is_gif(const char *path);
/* Adds the frame in `target` to the animation at `path` (opened on the first frame). */
bool _sl_viewer_add_frame(_sl_viewer *v, GLuint target, int width, int height, const char *path);
/* Remembers the first frame, then marks the pixels each later one changed. */
bool _sl_viewer_mark_changes(_sl_viewer *v, GLuint target, int width, int height);
/* The first frame with the changed pixels in red (and the overlay over it) into `path`. */
bool _sl_viewer_save_changes(_sl_viewer *v, const char *path, int frames, bool overlay, mat4 camera, GLuint target);
/* The frame in `target` as a PNG at `path`. */
bool _sl_viewer_save(GLuint target, int width, int height, const char *path);
/* Makes the screenshots' folder (one level) unless it is there; false, said on stderr, if it
 * cannot be made or is not a folder. */
bool _sl_viewer_screenshot_dir_make(const char *dir);
/* The X key: shadowlab-NNN.png in v->screenshot_dir (NULL: the current folder), never overwriting. */
void _sl_viewer_screenshot_key(_sl_viewer *v, GLuint target, int width, int height);

#endif
