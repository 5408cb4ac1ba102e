#!/usr/bin/env python3
"""Shadow acne: light rays on a floor, each shadow-map texel holding one depth.

Side view. The light comes in at angle theta from the floor's normal; a texel
is t wide across the rays and stores the depth of the floor point on its
centre ray. Every floor point whose ray falls in that texel is compared with
that one depth: the part of the texel's footprint beyond the stored depth
(plus the bias b) is in shadow. In the light's depth units a floor point at
distance u from the centre point lies u sin(theta) deeper, so the shadowed
length per texel is max(0, t / (2 cos theta) - b / sin theta), and it is zero
once b >= (t / 2) tan(theta): half a texel's depth change.

  acne.py [--angle DEG] [--texel T] [--texels N] [--bias B|needed] --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, LIGHT, BLUE, GREEN, GREY  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--angle", type=float, default=50.0, help="light angle from the normal, degrees")
    ap.add_argument("--texel", type=float, default=1.0, help="texel width across the rays")
    ap.add_argument("--texels", type=int, default=4)
    ap.add_argument("--bias", default="0", help="depth bias along the light, or 'needed': (t/2) tan(theta)")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    th = math.radians(a.angle)
    t = a.texel
    needed = 0.5 * t * math.tan(th)
    b = needed if a.bias == "needed" else float(a.bias)
    L = (math.sin(th), -math.cos(th))      # from the light into the scene
    Lp = (math.cos(th), math.sin(th))      # across the rays
    foot = t / math.cos(th)                # a texel's footprint on the floor
    n = a.texels
    # The rays come in from the upper left: leave room for them.
    rise = 190.0                           # pixels of ray above the floor
    run = rise * math.tan(th)
    scale = (870.0 - 20 - run) / (n * foot)
    c = Canvas(900, 450, ox=20 + run, oy=320, scale=scale, title=a.title or "shadow acne")
    c.fact(angle=a.angle, texel=t, bias=round(b, 6), needed_bias=round(needed, 6), texels=n,
           shadowed_per_texel=round(max(0.0, foot / 2 - b / math.sin(th)), 6))
    x_end = n * foot
    # Texel boundaries (dashed rays) and the centre rays (the light's samples).
    ray_len = rise / scale / math.cos(th)
    for i in range(n + 1):
        xb = i * foot
        c.line((xb - L[0] * ray_len, -L[1] * ray_len), (xb, 0), stroke=GREY, width=1.5, dash="6 6")
    red = 0.0
    for i in range(n):
        xc = (i + 0.5) * foot
        c.line((xc - L[0] * ray_len, -L[1] * ray_len), (xc - L[0] * 0.12 * ray_len, -L[1] * 0.12 * ray_len),
               stroke=LIGHT, width=3, arrow=True)
        # The stored depth (+ bias): a step across the texel, perpendicular to the rays.
        cx, cy = xc + b * L[0], b * L[1]
        h = t / 2
        c.line((cx - h * Lp[0], cy - h * Lp[1]), (cx + h * Lp[0], cy + h * Lp[1]), stroke=BLUE, width=5,
               id=f"step-{i}", data_texel=i)
        # Lit and shadowed parts of the texel's footprint.
        x0, x1 = i * foot, (i + 1) * foot
        split = min(x1, max(x0, xc + b / math.sin(th)))
        c.line((x0, 0), (split, 0), stroke=GREEN, width=7, id=f"lit-{i}")
        if split < x1:
            c.line((split, 0), (x1, 0), stroke=ACCENT, width=7, id=f"acne-{i}")
            red += x1 - split
    c.fact(shadowed_total=round(red, 6))
    c.line((0, -0.02 * foot), (x_end, -0.02 * foot), stroke=INK, width=1)
    # Labels.
    c.text((10, 28), a.title or (f"bias {b:.2f}" if b else "no bias"), size=24, px=True, weight="bold")
    c.text((10, 405), "blue: the one depth a texel stores" + (", moved by the bias" if b else ""),
           size=20, fill=BLUE, px=True)
    c.text((10, 435), "red: floor that compares as shadowed (acne)   green: lit", size=20, fill=ACCENT, px=True)
    c.text((890, 28), f"light at {a.angle:g}° from the normal", size=19, fill="#9a6a00", px=True, anchor="end")
    lit_word = "needed bias: (t/2)·tan θ = %.2f t" % (needed / t)
    c.text((890, 56), lit_word, size=19, px=True, anchor="end")
    c.save(a.out)


if __name__ == "__main__":
    main()
