#define _POSIX_C_SOURCE 200809L
#include "sl_viewer_split.h"

#include <stdlib.h>
#include <string.h>

#include "sl_overlay_types.h"

/* ---- The option ------------------------------------------------------------ */

void _sl_viewer_split_usage(FILE *f) {
    fprintf(f,
            "  --split A,B         two settings side by side, same camera, light and options: the left half\n"
            "                      as A draws it, the right as B, each labelled, a divider between. A side\n"
            "                      is words joined by ':', each setting one thing apart from the other\n"
            "                      side: a lab (2), lab 4's filter (--filter's names: pcss) or the code\n"
            "                      (student, solutions: builds that carry both); what a side does not\n"
            "                      name is the viewer's. E.g. --split 2,4 (hard shadows, PCF),\n"
            "                      --split 4:grid,4:pcss, --split student,solutions. Keys change both\n"
            "                      halves, except the setting the halves differ in; the overlay speaks\n"
            "                      of the left half; key Y shows the left half alone, and both again\n");
}

/* Whether the halves differ in `setting`. The left side's words become the viewer's settings and the right
 * half follows the viewer where its side is silent: so the right side must name it, apart from the left's. */
static bool _sl_split_apart(const _sl_split *s, _sl_split_setting setting) {
    const _sl_split_side *a = &s->sides[0], *b = &s->sides[1];
    switch (setting) {
    case _SL_SPLIT_LAB: return b->lab && a->lab != b->lab;
    case _SL_SPLIT_FILTER: return b->filter >= 0 && a->filter != b->filter;
    case _SL_SPLIT_CODE: return b->code >= 0 && a->code != b->code;
    }
    return false;
}

/* One word of a side: a lab number, a filter name or a code's name. */
static bool _sl_split_word(_sl_viewer *v, const char *word, _sl_split_side *side) {
    sl_filter_mode filter;
    char *end = NULL;
    long lab = strtol(word, &end, 10);
    if (end != word && !*end) {
        if (lab < 1 || lab > SL_RENDERER_MAX_LAB || !sl_lab_folder((int)lab)) {
            fprintf(stderr, "shadowlab: --split: %s is not one of this build's labs (1..%d)\n", word,
                    SL_RENDERER_MAX_LAB);
            return false;
        }
        side->lab = (int)lab;
    } else if (sl_filter_mode_parse(word, &filter)) {
        side->filter = (int)filter;
    } else if (strcmp(word, sl_build_labs_kind) == 0) {
        side->code = 0;
    } else if (v->second_functions && strcmp(word, v->second_kind) == 0) {
        side->code = 1;
    } else {
        fprintf(stderr, "shadowlab: --split: '%s' is no lab number, filter (none, hardware, grid, poisson, pcss) "
                        "or code (%s%s%s) of this build\n", word, sl_build_labs_kind,
                v->second_functions ? ", " : "", v->second_functions ? v->second_kind : "");
        return false;
    }
    return true;
}

bool _sl_viewer_split_parse(_sl_viewer *v, const char *text) {
    _sl_split *s = &v->split;
    const char *comma = strchr(text, ',');
    if (!comma || strchr(comma + 1, ',')) {
        fprintf(stderr, "shadowlab: --split takes two sides, A,B (e.g. 2,4 or 4:grid,4:pcss)\n");
        return false;
    }
    for (int i = 0; i < 2; i++) {
        _sl_split_side *side = &s->sides[i];
        *side = (_sl_split_side){.lab = 0, .filter = -1, .code = -1};
        const char *from = i == 0 ? text : comma + 1, *to = i == 0 ? comma : from + strlen(from);
        char words[128];
        snprintf(words, sizeof words, "%.*s", (int)(to - from), from);
        if (!words[0]) {
            fprintf(stderr, "shadowlab: --split: side %s is empty\n", i == 0 ? "A" : "B");
            return false;
        }
        for (char *save = NULL, *w = strtok_r(words, ":", &save); w; w = strtok_r(NULL, ":", &save))
            if (!_sl_split_word(v, w, side)) return false;
    }
    if (!_sl_split_apart(s, _SL_SPLIT_LAB) && !_sl_split_apart(s, _SL_SPLIT_FILTER) &&
        !_sl_split_apart(s, _SL_SPLIT_CODE)) {
        fprintf(stderr, "shadowlab: --split %s: the two sides set nothing apart\n", text);
        return false;
    }
    s->given = s->on = true;
    return true;
}

/* ---- The settings of each half ---------------------------------------------- */

/* The params a side draws with: the viewer's, with what the side names. */
static sl_render_params _sl_split_params(const _sl_viewer *v, const _sl_split_side *side) {
    sl_render_params p = v->params;
    if (side->lab) p.lab = side->lab;
    if (side->filter >= 0) p.filter.mode = (sl_filter_mode)side->filter;
    return p;
}

/* Whether a side draws with the second lab code. */
static bool _sl_split_second(const _sl_viewer *v, const _sl_split_side *side) {
    return side->code >= 0 ? side->code == 1 : v->show_second;
}

void _sl_viewer_split_show(_sl_viewer *v, bool on) {
    _sl_split *s = &v->split;
    if (!s->given) return;
    s->on = on;
    if (on) {
        v->params = _sl_split_params(v, &s->sides[0]);
        v->show_second = _sl_split_second(v, &s->sides[0]);
    }
    v->dirty_title = true;
}

bool _sl_viewer_split_holds(_sl_viewer *v, _sl_split_setting setting) {
    const _sl_split *s = &v->split;
    if (!s->on) return false;
    static const char *const names[] = {"labs", "filters", "codes"};
    bool held = _sl_split_apart(s, setting);
    if (held)
        printf("shadowlab: --split shows two of the %s side by side: Y shows the left half alone, where the key "
               "changes it\n", names[setting]);
    return held;
}

/* ---- Drawing ------------------------------------------------------------------ */

/* Where the right half waits while the left one draws: colour the size of the frame (made again when
 * that changes). */
static bool _sl_split_target(_sl_split *s, int width, int height) {
    if (s->framebuffer && s->width == width && s->height == height) return true;
    if (!s->framebuffer) {
        glGenFramebuffers(1, &s->framebuffer);
        glGenRenderbuffers(1, &s->color);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, s->color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s->color);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    s->width = complete ? width : 0;
    s->height = complete ? height : 0;
    return complete;
}

/* The right half's renderer, with the code its side draws with (made again when key U changes that code
 * for a side that follows the viewer's). */
static bool _sl_split_renderer(_sl_viewer *v, bool second) {
    _sl_split *s = &v->split;
    if (s->right_ready && s->right_second == second) return true;
    if (s->right_ready) sl_renderer_destroy(&s->right);
    s->right_ready = false;
    char err[16384];
    sl_renderer_desc rd = {.labs_dir = second ? v->second_dir : v->renderer.labs_dir};
    if (!sl_renderer_init(&s->right, &rd, err, sizeof err) || !sl_renderer_set_scene(&s->right, &v->scene, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --split: cannot draw the right half: %s\n", err);
        return false;
    }
    for (int lab = 1; lab <= SL_LAB_COUNT; lab++) s->right.fns[lab] = second ? v->second_functions : v->renderer.fns[lab];
    s->right_ready = true;
    s->right_second = second;
    return true;
}

/* The divider's width: two pixels, more in large frames, so it reads as a line and not as an edge. */
static int _sl_split_divider_width(const _sl_viewer *v, int width, int height) {
    int s = v->overlay ? sl_overlay_scale_for(v->overlay, width, height) : 2;
    return s <= 2 ? 2 : 2 * ((s + 1) / 2);
}

/* Copies the right half of framebuffer `from` into `to`. */
static void _sl_split_copy_right(GLuint from, GLuint to, int width, int height) {
    int half = width / 2;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(half, 0, width, height, half, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void _sl_viewer_split_draw_right(_sl_viewer *v, GLuint target, int width, int height) {
    _sl_split *s = &v->split;
    const _sl_split_side *right = &s->sides[1];
    if (!_sl_split_renderer(v, _sl_split_second(v, right)) || !_sl_split_target(s, width, height)) {
        fprintf(stderr, "shadowlab: --split: the halves are off; the left half's setting draws alone\n");
        s->on = false;
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        return;
    }
    /* drawn into the frame the single view draws into: another framebuffer may break a tie at an edge
     * the other way (an offscreen one is not flipped as the window's may be) */
    sl_render_params p = _sl_split_params(v, right);
    sl_renderer_draw(&s->right, &v->scene, &p, target, width, height);
    _sl_split_copy_right(target, s->framebuffer, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
}

void _sl_viewer_split_compose(_sl_viewer *v, GLuint target, int width, int height) {
    _sl_split *s = &v->split;
    int half = width / 2;
    _sl_split_copy_right(s->framebuffer, target, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    int d = _sl_split_divider_width(v, width, height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(half - d / 2, 0, d, height);
    glClearColor(0.92f, 0.92f, 0.92f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

/* What a half draws, from its renderer's last frame: its technique's words for it ("lab 2's hard
 * shadows", "lab 4's pcss filter"), the lab asked when that is not what draws, and the code. */
static void _sl_split_label_text(_sl_viewer *v, const _sl_split_side *side, const sl_frame_info *info, char *out,
                                 size_t n) {
    sl_render_params p = _sl_split_params(v, side);
    const sl_technique *t = sl_technique_of(info->lab_in_use);
    sl_view_context c = _sl_viewer_context(v, info);
    c.params = &p;
    if (!t || info->lab_in_use == 0) snprintf(out, n, "no shadows");
    else if (t->drawing_text) t->drawing_text(&c, out, n);
    else snprintf(out, n, "lab %d's %s", info->lab_in_use, t->name);
    size_t used = strlen(out);
    if (info->lab_in_use != p.lab && used < n)
        used += (size_t)snprintf(out + used, n - used, " (lab %d is off)", p.lab);
    const _sl_split *s = &v->split;
    if (_sl_split_apart(s, _SL_SPLIT_CODE) && used < n)
        snprintf(out + used, n - used, ", %s", _sl_split_second(v, side) ? v->second_kind : sl_build_labs_kind);
}

void _sl_viewer_split_labels(_sl_viewer *v, const sl_frame_info *left, int width, int height) {
    _sl_split *s = &v->split;
    if (!v->overlay || !s->right_ready) return;
    static const float white[3] = {1, 1, 1};
    int scale = sl_overlay_scale_for(v->overlay, width, height);
    /* a label's box as the overlay draws it: cells 6x10 font pixels, 3 of padding round them */
    int cell_w = SL_OVERLAY_CELL_W * scale, label_h = (SL_OVERLAY_CELL_H - 2 + 6) * scale;
    int half = width / 2;
    for (int i = 0; i < 2; i++) {
        char text[160];
        _sl_split_label_text(v, &s->sides[i], i == 0 ? left : sl_renderer_info(&s->right), text, sizeof text);
        /* cut to what fits in the half, then centred in it near the bottom (the overlay moves its bottom panels
         * above labels; its top ones would cover them) */
        int fits = (half - 8 * scale) / cell_w;
        if (fits < 1) continue;
        if ((int)strlen(text) > fits) text[fits] = '\0';
        int w = (int)strlen(text) * cell_w + 5 * scale;
        int x = i * half + (half - w) / 2, y = height - label_h - SL_OVERLAY_CELL_H * scale;
        sl_overlay_label(v->overlay, x < i * half ? i * half : x, y, white, "%s", text);
    }
}

void _sl_viewer_split_reload(_sl_viewer *v) {
    _sl_split *s = &v->split;
    if (!s->on || !s->right_ready) return;
    char err[16384];
    bool reloaded = false;
    if (!sl_renderer_reload_changed(&s->right, &reloaded, err, sizeof err))
        fprintf(stderr, "shadowlab: shader reload failed for the right half, keeping the previous version:\n%s\n", err);
}

void _sl_viewer_split_destroy(_sl_viewer *v) {
    _sl_split *s = &v->split;
    if (s->right_ready) sl_renderer_destroy(&s->right);
    s->right_ready = false;
    if (s->framebuffer) {
        glDeleteFramebuffers(1, &s->framebuffer);
        glDeleteRenderbuffers(1, &s->color);
    }
    s->framebuffer = s->color = 0;
}
