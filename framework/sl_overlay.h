/* sl_overlay: what the viewer draws over a rendered frame, for lectures and
 * screenshots: panels of text in the window's corners (a small bitmap font
 * built in, so nothing beyond GL 3.3 is needed), labels at pixel positions,
 * wire boxes in the scene (the light's frustum) and markers (the light).
 *
 * It is a list rebuilt every frame: clear, add panels and lines, draw. Any
 * part of the framework can add what its lab has to say, e.g. a panel per
 * cascade with its own colour, or a label on each unfolded cube face:
 *
 *   sl_overlay_clear(ov);
 *   sl_overlay_panel(ov, SL_OVERLAY_TOP_LEFT, "lab 4: PCF & PCSS");
 *   sl_overlay_line(ov, NULL, "filter: grid 3x3");
 *   sl_overlay_label(ov, 20, 40, red, "+X");
 *   sl_overlay_box(ov, inverse_light_view_projection, yellow);
 *   sl_overlay_draw(ov, camera_view_projection, target, width, height);
 *
 * Text is ASCII; other bytes show as '?'. Drawing changes GL state (blending,
 * depth test, the bound program and buffers); the renderer sets what it
 * needs at the start of each frame. */
#ifndef SL_OVERLAY_H
#define SL_OVERLAY_H

#include <stdbool.h>
#include <stddef.h>

#include <cglm/cglm.h>

#include "sl_gl.h"
#include "sl_overlay_types.h"


/* Builds the font texture and the two programs (framework/shaders/overlay_*);
 * needs a current GL context. NULL with a message in err on failure. */
sl_overlay *sl_overlay_create(const char *framework_dir, char *err, size_t err_size);
void sl_overlay_destroy(sl_overlay *ov);

/* Forgets every panel, label and box (call at the start of each frame). */
void sl_overlay_clear(sl_overlay *ov);
/* Font pixel size on screen: 1, 2, 3 ...; 0 (the default) picks one from the
 * framebuffer's size: 1, 2 from 800x480 up, 3 from 1600x1000 up (one more
 * for a lecture). */
void sl_overlay_set_scale(sl_overlay *ov, int scale);
int sl_overlay_scale_for(const sl_overlay *ov, int width, int height);
/* For a lecture hall: text from a TrueType font (sl_overlay_set_font), one
 * step larger, white on black; thin translucent boxes; and the status line. */
void sl_overlay_set_lecture(sl_overlay *ov, bool on);
/* The width in pixels boxes and markers are drawn with: the font scale; for a
 * lecture thin (1 pixel, 2 from 1000 pixels high) and the boxes translucent,
 * so they do not hide the scene they explain. */
int sl_overlay_line_width_for(const sl_overlay *ov, int width, int height);

/* The TrueType font a lecture's text is drawn with (NULL: DejaVu Sans); its
 * panels take DejaVuSansMono.ttf from the same folder. A font that cannot be
 * read is said once on stderr and the bitmap font draws instead. */
void sl_overlay_set_font(sl_overlay *ov, const char *path);
/* Whether a lecture's text is drawn from TrueType (false before the first
 * draw, and when the font could not be read). */
bool sl_overlay_truetype(const sl_overlay *ov);
/* A lecture's one line of text across the top left of the frame, sized from
 * the frame's height (1/27 of it) so it reads from the back of a hall, on a
 * translucent backing: what the frame shows, in a few words. */
void sl_overlay_status_line(sl_overlay *ov, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The status line's text height in pixels for a frame `height` pixels high. */
int sl_overlay_status_height_for(int height);

/* In a line's text, a whole cell of solid colour: a legend's colour sample
 * ("\x7f cascade 0" in the cascade's colour). */
#define SL_OVERLAY_SWATCH "\x7f"

/* Starts a panel in a corner; the lines added next go into it. Panels in the
 * same corner stack away from it (down from the top, up from the bottom).
 * title may be NULL; a title is drawn brighter. False when full. */
bool sl_overlay_panel(sl_overlay *ov, sl_overlay_corner corner, const char *title);
/* A line of text in the current panel (a top-left panel is opened if none
 * is); rgb NULL: light grey. Longer text is cut at 120 characters. */
void sl_overlay_line(sl_overlay *ov, const float *rgb, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* Text with its top-left corner at pixel (x, y) from the framebuffer's
 * top-left, on a dark backing, e.g. the name of a view drawn there. */
void sl_overlay_label(sl_overlay *ov, int x, int y, const float *rgb, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* A wire box in the scene: the cube [-1,1]^3 mapped by `to_world` (e.g. the
 * inverse of a light's projection x view: its frustum). Drawn bright where it
 * is in front of the scene and dim where the scene hides it. A matrix that
 * cannot be inverted upstream (NaNs) is skipped. False when full. */
bool sl_overlay_box(sl_overlay *ov, mat4 to_world, const float *rgb);
/* The same, at full strength through the scene (boxes that reach under the ground). */
bool sl_overlay_box_on_top(sl_overlay *ov, mat4 to_world, const float *rgb);
/* A marker at a world position (a light): a ring with four rays over
 * everything, `text` beside it (may be NULL). Not drawn when it is behind
 * the camera. False when full. */
bool sl_overlay_marker(sl_overlay *ov, const float position[3], const float *rgb, const char *text);

/* Draws everything into framebuffer `target`: boxes with the camera's
 * projection x view (depth-tested against the depth the frame left), then
 * panels and labels on top. */
void sl_overlay_draw(sl_overlay *ov, mat4 camera_view_projection, GLuint target, int width, int height);

/* The text of every panel as plain lines ("[status] text", "[corner] text", "[label] text",
 * "[marker] text"), for tests and logs: what a screenshot shows, in words. */
size_t sl_overlay_text(const sl_overlay *ov, char *out, size_t out_size);

#endif
