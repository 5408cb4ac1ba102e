/* sl_compare: image comparison that absorbs renderer noise but not mistakes,
 * and the statistics the diagnostics are built from. No GL here.
 *
 * A pixel passes when it is within `threshold` (every channel) of SOME pixel in
 * the other image's 3x3 neighbourhood, both ways (student -> reference and
 * reference -> student); the check passes when the failing fraction is at most
 * `fail_fraction`. Edges that moved by one pixel pass; a missing shadow does not. */
#ifndef SL_COMPARE_H
#define SL_COMPARE_H

#include <stdbool.h>

#include "sl_image.h"

/* How far a pixel may look for its match: the (2 * SL_COMPARE_RADIUS + 1)^2
 * neighbourhood, 3x3. */
#define SL_COMPARE_RADIUS 1

/* A visibility check also fails, whatever its pixel count, when more than
 * SL_VISIBILITY_MAX_SHADOW_LOST of the reference's shadow is lost
 * (sl_visibility_shadow_lost) and that shadow has at least
 * SL_VISIBILITY_MIN_SHADOW_PIXELS pixels. */
#define SL_VISIBILITY_MIN_SHADOW_PIXELS 25
#define SL_VISIBILITY_MAX_SHADOW_LOST 0.5

typedef struct sl_compare_stats {
    bool size_mismatch;
    long pixels, failing, nan_pixels;
    /* Of the failing pixels (not NaN), those whose channel 0 crossed 0.5, read as visibility: lit in the
     * student's where the reference is shadowed (a shadow lost), and shadowed where it is lit (one
     * gained). The rest of the failing pixels are on the same side of 0.5 in both: brightness only. */
    long failing_shadow_lost, failing_shadow_gained;
    double failing_fraction;
    double max_difference;     /* largest plain per-pixel difference */
    double mean_difference;    /* mean plain per-pixel difference (NaN pixels left out): systematic errors */
    double mean_student, mean_reference; /* channel 0 */
} sl_compare_stats;

/* Compares channel by channel; `diff` (may be NULL) receives an RGB image:
 * the reference darkened, failing pixels coloured by kind: red where the
 * student's is brighter (a shadow missing), blue where it is darker (a shadow
 * too many), magenta where it is NaN. */
sl_compare_stats sl_compare_images(const sl_image *student, const sl_image *reference, double threshold,
                                   sl_image *diff);

/* Two-valued terms (visibility): how student and reference disagree.
 * "shadowed" = below 0.5. Fractions of all pixels unless said otherwise. */
typedef struct sl_visibility_stats {
    double reference_shadowed;        /* fraction of pixels in shadow in the reference */
    double student_shadowed;
    double missing_shadow;            /* reference shadowed, student lit: of the reference's shadowed pixels */
    double extra_shadow;              /* reference lit, student shadowed: of the reference's lit pixels */
} sl_visibility_stats;

sl_visibility_stats sl_visibility_compare(const sl_image *student, const sl_image *reference);

/* Of the reference's shadowed pixels (below 0.5; only where `lit_mask`, if
 * given, is lit: surfaces facing the light), the fraction with no shadowed
 * pixel of the student's within one pixel: shadow missing, not moved.
 * `shadowed` receives how many the reference has. The pixel count of a check
 * cannot see a missing shadow that is small next to the image; this can. */
double sl_visibility_shadow_lost(const sl_image *student, const sl_image *reference, const sl_image *lit_mask,
                                 long *shadowed);

/* A check that measures a difference (the flicker between frames, the bleeding
 * with and without a reduction, penumbra widths) is met by a picture that is
 * dark everywhere: it has none. Each such check also fails when more than
 * SL_LIT_MAX_LOST of the surfaces the reference shows lit (at least
 * SL_LIT_MIN_PIXELS of them) are dark or NaN in the student's. */
#define SL_LIT_MAX_LOST 0.05
#define SL_LIT_MIN_PIXELS 100

typedef struct sl_lit_lost {
    long lit;        /* the reference's lit pixels (0.5 and above) where the mask is lit */
    long dark, nan;  /* of those, the student's below 0.5, and NaN */
    double fraction; /* (dark + nan) / lit */
    bool failed;     /* at least SL_LIT_MIN_PIXELS lit, more than SL_LIT_MAX_LOST of them lost */
} sl_lit_lost;

/* `reference` may be frames stacked top to bottom (lab 6's flicker), with a
 * `lit_mask` (may be NULL) of one frame's size: the mask then applies to each. */
sl_lit_lost sl_visibility_lit_lost(const sl_image *student, const sl_image *reference, const sl_image *lit_mask);

/* Lab 6's flicker along a camera path, measured on the receivers: the pixels a
 * lit mask of one frame's size shows facing the light. The picture's camera
 * stays put while the cascades follow the path, so a receiver pixel is one
 * place in the world: a change between lit and shadowed there is flicker. The
 * grader and the viewer's --case measure it with this one function. */
typedef struct sl_flicker {
    long receivers;  /* the mask's lit pixels */
    double score;    /* of the receivers, those changing between consecutive frames, averaged over the frame pairs */
    double shadowed; /* of the receivers, those in shadow, averaged over the frames */
} sl_flicker;

sl_flicker sl_flicker_measure(const sl_image *stacked, const sl_image *lit_mask, int frames);

/* Still frames have no flicker: they must also keep the reference's shadows,
 * at least SL_FLICKER_MIN_SHADOW_KEPT of its shadowed share, wherever the
 * reference has shadow on at least SL_FLICKER_MIN_REFERENCE_SHADOW of the
 * receivers (and the lit surfaces lit, sl_visibility_lit_lost). */
#define SL_FLICKER_MIN_SHADOW_KEPT 0.5
#define SL_FLICKER_MIN_REFERENCE_SHADOW 0.005
bool sl_flicker_shadows_kept(const sl_flicker *yours, const sl_flicker *reference);

/* Lab 5's bleeding check, in the reference's umbra (its visibility at most
 * SL_BLEEDING_UMBRA, on surfaces facing the light): the share of pixels lit
 * above the check's threshold with the reduction may be at most
 * SL_BLEEDING_MAX_KEPT of the share without it, or below SL_BLEEDING_NEGLIGIBLE;
 * an umbra of fewer than SL_BLEEDING_MIN_UMBRA_PIXELS pixels passes. */
#define SL_BLEEDING_UMBRA 0.02
#define SL_BLEEDING_MAX_KEPT 0.5
#define SL_BLEEDING_NEGLIGIBLE 0.01
#define SL_BLEEDING_MIN_UMBRA_PIXELS 100

/* Depth maps: the fraction of texels at (about) `value`, and whether all
 * texels different from `clear` lie inside the lower-left w x h rectangle
 * (GL's origin; images are stored top row first). */
double sl_fraction_equal(const sl_image *image, float value, float tolerance);
bool sl_content_only_in_lower_left(const sl_image *image, float clear, int w, int h);

#endif
