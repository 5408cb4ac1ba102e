#include "sl_overlay.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_font.h"
#include "sl_overlay_layout.h"
#include "sl_overlay_state.h"
#include "sl_shader.h"
#include "sl_ttf.h"

static const float _sl_default_rgb[3] = {0.85f, 0.85f, 0.85f}, _sl_lecture_rgb[3] = {1, 1, 1};
static const float _sl_title_rgb[3] = {1.0f, 0.85f, 0.35f}, _sl_lecture_title_rgb[3] = {1.0f, 0.92f, 0.2f};

sl_overlay *sl_overlay_create(const char *framework_dir, char *err, size_t err_size) {
    sl_overlay *ov = calloc(1, sizeof *ov);
    if (!ov) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    char shaders[SL_PATH_MAX], vs[SL_PATH_MAX + 32], fs[SL_PATH_MAX + 32];
    snprintf(shaders, sizeof shaders, "%s/shaders", framework_dir);
    snprintf(vs, sizeof vs, "%s/overlay_text.vert", shaders);
    snprintf(fs, sizeof fs, "%s/overlay_text.frag", shaders);
    sl_shader_desc td = {.vertex_path = vs, .fragment_path = fs, .search_dirs = {shaders}};
    if (!sl_program_build(&ov->text_program, &td, err, err_size)) {
        free(ov);
        return NULL;
    }
    snprintf(vs, sizeof vs, "%s/overlay_lines.vert", shaders);
    snprintf(fs, sizeof fs, "%s/overlay_lines.frag", shaders);
    sl_shader_desc ld = {.vertex_path = vs, .fragment_path = fs, .search_dirs = {shaders}};
    if (!sl_program_build(&ov->line_program, &ld, err, err_size)) {
        sl_program_destroy(&ov->text_program);
        free(ov);
        return NULL;
    }
    /* The font as one row of glyphs (sl_font.h). */
    enum { W = SL_FONT_ATLAS_W, H = SL_FONT_ATLAS_H };
    static unsigned char texels[W * H];
    sl_font_atlas(texels);
    glGenTextures(1, &ov->font_texture);
    glBindTexture(GL_TEXTURE_2D, ov->font_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, W, H, 0, GL_RED, GL_UNSIGNED_BYTE, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenVertexArrays(1, &ov->text_vao);
    glGenBuffers(1, &ov->text_vbo);
    glBindVertexArray(ov->text_vao);
    glBindBuffer(GL_ARRAY_BUFFER, ov->text_vbo);
    GLsizei stride = 8 * sizeof(float);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, (void *)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, (void *)(2 * sizeof(float)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, (void *)(4 * sizeof(float)));
    glGenVertexArrays(1, &ov->line_vao);
    glGenBuffers(1, &ov->line_vbo);
    glBindVertexArray(ov->line_vao);
    glBindBuffer(GL_ARRAY_BUFFER, ov->line_vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, (void *)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (void *)(4 * sizeof(float)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    sl_overlay_set_font(ov, NULL);
    return ov;
}

static void _sl_face_free(_sl_face *f) {
    if (f->texture) glDeleteTextures(1, &f->texture);
    f->texture = 0;
    sl_ttf_atlas_free(&f->atlas);
}

void sl_overlay_destroy(sl_overlay *ov) {
    if (!ov) return;
    sl_program_destroy(&ov->text_program);
    sl_program_destroy(&ov->line_program);
    glDeleteTextures(1, &ov->font_texture);
    _sl_face_free(&ov->sans);
    _sl_face_free(&ov->mono);
    glDeleteBuffers(1, &ov->text_vbo);
    glDeleteBuffers(1, &ov->line_vbo);
    glDeleteVertexArrays(1, &ov->text_vao);
    glDeleteVertexArrays(1, &ov->line_vao);
    free(ov->vertices);
    free(ov->line_vertices);
    free(ov);
}

void sl_overlay_clear(sl_overlay *ov) {
    ov->panel_count = 0;
    ov->line_count = 0;
    ov->label_count = 0;
    ov->box_count = 0;
    ov->marker_count = 0;
    ov->status_line[0] = '\0';
}

void sl_overlay_set_scale(sl_overlay *ov, int scale) { ov->scale = scale < 0 ? 0 : scale; }

void sl_overlay_set_lecture(sl_overlay *ov, bool on) { ov->lecture = on; }

int sl_overlay_scale_for(const sl_overlay *ov, int width, int height) {
    if (ov->scale > 0) return ov->scale;
    /* Big enough to read across a lecture hall, small enough to leave the scene visible. */
    return 1 + (width >= 800 && height >= 480) + (width >= 1600 && height >= 1000) + (ov->lecture ? 1 : 0);
}

int sl_overlay_line_width_for(const sl_overlay *ov, int width, int height) {
    /* In a hall the lines explain the picture; wide ones hide it (a frustum's edges crossed the scene). */
    if (ov->lecture) return height >= 1000 ? 2 : 1;
    return sl_overlay_scale_for(ov, width, height);
}

void sl_overlay_set_font(sl_overlay *ov, const char *path) {
    snprintf(ov->font_path, sizeof ov->font_path, "%s", path ? path : SL_TTF_DEFAULT_SANS);
    _sl_face_free(&ov->sans);
    _sl_face_free(&ov->mono);
    ov->font_failed = false;
}

bool sl_overlay_truetype(const sl_overlay *ov) { return ov->lecture && !ov->font_failed && ov->sans.texture; }

int sl_overlay_status_height_for(int height) {
    /* 40 pixels at 1080, 27 at 720: read from the back row of a hall on a projector of either */
    int px = height / 27;
    return px < 8 ? 8 : px;
}

void sl_overlay_status_line(sl_overlay *ov, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ov->status_line, sizeof ov->status_line, fmt, ap);
    va_end(ap);
}

bool sl_overlay_panel(sl_overlay *ov, sl_overlay_corner corner, const char *title) {
    if (ov->panel_count >= _SL_MAX_PANELS || corner < 0 || corner >= SL_OVERLAY_CORNER_COUNT) return false;
    ov->panels[ov->panel_count++] = (_sl_panel){.corner = corner};
    if (title) sl_overlay_line(ov, ov->lecture ? _sl_lecture_title_rgb : _sl_title_rgb, "%s", title);
    return true;
}

static _sl_text_line *_sl_new_line(sl_overlay *ov, const float *rgb, int panel, const char *fmt, va_list ap) {
    if (ov->line_count + ov->label_count >= _SL_MAX_LINES + _SL_MAX_LABELS) return NULL;
    _sl_text_line *l = &ov->lines[ov->line_count + ov->label_count];
    vsnprintf(l->text, sizeof l->text, fmt, ap);
    memcpy(l->rgb, rgb ? rgb : ov->lecture ? _sl_lecture_rgb : _sl_default_rgb, sizeof l->rgb);
    l->panel = panel;
    return l;
}

void sl_overlay_line(sl_overlay *ov, const float *rgb, const char *fmt, ...) {
    if (ov->panel_count == 0) sl_overlay_panel(ov, SL_OVERLAY_TOP_LEFT, NULL);
    if (ov->line_count >= _SL_MAX_LINES) return;
    va_list ap;
    va_start(ap, fmt);
    _sl_text_line *l = _sl_new_line(ov, rgb, ov->panel_count - 1, fmt, ap);
    va_end(ap);
    if (l) ov->line_count++;
}

void sl_overlay_label(sl_overlay *ov, int x, int y, const float *rgb, const char *fmt, ...) {
    if (ov->label_count >= _SL_MAX_LABELS) return;
    va_list ap;
    va_start(ap, fmt);
    _sl_text_line *l = _sl_new_line(ov, rgb, -1, fmt, ap);
    va_end(ap);
    if (!l) return;
    l->x = x;
    l->y = y;
    ov->label_count++;
}

static bool _sl_add_box(sl_overlay *ov, mat4 to_world, const float *rgb, bool on_top) {
    if (ov->box_count >= _SL_MAX_BOXES) return false;
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            if (!isfinite(to_world[c][r])) return false;
    glm_mat4_copy(to_world, ov->boxes[ov->box_count]);
    memcpy(ov->box_rgb[ov->box_count], rgb ? rgb : _sl_title_rgb, sizeof ov->box_rgb[0]);
    ov->box_on_top[ov->box_count] = on_top;
    ov->box_count++;
    return true;
}

bool sl_overlay_box(sl_overlay *ov, mat4 to_world, const float *rgb) { return _sl_add_box(ov, to_world, rgb, false); }

bool sl_overlay_box_on_top(sl_overlay *ov, mat4 to_world, const float *rgb) {
    return _sl_add_box(ov, to_world, rgb, true);
}

bool sl_overlay_marker(sl_overlay *ov, const float position[3], const float *rgb, const char *text) {
    if (ov->marker_count >= _SL_MAX_MARKERS) return false;
    for (int k = 0; k < 3; k++)
        if (!isfinite(position[k])) return false;
    _sl_marker *m = &ov->markers[ov->marker_count++];
    glm_vec3_copy((float *)position, m->position);
    memcpy(m->rgb, rgb ? rgb : _sl_title_rgb, sizeof m->rgb);
    snprintf(m->text, sizeof m->text, "%s", text ? text : "");
    return true;
}

/* ---- TrueType faces --------------------------------------------------------- */

/* The monospaced face beside the proportional one: DejaVuSansMono.ttf in the same folder, or where there
 * is none (a font of one's own) the font itself, each glyph centred in its cell. */
static void _sl_mono_path(const char *sans, char *out, size_t n) {
    const char *slash = strrchr(sans, '/');
    int dir = slash ? (int)(slash - sans) + 1 : 0;
    snprintf(out, n, "%.*sDejaVuSansMono.ttf", dir, sans);
    FILE *f = fopen(out, "rb");
    if (f) fclose(f);
    else snprintf(out, n, "%s", sans);
}

/* `f` rasterised from `path` at `px` pixels (kept while the size holds). False, with the bitmap font
 * standing in from then on and one line said, when the font cannot be read: a lecture goes on. */
static bool _sl_face_at(sl_overlay *ov, _sl_face *f, const char *path, int px) {
    if (ov->font_failed) return false;
    if (f->texture && f->atlas.pixel_height == px) return true;
    _sl_face_free(f);
    char err[SL_PATH_MAX + 128];
    if (!sl_ttf_atlas_make(path, px, &f->atlas, err, sizeof err)) {
        fprintf(stderr, "shadowlab: warning: %s; the overlay's text is the built-in bitmap font\n", err);
        ov->font_failed = true;
        _sl_face_free(&ov->sans);
        _sl_face_free(&ov->mono);
        return false;
    }
    glGenTextures(1, &f->texture);
    glBindTexture(GL_TEXTURE_2D, f->texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, f->atlas.width, f->atlas.height, 0, GL_RED, GL_UNSIGNED_BYTE,
                 f->atlas.texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    /* glyphs are drawn at the size they were rasterised, on whole pixels: nearest is exact */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return true;
}

/* ---- Drawing -------------------------------------------------------------- */
static bool _sl_reserve(sl_overlay *ov, size_t floats) {
    if (floats <= ov->vertex_capacity) return true;
    size_t cap = ov->vertex_capacity ? ov->vertex_capacity : 4096;
    while (cap < floats) cap *= 2;
    float *v = realloc(ov->vertices, cap * sizeof *v);
    if (!v) return false;
    ov->vertices = v;
    ov->vertex_capacity = cap;
    return true;
}

/* One quad (two triangles) from pixel rect (x0,y0)-(x1,y1) showing texture rect (u0,v0)-(u1,v1). */
static size_t _sl_quad_uv(float *out, float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1,
                          const float rgb[3], float alpha) {
    const float corners[6][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x1, y1, u1, v1},
                                 {x0, y0, u0, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
    for (int i = 0; i < 6; i++) {
        float *v = out + i * 8;
        memcpy(v, corners[i], 4 * sizeof(float));
        v[4] = rgb[0];
        v[5] = rgb[1];
        v[6] = rgb[2];
        v[7] = alpha;
    }
    return 6 * 8;
}

/* The same showing glyph g of the bitmap font. */
static size_t _sl_quad(float *out, float x0, float y0, float x1, float y1, int g, const float rgb[3], float alpha) {
    const float tex_w = (float)(SL_FONT_GLYPHS * (SL_FONT_GLYPH_W + 1));
    float u0 = (float)(g * (SL_FONT_GLYPH_W + 1)) / tex_w, u1 = (float)(g * (SL_FONT_GLYPH_W + 1) + SL_FONT_GLYPH_W) / tex_w;
    return _sl_quad_uv(out, x0, y0, x1, y1, u0, 0, u1, 1, rgb, alpha);
}

/* How text is drawn: the bitmap font at scale s, or a TrueType face; in cells cw wide (panels, labels) or,
 * with cw 0, each glyph its own advance (the status line). */
typedef struct _sl_pen {
    const _sl_face *face; /* NULL: the bitmap font */
    int s;
    float cw;
} _sl_pen;

/* A solid rect of the pen's texture (a backing, a colour sample). */
static size_t _sl_solid(float *out, const _sl_pen *pen, float x0, float y0, float x1, float y1, const float rgb[3],
                        float alpha) {
    if (!pen->face) return _sl_quad(out, x0, y0, x1, y1, SL_FONT_SOLID, rgb, alpha);
    const sl_ttf_atlas *a = &pen->face->atlas;
    float u = (float)(a->solid_x + 1) / (float)a->width, v = (float)(a->solid_y + 1) / (float)a->height;
    return _sl_quad_uv(out, x0, y0, x1, y1, u, v, u, v, rgb, alpha);
}

static float _sl_advance(const _sl_pen *pen, unsigned char c) {
    if (pen->cw > 0) return pen->cw;
    if (!pen->face) return (float)(SL_OVERLAY_CELL_W * pen->s);
    return pen->face->atlas.glyphs[(c >= 32 && c <= 126 ? c : '?') - SL_TTF_FIRST].advance;
}

static float _sl_text_width(const _sl_pen *pen, const char *text) {
    float w = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) w += _sl_advance(pen, *c);
    return w;
}

static size_t _sl_text(float *out, const char *text, float x, float y, const _sl_pen *pen, const float rgb[3]) {
    size_t n = 0;
    int s = pen->s;
    for (const unsigned char *c = (const unsigned char *)text; *c; x += _sl_advance(pen, *c), c++) {
        if (*c == ' ') continue;
        if (*c == (unsigned char)SL_OVERLAY_SWATCH[0]) { /* a whole cell: a legend's colour sample */
            float h = pen->face ? pen->face->atlas.ascent : (float)(SL_FONT_GLYPH_H * s);
            n += _sl_solid(out + n, pen, x, y, x + _sl_advance(pen, *c), y + h, rgb, 1);
            continue;
        }
        if (!pen->face) {
            int g = *c >= 32 && *c <= 126 ? *c - 32 : '?' - 32;
            n += _sl_quad(out + n, x, y, x + SL_FONT_GLYPH_W * s, y + SL_FONT_GLYPH_H * s, g, rgb, 1);
            continue;
        }
        /* on whole pixels, the glyph centred in its cell when the text is in cells */
        const sl_ttf_atlas *a = &pen->face->atlas;
        const sl_ttf_glyph *g = &a->glyphs[(*c <= 126 ? *c : '?') - SL_TTF_FIRST];
        if (g->w == 0 || g->h == 0) continue;
        float centre = pen->cw > 0 ? (pen->cw - g->advance) * 0.5f : 0;
        float gx = floorf(x + centre + 0.5f) + (float)g->left, gy = floorf(y + a->ascent + 0.5f) - (float)g->top;
        float W = (float)a->width, H = (float)a->height;
        n += _sl_quad_uv(out + n, gx, gy, gx + (float)g->w, gy + (float)g->h, (float)g->x / W, (float)g->y / H,
                         (float)(g->x + g->w) / W, (float)(g->y + g->h) / H, rgb, 1);
    }
    return n;
}

/* Draws the first n floats of the text quads with texture `texture`. */
static void _sl_flush_text(sl_overlay *ov, GLuint texture, size_t n, int width, int height) {
    if (n == 0) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(ov->text_program.id);
    glUniform2f(sl_program_uniform(&ov->text_program, "u_viewport"), (float)width, (float)height);
    glUniform1i(sl_program_uniform(&ov->text_program, "u_font"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindVertexArray(ov->text_vao);
    glBindBuffer(GL_ARRAY_BUFFER, ov->text_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * sizeof(float)), ov->vertices, GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, (GLsizei)(n / 8));
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}

static const float _sl_backing_rgb[3] = {0.05f, 0.05f, 0.07f}, _sl_lecture_backing_rgb[3] = {0, 0, 0};
#define _SL_BACKING_ALPHA 0.7f
#define _SL_LECTURE_BACKING_ALPHA 0.9f

/* ---- Lines: quads in clip space, so they are as wide as asked (core GL
 * draws no lines wider than 1 pixel) and keep their depth. */
#define _SL_LINE_FLOATS (6 * 8)

static bool _sl_reserve_lines(sl_overlay *ov, size_t floats) {
    if (floats <= ov->line_capacity) return true;
    size_t cap = ov->line_capacity ? ov->line_capacity : 4096;
    while (cap < floats) cap *= 2;
    float *v = realloc(ov->line_vertices, cap * sizeof *v);
    if (!v) return false;
    ov->line_vertices = v;
    ov->line_capacity = cap;
    return true;
}

/* The segment a-b (clip space) as a quad `px` pixels wide, cut at the near
 * plane; its ends reach half a width further so corners close. 0 floats if
 * it is wholly behind the camera. */
static size_t _sl_segment(float *out, vec4 a, vec4 b, float px, int width, int height, const float rgba[4]) {
    vec4 p, q;
    glm_vec4_copy(a, p);
    glm_vec4_copy(b, q);
    float dp = p[2] + p[3], dq = q[2] + q[3]; /* >= 0 in front of the near plane */
    if (dp < 0 && dq < 0) return 0;
    if (dp < 0) glm_vec4_lerp(p, q, dp / (dp - dq), p);
    else if (dq < 0) glm_vec4_lerp(q, p, dq / (dq - dp), q);
    if (p[3] <= 1e-6f || q[3] <= 1e-6f) return 0;
    float hw = (float)width * 0.5f, hh = (float)height * 0.5f;
    float sx = (q[0] / q[3] - p[0] / p[3]) * hw, sy = (q[1] / q[3] - p[1] / p[3]) * hh;
    float len = sqrtf(sx * sx + sy * sy);
    float dx = len > 1e-6f ? sx / len : 1, dy = len > 1e-6f ? sy / len : 0;
    /* half a width across (n) and along (t), in NDC units */
    float h = px * 0.5f;
    float nx = -dy * h / hw, ny = dx * h / hh, tx = dx * h / hw, ty = dy * h / hh;
    const float sides[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}; /* (end: -1 p, 1 q; side) */
    float corner[4][4];
    for (int i = 0; i < 4; i++) {
        const float *c = sides[i][0] < 0 ? p : q;
        float along = sides[i][0], across = sides[i][1];
        corner[i][0] = c[0] + (along * tx + across * nx) * c[3];
        corner[i][1] = c[1] + (along * ty + across * ny) * c[3];
        corner[i][2] = c[2];
        corner[i][3] = c[3];
    }
    static const int order[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) {
        memcpy(out + i * 8, corner[order[i]], 4 * sizeof(float));
        memcpy(out + i * 8 + 4, rgba, 4 * sizeof(float));
    }
    return _SL_LINE_FLOATS;
}

/* A box's 12 edges, each as a quad. */
static size_t _sl_box_quads(float *out, mat4 to_world, mat4 camera_view_projection, float px, int width, int height,
                            const float rgba[4]) {
    /* The cube's 12 edges as pairs of corners (bit 0: x, bit 1: y, bit 2: z). */
    static const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    vec4 clip[8];
    for (int i = 0; i < 8; i++) {
        vec4 ndc = {i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f, 1}, w;
        glm_mat4_mulv(to_world, ndc, w);
        float inv = fabsf(w[3]) > 1e-12f ? 1.0f / w[3] : 0.0f;
        glm_vec4_scale(w, inv, w);
        w[3] = 1;
        glm_mat4_mulv(camera_view_projection, w, clip[i]);
    }
    size_t n = 0;
    for (int e = 0; e < 12; e++) n += _sl_segment(out + n, clip[edges[e][0]], clip[edges[e][1]], px, width, height, rgba);
    return n;
}

/* A segment between two pixel positions (from the top-left), over everything. */
static size_t _sl_pixel_segment(float *out, float x0, float y0, float x1, float y1, float px, int width, int height,
                                const float rgba[4]) {
    vec4 a = {2 * x0 / (float)width - 1, 1 - 2 * y0 / (float)height, 0, 1};
    vec4 b = {2 * x1 / (float)width - 1, 1 - 2 * y1 / (float)height, 0, 1};
    return _sl_segment(out, a, b, px, width, height, rgba);
}

/* Where a world point falls in the frame (pixels from the top-left); false behind the camera. */
static bool _sl_project(mat4 camera_view_projection, const vec3 world, int width, int height, float *x, float *y) {
    vec4 w = {world[0], world[1], world[2], 1}, c;
    glm_mat4_mulv(camera_view_projection, w, c);
    if (c[3] <= 1e-6f) return false;
    *x = (c[0] / c[3] * 0.5f + 0.5f) * (float)width;
    *y = (0.5f - c[1] / c[3] * 0.5f) * (float)height;
    return true;
}

/* A marker: a ring of 8 sides with 4 rays, dark under bright so it shows on any background. */
static size_t _sl_marker_quads(float *out, float x, float y, float radius, float px, int width, int height,
                               const float rgb[3]) {
    size_t n = 0;
    const float dark[4] = {0, 0, 0, 1}, bright[4] = {rgb[0], rgb[1], rgb[2], 1};
    for (int pass = 0; pass < 2; pass++) {
        const float *c = pass ? bright : dark;
        float w = pass ? px : px + 2 * fmaxf(1, px * 0.5f);
        for (int i = 0; i < 8; i++) {
            float a0 = (float)i * (float)GLM_PI / 4, a1 = (float)(i + 1) * (float)GLM_PI / 4;
            n += _sl_pixel_segment(out + n, x + radius * cosf(a0), y + radius * sinf(a0), x + radius * cosf(a1),
                                   y + radius * sinf(a1), w, width, height, c);
        }
        for (int i = 0; i < 4; i++) {
            float a = (float)i * (float)GLM_PI / 2 + (float)GLM_PI / 4, cs = cosf(a), sn = sinf(a);
            n += _sl_pixel_segment(out + n, x + 1.4f * radius * cs, y + 1.4f * radius * sn, x + 2.2f * radius * cs,
                                   y + 2.2f * radius * sn, w, width, height, c);
        }
    }
    return n;
}

/* The boxes (faint through the scene, bright where nothing hides them; on-top
 * boxes bright everywhere) and the markers. The markers' positions on screen
 * go to `marker_xy` (NaN: not in view) for their texts. */
static void _sl_draw_lines(sl_overlay *ov, mat4 camera_view_projection, int width, int height,
                           float marker_xy[][2]) {
    for (int m = 0; m < ov->marker_count; m++) marker_xy[m][0] = marker_xy[m][1] = NAN;
    if (ov->box_count == 0 && ov->marker_count == 0) return;
    float px = (float)sl_overlay_line_width_for(ov, width, height);
    int s = sl_overlay_scale_for(ov, width, height);
    /* per box 2 passes of 12 edges; per marker 2 passes of 12 segments */
    if (!_sl_reserve_lines(ov, ((size_t)ov->box_count * 24 + (size_t)ov->marker_count * 24) * _SL_LINE_FLOATS)) return;
    float *v = ov->line_vertices;
    size_t n = 0, faint_end, bright_end;
    /* a lecture's boxes are translucent even where nothing hides them: the scene shows through */
    float faint_alpha = ov->lecture ? 0.3f : 0.35f, bright_alpha = ov->lecture ? 0.7f : 1.0f;
    for (int b = 0; b < ov->box_count; b++) {
        const float *c = ov->box_rgb[b];
        const float rgba[4] = {c[0], c[1], c[2], ov->box_on_top[b] ? 1.0f : faint_alpha};
        n += _sl_box_quads(v + n, ov->boxes[b], camera_view_projection, px, width, height, rgba);
    }
    faint_end = n;
    for (int b = 0; b < ov->box_count; b++) {
        if (ov->box_on_top[b]) continue;
        const float *c = ov->box_rgb[b];
        const float rgba[4] = {c[0], c[1], c[2], bright_alpha};
        n += _sl_box_quads(v + n, ov->boxes[b], camera_view_projection, px, width, height, rgba);
    }
    bright_end = n;
    for (int m = 0; m < ov->marker_count; m++) {
        float x, y;
        if (!_sl_project(camera_view_projection, ov->markers[m].position, width, height, &x, &y)) continue;
        marker_xy[m][0] = x;
        marker_xy[m][1] = y;
        n += _sl_marker_quads(v + n, x, y, 5.0f * (float)s, px, width, height, ov->markers[m].rgb);
    }
    if (n == 0) return;
    glUseProgram(ov->line_program.id);
    glBindVertexArray(ov->line_vao);
    glBindBuffer(GL_ARRAY_BUFFER, ov->line_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * sizeof(float)), v, GL_STREAM_DRAW);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    /* faint through everything (so a frustum behind the scene is still seen), then full strength where
     * nothing in the scene is in front, then the markers over all */
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, 0, (GLsizei)(faint_end / 8));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDrawArrays(GL_TRIANGLES, (GLint)(faint_end / 8), (GLsizei)((bright_end - faint_end) / 8));
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, (GLint)(bright_end / 8), (GLsizei)((n - bright_end) / 8));
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

/* The status line: DejaVu Sans (the bitmap font where it cannot be read) at a size from the frame's
 * height, on a translucent backing at the top left, cut where the frame ends. */
#define _SL_STATUS_BACKING_ALPHA 0.55f
static void _sl_draw_status_line(sl_overlay *ov, int width, int height) {
    int px = sl_overlay_status_height_for(height);
    _sl_pen pen = {.face = NULL, .s = px / SL_FONT_GLYPH_H > 0 ? px / SL_FONT_GLYPH_H : 1, .cw = 0};
    if (ov->lecture && _sl_face_at(ov, &ov->sans, ov->font_path, px)) pen.face = &ov->sans;
    float line_h = pen.face ? pen.face->atlas.line_height : (float)(SL_OVERLAY_CELL_H * pen.s);
    float margin = floorf((float)px * 0.3f), pad = floorf((float)px * 0.25f);
    char text[sizeof ov->status_line];
    snprintf(text, sizeof text, "%s", ov->status_line);
    float room = (float)width - 2 * margin - 2 * pad;
    for (size_t len = strlen(text); len > 0 && _sl_text_width(&pen, text) > room; len--) text[len - 1] = '\0';
    float w = _sl_text_width(&pen, text);
    size_t n = _sl_solid(ov->vertices, &pen, margin, margin, margin + w + 2 * pad, margin + line_h + 2 * pad,
                         _sl_lecture_backing_rgb, _SL_STATUS_BACKING_ALPHA);
    /* the bitmap font's glyphs sit in the upper 8 of its 10 rows: centre them in the backing */
    float y = margin + pad + (pen.face ? 0 : (float)pen.s);
    n += _sl_text(ov->vertices + n, text, margin + pad, y, &pen, _sl_lecture_rgb);
    _sl_flush_text(ov, pen.face ? pen.face->texture : ov->font_texture, n, width, height);
}

void sl_overlay_draw(sl_overlay *ov, mat4 camera_view_projection, GLuint target, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    float marker_xy[_SL_MAX_MARKERS][2];
    _sl_draw_lines(ov, camera_view_projection, width, height, marker_xy);

    int s = sl_overlay_scale_for(ov, width, height);
    /* the markers' texts: labels beside them, for this draw only */
    int labels_before = ov->label_count;
    for (int m = 0; m < ov->marker_count; m++)
        if (!isnan(marker_xy[m][0]) && ov->markers[m].text[0] &&
            ov->line_count + ov->label_count < _SL_MAX_LINES + _SL_MAX_LABELS + _SL_MAX_MARKERS) {
            _sl_text_line *l = &ov->lines[ov->line_count + ov->label_count++];
            snprintf(l->text, sizeof l->text, "%s", ov->markers[m].text);
            memcpy(l->rgb, ov->markers[m].rgb, sizeof l->rgb);
            l->panel = -1;
            l->x = (int)(marker_xy[m][0] + 12.0f * (float)s);
            l->y = (int)(marker_xy[m][1] + 4.0f * (float)s);
        }
    /* The auto scale (sl_overlay_scale_for) comes down a step at a time while the panels would overlap each
     * other or the labels (a lecture's text in a small window); a scale set with sl_overlay_set_scale stays. */
    static _sl_layout layout;
    for (;; s--) {
        _sl_overlay_lay_out(ov, s, width, height, labels_before, &layout);
        if (layout.fits || ov->scale > 0 || s <= 1) break;
    }
    const _sl_layout *L = &layout;
    /* A lecture's panels and labels in DejaVu Sans Mono sized to the bitmap font's cells, so the layout
     * and the labs' label positions hold; the bitmap font where it cannot be read. */
    _sl_pen pen = {.face = NULL, .s = s, .cw = (float)(SL_OVERLAY_CELL_W * s)};
    if (ov->lecture && ov->line_count + ov->label_count > 0) {
        char mono[SL_PATH_MAX + 32];
        _sl_mono_path(ov->font_path, mono, sizeof mono);
        if (_sl_face_at(ov, &ov->mono, mono, (int)(0.84f * (float)(SL_OVERLAY_CELL_H * s) + 0.5f))) pen.face = &ov->mono;
    }
    const float cw = (float)(SL_OVERLAY_CELL_W * s), ch = (float)(SL_OVERLAY_CELL_H * s), pad = (float)(3 * s);
    const float *backing = ov->lecture ? _sl_lecture_backing_rgb : _sl_backing_rgb;
    const float backing_alpha = ov->lecture ? _SL_LECTURE_BACKING_ALPHA : _SL_BACKING_ALPHA;
    int total = ov->line_count + ov->label_count;
    /* Per glyph a quad, per panel and label a backing: 48 floats each (a wrapped line's indent is no glyph);
     * the status line's after them. */
    size_t chars = 0;
    for (int i = 0; i < total; i++) chars += strlen(ov->lines[i].text) + 1;
    chars += strlen(ov->status_line) + 1;
    if (!_sl_reserve(ov, (chars + (size_t)ov->panel_count + 1) * 48)) {
        ov->label_count = labels_before;
        return;
    }
    /* Backings first (they are drawn under the text), then the glyphs. */
    float *v = ov->vertices;
    size_t n = 0;
    for (int p = 0; p < ov->panel_count; p++)
        if (L->panel_w[p] > 0)
            n += _sl_solid(v + n, &pen, L->panel_x[p], L->panel_y[p], L->panel_x[p] + L->panel_w[p],
                           L->panel_y[p] + L->panel_h[p], backing, backing_alpha);
    for (int i = 0; i < total; i++) {
        const _sl_text_line *l = &ov->lines[i];
        if (l->panel >= 0) continue;
        float w = (float)strlen(l->text) * cw - (float)s + 2 * pad, h = ch - 2.0f * (float)s + 2 * pad;
        n += _sl_solid(v + n, &pen, (float)l->x, (float)l->y, (float)l->x + w, (float)l->y + h, backing, backing_alpha);
    }
    int row[_SL_MAX_PANELS] = {0};
    for (int r = 0; r < L->row_count; r++) {
        const _sl_row *w = &L->rows[r];
        const _sl_text_line *l = &ov->lines[w->line];
        char part[_SL_LINE_CHARS];
        snprintf(part, sizeof part, "%s%.*s", w->indent ? "  " : "", w->length, l->text + w->start);
        n += _sl_text(v + n, part, L->panel_x[l->panel] + pad, L->panel_y[l->panel] + pad + (float)row[l->panel]++ * ch,
                      &pen, l->rgb);
    }
    for (int i = 0; i < total; i++) {
        const _sl_text_line *l = &ov->lines[i];
        if (l->panel < 0) n += _sl_text(v + n, l->text, (float)l->x + pad, (float)l->y + pad, &pen, l->rgb);
    }
    ov->label_count = labels_before; /* the markers' texts were for this draw */
    _sl_flush_text(ov, pen.face ? pen.face->texture : ov->font_texture, n, width, height);
    if (ov->status_line[0]) _sl_draw_status_line(ov, width, height);
}

size_t sl_overlay_text(const sl_overlay *ov, char *out, size_t out_size) {
    static const char *const names[] = {"top left", "top right", "bottom left", "bottom right"};
    size_t used = 0;
    if (out_size) out[0] = '\0';
    if (ov->status_line[0]) {
        int k = snprintf(out, out_size, "[status] %s\n", ov->status_line);
        if (k > 0) used += (size_t)k;
    }
    for (int i = 0; i < ov->line_count + ov->label_count; i++) {
        const _sl_text_line *l = &ov->lines[i];
        const char *where = l->panel >= 0 ? names[ov->panels[l->panel].corner] : "label";
        char text[_SL_LINE_CHARS]; /* a colour sample reads as '#' */
        snprintf(text, sizeof text, "%s", l->text);
        for (char *c = text; *c; c++)
            if (*c == SL_OVERLAY_SWATCH[0]) *c = '#';
        int k = used < out_size ? snprintf(out + used, out_size - used, "[%s] %s\n", where, text)
                                : snprintf(NULL, 0, "[%s] %s\n", where, text);
        if (k > 0) used += (size_t)k;
    }
    for (int m = 0; m < ov->marker_count; m++) {
        const char *t = ov->markers[m].text;
        int k = used < out_size ? snprintf(out + used, out_size - used, "[marker] %s\n", t)
                                : snprintf(NULL, 0, "[marker] %s\n", t);
        if (k > 0) used += (size_t)k;
    }
    return used;
}
