#!/usr/bin/env python3
"""Lab 4's Poisson disk, read from the lab's own shader, and what rotating it per pixel does.

  poisson.py disk --out FILE.svg
      the 16 points of PCF_POISSON_DISK (labs/lab4_pcf/shaders/pcf.glsl), and the
      same points turned by pcf_rotation() for two neighbouring pixels
  poisson.py edge --rotate yes|no [--radius R] --out FILE.png
      a straight shadow edge, slanted across a map of 1-texel squares, filtered
      with the 16 taps as pcf_poisson does (radius R texels): the same pattern at
      every pixel gives at most 17 levels, laid out in bands along the edge;
      turned per pixel (pcf_rotation's integer hash, re-done here bit for bit)
      the bands become noise
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREY  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHADER = os.path.join(ROOT, "labs", "lab4_pcf", "shaders", "pcf.glsl")


def disk():
    text = open(SHADER, encoding="utf-8").read()
    block = re.search(r"PCF_POISSON_DISK\[16\]\s*=\s*vec2\[\]\((.*?)\);", text, re.S).group(1)
    pts = [(float(x), float(y)) for x, y in re.findall(r"vec2\(\s*([-0-9.]+),\s*([-0-9.]+)\)", block)]
    assert len(pts) == 16, "PCF_POISSON_DISK should hold 16 points"
    return pts


def rotation(px, py):
    """pcf_rotation(pixel): the same integer hash as the shader (uint arithmetic mod 2^32)."""
    m = 0xFFFFFFFF
    h = ((int(px) * 73856093) & m) ^ ((int(py) * 19349663) & m)
    h = ((h ^ (h >> 13)) * 1274126177) & m
    angle = float(h >> 22) * (6.28318530718 / 1024.0)
    return math.cos(angle), math.sin(angle)


def rotate(p, cs):
    c, s = cs
    # GLSL mat2(c, s, -s, c) is column-major: columns (c, s) and (-s, c).
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def draw_disk(out):
    pts = disk()
    c = Canvas(900, 420, ox=0, oy=0, scale=1, title="Poisson disk")
    panels = [("the lab's 16 points", None, 150), ("pixel (10, 7)", rotation(10, 7), 450),
              ("pixel (11, 7)", rotation(11, 7), 750)]
    c.fact(points=" ".join("%g,%g" % p for p in pts))
    for title, rot, cx in panels:
        cy, r = 230, 140
        c.circle((cx, -cy), r_px=r, stroke=GREY, width=2, dash="5 5")
        for i, p in enumerate(pts):
            q = rotate(p, rot) if rot else p
            c.circle((cx + r * q[0], -(cy - r * q[1])), r_px=7, fill=ACCENT if rot else BLUE, stroke="none",
                     id=f"pt-{'fixed' if rot is None else title.split()[1]}-{i}", data_x=round(q[0], 5),
                     data_y=round(q[1], 5))
        c.text((cx, 60), title, size=22, px=True, anchor="middle", weight="bold")
    c.text((450, 405), "radius: poisson-radius texels (PCF), or the blocker search / penumbra width (PCSS)",
           size=17, px=True, anchor="middle", fill=GREY)
    c.save(out)


def draw_edge(out, rotate_taps, radius):
    from PIL import Image
    pts = disk()
    texel = 9                      # pixels per map texel: a magnified map
    W, H = 360, 240
    slope = 0.27                   # the occluder's edge: x_texel = 18 + slope * y_texel
    def occluded(tx, ty):          # a texel holds the occluder's depth (shadow) left of the edge
        return (tx + 0.5) < 18.0 + slope * (ty + 0.5)
    img = Image.new("L", (W, H))
    px = img.load()
    for y in range(H):
        for x in range(W):
            u, v = x / texel, y / texel
            cs = rotation(x, y) if rotate_taps else (1.0, 0.0)
            lit = 0
            for p in pts:
                q = rotate(p, cs)
                if not occluded(math.floor(u + q[0] * radius), math.floor(v + q[1] * radius)):
                    lit += 1
            px[x, y] = int(round(255 * (0.15 + 0.85 * lit / 16)))
    img.resize((W * 2, H * 2), Image.NEAREST).save(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=["disk", "edge"])
    ap.add_argument("--rotate", choices=["yes", "no"], default="yes")
    ap.add_argument("--radius", type=float, default=2.5)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    if a.what == "disk":
        draw_disk(a.out)
    else:
        draw_edge(a.out, a.rotate == "yes", a.radius)


if __name__ == "__main__":
    main()
