#include "sl_overlay_layout.h"

#include <string.h>

static bool _sl_overlaps(float ax, float ay, float aw, float ah, float bx, float by, float bw, float bh) {
    return ax < bx + bw && bx < ax + aw && ay < by + bh && by < ay + ah;
}

void _sl_overlay_lay_out(const sl_overlay *ov, int s, int width, int height, int labels, _sl_layout *L) {
    const float cw = (float)(SL_OVERLAY_CELL_W * s), ch = (float)(SL_OVERLAY_CELL_H * s);
    const float margin = (float)(4 * s), pad = (float)(3 * s);
    int cols = (int)(((float)width - 2 * margin - 2 * pad + (float)s) / cw);
    if (cols < 12) cols = 12;
    L->row_count = 0;
    L->fits = true;
    int rows[_SL_MAX_PANELS] = {0}, widest[_SL_MAX_PANELS] = {0};
    for (int i = 0; i < ov->line_count + ov->label_count; i++) {
        const _sl_text_line *l = &ov->lines[i];
        if (l->panel < 0) continue;
        int length = (int)strlen(l->text), start = 0;
        bool indent = false;
        do {
            int room = indent ? cols - 2 : cols, take = length - start;
            if (take > room) { /* at the last space that fits, or cut */
                take = room;
                for (int k = room; k > room / 2; k--)
                    if (l->text[start + k] == ' ') {
                        take = k;
                        break;
                    }
            }
            if (L->row_count < _SL_MAX_ROWS) L->rows[L->row_count++] = (_sl_row){i, start, take, indent};
            rows[l->panel]++;
            if (take + (indent ? 2 : 0) > widest[l->panel]) widest[l->panel] = take + (indent ? 2 : 0);
            start += take;
            while (start < length && l->text[start] == ' ') start++;
            indent = true;
        } while (start < length);
    }
    float left_width[2] = {0, 0}; /* widest left panel at the top and at the bottom */
    for (int p = 0; p < ov->panel_count; p++) {
        L->panel_w[p] = rows[p] ? (float)widest[p] * cw - (float)s + 2 * pad : 0;
        L->panel_h[p] = rows[p] ? (float)rows[p] * ch - 2.0f * (float)s + 2 * pad : 0;
        sl_overlay_corner corner = ov->panels[p].corner;
        if (corner == SL_OVERLAY_TOP_LEFT && L->panel_w[p] > left_width[0]) left_width[0] = L->panel_w[p];
        if (corner == SL_OVERLAY_BOTTOM_LEFT && L->panel_w[p] > left_width[1]) left_width[1] = L->panel_w[p];
    }
    float next_y[SL_OVERLAY_CORNER_COUNT]; /* how far each corner's stack has grown */
    for (int c = 0; c < SL_OVERLAY_CORNER_COUNT; c++) next_y[c] = margin;
    /* Left stacks first, so a right-hand panel too wide to sit beside them can start below (or above) them. */
    for (int pass = 0; pass < 2; pass++)
        for (int p = 0; p < ov->panel_count; p++) {
            sl_overlay_corner corner = ov->panels[p].corner;
            bool right = corner == SL_OVERLAY_TOP_RIGHT || corner == SL_OVERLAY_BOTTOM_RIGHT;
            if (right != (pass == 1) || L->panel_w[p] == 0) continue;
            float w = L->panel_w[p], h = L->panel_h[p];
            bool bottom = corner == SL_OVERLAY_BOTTOM_LEFT || corner == SL_OVERLAY_BOTTOM_RIGHT;
            float x = right ? (float)width - margin - w : margin;
            if (right) {
                int band = bottom ? 1 : 0;
                sl_overlay_corner beside = bottom ? SL_OVERLAY_BOTTOM_LEFT : SL_OVERLAY_TOP_LEFT;
                if (left_width[band] > 0 && x < margin + left_width[band] + margin && next_y[corner] < next_y[beside])
                    next_y[corner] = next_y[beside];
            }
            for (bool moved = bottom; moved;) { /* up above the labels it would cover */
                moved = false;
                float y = (float)height - next_y[corner] - h;
                for (int i = 0; i < ov->line_count + labels; i++) { /* the labels, not the markers' texts */
                    const _sl_text_line *l = &ov->lines[i];
                    if (l->panel >= 0) continue;
                    float lw = (float)strlen(l->text) * cw - (float)s + 2 * pad, lh = ch - 2.0f * (float)s + 2 * pad;
                    if (_sl_overlaps(x, y, w, h, (float)l->x, (float)l->y, lw, lh)) {
                        next_y[corner] = (float)height - (float)l->y + margin;
                        moved = true;
                    }
                }
            }
            L->panel_x[p] = x;
            L->panel_y[p] = bottom ? (float)height - next_y[corner] - h : next_y[corner];
            next_y[corner] += h + margin;
        }
    for (int p = 0; p < ov->panel_count && L->fits; p++) {
        if (L->panel_w[p] == 0) continue;
        float x = L->panel_x[p], y = L->panel_y[p], w = L->panel_w[p], h = L->panel_h[p];
        if (x < 0 || y < 0 || x + w > (float)width || y + h > (float)height) L->fits = false;
        for (int q = p + 1; q < ov->panel_count; q++)
            if (L->panel_w[q] > 0 && _sl_overlaps(x, y, w, h, L->panel_x[q], L->panel_y[q], L->panel_w[q], L->panel_h[q]))
                L->fits = false;
    }
}

