/* sl_case_view_pictures: what the viewer's --case makes of a check's pictures, without GL: which
 * checks have one, how depths are stretched, the legends, flicker's marks, one channel. */
#ifndef SL_CASE_VIEW_PICTURES_H
#define SL_CASE_VIEW_PICTURES_H

#include <stdbool.h>

#include "sl_case.h"
#include "sl_image.h"

/* Checks whose capture is a picture the reference can be set beside (probes and matrices are numbers). */
bool _sl_case_view_has_picture(sl_check_kind k);
/* Maps and per-texel buffers, square and shown scaled. */
bool _sl_case_view_is_map(sl_check_kind k);
/* Depths and distances, each picture stretched to its own range. */
bool _sl_case_view_is_distance(sl_check_kind k);
/* The smallest and largest finite value of channel 0 (a depth map's cleared texels left out). */
bool _sl_case_view_value_range(const sl_image *img, sl_check_kind kind, float out[2]);
/* The difference panel's colours' meanings; what the panels show. */
void _sl_case_view_diff_legend(sl_check_kind k, const char **red, const char **blue);
const char *_sl_case_view_legend(sl_check_kind k);
/* Flicker: the last of `frames` stacked frames, with the receivers (the lit mask's pixels) that change between
 * lit and shadowed from one frame to the next in red: what sl_flicker_measure counts. */
sl_image _sl_case_view_flicker_marks(const sl_image *stacked, const sl_image *lit_mask, int frames);
/* The panels' own legend where they carry marks (flicker's red); NULL where they have none. */
const char *_sl_case_view_marks_legend(sl_check_kind k);
/* The last frame of a stack (a view into it: not to be freed). */
sl_image _sl_case_view_last_frame(const sl_image *stacked, int frames);
/* One channel of an image, as an image of its own. */
sl_image _sl_case_view_channel(const sl_image *img, int channel);

#endif
