#!/usr/bin/env python3
"""Chebyshev's bound against the true step (variance shadow maps).

Inside the filter region a fraction alpha of the depths is an occluder at d1
and the rest the receiver's own surface at d2. The true lit fraction for a
receiver at depth t is the fraction of depths >= t: a step down to 1 - alpha
at d1 and to 0 at d2. From the two moments, mu = E[d] and sigma^2 = E[d^2] -
mu^2, Chebyshev's one-sided inequality bounds it:

    p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2)   for t > mu,   1 otherwise.

At t = d2 (the receiver itself) the bound is exact, 1 - alpha; deeper
receivers (a second surface behind the receiver) get p_max > 0 where the
truth is 0: light bleeding. Dashed: linstep(amount, 1, p_max), the
bleeding reduction.

  chebyshev.py [--alpha A] [--d1 D] [--d2 D] [--reduce A] --out FILE.svg
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg import Canvas, INK, ACCENT, BLUE, GREY  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--alpha", type=float, default=0.6, help="the occluder's share of the filter region")
    ap.add_argument("--d1", type=float, default=0.3, help="the occluder's depth")
    ap.add_argument("--d2", type=float, default=0.6, help="the receiver's depth")
    ap.add_argument("--reduce", type=float, default=0.3, help="bleeding reduction amount (0: none drawn)")
    ap.add_argument("--title", default="")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    al, d1, d2 = a.alpha, a.d1, a.d2
    mu = al * d1 + (1 - al) * d2
    m2 = al * d1 * d1 + (1 - al) * d2 * d2
    var = m2 - mu * mu
    def pmax(t):
        return 1.0 if t <= mu else var / (var + (t - mu) ** 2)
    def linstep(lo, hi, x):
        return min(1.0, max(0.0, (x - lo) / (hi - lo)))
    W, H = 870, 390
    c = Canvas(960, 540, ox=70, oy=478, scale=1.0, title=a.title or "Chebyshev's bound")
    c.fact(alpha=al, d1=d1, d2=d2, mu=round(mu, 6), variance=round(var, 6), reduce=a.reduce, plot_w=W, plot_h=H)
    P = lambda t, v: (t * W, v * H)  # noqa: E731  (t in [0, 1], visibility in [0, 1])
    # Axes and grid.
    c.line(P(0, 0), P(1, 0), stroke=INK, width=2)
    c.line(P(0, 0), P(0, 1.02), stroke=INK, width=2)
    for v in (0.5, 1.0):
        c.line(P(0, v), P(1, v), stroke="#e2e4e8", width=1)
        c.text((P(0, v)[0] - 8, P(0, v)[1] - 7), f"{v:g}", size=18, anchor="end")
    c.text((P(1, 0)[0], P(1, 0)[1] - 40), "receiver depth t →", size=20, anchor="end")
    c.text((P(0, 1.0)[0] + 10, P(0, 1.0)[1] - 30), "lit fraction", size=20)
    # The truth: a two-step staircase.
    true_pts = [P(0, 1), P(d1, 1), P(d1, 1 - al), P(d2, 1 - al), P(d2, 0), P(1, 0)]
    c.polyline(true_pts, stroke=INK, width=5, id="true")
    # The bound, sampled.
    ts = [i / 400 for i in range(401)]
    c.polyline([P(t, pmax(t)) for t in ts], stroke=ACCENT, width=4, id="bound",
               data_t=" ".join("%.4f" % t for t in ts))
    if a.reduce > 0:
        c.polyline([P(t, linstep(a.reduce, 1.0, pmax(t))) for t in ts], stroke=BLUE, width=3, dash="9 6",
                   id="reduced")
    # Marks: mu, d1, d2, the exact point, a bleeding receiver.
    for t, name in ((d1, "d_1"), (mu, "μ"), (d2, "d_2")):
        c.line(P(t, 0), P(t, -0.03), stroke=INK, width=2)
        c.text((P(t, 0)[0], P(t, 0)[1] - 36), name, size=20, anchor="middle", italic=True)
    c.circle(P(d2, 1 - al), r_px=8, fill=ACCENT, stroke="none")
    c.text((P(d2, 1 - al)[0] + 12, P(d2, 1 - al)[1] + 26), "exact at the receiver: 1 − α", size=18, fill=ACCENT)
    tb = min(0.95, d2 + 0.25)
    c.line(P(tb, 0), P(tb, pmax(tb)), stroke=ACCENT, width=3, arrow=True)
    c.text((P(tb, 0)[0] - 10, P(tb, 0)[1] - 60), "bleeding: truth 0, bound %.2f" % pmax(tb), size=18,
           fill=ACCENT, anchor="end")
    c.text((10, 30), a.title or "true lit fraction (black) and Chebyshev's bound (red)", size=22, px=True,
           weight="bold")
    if a.reduce > 0:
        c.text((950, 30), f"dashed: linstep({a.reduce:g}, 1, p_{{max}})", size=18, px=True, fill=BLUE, anchor="end")
    c.save(a.out)


if __name__ == "__main__":
    main()
