/* sl_font: the overlay's bitmap font, drawn for this project: 5x8 glyphs for
 * ASCII 32..126, row 7 for descenders, and after '~' a solid glyph (panels'
 * backings use it, so text and backings are one draw call). */
#ifndef SL_FONT_H
#define SL_FONT_H

#define SL_FONT_GLYPH_W 5
#define SL_FONT_GLYPH_H 8
#define SL_FONT_GLYPHS 96 /* ASCII 32..126, then the solid one */
#define SL_FONT_SOLID 95
/* The atlas: one row of glyphs, each followed by a blank column so neighbours never bleed into each other. */
#define SL_FONT_ATLAS_W (SL_FONT_GLYPHS * (SL_FONT_GLYPH_W + 1))
#define SL_FONT_ATLAS_H SL_FONT_GLYPH_H

/* Fills `texels` (SL_FONT_ATLAS_W x SL_FONT_ATLAS_H, one byte each, rows top down) with the atlas:
 * 255 where a glyph has ink, 0 elsewhere. */
void sl_font_atlas(unsigned char *texels);

#endif
