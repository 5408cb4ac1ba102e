/* sl_diag_words: the words a message chooses for what it measured, so that
 * every lab says them the same way: how large an effect is, and which slip of
 * units an angle read back from a matrix matches. A message says the slip
 * rather than a raw angle the student never wrote ("the field of view is 117
 * degrees" for glm_perspective(90.0f, ...)). */
#ifndef SL_DIAG_WORDS_H
#define SL_DIAG_WORDS_H

#include <stdbool.h>
#include <stddef.h>

/* How much light a surface lit in the reference lost, as one word. Below
 * SL_DIAG_SLIGHT_LOSS of the light (a mean visibility above 0.9) "slightly",
 * below SL_DIAG_NOTICEABLE_LOSS "noticeably", from there on "strongly". */
#define SL_DIAG_SLIGHT_LOSS 0.10
#define SL_DIAG_NOTICEABLE_LOSS 0.30
const char *sl_diag_darkening_word(double mean_visibility);

/* How much of the reference's lit area is shadowed here, as the words a message starts with: "almost
 * everything" from SL_DIAG_ALMOST_ALL of it, "most of the lit area" below (the messages that use it
 * fire from half of it on). */
#define SL_DIAG_ALMOST_ALL 0.90
const char *sl_diag_shadowed_share_words(double fraction_of_lit);

/* The field of view, in degrees, that glm_perspective's matrix was made
 * with, from its m11 = 1 / tan(fovy / 2): the angle folded into (0, 180),
 * as the matrix shows it; NaN when m11 is 0 or not a number. */
double sl_diag_perspective_fov_deg(double m11);

/* A field of view read back from glm_perspective's m11 against the one the
 * contract asks for (expected_deg, in degrees), which the student writes as
 * `expression` ("90.0f", "2 * spot_angle_deg"). When m11 is what a slip of
 * units gives, writes it into text and returns true:
 *   the degrees passed as radians:  "90 was passed as radians: use glm_rad(90.0f)"
 *   glm_rad applied twice (radians taken for degrees): "glm_rad was applied twice: ..."
 * False, text untouched, when neither fits. */
bool sl_diag_angle_slip(double m11, double expected_deg, const char *expression, char *text, size_t n);

#endif
