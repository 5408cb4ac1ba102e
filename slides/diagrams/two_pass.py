#!/usr/bin/env python3
"""Williams' two passes, side view: the light's camera stores, per texel, the
distance to the nearest surface along its ray; the camera pass looks up the
texel of each visible point and compares its own distance to the light.

A point P on the floor behind a box: its ray from the light first meets the
box's top at distance d (stored), P itself is at distance z > d: shadow. A
point Q beside the box: the stored distance is its own: lit.

  two_pass.py --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, LIGHT, BLUE, GREEN, GREY  # noqa: E402


def hit_box(o, d, box):
    """Distance along the ray o + s d to the box [x0, x1] x [y0, y1] (slab test), or None."""
    (x0, x1), (y0, y1) = box
    lo, hi = -math.inf, math.inf
    for oc, dc, a, b in ((o[0], d[0], x0, x1), (o[1], d[1], y0, y1)):
        if abs(dc) < 1e-12:
            if not a <= oc <= b:
                return None
            continue
        s0, s1 = sorted(((a - oc) / dc, (b - oc) / dc))
        lo, hi = max(lo, s0), min(hi, s1)
    return lo if lo <= hi and lo > 0 else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    light = (1.0, 5.6)
    box = ((3.0, 5.0), (0.0, 2.8))
    P, Q = (7.6, 0.0), (1.8, 0.0)
    c = Canvas(960, 500, ox=60, oy=420, scale=68, title="two passes")
    c.polygon([(box[0][0], 0), (box[0][1], 0), (box[0][1], box[1][1]), (box[0][0], box[1][1])], fill="#e6c7c0",
              stroke=INK, width=2)
    c.line((-0.3, 0), (11.3, 0), stroke=GREY, width=6)
    # The light's camera: a frustum, its image plane (the map), a few texels.
    c.circle(light, r_px=14, fill=LIGHT, stroke="none")
    c.text((light[0], light[1] + 0.3), "light (camera 1)", size=20, anchor="middle", fill="#9a6a00")
    facts = {}
    for name, pt, col in (("P", P, ACCENT), ("Q", Q, GREEN)):
        d = (pt[0] - light[0], pt[1] - light[1])
        L = math.hypot(*d)
        u = (d[0] / L, d[1] / L)
        s_box = hit_box(light, u, box)
        stored = min(L, s_box) if s_box is not None else L
        facts[name] = (L, stored)
        first = (light[0] + u[0] * stored, light[1] + u[1] * stored)
        c.line(light, first, stroke=BLUE, width=4, id=f"stored-{name}", data_stored=round(stored, 6))
        if stored < L - 1e-9:
            c.line(first, pt, stroke=ACCENT, width=3, dash="8 6", id=f"beyond-{name}", data_z=round(L, 6))
            c.circle(first, r_px=7, fill=BLUE, stroke="none")
        c.circle(pt, r_px=9, fill=col, stroke="none")
        c.text((pt[0] - 0.35, pt[1] + 0.2), name, size=24, anchor="middle", fill=col, weight="bold")
    c.fact(P_z=round(facts["P"][0], 6), P_d=round(facts["P"][1], 6), Q_z=round(facts["Q"][0], 6),
           Q_d=round(facts["Q"][1], 6))
    # The camera.
    cam = (11.4, 4.4)
    c.circle(cam, r_px=12, fill=INK, stroke="none")
    c.text((cam[0] - 0.1, cam[1] + 0.3), "camera (pass 2)", size=20, anchor="end")
    for pt in (P, Q):
        c.line(cam, pt, stroke=GREY, width=1.5, dash="3 6")
    c.text((20, 462), "pass 1: the light's camera stores the nearest distance d per texel (blue)", size=20,
           px=True, fill=BLUE)
    c.text((20, 490), "pass 2: a visible point at distance z from the light is in shadow when z > d", size=20,
           px=True, fill=ACCENT)
    c.text((P[0] + 0.3, 0.5), "P: z = %.2f > d = %.2f: shadow" % facts["P"], size=18, fill=ACCENT)
    c.text((Q[0] + 0.3, 0.5), "Q: z = d = %.2f: lit" % facts["Q"][0], size=18, fill=GREEN)
    c.save(a.out)


if __name__ == "__main__":
    main()
