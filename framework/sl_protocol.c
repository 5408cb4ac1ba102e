#include "sl_protocol.h"

#include <string.h>

static const char *const _sl_capture_names[SL_CAPTURE_END] = {
    "fbo", "depth_map", "matrices", "visibility", "lit_mask", "image",
    "moments", "moments_blurred", "moments_target", "visibility_unreduced", "moments_passes", "cascade_index", "flicker",
    "cube_face_0", "cube_face_1", "cube_face_2", "cube_face_3", "cube_face_4", "cube_face_5", "path",
    "probe_0", "probe_1", "probe_2", "probe_3", "probe_4", "probe_5", "probe_6", "probe_7",
};
_Static_assert(SL_CAPTURE_END == 28 && SL_CAPTURE_END <= 32, /* captures are bits of a uint32_t */ "a name for every capture");

const char *sl_capture_name(int capture) {
    return capture >= 0 && capture < SL_CAPTURE_END ? _sl_capture_names[capture] : "?";
}

int sl_capture_parse(const char *name) {
    for (int i = 0; i < SL_CAPTURE_END; i++)
        if (strcmp(name, _sl_capture_names[i]) == 0) return i;
    return -1;
}
