#!/usr/bin/env python3
"""PCSS (Fernando 2005): the penumbra by similar triangles, and the blocker search region.

Side view, depths measured down from the light. An area light w_light wide,
a blocker whose edge is at depth d_b, a receiver at depth d_r. The lines from
the light's two ends through the blocker's edge bound the penumbra on the
receiver; by similar triangles its width is

    w_penumbra = (d_r - d_b) * w_light / d_b

The blocker search looks in the shadow map (on its near plane, depth n) over
the region the light's cone from the receiver point covers:
w_search = w_light * (d_r - n) / d_r.

  pcss.py [--light W] [--blocker D] [--receiver D] [--near N] --out FILE.svg
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, LIGHT, BLUE, GREEN, GREY  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--light", type=float, default=1.6, help="the light's width")
    ap.add_argument("--blocker", type=float, default=2.0, help="the blocker's depth below the light")
    ap.add_argument("--receiver", type=float, default=5.0, help="the receiver's depth below the light")
    ap.add_argument("--near", type=float, default=0.7, help="the shadow map's near plane")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    w, db, dr, n = a.light, a.blocker, a.receiver, a.near
    edge = 0.9                                     # the blocker's right edge, x
    # y is height above the receiver; the light is at y = dr.
    y_light, y_block, y_near = dr, dr - db, dr - n
    ends = (-w / 2, w / 2)
    def hit(l):  # where the line from light end l through the blocker's edge meets the receiver
        return l + (edge - l) * dr / db
    x_umbra, x_lit = hit(w / 2), hit(-w / 2)       # full shadow left of x_umbra, fully lit right of x_lit
    width = x_lit - x_umbra
    scale = 88.0
    c = Canvas(960, 560, ox=350, oy=485, scale=scale, title=a.title or "PCSS similar triangles")
    c.fact(light=w, blocker=db, receiver=dr, near=n, penumbra=round(width, 6),
           penumbra_formula=round((dr - db) * w / db, 6), search=round(w * (dr - n) / dr, 6))
    # Penumbra wedge, umbra.
    c.polygon([(edge, y_block), (x_umbra, 0), (x_lit, 0)], fill="#f3d9a0", opacity=0.8)
    c.polygon([(-3.2, y_block), (edge, y_block), (x_umbra, 0), (-3.2, 0)], fill="#c9ccd3", opacity=0.6)
    # Light, blocker, receiver.
    c.line((-w / 2, y_light), (w / 2, y_light), stroke=LIGHT, width=9, id="light")
    c.line((-3.2, y_block), (edge, y_block), stroke=INK, width=8, id="blocker")
    c.line((-3.5, 0), (6.8, 0), stroke=GREY, width=6, id="receiver")
    for l in ends:
        c.line((l, y_light), (hit(l), 0), stroke="#9a6a00", width=2.5, dash="8 5")
    c.line((x_umbra, -0.25), (x_lit, -0.25), stroke=ACCENT, width=6, id="penumbra")
    c.text(((x_umbra + x_lit) / 2, -0.62), "penumbra w_p", size=22, fill=ACCENT, anchor="middle")
    # Blocker search: from the receiver point p, the cone to the light, cut by the near plane.
    p = ((x_umbra + x_lit) / 2, 0.0)
    sl, sr = [(p[0] + (l - p[0]) * (dr - n) / dr) for l in ends]
    c.polygon([p, (-w / 2, y_light), (w / 2, y_light)], fill="#bcd3ee", opacity=0.45)
    c.line((-3.5, y_near), (6.8, y_near), stroke=BLUE, width=1.5, dash="4 6")
    c.line((sl, y_near), (sr, y_near), stroke=BLUE, width=7, id="search")
    c.circle(p, r_px=7, fill=BLUE, stroke="none")
    c.text((p[0] + 0.12, 0.2), "p", size=22, fill=BLUE)
    c.text((6.75, y_near + 0.15), "shadow map's near plane", size=18, fill=BLUE, anchor="end")
    c.text((sr + 0.15, y_near - 0.45), "blocker search region", size=20, fill=BLUE)
    # Dimensions.
    def dim(x, y0, y1, label):
        c.line((x, y0), (x, y1), stroke=INK, width=1.5, arrow=True)
        c.line((x, y1), (x, y0), stroke=INK, width=1.5, arrow=True)
        c.text((x - 0.12, (y0 + y1) / 2), label, size=22, anchor="end", italic=True)
    dim(-2.6, y_light, y_block, "d_b")
    dim(-3.35, y_light, 0.0, "d_r")
    c.text((0, y_light + 0.2), "area light w_{light}", size=22, fill="#9a6a00", anchor="middle")
    c.text((-1.2, y_block + 0.18), "blocker", size=20)
    c.text((6.6, 0.18), "receiver", size=20, fill=GREY, anchor="end")
    c.text((950, 30), "w_p = (d_r − d_b) · w_{light} / d_b = %.2f" % width, size=22, px=True, anchor="end",
           fill=ACCENT)
    c.save(a.out)


if __name__ == "__main__":
    main()
