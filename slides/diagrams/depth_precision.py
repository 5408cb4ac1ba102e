#!/usr/bin/env python3
"""Depth precision: how far apart two distinguishable depths are, at each distance.

A perspective light (or camera) with near n and far f stores
d(z) = f (z - n) / (z (f - n)): most of [0, 1] is spent near n. The world
distance between two neighbouring stored values at distance z is
Delta_z = Delta_d / d'(z), with d'(z) = f n / ((f - n) z^2), and Delta_d the
format's step at that value:

  - 24-bit fixed point: Delta_d = 2^-24 everywhere;
  - 32-bit float, d as is: Delta_d is the float spacing near d, i.e. near 1
    (2^-24): no better than 24 bits;
  - 32-bit float, reversed (1 - d, far = 0): the float spacing shrinks with
    the value, which cancels the 1/z^2 crowding: Delta_z grows only like z.

The float spacings are measured by rounding to float32 (struct), not assumed.

  depth_precision.py [--near N] [--far F] --out FILE.svg
"""
import argparse
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREEN, GREY  # noqa: E402


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32_step(x):
    """The distance from float32(x) to the next float32 up."""
    b = struct.unpack("<I", struct.pack("<f", f32(x)))[0]
    return struct.unpack("<f", struct.pack("<I", b + 1))[0] - f32(x)


def curves(n, f, z):
    slope = f * n / ((f - n) * z * z)
    d = f * (z - n) / (z * (f - n))
    rev = n * (f - z) / (z * (f - n))
    return {
        "fixed24": 2.0 ** -24 / slope,
        "float": f32_step(d) / slope,
        "reversed": f32_step(max(rev, 1e-30)) / slope,
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--near", type=float, default=0.1)
    ap.add_argument("--far", type=float, default=1000.0)
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    n, f = a.near, a.far
    zs = [n * (f / n) ** (i / 120) for i in range(1, 120)]
    vals = {k: [curves(n, f, z)[k] for z in zs] for k in ("fixed24", "float", "reversed")}
    lo_e, hi_e = -9, 2                       # decades on the y axis (metres)
    W, H = 820, 400
    c = Canvas(960, 520, ox=100, oy=450, scale=1.0, title=a.title or "depth precision")
    c.fact(near=n, far=f, plot_w=W, plot_h=H, log_y_min=lo_e, log_y_max=hi_e)
    lx = lambda z: W * math.log10(z / n) / math.log10(f / n)  # noqa: E731
    ly = lambda v: H * (math.log10(v) - lo_e) / (hi_e - lo_e)  # noqa: E731
    for e in range(lo_e, hi_e + 1):
        c.line((0, ly(10.0 ** e)), (W, ly(10.0 ** e)), stroke="#e8e9ed", width=1)
        if e % 2 == 0 or e == hi_e:
            c.text((-10, ly(10.0 ** e) - 6), f"1e{e}", size=16, anchor="end")
    z = n
    while z <= f * 1.0001:
        c.line((lx(z), 0), (lx(z), -6), stroke=INK, width=2)
        c.text((lx(z), -28), f"{z:g} m", size=16, anchor="middle")
        z *= 10
    c.line((0, 0), (W, 0), stroke=INK, width=2)
    c.line((0, 0), (0, H), stroke=INK, width=2)
    style = {"fixed24": (INK, "24-bit fixed point (GL_DEPTH_COMPONENT24)", None),
             "float": (ACCENT, "32-bit float, 0 at near", "10 6"),
             "reversed": (GREEN, "32-bit float, reversed: 1 at near, 0 at far", None)}
    for i, (k, (col, name, dash)) in enumerate(style.items()):
        pts = [(lx(zz), ly(v)) for zz, v in zip(zs, vals[k]) if v > 0]
        c.polyline(pts, stroke=col, width=4, dash=dash, id=f"curve-{k}",
                   data_z=" ".join("%.6g" % zz for zz in zs), data_dz=" ".join("%.6g" % v for v in vals[k]))
        c.text((110 + 0, 70 + 26 * i), name, size=18, fill=col, px=True)
    c.text((10, 30), a.title or f"smallest depth difference a map can tell, near {n:g} m, far {f:g} m", size=21,
           px=True, weight="bold")
    c.text((100 + W, 505), "distance from the light (log)", size=17, px=True, anchor="end", fill=GREY)
    c.save(a.out)


if __name__ == "__main__":
    main()
