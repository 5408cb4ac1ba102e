#include "sl_ttf.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef SL_HAVE_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#endif

bool sl_ttf_available(void) {
#ifdef SL_HAVE_FREETYPE
    return true;
#else
    return false;
#endif
}

void sl_ttf_atlas_free(sl_ttf_atlas *a) {
    if (!a) return;
    free(a->texels);
    memset(a, 0, sizeof *a);
}

static int _sl_glyph_index(unsigned char c) { return c >= SL_TTF_FIRST && c < SL_TTF_FIRST + SL_TTF_GLYPHS ? c - SL_TTF_FIRST : '?' - SL_TTF_FIRST; }

float sl_ttf_text_width(const sl_ttf_atlas *a, const char *text) {
    float w = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) w += a->glyphs[_sl_glyph_index(*c)].advance;
    return w;
}

bool sl_ttf_atlas_make(const char *path, int pixel_height, sl_ttf_atlas *out, char *err, size_t err_size) {
    memset(out, 0, sizeof *out);
#ifndef SL_HAVE_FREETYPE
    (void)path;
    (void)pixel_height;
    snprintf(err, err_size, "this build has no FreeType (Debian: libfreetype-dev)");
    return false;
#else
    if (pixel_height < 4 || pixel_height > 512) {
        snprintf(err, err_size, "a font size of %d pixels is out of range (4-512)", pixel_height);
        return false;
    }
    /* FreeType's own message for a missing file is a bare code: say it in words first. */
    FILE *probe = fopen(path, "rb");
    if (!probe) {
        snprintf(err, err_size, "no font file %s", path);
        return false;
    }
    fclose(probe);
    FT_Library lib;
    if (FT_Init_FreeType(&lib)) {
        snprintf(err, err_size, "FreeType does not start");
        return false;
    }
    FT_Face face;
    if (FT_New_Face(lib, path, 0, &face)) {
        snprintf(err, err_size, "%s is not a font FreeType reads", path);
        FT_Done_FreeType(lib);
        return false;
    }
    bool ok = FT_Set_Pixel_Sizes(face, 0, (FT_UInt)pixel_height) == 0;
    /* Glyphs side by side in one row, each with a blank texel around it so linear filtering never
     * takes a neighbour's ink; the solid block goes last. */
    int width = 4, height = 4;
    for (int g = 0; ok && g < SL_TTF_GLYPHS; g++) {
        if (FT_Load_Char(face, (FT_ULong)(SL_TTF_FIRST + g), FT_LOAD_RENDER)) continue;
        FT_Bitmap *b = &face->glyph->bitmap;
        width += (int)b->width + 2;
        if ((int)b->rows + 2 > height) height = (int)b->rows + 2;
    }
    if (ok) out->texels = calloc((size_t)width * (size_t)height, 1);
    if (!ok || !out->texels) {
        snprintf(err, err_size, "cannot size %s at %d pixels", path, pixel_height);
        FT_Done_Face(face);
        FT_Done_FreeType(lib);
        return false;
    }
    out->width = width;
    out->height = height;
    out->pixel_height = pixel_height;
    out->ascent = (float)face->size->metrics.ascender / 64.0f;
    out->line_height = (float)face->size->metrics.height / 64.0f;
    int x = 1;
    for (int g = 0; g < SL_TTF_GLYPHS; g++) {
        sl_ttf_glyph *o = &out->glyphs[g];
        if (FT_Load_Char(face, (FT_ULong)(SL_TTF_FIRST + g), FT_LOAD_RENDER)) continue;
        FT_GlyphSlot s = face->glyph;
        FT_Bitmap *b = &s->bitmap;
        o->x = x;
        o->y = 1;
        o->w = (int)b->width;
        o->h = (int)b->rows;
        o->left = s->bitmap_left;
        o->top = s->bitmap_top;
        o->advance = (float)s->advance.x / 64.0f;
        for (int r = 0; r < o->h; r++)
            memcpy(out->texels + (size_t)(o->y + r) * (size_t)width + (size_t)x, b->buffer + (ptrdiff_t)r * b->pitch,
                   (size_t)o->w);
        x += o->w + 2;
    }
    out->solid_x = x;
    out->solid_y = 1;
    for (int r = 0; r < 2; r++) memset(out->texels + (size_t)(1 + r) * (size_t)width + (size_t)x, 255, 2);
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    return true;
#endif
}
