/* sl_capture: read-backs of what a frame drew, as top-down images (row 0 at the top) and numbers: what
 * the grader's runner sends back and the viewer's --case compares. GL only; no lab code runs here. */
#ifndef SL_CAPTURE_H
#define SL_CAPTURE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"
#include "sl_params.h"
#include "sl_protocol.h"
#include "shadowlab.h"

bool sl_capture_framebuffer(GLuint framebuffer, int width, int height, int channels, sl_image *out);
/* The depth texture's texels (1 channel); false if it is not a depth texture. */
bool sl_capture_depth_texture(GLuint texture, sl_image *out, char *err, size_t err_size);

/* One face of a depth cube map as a top-down image (1 channel, face size
 * squared); false with err set if the texture is no depth cube map. */
bool sl_capture_cube_face(GLuint cube, int face, sl_image *out, char *err, size_t err_size);

/* Level 0 of a moments texture (2 channels, top row first), and what the
 * grader checks of the target: framebuffer status, the texture's internal
 * format, width, height, red and green bits, whether it is a float format,
 * the depth attachment's type, then for moments[0] and moments[1] the width of mipmap level 1 (0: none)
 * and the min filter, then framebuffer[1]'s status (0: not a framebuffer), whether moments[0]
 * is framebuffer[0]'s colour attachment, then for the blur's two passes the moments texture each read
 * on unit 0 and the framebuffer each drew into (14-17, from sl_frame_info's vsm_blur_read and
 * vsm_blur_drew: -2 here, the caller fills them in), and moments[0]'s mag filter (18)
 * (SL_MOMENTS_TARGET_NUMBERS numbers). */
bool sl_vsm_capture_moments(GLuint texture, sl_image *out, char *err, size_t err_size);
void sl_vsm_describe_target(const sl_moments_target *t, double out[SL_MOMENTS_TARGET_NUMBERS]);

#endif
