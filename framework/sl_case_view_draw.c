#include "sl_case_view_draw.h"

#include <stdio.h>
#include <string.h>

#include "sl_case_view_pictures.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* Draws a panel's picture in slot `slot` (width x height, above the summary band); false if it has none yet. */
static void _sl_draw_panel(_sl_case_view *v, int panel, int slot, int width, int height) {
    /* the picture's aspect kept: a square map in a wide panel is centred */
    int pw = v->panel_size[panel][0], ph = v->panel_size[panel][1], w = width, h = height;
    if (pw > 0 && ph > 0) {
        if ((long)width * ph > (long)height * pw) w = (int)((long)height * pw / ph);
        else h = (int)((long)width * ph / pw);
    }
    glViewport(slot * width + (width - w) / 2, v->band + (height - h) / 2, w, h);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, v->textures[panel]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

/* A panel's label: whose picture, and for depths and distances the range it is stretched from. */
static void _sl_label(_sl_case_view *v, int panel, int x, int y) {
    static const char *const names[_SL_PANELS] = {"yours", "reference", "difference"};
    static const float colours[_SL_PANELS][3] = {{1, 1, 1}, {1, 1, 1}, {1, 0.85f, 0.35f}};
    static const float red[3] = {1, 0.35f, 0.3f}, blue[3] = {0.45f, 0.65f, 1}, grey[3] = {0.75f, 0.75f, 0.75f};
    int line = (SL_OVERLAY_CELL_H * 16 / 10) * v->text_scale; /* a label's backing is a little taller than a cell */
    if (panel == _SL_DIFF) {
        const char *r, *b;
        _sl_case_view_diff_legend(v->check->kind, &r, &b);
        sl_overlay_label(v->overlay, x, y, colours[panel], "%s", names[panel]);
        sl_overlay_label(v->overlay, x, y + line, red, "%s", r);
        sl_overlay_label(v->overlay, x, y + 2 * line, blue, "%s", b);
    } else if (_sl_case_view_marks_legend(v->check->kind)) {
        sl_overlay_label(v->overlay, x, y, colours[panel], "%s", names[panel]);
        sl_overlay_label(v->overlay, x, y + line, red, "%s", _sl_case_view_marks_legend(v->check->kind));
    } else if (v->stretched[panel]) {
        sl_overlay_label(v->overlay, x, y, colours[panel], "%s", names[panel]);
        if (v->range[panel][1] > v->range[panel][0])
            sl_overlay_label(v->overlay, x, y + line, grey, "%.4f - %.4f%s", (double)v->range[panel][0],
                             (double)v->range[panel][1], v->check->kind == SL_CHECK_DEPTH_MAP && v->range[panel][1] < 1
                                                             ? " (1: cleared)" : "");
        else
            sl_overlay_label(v->overlay, x, y + line, grey, "all %.4f", (double)v->range[panel][0]);
    } else {
        sl_overlay_label(v->overlay, x, y, colours[panel], "%s", names[panel]);
    }
}

/* Text in lines of at most `width` characters, broken at spaces, into the current panel; at most `lines`.
 * Returns the lines used; `cut_short` (may be NULL) says whether text was left over. Without an
 * overlay, only counts. */
static int _sl_band_text(sl_overlay *ov, const float *rgb, const char *text, int width, int lines, bool *cut_short) {
    int used = 0;
    while (*text && used < lines) {
        int len = (int)strlen(text), cut = len;
        if (len > width) {
            cut = width;
            while (cut > width / 2 && text[cut] != ' ') cut--;
            if (text[cut] != ' ') cut = width;
        }
        if (ov) sl_overlay_line(ov, rgb, "%.*s", cut, text);
        used++;
        text += cut;
        while (*text == ' ') text++;
    }
    if (cut_short) *cut_short = *text != '\0';
    return used;
}

/* The band's width in characters, for a window `width` pixels wide at overlay scale `s`. */
static int _sl_band_chars(int width, int s) {
    int chars = (width - 16 * s) / (SL_OVERLAY_CELL_W * s);
    return chars > 118 ? 118 : chars; /* the overlay's longest line */
}

bool _sl_case_view_band_fits(_sl_case_view *v, int width, int height) {
    if (!v->overlay) return true;
    int chars = _sl_band_chars(width, sl_overlay_scale_for(v->overlay, width, height));
    bool summary_cut = false, criterion_cut = false;
    int used = _sl_band_text(NULL, NULL, v->summary, chars, 2, &summary_cut);
    _sl_band_text(NULL, NULL, v->criterion, chars, _SL_BAND_LINES - used, &criterion_cut);
    return !summary_cut && !criterion_cut;
}

void _sl_case_view_draw(_sl_case_view *v, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(v->panel_program.id);
    glUniform1i(sl_program_uniform(&v->panel_program, "u_texture"), 0);
    glBindVertexArray(v->vao);
    int panels_h = height - v->band > 0 ? height - v->band : height;
    if (v->overlay) sl_overlay_clear(v->overlay);
    int s = v->overlay ? sl_overlay_scale_for(v->overlay, width, height) : 1;
    if (v->side_by_side) {
        for (int panel = 0; panel < _SL_PANELS; panel++) {
            _sl_draw_panel(v, panel, panel, width / 3, panels_h);
            if (v->overlay) _sl_label(v, panel, panel * (width / 3) + 4 * s, 4 * s);
        }
    } else {
        int panel = v->show_diff ? _SL_DIFF : v->show_reference ? _SL_REFERENCE : _SL_STUDENT;
        _sl_draw_panel(v, panel, 0, width, panels_h);
        if (v->overlay) _sl_label(v, panel, 4 * s, 4 * s);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    if (!v->overlay) return;
    /* the summary and the criterion under the panels */
    sl_overlay_panel(v->overlay, SL_OVERLAY_BOTTOM_LEFT, NULL);
    int chars = _sl_band_chars(width, s);
    int used = _sl_band_text(v->overlay, NULL, v->summary, chars, 2, NULL);
    _sl_band_text(v->overlay, (const float[3]){0.6f, 0.8f, 1.0f}, v->criterion, chars, _SL_BAND_LINES - used, NULL);
    mat4 identity;
    glm_mat4_identity(identity);
    sl_overlay_draw(v->overlay, identity, 0, width, height);
}

void _sl_case_view_title(_sl_case_view *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    if (!w) return;
    char title[512];
    const char *layout = v->side_by_side ? "yours | reference | difference (red: shadow missing, blue: extra)"
                         : v->show_diff  ? "difference (red: shadow missing, blue: extra)"
                         : v->show_reference ? "reference" : "yours";
    snprintf(title, sizeof title, "shadowlab — %s — %s — %s%s", v->summary, layout, _sl_case_view_legend(v->check->kind),
             v->shown_count > 1 ? " — C: next check" : "");
    glfwSetWindowTitle(w, title);
}

