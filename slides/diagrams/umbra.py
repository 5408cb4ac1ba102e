#!/usr/bin/env python3
"""Umbra and penumbra of an area light (side view), and the penumbra's width.

A light w_light wide at height d_r above a receiver, a blocker B wide at depth d_b below
the light. A receiver point sees none of the light (umbra) where every line to the light
passes through the blocker; all of it (lit) where none does; part of it (penumbra) in
between. The penumbra's bounds are the lines from each end of the light through each edge
of the blocker; by similar triangles each penumbra is

    w_penumbra = (d_r - d_b) * w_light / d_b

wide, and the umbra B * d_r / d_b - w_penumbra (none once the light is wide enough).

  umbra.py [--light W] [--blocker-width B] [--blocker D] [--receiver D] --out FILE.svg
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREY  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--light", type=float, default=1.6, help="the light's width")
    ap.add_argument("--blocker-width", type=float, default=2.4, help="the blocker's width")
    ap.add_argument("--blocker", type=float, default=2.0, help="the blocker's depth below the light")
    ap.add_argument("--receiver", type=float, default=5.0, help="the receiver's depth below the light")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    w, B, db, dr = a.light, a.blocker_width, a.blocker, a.receiver
    yl, yb = dr, dr - db                            # heights above the receiver
    def hit(l, e):  # where the line from the light's point l through the blocker's point e meets the receiver
        return l + (e - l) * dr / db
    # Right side: inner bound (the light's right end hidden) and outer bound (all of it seen).
    u = hit(w / 2, B / 2)                           # the umbra's right end (mirror on the left)
    o = hit(-w / 2, B / 2)                          # the penumbra's right end
    pen = o - u
    SUN = "#9a6a00"
    c = Canvas(1200, 640, ox=560, oy=505, scale=86.0, title=a.title or "Umbra and penumbra")
    c.fact(light=w, blocker_width=B, blocker=db, receiver=dr, penumbra=round(pen, 6),
           penumbra_formula=round((dr - db) * w / db, 6), umbra=round(2 * u, 6))
    # Regions between the blocker and the receiver.
    c.polygon([(-B / 2, yb), (B / 2, yb), (u, 0), (-u, 0)], fill="#9ea3ad", opacity=0.75, id="umbra-region")
    c.polygon([(B / 2, yb), (u, 0), (o, 0)], fill="#f3d9a0", opacity=0.9, id="penumbra-right-region")
    c.polygon([(-B / 2, yb), (-u, 0), (-o, 0)], fill="#f3d9a0", opacity=0.9, id="penumbra-left-region")
    # The four bounding rays.
    for l, e in ((w / 2, B / 2), (-w / 2, B / 2), (-w / 2, -B / 2), (w / 2, -B / 2)):
        c.line((l, yl), (hit(l, e), 0), stroke=SUN, width=2, dash="8 5")
    c.line((-w / 2, yl), (w / 2, yl), stroke="#e6a100", width=10, id="light")
    c.line((-B / 2, yb), (B / 2, yb), stroke=INK, width=9, id="blocker")
    c.line((-6.2, 0), (6.3, 0), stroke=GREY, width=6, id="receiver")
    # The regions on the receiver, marked below it.
    c.line((-u, -0.3), (u, -0.3), stroke=INK, width=7, id="umbra")
    c.line((u, -0.3), (o, -0.3), stroke=ACCENT, width=7, id="penumbra")
    c.line((-o, -0.3), (-u, -0.3), stroke=ACCENT, width=7, id="penumbra-left")
    c.text((0, -0.75), "umbra", size=24, anchor="middle", weight="bold")
    c.text(((u + o) / 2, -0.75), "penumbra w_p", size=24, fill=ACCENT, anchor="middle")
    c.text((-(u + o) / 2, -0.75), "penumbra", size=24, fill=ACCENT, anchor="middle")
    c.text((o + 0.2, 0.2), "lit", size=24, fill=GREY)
    c.text((-o - 0.2, 0.2), "lit", size=24, fill=GREY, anchor="end")
    # Dimensions, on the left.
    def dim(x, y0, y1, label):
        c.line((x, y0), (x, y1), stroke=INK, width=1.5, arrow=True)
        c.line((x, y1), (x, y0), stroke=INK, width=1.5, arrow=True)
        c.text((x - 0.12, (y0 + y1) / 2 - 0.1), label, size=24, anchor="end", italic=True)
    dim(-5.0, yl, yb, "d_b")
    dim(-5.9, yl, 0.0, "d_r")
    c.line((-5.9, yl), (-w / 2, yl), stroke=GREY, width=1, dash="3 4")
    c.line((-5.0, yb), (-B / 2, yb), stroke=GREY, width=1, dash="3 4")
    c.text((w / 2 + 0.25, yl - 0.1), "area light, w_{light} wide", size=24, fill=SUN)
    c.text((B / 2 + 0.25, yb - 0.1), "blocker", size=24)
    c.text((6.3, 0.2), "receiver", size=24, fill=GREY, anchor="end")
    c.text((1190, 626), "w_p = (d_r − d_b) · w_{light} / d_b = %.2f" % pen, size=26, px=True, anchor="end",
           fill=ACCENT)
    c.text((10, 626), "the code's --light-size: w_{light} / 2", size=22, px=True, fill=SUN)
    c.save(a.out)


if __name__ == "__main__":
    main()
