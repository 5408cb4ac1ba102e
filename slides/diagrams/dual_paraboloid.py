#!/usr/bin/env python3
"""Dual-paraboloid maps (Brabec et al. 2002): the mapping, its seam, and why edges bend.

A unit direction d = (x, y, z) from the light with z >= 0 goes to the front map at

    (u, v) = (x, y) / (1 + z)          (the back map: z <= 0, (x, y) / (1 - z))

Left: the front map, the unit disk; its rim (z = 0) is where the two maps meet: the seam.
The picture of a straight edge in the scene is a curve on the map, but the rasteriser
joins the projected vertices with a straight chord: the drawn edge is off by the gap
between the two, unless the geometry is finely tessellated.
Right: the map radius against the angle from the axis, rho = tan(alpha / 2): texels
cover twice the angle at the centre that they cover at the rim.

  dual_paraboloid.py [--edge-y Y] [--edge-z Z] --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREY  # noqa: E402


def project(p):
    n = math.sqrt(sum(c * c for c in p))
    x, y, z = (c / n for c in p)
    return x / (1 + z), y / (1 + z)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--edge-y", type=float, default=0.35)
    ap.add_argument("--edge-z", type=float, default=0.2)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    R = 180.0
    c = Canvas(960, 540, ox=250, oy=258, scale=R, title="dual-paraboloid mapping")
    c.fact(edge_y=a.edge_y, edge_z=a.edge_z)
    c.circle((0, 0), r_world=1.0, stroke=ACCENT, width=4, dash="10 6", id="seam")
    c.line((-1.1, 0), (1.1, 0), stroke="#e2e4e8", width=1)
    c.line((0, -1.1), (0, 1.1), stroke="#e2e4e8", width=1)
    # A straight edge in the scene, in front of the light, from x = -2 to x = 2.
    ts = [i / 100 for i in range(101)]
    pts3 = [(-2 + 4 * t, a.edge_y, a.edge_z) for t in ts]
    curve = [project(p) for p in pts3]
    c.polyline(curve, stroke=BLUE, width=4, id="edge-curve",
               data_points=" ".join("%.5f,%.5f" % q for q in curve))
    c.line(curve[0], curve[-1], stroke=INK, width=3, dash="8 5", id="edge-chord")
    c.circle(curve[0], r_px=6, fill=INK, stroke="none")
    c.circle(curve[-1], r_px=6, fill=INK, stroke="none")
    c.text((20, 30), "the front map (z ≥ 0)", size=22, px=True, weight="bold")
    c.text((20, 500), "red dashed: the rim, z = 0 — the seam with the back map", size=18, px=True, fill=ACCENT)
    c.text((20, 526), "blue: a straight edge's true image; dashed: what the rasteriser draws", size=18, px=True,
           fill=BLUE)
    # Right: rho(alpha).
    ox, oy, W, H = 560, 420, 360, 330
    c.raw(f'<line x1="{ox}" y1="{oy}" x2="{ox + W}" y2="{oy}" stroke="{INK}" stroke-width="2"/>')
    c.raw(f'<line x1="{ox}" y1="{oy}" x2="{ox}" y2="{oy - H}" stroke="{INK}" stroke-width="2"/>')
    al = [i * (math.pi / 2) / 90 for i in range(91)]
    rho = [math.tan(x / 2) for x in al]
    pts = " ".join("%.2f,%.2f" % (ox + W * x / (math.pi / 2), oy - H * r) for x, r in zip(al, rho))
    c.raw(f'<polyline points="{pts}" stroke="{BLUE}" stroke-width="4" fill="none" id="rho" '
          f'data-alpha="{" ".join("%.5f" % x for x in al)}" data-rho="{" ".join("%.5f" % r for r in rho)}"/>')
    for deg in (0, 45, 90):
        x = ox + W * deg / 90
        c.text((x, oy + 24), f"{deg}°", size=16, px=True, anchor="middle")
    c.text((ox - 8, oy - H + 6), "1", size=16, px=True, anchor="end")
    c.text((ox + W / 2, oy + 50), "angle from the map's axis α", size=18, px=True, anchor="middle")
    c.text((ox + 10, oy - H - 14), "map radius ρ = tan(α/2)", size=18, px=True, fill=BLUE)
    c.save(a.out)


if __name__ == "__main__":
    main()
