/* sl_overlay_types: the overlay's corners, its font cell and its handle, below the overlay's modules
 * (sl_overlay.h for its users, sl_overlay_state.h and sl_overlay_layout.h inside it). */
#ifndef SL_OVERLAY_TYPES_H
#define SL_OVERLAY_TYPES_H

typedef enum sl_overlay_corner {
    SL_OVERLAY_TOP_LEFT,
    SL_OVERLAY_TOP_RIGHT,
    SL_OVERLAY_BOTTOM_LEFT,
    SL_OVERLAY_BOTTOM_RIGHT,
    SL_OVERLAY_CORNER_COUNT
} sl_overlay_corner;

/* The font's cell in font pixels (a 5x8 glyph with spacing); on screen each
 * font pixel is `scale` pixels wide and high. */
#define SL_OVERLAY_CELL_W 6
#define SL_OVERLAY_CELL_H 10

typedef struct sl_overlay sl_overlay;

#endif
