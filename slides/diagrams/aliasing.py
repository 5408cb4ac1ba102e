#!/usr/bin/env python3
"""Shadow-map aliasing: a texel's footprint on a receiver, and how many pixels it covers.

Side view. A directional light shines straight down; each texel of its map is a beam of
parallel rays tau wide. Where a beam meets a receiver it lights a footprint; the camera
sees the footprint through its near plane, at distance n from the eye. In pixels per
texel (Stamminger & Drettakis 2002; Lloyd et al. 2008):

    ds/dp ~ (n / z) * (tau / pixel) * (cos phi / cos theta)

Left, perspective aliasing: two texels' footprints on the floor, one near the camera
(depth z1) and one far (z2), projected through the eye onto its near plane: the near one's
image is about z2/z1 times longer (n/z). Right, projective aliasing: a beam tau wide meets
a surface whose normal is theta from the light's direction: its footprint is tau / cos(theta)
long, and a camera that sees it head-on (phi ~ 0) sees all of that length.

  aliasing.py [--texel T] [--near N] [--theta DEG] --out FILE.svg
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, LIGHT, BLUE, GREY  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--texel", type=float, default=0.8, help="a texel's width across the light's rays")
    ap.add_argument("--near", type=float, default=2.0, help="the camera's near-plane distance")
    ap.add_argument("--theta", type=float, default=72.0, help="right: the angle between the surface normal and the light")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    tau, n, th = a.texel, a.near, math.radians(a.theta)
    c = Canvas(1280, 640, ox=30, oy=468, scale=80.0, title=a.title or "Perspective and projective aliasing")
    top = 5.0                                       # the map's row of texels (light space)
    SUN = "#9a6a00"

    def beam(x0, x1, y_end0, y_end1, id_):
        c.polygon([(x0, top), (x1, top), (x1, y_end1), (x0, y_end0)], fill="#f8e3a8", opacity=0.9, id=id_)
        c.line((x0, top), (x0, y_end0), stroke=SUN, width=2)
        c.line((x1, top), (x1, y_end1), stroke=SUN, width=2)

    # ---- left: perspective aliasing.
    eye = (0.35, 4.3)
    aim = (5.0, 0.0)
    d = (aim[0] - eye[0], aim[1] - eye[1])
    dl = math.hypot(*d)
    d = (d[0] / dl, d[1] / dl)                      # the view direction
    def project(p):
        """p through the eye onto the near plane (distance n along d): the image point, and p's depth z."""
        v = (p[0] - eye[0], p[1] - eye[1])
        z = v[0] * d[0] + v[1] * d[1]
        return (eye[0] + v[0] * n / z, eye[1] + v[1] * n / z), z
    feet = {"near": 1.7, "far": 6.2}
    colours = {"near": ACCENT, "far": BLUE}
    c.line((-0.2, 0), (7.6, 0), stroke=GREY, width=5, id="floor")
    images, depths = {}, {}
    for name, x0 in feet.items():
        x1 = x0 + tau
        beam(x0, x1, 0.0, 0.0, f"beam-{name}")
        c.line((x0, 0), (x1, 0), stroke=colours[name], width=9, id=f"foot-{name}")
        (i0, z0), (i1, z1) = project((x0, 0)), project((x1, 0))
        for p in ((x0, 0), (x1, 0)):
            c.line(p, eye, stroke=colours[name], width=1.5, dash="6 5")
        images[name] = (i0, i1)
        depths[name] = (z0 + z1) / 2
    # The near plane: perpendicular to d, n from the eye, long enough for both images.
    ctr = (eye[0] + d[0] * n, eye[1] + d[1] * n)
    perp = (-d[1], d[0])
    c.line((ctr[0] + perp[0] * 0.3, ctr[1] + perp[1] * 0.3), (ctr[0] - perp[0] * 1.3, ctr[1] - perp[1] * 1.3),
           stroke=INK, width=3, id="near-plane")
    for k in range(-3, 15):                         # the screen's pixels
        q = (ctr[0] - perp[0] * 0.1 * k, ctr[1] - perp[1] * 0.1 * k)
        c.line((q[0] - d[0] * 0.08, q[1] - d[1] * 0.08), (q[0] + d[0] * 0.08, q[1] + d[1] * 0.08), stroke=INK, width=1.5)
    for name, (i0, i1) in images.items():
        c.line(i0, i1, stroke=colours[name], width=9, id=f"image-{name}")
    c.line(eye, ctr, stroke=GREY, width=1.5)
    c.circle(eye, r_px=9, fill=INK, stroke="none")
    c.text((eye[0] - 0.05, eye[1] + 0.3), "eye", size=22)
    c.text(((eye[0] + ctr[0]) / 2 + 0.05, (eye[1] + ctr[1]) / 2 - 0.42), "n", size=24, italic=True)
    c.text((ctr[0] + perp[0] * 0.3 + 0.1, ctr[1] + perp[1] * 0.3 + 0.05), "screen", size=22)
    c.text((feet["near"] + tau / 2, -0.45), "z₁: many pixels", size=22, fill=ACCENT, anchor="middle")
    c.text((feet["far"] + tau / 2, -0.45), "z₂: few", size=22, fill=BLUE, anchor="middle")
    # The map's texels along the top.
    for k in range(9):
        x = 0.3 + k * tau
        c.rect_px(*c.px(x, top + 0.3), tau * c.s, 0.3 * c.s, fill="#fff6dc", stroke=SUN, width=1.5)
    c.text((0.3, top + 0.55), "shadow map: texels τ wide", size=22, fill=SUN)
    c.text((3.9, -1.15), "perspective aliasing: n / z", size=26, weight="bold", anchor="middle")
    len_near = math.dist(*images["near"])
    len_far = math.dist(*images["far"])

    # ---- right: projective aliasing.
    # A steep surface rising from the floor at base: its normal theta from the light's direction.
    nrm = (-math.sin(th), math.cos(th))             # up and to the left
    along = (math.cos(th), math.sin(th))            # up the surface
    base = (9.3, 0.0)
    def on_surface(x):                              # where the vertical line at x meets the surface
        t = (x - base[0]) / along[0]
        return (x, base[1] + t * along[1])
    bx = base[0] + 0.9 * along[0] / along[1]        # the beam meets the surface from 0.9 up
    s0, s1 = on_surface(bx), on_surface(bx + tau)
    top_s = on_surface(base[0] + (top - 0.4) * along[0] / along[1])
    c.polygon([base, top_s, (top_s[0] + 1.2, top_s[1]), (top_s[0] + 1.2, 0)], fill="#e6e8ec", opacity=1.0)
    beam(bx, bx + tau, s0[1], s1[1], "beam-steep")
    c.line(base, top_s, stroke=GREY, width=5, id="surface")
    c.line(s0, s1, stroke=ACCENT, width=9, id="foot-steep")
    mid = ((s0[0] + s1[0]) / 2, (s0[1] + s1[1]) / 2)
    c.line(mid, (mid[0] + nrm[0] * 1.3, mid[1] + nrm[1] * 1.3), stroke=INK, width=2.5, arrow=True, id="normal")
    c.text((mid[0] + nrm[0] * 1.3 - 0.1, mid[1] + nrm[1] * 1.3 - 0.1), "N", size=24, anchor="end", weight="bold")
    c.line((bx - 0.35, mid[1]), (bx - 0.35, mid[1] + 1.3), stroke=LIGHT, width=2.5, arrow=True, id="to-light")
    c.text((bx - 0.45, mid[1] + 1.25), "L", size=24, fill=LIGHT, weight="bold", anchor="end")
    arc = [(mid[0] + 0.75 * math.sin(-u * th), mid[1] + 0.75 * math.cos(u * th)) for u in [i / 12 for i in range(13)]]
    c.line(mid, (mid[0], mid[1] + 0.95), stroke=INK, width=1.5, dash="4 4")
    c.polyline(arc, stroke=INK, width=2)
    c.text((mid[0] - 0.28, mid[1] + 0.95), "θ", size=24, italic=True, anchor="middle")
    c.text((s1[0] + 0.35, (s0[1] + s1[1]) / 2 - 0.2), "τ / cos θ", size=24, fill=ACCENT)
    # The camera sees the steep footprint from near its normal: cos(phi) ~ 1.
    vphi = math.radians(25.0)
    view = (nrm[0] * math.cos(vphi) - nrm[1] * math.sin(vphi), nrm[0] * math.sin(vphi) + nrm[1] * math.cos(vphi))
    eye2 = (mid[0] + view[0] * 2.5, mid[1] + view[1] * 2.5)
    c.line(eye2, mid, stroke=GREY, width=1.5, dash="6 5")
    c.circle(eye2, r_px=9, fill=INK, stroke="none")
    c.text((eye2[0] - 0.1, eye2[1] - 0.45), "eye, φ small", size=22)
    # A beam on the floor beside it, facing the light: a footprint of tau.
    fx = 13.4
    beam(fx, fx + tau, 0.0, 0.0, "beam-flat")
    c.line((8.3, 0), (15.6, 0), stroke=GREY, width=5)
    c.line((fx, 0), (fx + tau, 0), stroke=BLUE, width=9, id="foot-flat")
    c.text((fx + tau / 2, -0.45), "facing it: τ", size=22, fill=BLUE, anchor="middle")
    c.text((12.0, -1.15), "projective aliasing: cos φ / cos θ", size=26, weight="bold", anchor="middle")
    c.line((7.95, -1.4), (7.95, top + 0.6), stroke="#d5d8de", width=2)

    # The formula, and what it counts.
    c.text((640, 625), "ds/dp ≈ (n / z) · (τ / pixel) · (cos φ / cos θ)    pixels per texel",
           size=28, px=True, anchor="middle", fill=INK)
    vx, vy = eye2[0] - mid[0], eye2[1] - mid[1]
    phi = math.degrees(math.acos((vx * nrm[0] + vy * nrm[1]) / math.hypot(vx, vy)))
    c.fact(texel=tau, near=n, theta=a.theta, phi=round(phi, 4),
           eye_x=eye[0], eye_y=eye[1], dir_x=round(d[0], 6), dir_y=round(d[1], 6),
           z_near=round(depths["near"], 6), z_far=round(depths["far"], 6),
           image_near=round(len_near, 6), image_far=round(len_far, 6),
           steep_footprint=round(math.dist(s0, s1), 6))
    c.save(a.out)


if __name__ == "__main__":
    main()
