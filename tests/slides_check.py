#!/usr/bin/env python3
"""slides_check.py: the slides' tests that look inside what the build made.

  slides_check.py diagrams OUT_DIR        each diagram against the formula it draws
  slides_check.py figures OUT_DIR         figures that should differ do, where the decks say
  slides_check.py keys SLIDES_DIR HELP_FILE GRADER_SOURCES...
                                          every key and option a deck names exists
  slides_check.py browser OUT_DIR REVIEW_DIR
                                          every HTML deck in headless Chromium, slide by slide

Run by tests/slides.sh; exit 0 when every check passes, 1 with one line per problem.
"""
import glob
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

PROBLEMS = []


def problem(msg):
    PROBLEMS.append(msg)
    print("slides-check: " + msg, file=sys.stderr)


def near(a, b, tol):
    return abs(a - b) <= tol


# ---------------------------------------------------------------- diagrams

class Svg:
    """A generated diagram, read back in world units through the transform its root records."""

    def __init__(self, path):
        self.path = path
        self.root = ET.parse(path).getroot()
        self.ox = float(self.root.get("data-origin-x"))
        self.oy = float(self.root.get("data-origin-y"))
        self.s = float(self.root.get("data-scale"))
        self.els = {el.get("id"): el for el in self.root.iter() if el.get("id")}

    def fact(self, name):
        return float(self.root.get("data-" + name.replace("_", "-")))

    def world(self, x, y):
        return ((x - self.ox) / self.s, (self.oy - y) / self.s)

    def line(self, id_):
        el = self.els.get(id_)
        if el is None:
            return None
        a = self.world(float(el.get("x1")), float(el.get("y1")))
        # An arrow's shaft stops at its head: data-x2/y2 hold the drawn end.
        b = self.world(float(el.get("data-x2") or el.get("x2")), float(el.get("data-y2") or el.get("y2")))
        return a, b

    def points(self, id_, world=True):
        el = self.els[id_]
        pts = [tuple(float(v) for v in p.split(",")) for p in el.get("points").split()]
        return [self.world(*p) for p in pts] if world else pts


def check_acne(path):
    g = Svg(path)
    th = math.radians(g.fact("angle"))
    t, b, n = g.fact("texel"), g.fact("bias"), int(g.fact("texels"))
    if not near(g.fact("needed_bias"), 0.5 * t * math.tan(th), 1e-5):
        problem(f"{path}: needed bias {g.fact('needed_bias')} is not (t/2) tan(theta)")
    L, Lp = (math.sin(th), -math.cos(th)), (math.cos(th), math.sin(th))
    foot = t / math.cos(th)
    tol = 1.5 / g.s                                  # a pixel and a half, in world units
    total = 0.0
    for i in range(n):
        xc = (i + 0.5) * foot
        # The step: the stored depth (+ bias), across the texel, perpendicular to the rays.
        step = g.line(f"step-{i}")
        want = [(xc + b * L[0] - s * t / 2 * Lp[0], b * L[1] - s * t / 2 * Lp[1]) for s in (1, -1)]
        for got, w in zip(step, want):
            if not (near(got[0], w[0], tol) and near(got[1], w[1], tol)):
                problem(f"{path}: texel {i}'s step is drawn at {got}, the stored depth + bias puts it at {w}")
        # The shadowed part of the footprint: where the floor is deeper than the step.
        shadowed = max(0.0, foot / 2 - b / math.sin(th))
        red = g.line(f"acne-{i}")
        drawn = 0.0 if red is None else abs(red[1][0] - red[0][0])
        if not near(drawn, shadowed, tol):
            problem(f"{path}: texel {i}: {drawn:.3f} of the floor drawn as acne, the formula says {shadowed:.3f}")
        if red is not None:
            # Every red point really compares as shadowed: depth along L beyond the step's.
            for x in (red[0][0] + tol, red[1][0] - tol):
                if not (x - xc) * math.sin(th) > b - 1e-9:
                    problem(f"{path}: texel {i}: the point x={x:.3f} is drawn as acne but is lit")
        total += drawn
    if b >= 0.5 * t * math.tan(th) - 1e-9 and total > tol:
        problem(f"{path}: a bias of (t/2) tan(theta) or more leaves acne drawn")


def check_pcss(path):
    g = Svg(path)
    w, db, dr, n = g.fact("light"), g.fact("blocker"), g.fact("receiver"), g.fact("near")
    tol = 1.5 / g.s
    light, blocker, pen, search = g.line("light"), g.line("blocker"), g.line("penumbra"), g.line("search")
    if not (near(abs(light[1][0] - light[0][0]), w, tol) and near(light[0][1], dr, tol)):
        problem(f"{path}: the light is not w_light = {w} wide at height d_r")
    if not near(blocker[0][1], dr - db, tol):
        problem(f"{path}: the blocker is not at depth d_b")
    edge = max(blocker[0][0], blocker[1][0])
    width = abs(pen[1][0] - pen[0][0])
    formula = (dr - db) * w / db
    if not near(width, formula, tol):
        problem(f"{path}: the penumbra is drawn {width:.3f} wide, (d_r - d_b) w_light / d_b = {formula:.3f}")
    # Its ends lie on the lines from the light's ends through the blocker's edge.
    for l, x in ((w / 2, min(pen[0][0], pen[1][0])), (-w / 2, max(pen[0][0], pen[1][0]))):
        hit = l + (edge - l) * dr / db
        if not near(hit, x, tol):
            problem(f"{path}: a penumbra end at x={x:.3f}, the line from the light's end {l} through the "
                    f"blocker's edge meets the receiver at {hit:.3f}")
    sw = abs(search[1][0] - search[0][0])
    if not near(sw, w * (dr - n) / dr, tol) or not near(search[0][1], dr - n, tol):
        problem(f"{path}: the search region is {sw:.3f} wide, w_light (d_r - n) / d_r = {w * (dr - n) / dr:.3f}")


def split(n, f, m, lam, i):
    return lam * n * (f / n) ** (i / m) + (1 - lam) * (n + (f - n) * i / m)


def check_splits(path):
    g = Svg(path)
    n, f, m, lam = g.fact("near"), g.fact("far"), int(g.fact("cascades")), g.fact("lambda")
    k = math.tan(math.radians(g.fact("fov")) / 2)
    tol = 1.5 / g.s
    for i in range(m + 1):
        want = split(n, f, m, lam, i)
        a, b = g.line(f"split-{i}")
        if not (near(a[0], want, tol) and near(b[0], want, tol)):
            problem(f"{path}: split {i} drawn at {a[0]:.3f}, the practical scheme says {want:.3f}")
        if not near(abs(b[1] - a[1]), 2 * k * want, 2 * tol):
            problem(f"{path}: split {i} does not span the frustum's width there")
    for i in range(m):
        el = g.els.get(f"sphere-{i}")
        if el is None:
            continue
        cx, cy = g.world(float(el.get("cx")), float(el.get("cy")))
        r = float(el.get("r")) / g.s
        corners = [(x, s * k * x) for x in (split(n, f, m, lam, i), split(n, f, m, lam, i + 1)) for s in (1, -1)]
        d = [math.hypot(x - cx, y - cy) for x, y in corners]
        if max(d) > r + tol:
            problem(f"{path}: slice {i}'s circle (r {r:.3f}) does not hold its corners (up to {max(d):.3f})")
        if max(d) < r - tol:
            problem(f"{path}: slice {i}'s circle is larger than it needs to be")
    for el in g.root.iter("{http://www.w3.org/2000/svg}line"):
        if el.get("data-scheme") is not None:
            l = float(el.get("data-scheme"))
            x = (float(el.get("x1")) - 60) / g.s
            if not any(near(x, split(n, f, m, l, i), tol) for i in range(m + 1)):
                problem(f"{path}: a tick of the lambda={l} scheme at {x:.3f} is not one of its splits")


# OpenGL 4.6 core, §8.13: the face a direction picks, and its sc, tc as functions of r.
GL_CUBE = {
    "+X": ((1, 0, 0), (0, 0, -1), (0, -1, 0)),
    "-X": ((-1, 0, 0), (0, 0, 1), (0, -1, 0)),
    "+Y": ((0, 1, 0), (1, 0, 0), (0, 0, 1)),
    "-Y": ((0, -1, 0), (1, 0, 0), (0, 0, -1)),
    "+Z": ((0, 0, 1), (1, 0, 0), (0, -1, 0)),
    "-Z": ((0, 0, -1), (-1, 0, 0), (0, -1, 0)),
}


def vec(s):
    return tuple(int(round(float(v))) for v in s.split())


def add(a, b, k=1):
    return tuple(x + k * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def check_cube(path):
    g = Svg(path)
    cells = {}
    for face, (axis, s_dir, t_dir) in GL_CUBE.items():
        up_el, right_el = g.els.get(f"up-{face}"), g.els.get(f"right-{face}")
        if up_el is None or right_el is None:
            problem(f"{path}: face {face} has no up or right arrow")
            continue
        up, right = vec(up_el.get("data-up")), vec(right_el.get("data-right"))
        if up != t_dir:
            problem(f"{path}: face {face}: up {up} drawn, the cube-map convention's t grows along {t_dir}")
        if right != s_dir or cross(axis, up) != right:
            problem(f"{path}: face {face}: right {right}, expected s along {s_dir} = forward x up")
        cr, cu = vec(right_el.get("data-cell-right")), vec(right_el.get("data-cell-up"))
        col, row = vec(right_el.get("data-cell"))
        cells[(col, row)] = (axis, cr, cu)
        # The arrows point where the vectors lie in the cell's own frame.
        for el, v in ((up_el, up), (right_el, right)):
            dx = float(el.get("data-x2") or el.get("x2")) - float(el.get("x1"))
            dy = float(el.get("y1")) - float(el.get("data-y2") or el.get("y2"))
            want = (sum(a * b for a, b in zip(v, cr)), sum(a * b for a, b in zip(v, cu)))
            ln = math.hypot(dx, dy)
            if ln == 0 or not (near(dx / ln, want[0], 1e-3) and near(dy / ln, want[1], 1e-3)):
                problem(f"{path}: face {face}: an arrow points ({dx:.0f}, {dy:.0f}) in the cell, expected {want}")
    # The net is continuous: neighbouring cells share the world edge between them.
    for (col, row), (axis, cr, cu) in cells.items():
        right_n, below_n = cells.get((col + 1, row)), cells.get((col, row + 1))
        if right_n and add(axis, cr) != add(right_n[0], right_n[1], -1):
            problem(f"{path}: cells ({col},{row}) and ({col + 1},{row}) do not share an edge")
        if below_n and add(axis, cu, -1) != add(below_n[0], below_n[2]):
            problem(f"{path}: cells ({col},{row}) and ({col},{row + 1}) do not share an edge")
    if len(cells) != 6:
        problem(f"{path}: {len(cells)} faces drawn, not 6")


def check_chebyshev(path):
    g = Svg(path)
    al, d1, d2 = g.fact("alpha"), g.fact("d1"), g.fact("d2")
    W, H = g.fact("plot_w"), g.fact("plot_h")
    mu = al * d1 + (1 - al) * d2
    var = al * d1 * d1 + (1 - al) * d2 * d2 - mu * mu
    if not (near(mu, g.fact("mu"), 1e-5) and near(var, g.fact("variance"), 1e-5)):
        problem(f"{path}: mu or sigma^2 recorded wrongly")
    pmax = lambda t: 1.0 if t <= mu else var / (var + (t - mu) ** 2)  # noqa: E731
    true = lambda t: 1.0 if t <= d1 else ((1 - al) if t <= d2 else 0.0)  # noqa: E731
    pts = g.points("bound")
    bad = 0
    for x, y in pts:
        t, v = x / W, y / H
        if not near(v, pmax(t), 2.0 / H):
            bad += 1
        if v < true(t) - 2.0 / H:
            problem(f"{path}: the bound lies below the true lit fraction at t={t:.3f}: not an upper bound")
            break
    if bad:
        problem(f"{path}: {bad} of {len(pts)} points of the curve are not sigma^2 / (sigma^2 + (t - mu)^2)")
    if not near(pmax(d2), 1 - al, 1e-9):
        problem(f"{path}: the bound is not exact at the receiver (1 - alpha)")


def f32_step(x):
    v = struct.unpack("<f", struct.pack("<f", x))[0]
    b = struct.unpack("<I", struct.pack("<f", v))[0]
    return struct.unpack("<f", struct.pack("<I", b + 1))[0] - v


def check_depth_precision(path):
    g = Svg(path)
    n, f = g.fact("near"), g.fact("far")
    series = {}
    for k in ("fixed24", "float", "reversed"):
        el = g.els[f"curve-{k}"]
        zs = [float(v) for v in el.get("data-z").split()]
        dz = [float(v) for v in el.get("data-dz").split()]
        series[k] = dict(zip(zs, dz))
        for z, v in zip(zs, dz):
            slope = f * n / ((f - n) * z * z)
            d = f * (z - n) / (z * (f - n))
            rev = n * (f - z) / (z * (f - n))
            want = {"fixed24": 2.0 ** -24, "float": f32_step(d), "reversed": f32_step(rev)}[k] / slope
            if not near(v, want, 1e-4 * want + 1e-15):
                problem(f"{path}: {k} at z={z:g}: {v:g} drawn, {want:g} computed")
                break
    # What the deck says about them: float is no better than 24 bits far away; reversed is far better.
    zs = sorted(series["fixed24"])
    zf = zs[int(len(zs) * 0.8)]
    if not series["float"][zf] > 0.5 * series["fixed24"][zf]:
        problem(f"{path}: float is drawn much better than 24-bit at z={zf:g}: the deck says it is no better")
    if not series["reversed"][zf] * 100 < series["float"][zf]:
        problem(f"{path}: reversed-Z is not 100x finer than plain float at z={zf:g}")


def check_second_depth(path):
    g = Svg(path)
    for i in range(int(g.fact("texels"))):
        d1 = float(g.els[f"first-{i}"].get("data-depth"))
        d2 = float(g.els[f"second-{i}"].get("data-depth"))
        a, b = g.line(f"mid-{i}")
        if not (d1 <= d2 and near(-a[1], (d1 + d2) / 2, 1.5 / g.s)):
            problem(f"{path}: column {i}: the midpoint is drawn at depth {-a[1]:.3f}, (d1 + d2)/2 = {(d1 + d2) / 2:.3f}")


def check_poisson(path, root):
    g = Svg(path)
    text = open(os.path.join(root, "labs/lab4_pcf/shaders/pcf.glsl"), encoding="utf-8").read()
    block = re.search(r"PCF_POISSON_DISK\[16\]\s*=\s*vec2\[\]\((.*?)\);", text, re.S).group(1)
    table = [(float(x), float(y)) for x, y in re.findall(r"vec2\(\s*([-0-9.]+),\s*([-0-9.]+)\)", block)]
    for i, (x, y) in enumerate(table):
        el = g.els.get(f"pt-fixed-{i}")
        if el is None or not (near(float(el.get("data-x")), x, 1e-4) and near(float(el.get("data-y")), y, 1e-4)):
            problem(f"{path}: point {i} is not the shader's PCF_POISSON_DISK[{i}] = ({x}, {y})")
    # The rotated copies keep every point's distance from the centre (a rotation).
    for el in g.root.iter("{http://www.w3.org/2000/svg}circle"):
        pid = el.get("id") or ""
        if pid.startswith("pt-") and not pid.startswith("pt-fixed"):
            i = int(pid.rsplit("-", 1)[1])
            r0 = math.hypot(*table[i])
            r1 = math.hypot(float(el.get("data-x")), float(el.get("data-y")))
            if not near(r0, r1, 1e-3):
                problem(f"{path}: a rotated point {pid} changed its distance from the centre")


def check_dual_paraboloid(path):
    g = Svg(path)
    y, z = g.fact("edge_y"), g.fact("edge_z")
    el = g.els["edge-curve"]
    pts = [tuple(float(v) for v in p.split(",")) for p in el.get("data-points").split()]
    for i, (u, v) in enumerate(pts):
        t = i / (len(pts) - 1)
        p = (-2 + 4 * t, y, z)
        ln = math.sqrt(sum(c * c for c in p))
        want = (p[0] / ln / (1 + p[2] / ln), p[1] / ln / (1 + p[2] / ln))
        if not (near(u, want[0], 1e-4) and near(v, want[1], 1e-4)):
            problem(f"{path}: the edge's image at t={t:.2f} is not (x, y)/(1 + z)")
            break
        if u * u + v * v > 1 + 1e-9:
            problem(f"{path}: a front-hemisphere point maps outside the unit disk")
    rho_el = g.els["rho"]
    for a, r in zip(rho_el.get("data-alpha").split(), rho_el.get("data-rho").split()):
        if not near(float(r), math.tan(float(a) / 2), 1e-4):
            problem(f"{path}: rho is not tan(alpha/2) at alpha={a}")
            break
    if not near(math.tan(math.pi / 4), 1.0, 1e-12):
        problem("math is broken")


def check_two_pass(path):
    g = Svg(path)
    if not g.fact("P_z") > g.fact("P_d") + 0.1:
        problem(f"{path}: P is drawn in shadow but z > d does not hold")
    if not near(g.fact("Q_z"), g.fact("Q_d"), 1e-6):
        problem(f"{path}: Q is drawn lit but its stored distance is not its own")


def check_aliasing(path):
    """Each texel's footprint under its beam; the images on the near plane are the footprints seen
    through the eye; the near one's is the longer; the steep footprint is tau / cos(theta)."""
    g = Svg(path)
    tau, n, th = g.fact("texel"), g.fact("near"), math.radians(g.fact("theta"))
    eye, d = (g.fact("eye_x"), g.fact("eye_y")), (g.fact("dir_x"), g.fact("dir_y"))
    tol = 1.5 / g.s
    lengths = {}
    for name in ("near", "far"):
        foot = g.line(f"foot-{name}")
        if foot is None or g.line(f"image-{name}") is None:
            problem(f"{path}: no {name} footprint or image drawn")
            return
        (x0, y0), (x1, y1) = foot
        if not (near(abs(x1 - x0), tau, tol) and near(y0, 0, tol) and near(y1, 0, tol)):
            problem(f"{path}: the {name} footprint is not one texel ({tau}) of the floor")
        beam = g.points(f"beam-{name}")
        xs = sorted({round(p[0], 3) for p in beam})
        if not (near(xs[0], min(x0, x1), tol) and near(xs[-1], max(x0, x1), tol)):
            problem(f"{path}: the {name} footprint is not under its texel's beam")
        want = []
        for p in ((x0, y0), (x1, y1)):
            v = (p[0] - eye[0], p[1] - eye[1])
            z = v[0] * d[0] + v[1] * d[1]
            want.append((eye[0] + v[0] * n / z, eye[1] + v[1] * n / z))
        got = g.line(f"image-{name}")
        for w in want:
            if not any(near(w[0], q[0], tol) and near(w[1], q[1], tol) for q in got):
                problem(f"{path}: the {name} image does not end where the footprint projects on the near plane ({w})")
        lengths[name] = math.dist(*got)
    if not lengths["near"] > 2 * lengths["far"]:
        problem(f"{path}: the near footprint's image ({lengths['near']:.3f}) is not much longer than the far one's "
                f"({lengths['far']:.3f}): perspective aliasing is not drawn")
    steep = g.line("foot-steep")
    if not near(math.dist(*steep), tau / math.cos(th), tol):
        problem(f"{path}: the steep footprint is {math.dist(*steep):.3f} long, tau / cos(theta) = {tau / math.cos(th):.3f}")
    flat = g.line("foot-flat")
    if not near(math.dist(*flat), tau, tol):
        problem(f"{path}: the footprint facing the light is not tau long")
    (nx0, ny0), (nx1, ny1) = g.line("normal")
    ang = math.degrees(math.atan2(abs(nx1 - nx0), ny1 - ny0))
    if not near(ang, g.fact("theta"), 1.0):
        problem(f"{path}: the normal is drawn {ang:.1f} degrees from the light, theta = {g.fact('theta')}")


def check_umbra(path):
    """The umbra and both penumbrae end where the lines from the light's ends through the blocker's
    edges meet the receiver; each penumbra is (d_r - d_b) w_light / d_b wide."""
    g = Svg(path)
    w, B, db, dr = g.fact("light"), g.fact("blocker_width"), g.fact("blocker"), g.fact("receiver")
    tol = 1.5 / g.s
    light, blocker = g.line("light"), g.line("blocker")
    if not (near(abs(light[1][0] - light[0][0]), w, tol) and near(light[0][1], dr, tol)):
        problem(f"{path}: the light is not w_light = {w} wide at height d_r")
    if not (near(abs(blocker[1][0] - blocker[0][0]), B, tol) and near(blocker[0][1], dr - db, tol)):
        problem(f"{path}: the blocker is not {B} wide at depth d_b")
    lx = sorted(p[0] for p in light)
    bx = sorted(p[0] for p in blocker)
    def hit(l, e):
        return l + (e - l) * dr / db
    # The umbra: between the lines from each end of the light through the blocker's edge on its side;
    # each penumbra: from there to the line from the light's other end through the same edge.
    want = {"umbra": (hit(lx[0], bx[0]), hit(lx[1], bx[1])),
            "penumbra": (hit(lx[1], bx[1]), hit(lx[0], bx[1])),
            "penumbra-left": (hit(lx[1], bx[0]), hit(lx[0], bx[0]))}
    for id_, (x0, x1) in want.items():
        got = g.line(id_)
        if got is None:
            problem(f"{path}: no {id_} drawn")
            continue
        g0, g1 = sorted(p[0] for p in got)
        lo, hi = sorted((x0, x1))
        if not (near(g0, lo, tol) and near(g1, hi, tol)):
            problem(f"{path}: the {id_} is drawn from {g0:.3f} to {g1:.3f}, the lines through the blocker's edges "
                    f"give {lo:.3f} to {hi:.3f}")
    pen = g.line("penumbra")
    width, formula = abs(pen[1][0] - pen[0][0]), (dr - db) * w / db
    if not near(width, formula, tol):
        problem(f"{path}: the penumbra is drawn {width:.3f} wide, (d_r - d_b) w_light / d_b = {formula:.3f}")


def diagrams(out, root):
    checks = {"acne": check_acne, "pcss": check_pcss, "splits": check_splits, "cube_faces": check_cube,
              "chebyshev": check_chebyshev, "depth_precision": check_depth_precision,
              "second_depth": check_second_depth, "dual_paraboloid": check_dual_paraboloid,
              "two_pass": check_two_pass, "aliasing": check_aliasing,
              "umbra": check_umbra}
    manifest = json.load(open(os.path.join(out, "figures", "manifest.json")))
    decks = {}
    for deck in glob.glob(os.path.join(root, "slides", "lab*.md")):
        for line in open(deck, encoding="utf-8"):
            m = re.match(r"<!-- diagram: (\S+)\.py (.*?)-->", line.strip())
            if m:
                target = re.search(r"--out (\S+)", m.group(2)).group(1)
                decks[target] = (m.group(1), m.group(2))
    seen = set()
    for target, (script, args) in sorted(decks.items()):
        path = os.path.join(out, target)
        if manifest.get(target, {}).get("status") not in ("rendered", "cached"):
            problem(f"{target}: not made ({manifest.get(target, {}).get('status')})")
            continue
        if script == "poisson":
            if target.endswith(".svg"):
                check_poisson(path, root)
            seen.add(script)
            continue
        if script not in checks:
            problem(f"{target}: no check for the diagram script {script}.py: add one to tests/slides_check.py")
            continue
        checks[script](path)
        seen.add(script)
    for need in ("acne", "pcss", "splits", "cube_faces", "chebyshev", "aliasing", "umbra"):
        if need not in seen:
            problem(f"no deck draws the {need} diagram")
    print(f"slides-check: {len(decks)} diagrams checked against their formulas")


# ---------------------------------------------------------------- figures

def grey(path):
    from PIL import Image
    return Image.open(path).convert("L")


def partial_pixels(path):
    """Pixels neither shadowed nor lit: a penumbra's area in a visibility picture."""
    return sum(1 for v in grey(path).getdata() if 40 < v < 215)


def changed_fraction(a, b, threshold=24):
    ga, gb = grey(a), grey(b)
    if ga.size != gb.size:
        return 1.0
    d = [abs(x - y) > threshold for x, y in zip(ga.getdata(), gb.getdata())]
    return sum(d) / len(d)


def stripes(path, box=None):
    """High-frequency energy: the mean absolute difference between horizontal neighbours (acne)."""
    g = grey(path)
    if box:
        g = g.crop(box)
    w, h = g.size
    px = g.load()
    return sum(abs(px[x, y] - px[x + 1, y]) for y in range(h) for x in range(w - 1)) / ((w - 1) * h)


def red_pixels(path):
    from PIL import Image
    im = Image.open(path).convert("RGB")
    return sum(1 for r, g, b in im.getdata() if r > 200 and g < 70 and b < 70)


def mean_difference(a, b):
    ga, gb = grey(a), grey(b)
    return sum(abs(x - y) for x, y in zip(ga.getdata(), gb.getdata())) / (ga.width * ga.height)


def leaked_pixels(leaking, reduced):
    """Pixels lit above 0.2 in one picture and dark (under 0.05) in the other."""
    return sum(1 for x, y in zip(grey(leaking).getdata(), grey(reduced).getdata()) if x > 51 and y < 13)


def figures(out):
    F = lambda name: os.path.join(out, "figures", name)  # noqa: E731
    need = ["lab3_bias_0_crop.png", "lab3_bias_0005_crop.png", "lab3_bias_005_crop.png", "lab3_bias_1_crop.png",
            "lab4_grid_r0_crop.png", "lab4_grid_r1_crop.png", "lab4_grid_r3_crop.png", "lab4_none_crop.png",
            "lab4_hardware_crop.png", "lab4_pole_pcss_crop.png", "lab4_pole_pcss_large_crop.png",
            "lab5_vsm_r0_crop.png", "lab5_vsm_r2_crop.png", "lab5_vsm_r6_crop.png", "lab5_bleeding.png",
            "lab5_bleeding_reduced.png", "lab6_shimmer_changes.png", "lab6_snapped_changes.png",
            "lab7_room_hard_crop.png", "lab7_room_soft_crop.png", "lab1_map_128_crop.png", "lab1_map_2048_crop.png",
            "lab4_poisson_fixed.png", "lab4_poisson_rotated.png", "lab4_pole_truth_crop.png",
            "lab4_pole_grid_wide.png", "lab4_pole_pcss_wide.png", "lab4_pole_vsm_wide.png", "lab5_pcf_r3_crop.png",
            "lab5_vsm_r3_crop.png", "lab5_bleeding_crop.png", "lab5_bleeding_reduced_crop.png"]
    manifest = json.load(open(os.path.join(out, "figures", "manifest.json")))
    left_out = [n for n in need if manifest.get("figures/" + n, {}).get("status") == "missing"]
    if left_out:
        # A copy without solutions and without the pre-rendered figures: nothing to compare.
        print(f"slides-check: SKIPPED: {len(left_out)} figures were left out (no solutions, none pre-rendered)")
        sys.exit(77)
    missing = [n for n in need if not os.path.isfile(F(n))]
    for n in missing:
        problem(f"figure {n} is missing (the figure tests need it)")
    if missing:
        return
    # Lab 3: acne at b = 0 and 0.0005, none at 0.005; at 0.1 the contact shadows move (Peter Panning).
    s0, s1, s2 = stripes(F("lab3_bias_0_crop.png")), stripes(F("lab3_bias_0005_crop.png")), \
        stripes(F("lab3_bias_005_crop.png"))
    print(f"slides-check: lab 3 bias sweep, stripes (acne) 0: {s0:.1f}, 0.0005: {s1:.1f}, 0.005: {s2:.1f}")
    if not s0 > 2 * s2:
        problem(f"lab 3's bias sweep: b = 0 should show acne that 0.005 does not (stripe energy {s0:.1f}, {s2:.1f})")
    # 0.0005: the deck says acne is left where the light grazes the sphere (its lower left).
    sphere = (205, 165, 285, 240)
    q1, q2 = stripes(F("lab3_bias_0005.png"), sphere), stripes(F("lab3_bias_005.png"), sphere)
    print(f"slides-check: lab 3, the sphere at b = 0.0005 / 0.005: stripes {q1:.1f} / {q2:.1f}")
    if not q1 > 1.5 * q2:
        problem(f"lab 3: at b = 0.0005 the sphere should still show acne ({q1:.1f} against {q2:.1f} at 0.005)")
    pp = changed_fraction(F("lab3_bias_005_crop.png"), F("lab3_bias_1_crop.png"))
    print(f"slides-check: lab 3 bias 0.1 against 0.005: {pp:.1%} of the crop changed (Peter Panning)")
    if pp < 0.01:
        problem(f"lab 3's '0.1: shadows detach' crop looks like 0.005 ({pp:.2%} of pixels differ)")
    # Lab 4: the penumbra grows with the kernel, hardware PCF softens the single comparison.
    r = [partial_pixels(F(f"lab4_grid_r{k}_crop.png")) for k in (0, 1, 3)]
    print(f"slides-check: lab 4 grid r=0/1/3, penumbra pixels in the crop: {r}")
    if not (r[0] < r[1] < r[2] and r[2] > 1.5 * r[1]):
        problem(f"lab 4's grid PCF crops: the penumbra should widen with r (partial pixels {r})")
    h0, h1 = partial_pixels(F("lab4_none_crop.png")), partial_pixels(F("lab4_hardware_crop.png"))
    if not h1 > h0:
        problem(f"lab 4: hardware PCF's crop is no softer than one comparison ({h1} vs {h0})")
    p0, p1 = partial_pixels(F("lab4_pole_pcss_crop.png")), partial_pixels(F("lab4_pole_pcss_large_crop.png"))
    print(f"slides-check: lab 4 PCSS, light 0.35 and 0.7: {p0}, {p1} penumbra pixels")
    if not p1 > 1.2 * p0:
        problem(f"lab 4: PCSS with a light twice as wide is not softer ({p1} vs {p0})")
    f0, f1 = stripes(F("lab4_poisson_fixed.png")), stripes(F("lab4_poisson_rotated.png"))
    if not changed_fraction(F("lab4_poisson_fixed.png"), F("lab4_poisson_rotated.png"), 8) > 0.02:
        problem("lab 4: the fixed and rotated Poisson pictures do not differ")
    # Lab 5: the blur widens VSM's penumbra; the reduction darkens the bleeding.
    v = [partial_pixels(F(f"lab5_vsm_r{k}_crop.png")) for k in (0, 2, 6)]
    print(f"slides-check: lab 5 VSM blur 0/2/6, penumbra pixels: {v}")
    if not (v[0] < v[1] < v[2]):
        problem(f"lab 5: VSM's penumbra should widen with the blur (partial pixels {v})")
    m0 = sum(grey(F("lab5_bleeding.png")).getdata())
    m1 = sum(grey(F("lab5_bleeding_reduced.png")).getdata())
    if not m0 > m1:
        problem("lab 5: the bleeding figure is not lighter than the reduced one")
    # Lab 4, the truth: the mean of hard shadows from points over the light is softer than a fixed
    # 5x5 kernel, and PCSS, which estimates the penumbra from that light, is the nearest to it.
    truth = F("lab4_pole_truth_crop.png")
    err = {k: mean_difference(truth, F(f"lab4_pole_{k}_wide.png")) for k in ("grid", "pcss", "vsm")}
    pt, pg = partial_pixels(truth), partial_pixels(F("lab4_pole_grid_wide.png"))
    print(f"slides-check: lab 4 against the truth, mean grey difference PCF / PCSS / VSM: "
          f"{err['grid']:.2f} / {err['pcss']:.2f} / {err['vsm']:.2f}; penumbra pixels truth {pt}, PCF {pg}")
    if not pt > 1.5 * pg:
        problem(f"lab 4: the averaged area light's shadow is not softer than PCF 5x5 ({pt} vs {pg} penumbra pixels)")
    if not err["pcss"] < 0.8 * min(err["grid"], err["vsm"]):
        problem(f"lab 4: PCSS is not the nearest to the truth (mean differences {err})")
    # Lab 5: VSM and PCF with the same footprint differ where the slide shows them; the bleeding
    # crop shows light inside the wide slab's shadow that the reduction removes.
    vp = changed_fraction(F("lab5_pcf_r3_crop.png"), F("lab5_vsm_r3_crop.png"))
    print(f"slides-check: lab 5 VSM against PCF, {vp:.1%} of the crop differs")
    if vp < 0.03:
        problem(f"lab 5: the VSM and PCF crops hardly differ ({vp:.2%} of pixels)")
    leak = leaked_pixels(F("lab5_bleeding_crop.png"), F("lab5_bleeding_reduced_crop.png"))
    print(f"slides-check: lab 5 bleeding, {leak} pixels of the crop lit without the reduction, dark with it")
    if leak < 500:
        problem(f"lab 5: the bleeding crop shows little leak ({leak} pixels lit above 0.2 that the reduction darkens)")
    # Lab 6: without snapping many more edges move.
    c0, c1 = red_pixels(F("lab6_shimmer_changes.png")), red_pixels(F("lab6_snapped_changes.png"))
    print(f"slides-check: lab 6 pixels that changed, not snapped / snapped: {c0} / {c1}")
    if not c0 > 5 * max(c1, 20):
        problem(f"lab 6: the shimmer stills do not differ as the deck says ({c0} vs {c1} changed pixels)")
    # Lab 7: the soft lookup widens the penumbra.
    k0, k1 = partial_pixels(F("lab7_room_hard_crop.png")), partial_pixels(F("lab7_room_soft_crop.png"))
    if not k1 > k0:
        problem(f"lab 7: the soft crop is no softer than the hard one ({k1} vs {k0})")
    # Lab 1: map resolution shows.
    if changed_fraction(F("lab1_map_128_crop.png"), F("lab1_map_2048_crop.png")) < 0.01:
        problem("lab 1: the 128 and 2048 map crops do not differ")
    print("slides-check: figures compared")


# ---------------------------------------------------------------- keys and options

def listed_keys(text):
    """{key: set of labs (0: every lab)} from `shadowlab --list-keys` (LAB<tab>KEYS<tab>WHAT),
    the key table that --help, the overlay's key panel and the viewer's dispatch share."""
    keys = {}
    for line in text.splitlines():
        parts = line.split("\t")
        if len(parts) != 3:
            continue
        lab, names = parts[0], parts[1]
        if lab == "case":
            continue
        labs = {0} if lab == "all" else {int(lab)}
        for tok in names.split():
            if re.fullmatch(r"\d-\d", tok):
                for d in range(int(tok[0]), int(tok[2]) + 1):
                    keys.setdefault(str(d), set()).update(labs)
            else:
                keys.setdefault(tok, set()).update(labs)
    return keys


def keys(slides, help_file, list_file, grader_sources):
    text = open(help_file, encoding="utf-8").read()
    options = set(re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", text))
    known = listed_keys(open(list_file, encoding="utf-8").read())
    grader = ""
    for p in grader_sources:
        grader += open(p, encoding="utf-8", errors="replace").read()
    # The lab-section contexts the parser found, for the report.
    nk = 0
    no = 0
    for deck in sorted(glob.glob(os.path.join(slides, "lab[0-9]*.md"))):
        lab = int(re.match(r"lab(\d)", os.path.basename(deck)).group(1))
        for no_line, line in enumerate(open(deck, encoding="utf-8"), 1):
            for k in re.findall(r"<kbd>([^<]+)</kbd>", line):
                nk += 1
                labs = known.get(k)
                if labs is None:
                    problem(f"{os.path.basename(deck)}:{no_line}: key {k} is not in shadowlab --help")
                elif 0 not in labs and lab not in labs:
                    problem(f"{os.path.basename(deck)}:{no_line}: key {k} is lab {sorted(labs)}'s in shadowlab "
                            f"--help, not lab {lab}'s")
            if line.startswith(("<!-- diagram:", "<!-- derive:")) or "cmake " in line:
                continue
            grade_line = "shadowlab-grade" in line
            for opt in re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", line):
                if line.startswith("<!-- truth:") and opt == "--samples":
                    continue   # render_figures.py's own (the number of light positions), not the viewer's
                no += 1
                if grade_line:
                    if f'"{opt}"' not in grader and f"{opt} " not in grader and f"{opt}=" not in grader:
                        problem(f"{os.path.basename(deck)}:{no_line}: {opt} is not an option of shadowlab-grade")
                elif opt not in options:
                    problem(f"{os.path.basename(deck)}:{no_line}: option {opt} is not in shadowlab --help")
    print(f"slides-check: {nk} keys and {no} options named in the decks, checked against the key table and --help")


# ---------------------------------------------------------------- browser

# The check run in each deck (same origin, in an iframe of the harness): step through every
# slide with dzslides' own functions, and look at what each shows.
HARNESS = r"""<!DOCTYPE html><html><body><pre id="slide-check"></pre><script>
var decks = DECKS;
var results = {};
function checkDeck(win, doc) {
  var out = {slides: [], fonts: doc.fonts ? doc.fonts.check('16px KaTeX_Main') : null};
  var secs = Array.prototype.slice.call(doc.querySelectorAll('body > section'));
  var Dz = win.Dz;
  try { Dz.setCursor(1, 0); Dz.onhashchange(); } catch (e) { out.error = String(e); }
  secs.forEach(function (s, i) {
    if (i > 0) { try { Dz.forward(); Dz.onhashchange(); } catch (e) { out.error = String(e); } }
    var shown = doc.querySelector('section[aria-selected]');
    var imgs = Array.prototype.slice.call(s.querySelectorAll('img'));
    var broken = imgs.filter(function (im) { return !(im.complete && im.naturalWidth > 0); })
                     .map(function (im) { return (im.getAttribute('src') || '').slice(0, 50); });
    var h = s.querySelector('h1');
    // The lecturer's notes are not drawn on the slide (the speaker view shows them).
    var kx = Array.prototype.slice.call(s.querySelectorAll('.katex'))
                  .filter(function (k) { return !k.closest('.notes'); });
    out.slides.push({
      index: i + 1, title: h ? h.textContent : '', shown: shown === s,
      text: (s.innerText || '').replace(/\s+/g, ' ').trim().length,
      // A diagram is an <img> (the deck builder gives pandoc data: URIs); one pandoc put inline
      // as <svg> counts too (KaTeX's own <svg>s sit inside .katex, never a paragraph's child).
      images: imgs.length + s.querySelectorAll('section > p > svg, section figure > svg').length, broken: broken,
      svg: s.querySelectorAll('img[src^="data:image/svg"], section > p > svg, section figure > svg').length,
      katex: kx.length, katexDisplay: s.querySelectorAll('.katex-display').length,
      katexBad: kx.filter(function (k) { return k.getBoundingClientRect().width < 2; }).length,
      katexErrors: s.querySelectorAll('.katex-error').length,
      leftOut: s.querySelectorAll('.left-out').length,
      overflow: s.scrollHeight > s.clientHeight + 2 ? s.scrollHeight - s.clientHeight : 0
    });
  });
  return out;
}
function next(i) {
  if (i >= decks.length) {
    document.getElementById('slide-check').textContent = 'SLIDE' + 'CHECK' + JSON.stringify(results) + 'SLIDE' + 'CHECK';
    return;
  }
  var f = document.createElement('iframe');
  f.style.width = '1024px'; f.style.height = '768px';
  f.onload = function () {
    var w = f.contentWindow, d = f.contentDocument;
    (d.fonts && d.fonts.ready ? d.fonts.ready : Promise.resolve()).then(function () {
      setTimeout(function () {
        try { results[decks[i]] = checkDeck(w, d); } catch (e) { results[decks[i]] = {error: String(e), slides: []}; }
        f.remove();
        next(i + 1);
      }, 100);
    });
  };
  f.src = decks[i];
  document.body.appendChild(f);
}
next(0);
</script></body></html>
"""

# Slides to look at, stacked in one tall page: one screenshot for all of them.
SHOTS = r"""<!DOCTYPE html><html><head><style>body{margin:0} iframe{display:block;border:0;width:1024px;height:768px}</style>
</head><body>FRAMES</body></html>
"""

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars"]


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        p = shutil.which(name)
        if p:
            return p
    return None


def serve(root):
    """A web server on the loopback for the decks (the harness reads them in iframes: same origin)."""
    import functools
    import http.server
    import threading

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *a):
            pass
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=root))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd, f"http://127.0.0.1:{httpd.server_address[1]}/"


def browser(out, review):
    from PIL import Image
    exe = chromium()
    if not exe:
        print("slides-check: SKIPPED: no chromium (scripts/install-slides-deps.sh installs it)")
        sys.exit(77)
    os.makedirs(review, exist_ok=True)
    decks = [os.path.relpath(p, out) for p in sorted(glob.glob(os.path.join(out, "lab[0-9]*.html")))] + \
        [os.path.relpath(p, out) for p in sorted(glob.glob(os.path.join(out, "student", "lab[0-9]*.html")))]
    if not decks:
        problem(f"no HTML decks in {out}")
        return
    profile = tempfile.mkdtemp(prefix="slides-chromium-")
    httpd, base = serve(out)
    harness = os.path.join(out, ".slide-check.html")
    shots_page = os.path.join(out, ".slide-shots.html")
    try:
        with open(harness, "w", encoding="utf-8") as f:
            f.write(HARNESS.replace("DECKS", json.dumps(decks)))
        r = subprocess.run([exe] + CHROMIUM_FLAGS + ["--window-size=1024,768", f"--user-data-dir={profile}",
                                                    "--virtual-time-budget=600000", "--dump-dom",
                                                    base + ".slide-check.html"],
                           capture_output=True, text=True, timeout=900)
        m = re.search(r'<pre id="slide-check">SLIDECHECK(.*?)SLIDECHECK</pre>', r.stdout, re.S)
        if not m:
            problem(f"the decks' check did not finish in Chromium ({r.stderr.strip()[-300:]})")
            return
        results = json.loads(m.group(1).replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))
        picks = []
        for deck in decks:
            res = results.get(deck, {"slides": [], "error": "not checked"})
            slides = res["slides"]
            if res.get("error") or not slides:
                problem(f"{deck}: {res.get('error') or 'no slides'}")
                continue
            if sum(s["katex"] for s in slides) and res.get("fonts") is False:
                problem(f"{deck}: KaTeX's fonts did not load")
            for s in slides:
                where = f"{deck} slide {s['index']} ({s['title']})"
                if not s["shown"]:
                    problem(f"{where}: stepping forward did not show it")
                if s["broken"]:
                    problem(f"{where}: missing image(s) {s['broken']}")
                if s["katexErrors"] or s["katexBad"]:
                    problem(f"{where}: {s['katexErrors']} KaTeX errors, {s['katexBad']} empty formulas")
                if s["text"] < 8 and s["images"] == 0:
                    problem(f"{where}: blank")
                if s["overflow"]:
                    problem(f"{where}: runs {s['overflow']} px past the bottom of the slide")
            print(f"slides-check: {deck}: {len(slides)} slides, {sum(s['images'] for s in slides)} images, "
                  f"{sum(s['katex'] for s in slides)} formulas, stepped through")
            # For review: a lecturer's deck's first diagram; lab 5's first display math; a students' note.
            if deck.startswith("student"):
                s = next((s for s in slides if s["leftOut"]), None)
                if s and "lab7" in deck:
                    picks.append((deck, s["index"]))
            else:
                s = next((s for s in slides if s["svg"]), None)
                if s:
                    picks.append((deck, s["index"]))
                if "lab5" in deck:
                    s = next((s for s in slides if s["katexDisplay"]), None)
                    if s:
                        picks.append((deck, s["index"]))
        if not picks:   # a window 0 px high: Chromium would wait for it until the timeout
            return
        # One screenshot of the picked slides stacked, cut into one PNG per slide.
        frames = "".join(f'<iframe src="{d}#{i}"></iframe>' for d, i in picks)
        with open(shots_page, "w", encoding="utf-8") as f:
            f.write(SHOTS.replace("FRAMES", frames))
        tall = os.path.join(review, ".all.png")
        subprocess.run([exe] + CHROMIUM_FLAGS + [f"--window-size=1024,{768 * len(picks)}",
                                                f"--user-data-dir={profile}", "--virtual-time-budget=20000",
                                                f"--screenshot={tall}", base + ".slide-shots.html"],
                       capture_output=True, timeout=600)
        if not os.path.isfile(tall):
            problem("no screenshot of the slides picked for review")
            return
        im = Image.open(tall).convert("RGB")
        for k, (deck, idx) in enumerate(picks):
            png = os.path.join(review, deck.replace("/", "-").replace(".html", f"-{idx:02d}.png"))
            part = im.crop((0, 768 * k, 1024, 768 * (k + 1)))
            part.save(png)
            lo, hi = part.convert("L").getextrema()
            if hi - lo < 30:
                problem(f"{png}: the slide is blank on screen")
        os.remove(tall)
        print(f"slides-check: {len(picks)} slides kept for review in {review}")
    finally:
        httpd.shutdown()
        shutil.rmtree(profile, ignore_errors=True)
        for p in (harness, shots_page):
            if os.path.exists(p):
                os.remove(p)


def main():
    what = sys.argv[1]
    if what == "diagrams":
        diagrams(sys.argv[2], os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    elif what == "figures":
        figures(sys.argv[2])
    elif what == "keys":
        keys(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:])
    elif what == "browser":
        browser(sys.argv[2], sys.argv[3])
    else:
        sys.exit("usage: slides_check.py diagrams|figures|keys|browser ...")
    if PROBLEMS:
        print(f"slides-check: {len(PROBLEMS)} problem(s)", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
