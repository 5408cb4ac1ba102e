#!/usr/bin/env python3
"""Second-depth and midpoint shadow maps, side view under a sun (rays straight down).

For each texel (a column) the first surface the light meets stores d1, the
second d2; where a column meets only the floor, d2 is the far plane. The
midpoint map compares a point's depth z with (d1 + d2) / 2 (Woo 1992): lit
iff z <= (d1 + d2) / 2. Depths are measured down from the light's near plane.

  second_depth.py [--texels N] --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, LIGHT, BLUE, GREY  # noqa: E402

PURPLE = "#7b3fa0"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--texels", type=int, default=24)
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    far, floor = 10.0, 7.0                 # depths below the near plane
    box = (1.0, 4.0, 4.0)                  # x0, x1, top depth (the box stands on the floor)
    ball = (7.5, 5.6, 1.4)                 # centre x, centre depth, radius
    width = 12.0
    scale = 70.0
    c = Canvas(900, 680, ox=30, oy=20 - 2.6 * scale, scale=scale, title=a.title or "second depth and midpoint")
    D = lambda x, d: (x, -d)  # noqa: E731  (depth grows downwards)

    def surfaces(x):
        hits = [floor]
        if box[0] <= x <= box[1]:
            hits += [box[2], floor]
        dx = x - ball[0]
        if abs(dx) < ball[2]:
            h = math.sqrt(ball[2] ** 2 - dx * dx)
            hits += [ball[1] - h, ball[1] + h]
        hits = sorted(hits)
        d1 = hits[0]
        d2 = hits[1] if len(hits) > 1 else far
        return d1, d2

    # The scene.
    c.polygon([D(box[0], box[2]), D(box[1], box[2]), D(box[1], floor), D(box[0], floor)], fill="#e6c7c0",
              stroke=INK, width=2)
    c.circle(D(ball[0], ball[1]), r_world=ball[2], fill="#efe3b0", stroke=INK, width=2)
    c.line(D(0, floor), D(width, floor), stroke=GREY, width=6)
    c.line(D(0, far), D(width, far), stroke=GREY, width=1.5, dash="6 6")
    c.text(D(width - 0.1, far - 0.15), "far plane", size=18, fill=GREY, anchor="end")
    for x in (0.6, 3.0, 6.2, 9.4, 11.0):
        c.line(D(x, 2.7), D(x, 3.5), stroke=LIGHT, width=3, arrow=True)
    t = width / a.texels
    c.fact(texels=a.texels, texel=t, far=far, floor=floor)
    for i in range(a.texels):
        x0, x1 = i * t, (i + 1) * t
        d1, d2 = surfaces((x0 + x1) / 2)
        mid = (d1 + d2) / 2
        c.line(D(x0, d1), D(x1, d1), stroke=BLUE, width=5, id=f"first-{i}", data_depth=round(d1, 6))
        c.line(D(x0, d2), D(x1, d2), stroke=PURPLE, width=5, id=f"second-{i}", data_depth=round(d2, 6))
        c.line(D(x0, mid), D(x1, mid), stroke=ACCENT, width=4, dash="7 4", id=f"mid-{i}",
               data_depth=round(mid, 6))
    c.text((20, 612), "blue: first depth d₁ (what a plain map stores)", size=20, fill=BLUE, px=True)
    c.text((20, 638), "purple: second depth d₂ (culling the front faces stores it)", size=20, fill=PURPLE, px=True)
    c.text((20, 664), "red dashed: the midpoint (d₁ + d₂) / 2, what the lookup compares with", size=20,
           fill=ACCENT, px=True)
    c.save(a.out)


if __name__ == "__main__":
    main()
