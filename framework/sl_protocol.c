#include "sl_protocol.h"

#include <string.h>

static const char *const _sl_capture_names[SL_CAPTURE_KIND_COUNT] = {
    "fbo", "depth_map", "matrices", "visibility", "lit_mask", "image",
};

const char *sl_capture_name(sl_capture_kind kind) {
    return (unsigned)kind < SL_CAPTURE_KIND_COUNT ? _sl_capture_names[kind] : "?";
}

int sl_capture_parse(const char *name) {
    for (int i = 0; i < SL_CAPTURE_KIND_COUNT; i++)
        if (strcmp(name, _sl_capture_names[i]) == 0) return i;
    return -1;
}
