#!/usr/bin/env python3
"""A cube map's six faces unfolded, each with the up vector its camera uses.

The net is laid out as the viewer's cross (framework/shaders/cube_cross.frag:
the faces as seen from the light, world up drawn up for the four around the
horizon, +Y above and -Y below -Z). Inside each face: the arrow of the up
vector the face's camera is built with (lookAt(light, light + forward, up))
and of its right vector (forward x up), i.e. the directions in which the
face's texture coordinates t and s grow. They come from the cube-map
convention (OpenGL 4.6 core spec, §8.13, cube map texture selection: which of the direction's components
give s and t on each face); around the horizon they point down and away, so
those four faces are stored upside down relative to the world.

  cube_faces.py --out FILE.svg
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREY  # noqa: E402

# face: forward, up (what the face's camera uses; the lab's table)
FACES = {
    "+X": ((1, 0, 0), (0, -1, 0)),
    "-X": ((-1, 0, 0), (0, -1, 0)),
    "+Y": ((0, 1, 0), (0, 0, 1)),
    "-Y": ((0, -1, 0), (0, 0, -1)),
    "+Z": ((0, 0, 1), (0, -1, 0)),
    "-Z": ((0, 0, -1), (0, -1, 0)),
}
# The cross as the viewer draws it: cell (column, row from the top) -> face, and the
# world directions the cell's own right and up stand for.
CROSS = {
    "+Y": ((1, 0), (1, 0, 0), (0, 0, 1)),
    "-X": ((0, 1), (0, 0, -1), (0, 1, 0)),
    "-Z": ((1, 1), (1, 0, 0), (0, 1, 0)),
    "+X": ((2, 1), (0, 0, 1), (0, 1, 0)),
    "+Z": ((3, 1), (-1, 0, 0), (0, 1, 0)),
    "-Y": ((1, 2), (1, 0, 0), (0, 0, -1)),
}


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def vec(v):
    return "(" + ", ".join("−1" if x == -1 else str(x) for x in v) + ")"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    cell = 190
    x0, y0 = 20, 60
    c = Canvas(4 * cell + 40, 3 * cell + 90, title=a.title or "cube map faces and up vectors")
    c.text((20, 34), a.title or "the six faces, unfolded around the light (as the viewer's cross)", size=22,
           px=True, weight="bold")
    for name, ((col, row), cell_right, cell_up) in CROSS.items():
        fwd, up = FACES[name]
        right = cross(fwd, up)
        px, py = x0 + col * cell, y0 + row * cell
        c.rect_px(px, py, cell, cell, fill="#f4f5f8", stroke=INK, width=2.5)
        cx, cy = px + cell / 2, py + cell / 2 - 18
        # The face's up and right in the cell's picture (its own right and up are world directions).
        def to_px(v, length):
            return (cx + length * dot(v, cell_right), cy - length * dot(v, cell_up))
        ux, uy = to_px(up, 62)
        rx, ry = to_px(right, 62)
        c.line_px(cx, cy, ux, uy, stroke=ACCENT, width=5, arrow=True, id=f"up-{name}", data_face=name,
                  data_up=" ".join(map(str, up)))
        c.line_px(cx, cy, rx, ry, stroke=BLUE, width=4, arrow=True, id=f"right-{name}", data_face=name,
                  data_right=" ".join(map(str, right)), data_cell_right=" ".join(map(str, cell_right)),
                  data_cell_up=" ".join(map(str, cell_up)), data_cell=f"{col} {row}")
        c.text((px + 10, py + 30), name, size=26, px=True, weight="bold")
        c.text((px + cell - 8, py + cell - 30), "up " + vec(up), size=16, px=True, anchor="end", fill=ACCENT)
        c.text((px + cell - 8, py + cell - 10), "right " + vec(right), size=16, px=True, anchor="end", fill=BLUE)
    c.text((20 + 2 * cell + 10, y0 + 2 * cell + 40), "red: the face camera's up vector (t grows)", size=18, px=True,
           fill=ACCENT)
    c.text((20 + 2 * cell + 10, y0 + 2 * cell + 66), "blue: forward × up (s grows)", size=18, px=True, fill=BLUE)
    c.text((20 + 2 * cell + 10, y0 + 2 * cell + 92), "the cross itself: world up drawn up", size=18, px=True,
           fill=GREY)
    c.save(a.out)


if __name__ == "__main__":
    main()
