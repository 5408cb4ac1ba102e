#include "sl_case_view_pictures.h"

#include <math.h>

/* Checks whose capture is a picture the reference can be set beside (probes and
 * matrices are numbers). Flicker's capture is every frame of a camera path,
 * stacked: it is shown as its last frame with what changed along the path in red. */
bool _sl_case_view_has_picture(sl_check_kind k) {
    switch (k) {
    case SL_CHECK_VISIBILITY: case SL_CHECK_PENUMBRA: case SL_CHECK_BLEEDING: case SL_CHECK_DEPTH_MAP:
    case SL_CHECK_IMAGE: case SL_CHECK_MOMENTS: case SL_CHECK_MOMENTS_BLURRED: case SL_CHECK_CASCADE_INDEX:
    case SL_CHECK_CUBE_FACE: case SL_CHECK_FLICKER:
        return true;
    default:
        return false;
    }
}

/* Maps and per-texel buffers are square and shown scaled; pictures at the camera's size. */
bool _sl_case_view_is_map(sl_check_kind k) {
    return k == SL_CHECK_DEPTH_MAP || k == SL_CHECK_MOMENTS || k == SL_CHECK_MOMENTS_BLURRED || k == SL_CHECK_CUBE_FACE;
}

/* Depths and distances: their values crowd a small part of 0..1, so each picture is stretched. */
bool _sl_case_view_is_distance(sl_check_kind k) { return k == SL_CHECK_DEPTH_MAP || k == SL_CHECK_CUBE_FACE; }

/* The smallest and largest finite value of channel 0; false if there is none. A
 * depth map's texels the clear left at 1 (nothing drawn there) are left out
 * when it has others, so the drawn ones get the whole grey scale. */
bool _sl_case_view_value_range(const sl_image *img, sl_check_kind kind, float out[2]) {
    bool any = false, drawn = false;
    for (long i = 0; kind == SL_CHECK_DEPTH_MAP && img->data && i < (long)img->width * img->height && !drawn; i++)
        drawn = img->data[i * img->channels] < 1.0f;
    for (long i = 0; img->data && i < (long)img->width * img->height; i++) {
        float x = img->data[i * img->channels];
        if (!isfinite(x) || (drawn && x >= 1.0f)) continue;
        if (!any || x < out[0]) out[0] = x;
        if (!any || x > out[1]) out[1] = x;
        any = true;
    }
    return any;
}

/* The difference panel's colours where yours and the reference's disagree: red (yours brighter), blue. */
void _sl_case_view_diff_legend(sl_check_kind k, const char **red, const char **blue) {
    switch (k) {
    case SL_CHECK_DEPTH_MAP: case SL_CHECK_CUBE_FACE: *red = "red: yours farther", *blue = "blue: yours nearer"; break;
    case SL_CHECK_MOMENTS: case SL_CHECK_MOMENTS_BLURRED: case SL_CHECK_CASCADE_INDEX:
        *red = "red: yours higher", *blue = "blue: yours lower";
        break;
    default: *red = "red: a shadow missing", *blue = "blue: one too many"; break;
    }
}

/* What the panels show, for the title and the terminal. */
const char *_sl_case_view_legend(sl_check_kind k) {
    switch (k) {
    case SL_CHECK_DEPTH_MAP: return "depth (black nearest, white farthest of each picture's own range)";
    case SL_CHECK_CUBE_FACE: return "distance / far (black nearest, white farthest of each picture's own range)";
    case SL_CHECK_MOMENTS: case SL_CHECK_MOMENTS_BLURRED: return "moments (red: depth, green: depth squared)";
    case SL_CHECK_CASCADE_INDEX: return "cascade (red 0, green 1, blue 2, yellow 3, grey none)";
    case SL_CHECK_IMAGE: return "shaded image";
    case SL_CHECK_FLICKER:
        return "the last frame of the path, in red the receivers (surfaces facing the light) that change between "
               "lit and shadowed from one frame to the next";
    default: return "visibility (white lit, black shadow)";
    }
}

/* Flicker: of a path's frames stacked top to bottom (each the mask's size),
 * the last frame in grey with every receiver that changes between lit and
 * shadowed (or to or from NaN) between two consecutive frames in red: the
 * changes sl_flicker_measure counts. Without a mask of the frame's size, no marks. */
sl_image _sl_case_view_flicker_marks(const sl_image *stacked, const sl_image *lit_mask, int frames) {
    int w = stacked->width, h = frames > 0 ? stacked->height / frames : 0;
    sl_image out = sl_image_alloc(w, h, 3);
    if (!out.data || !stacked->data || frames < 1) return out;
    bool masked = lit_mask->data && lit_mask->width == w && lit_mask->height == h;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            bool changed = false;
            for (int f = 1; masked && f < frames && !changed; f++) {
                if (sl_image_pixel(lit_mask, x, y)[0] < 0.5f) break;
                float now = sl_image_pixel(stacked, x, f * h + y)[0];
                float before = sl_image_pixel(stacked, x, (f - 1) * h + y)[0];
                changed = (now >= 0.5f) != (before >= 0.5f) || isnan(now) != isnan(before);
            }
            float grey = sl_image_pixel(stacked, x, (frames - 1) * h + y)[0];
            float *q = sl_image_pixel(&out, x, y);
            q[0] = changed ? 1 : grey, q[1] = changed ? 0.05f : grey, q[2] = changed ? 0.05f : grey;
        }
    return out;
}

const char *_sl_case_view_marks_legend(sl_check_kind k) {
    return k == SL_CHECK_FLICKER ? "red: changed between frames" : NULL;
}

/* The last frame of a path's stack (a view into it: not to be freed). */
sl_image _sl_case_view_last_frame(const sl_image *stacked, int frames) {
    int h = frames > 0 ? stacked->height / frames : stacked->height;
    sl_image last = *stacked;
    last.height = h;
    if (stacked->data && frames > 0) last.data = stacked->data + (size_t)(frames - 1) * (size_t)h * (size_t)stacked->width * (size_t)stacked->channels;
    return last;
}

/* One channel of an image, as an image of its own (the grader compares lab 5's moments per channel). */
sl_image _sl_case_view_channel(const sl_image *img, int channel) {
    sl_image out = sl_image_alloc(img->width, img->height, 1);
    for (long i = 0; out.data && i < (long)img->width * img->height; i++) out.data[i] = img->data[i * img->channels + channel];
    return out;
}

