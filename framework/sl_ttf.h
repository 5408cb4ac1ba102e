/* sl_ttf: TrueType text for the lecture overlay, rasterised with FreeType into one atlas of
 * ASCII 32..126 at a pixel height chosen from the window (so it reads from the back of a hall, where
 * the built-in 5x8 font scaled up shows its blocks). A build without FreeType, or a missing font
 * file, makes no atlas and says why; the overlay then keeps its bitmap font. */
#ifndef SL_TTF_H
#define SL_TTF_H

#include <stdbool.h>
#include <stddef.h>

#define SL_TTF_FIRST 32
#define SL_TTF_GLYPHS 95 /* ASCII 32..126 */

/* Debian's fonts-dejavu-core: the proportional face for a line of text, the monospaced one for
 * panels whose columns line up. */
#define SL_TTF_DEFAULT_SANS "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#define SL_TTF_DEFAULT_MONO "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf"

typedef struct sl_ttf_glyph {
    int x, y, w, h;       /* its box in the atlas, in texels */
    int left, top;        /* the box's offset from the pen: right of it, up from the baseline */
    float advance;        /* how far the pen moves, in pixels */
} sl_ttf_glyph;

typedef struct sl_ttf_atlas {
    unsigned char *texels; /* width x height, one byte of coverage each, rows top down */
    int width, height;
    int pixel_height;      /* the size asked for */
    float ascent, line_height; /* pixels from a line's top to its baseline, and between baselines */
    sl_ttf_glyph glyphs[SL_TTF_GLYPHS];
    int solid_x, solid_y;  /* a 2x2 block of full coverage: backings drawn from the same texture */
} sl_ttf_atlas;

/* Whether this build can read TrueType fonts at all. */
bool sl_ttf_available(void);
/* Rasterises the font file at `path` with glyphs `pixel_height` pixels high (its em). False with the
 * reason in err (no such file, not a font, no FreeType in this build); `out` then holds nothing. */
bool sl_ttf_atlas_make(const char *path, int pixel_height, sl_ttf_atlas *out, char *err, size_t err_size);
void sl_ttf_atlas_free(sl_ttf_atlas *a);
/* The width in pixels of `text` on one line (bytes outside ASCII 32..126 count as '?'). */
float sl_ttf_text_width(const sl_ttf_atlas *a, const char *text);

#endif
