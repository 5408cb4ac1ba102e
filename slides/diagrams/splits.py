#!/usr/bin/env python3
"""Cascade splits seen from above: the practical split scheme (Zhang et al. 2006).

The camera at the left looks right; its frustum between the near plane n
and the far plane f is cut at

    C_i = lambda * n * (f/n)^(i/m) + (1 - lambda) * (n + (f - n) * i/m),  i = 0..m

and each slice gets its own map, fitted to the slice's bounding circle (the
top view of the bounding sphere lab 6 fits). A strip below compares the
uniform (lambda = 0), logarithmic (lambda = 1) and practical splits.

  splits.py [--near N] [--far F] [--cascades M] [--lambda L] [--fov DEG] --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, GREY  # noqa: E402

# The viewer's cascade tints (--show-cascades): red, green, blue, yellow.
COLOURS = ["#d9534f", "#4caf50", "#3f7fd9", "#e0b000"]


def split(n, f, m, lam, i):
    return lam * n * (f / n) ** (i / m) + (1 - lam) * (n + (f - n) * i / m)


def bounding_circle(x0, a, x1, b):
    """The smallest circle holding the symmetric trapezoid (x0, +-a), (x1, +-b): centre on the axis."""
    c = (x1 * x1 + b * b - x0 * x0 - a * a) / (2 * (x1 - x0))
    c = min(max(c, x0), x1)
    r = max(math.hypot(c - x0, a), math.hypot(x1 - c, b))
    return c, r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--near", type=float, default=1.0)
    ap.add_argument("--far", type=float, default=60.0)
    ap.add_argument("--cascades", type=int, default=4)
    ap.add_argument("--lambda", dest="lam", type=float, default=0.8)
    ap.add_argument("--fov", type=float, default=26.0, help="horizontal field of view, degrees")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    n, f, m, lam = a.near, a.far, a.cascades, a.lam
    k = math.tan(math.radians(a.fov) / 2)
    scale = 860.0 / f
    c = Canvas(960, 630, ox=60, oy=262, scale=scale, title=a.title or "cascade splits from above")
    C = [split(n, f, m, lam, i) for i in range(m + 1)]
    c.fact(near=n, far=f, cascades=m, **{"lambda": lam}, fov=a.fov, splits=" ".join("%.6g" % x for x in C))
    # Slices, bounding circles of the near ones (the far ones are larger than the picture).
    for i in range(m):
        x0, x1 = C[i], C[i + 1]
        c.polygon([(x0, -k * x0), (x1, -k * x1), (x1, k * x1), (x0, k * x0)], fill=COLOURS[i % 4], opacity=0.35,
                  id=f"slice-{i}")
        cx, r = bounding_circle(x0, k * x0, x1, k * x1)
        if r * scale < 240:
            c.circle((cx, 0), r_world=r, stroke=COLOURS[i % 4], width=2.5, dash="7 5", id=f"sphere-{i}",
                     data_centre=round(cx, 6), data_radius=round(r, 6))
    for i, x in enumerate(C):
        c.line((x, -k * x), (x, k * x), stroke=INK, width=3, id=f"split-{i}", data_depth=round(x, 6))
        lab = "n" if i == 0 else ("f" if i == m else f"C_{i}")
        c.text((x, k * x + 8 / scale), lab, size=20, anchor="middle", italic=True)
    c.line((0, 0), (f, -k * f), stroke=GREY, width=2)
    c.line((0, 0), (f, k * f), stroke=GREY, width=2)
    c.circle((0, 0), r_px=8, fill=INK, stroke="none")
    c.text((8, 28), a.title or f"{m} cascades, λ = {lam:g}: slices seen from above", size=22, px=True, weight="bold")
    c.text((8, 56), "dashed: each slice's bounding circle (the map is fitted to it)", size=18, px=True, fill=GREY)
    # The three schemes on one axis.
    rows = [("uniform, λ = 0", 0.0), ("logarithmic, λ = 1", 1.0), (f"practical, λ = {lam:g}", lam)]
    for r_i, (name, l) in enumerate(rows):
        y = 500 + r_i * 42
        c.text((60 + n * scale - 8, y + 6), "", size=18, px=True)
        c.raw(f'<line x1="{60 + n * scale:.2f}" y1="{y}" x2="{60 + f * scale:.2f}" y2="{y}" stroke="{GREY}" stroke-width="2"/>')
        for i in range(m + 1):
            x = split(n, f, m, l, i)
            c.raw(f'<line x1="{60 + x * scale:.2f}" y1="{y - 11}" x2="{60 + x * scale:.2f}" y2="{y + 11}" '
                  f'stroke="{INK}" stroke-width="3" data-scheme="{l}" data-depth="{x:.6g}"/>')
        c.text((955, y - 10), name, size=18, px=True, anchor="end")
    c.save(a.out)


if __name__ == "__main__":
    main()
