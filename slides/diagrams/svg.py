"""A few lines of SVG for the decks' diagrams: a canvas with a world-to-pixel
transform, and shapes that carry their world coordinates.

Every drawn element can take an id and data-* attributes; the root <svg>
records the transform (data-origin-x/y, data-scale: pixel = origin + scale *
world, y up), so a test can read a drawn line back in world units and check
it against the formula it illustrates (tests/slides_check.py)."""

import math
from xml.sax.saxutils import escape

INK = "#1d2026"
ACCENT = "#c0392b"  # what goes wrong: acne, shadowed, the error
LIGHT = "#e6a100"   # lights and their rays
BLUE = "#1b4f8a"
GREEN = "#2e7d32"
GREY = "#8a8f98"
FONT = "DejaVu Sans, Liberation Sans, Arial, sans-serif"


def fmt(v):
    return f"{v:.6f}".rstrip("0").rstrip(".") if isinstance(v, float) else str(v)


def _segments(s):
    """'d_b', 'w_{light}' -> [('d', False), ('b', True)]: text and subscripts."""
    import re
    out, pos = [], 0
    for m in re.finditer(r"_(\{[^}]*\}|[A-Za-z0-9](?![A-Za-z0-9]))", s):
        if m.start() > pos:
            out.append((s[pos:m.start()], False))
        out.append((m.group(1).strip("{}"), True))
        pos = m.end()
    if pos < len(s):
        out.append((s[pos:], False))
    return out


_FONTS = {}


def _width(text, size, weight):
    """The text's width in pixels in DejaVu Sans (what the decks use), measured where Pillow and
    the font are there, estimated otherwise."""
    key = (size, weight)
    if key not in _FONTS:
        try:
            from PIL import ImageFont
            name = "DejaVuSans-Bold.ttf" if weight == "bold" else "DejaVuSans.ttf"
            _FONTS[key] = ImageFont.truetype("/usr/share/fonts/truetype/dejavu/" + name, size)
        except Exception:
            _FONTS[key] = None
    font = _FONTS[key]
    return font.getlength(text) if font else 0.58 * size * len(text)


class Canvas:
    """width x height pixels; world (0, 0) at pixel (ox, oy), y up, `scale` pixels per unit."""

    def __init__(self, width, height, ox=0.0, oy=0.0, scale=1.0, title=""):
        self.w, self.h, self.ox, self.oy, self.s = width, height, ox, oy, scale
        self.items = []
        self.title = title
        self.facts = {}
        self.markers = set()

    def px(self, x, y):
        return (self.ox + self.s * x, self.oy - self.s * y)

    def fact(self, **kv):
        """Numbers the diagram was drawn from, recorded on the root element."""
        self.facts.update(kv)

    @staticmethod
    def _attrs(kw):
        out = []
        for k, v in kw.items():
            if v is None:
                continue
            k = k.rstrip("_").replace("_", "-")
            out.append(f'{k}="{escape(fmt(v), {chr(34): "&quot;"})}"')
        return " ".join(out)

    def raw(self, text):
        self.items.append(text)

    def line(self, a, b, stroke=INK, width=3, dash=None, arrow=False, **kw):
        (x1, y1), (x2, y2) = self.px(*a), self.px(*b)
        self.line_px(x1, y1, x2, y2, stroke=stroke, width=width, dash=dash, arrow=arrow, **kw)

    def line_px(self, x1, y1, x2, y2, stroke=INK, width=3, dash=None, arrow=False, **kw):
        """A line in pixels; with arrow, a head drawn as a triangle (SVG markers are not
        drawn alike everywhere: WeasyPrint ignores their orientation)."""
        head = max(9.0, 3.2 * width)
        if arrow:
            d = math.hypot(x2 - x1, y2 - y1) or 1.0
            ux, uy = (x2 - x1) / d, (y2 - y1) / d
            bx, by = x2 - ux * head, y2 - uy * head          # the head's base
            tip = f"{x2:.2f},{y2:.2f}"
            left = f"{bx - uy * head * 0.5:.2f},{by + ux * head * 0.5:.2f}"
            right = f"{bx + uy * head * 0.5:.2f},{by - ux * head * 0.5:.2f}"
            lx2, ly2 = bx + ux * 1.0, by + uy * 1.0          # the shaft stops inside the head
        else:
            lx2, ly2 = x2, y2
        extra = self._attrs(dict(stroke_dasharray=dash, **kw))
        # x2/y2 in data-* keep the drawn end (the tip) for the tests.
        self.items.append(f'<line x1="{x1:.2f}" y1="{y1:.2f}" x2="{lx2:.2f}" y2="{ly2:.2f}" '
                          f'data-x2="{x2:.2f}" data-y2="{y2:.2f}" '
                          f'stroke="{stroke}" stroke-width="{width}" stroke-linecap="round" {extra}/>')
        if arrow:
            self.items.append(f'<polygon points="{tip} {left} {right}" fill="{stroke}" stroke="none"/>')

    def polyline(self, pts, stroke=INK, width=3, fill="none", dash=None, **kw):
        p = " ".join("%.2f,%.2f" % self.px(x, y) for x, y in pts)
        extra = self._attrs(dict(stroke_dasharray=dash, **kw))
        self.items.append(f'<polyline points="{p}" stroke="{stroke}" stroke-width="{width}" fill="{fill}" '
                          f'stroke-linejoin="round" stroke-linecap="round" {extra}/>')

    def polygon(self, pts, fill="#ddd", stroke="none", width=0, opacity=1.0, **kw):
        p = " ".join("%.2f,%.2f" % self.px(x, y) for x, y in pts)
        extra = self._attrs(kw)
        self.items.append(f'<polygon points="{p}" fill="{fill}" fill-opacity="{opacity}" stroke="{stroke}" '
                          f'stroke-width="{width}" {extra}/>')

    def circle(self, c, r_world=None, r_px=None, fill="none", stroke=INK, width=2, dash=None, **kw):
        x, y = self.px(*c)
        r = r_px if r_px is not None else r_world * self.s
        extra = self._attrs(dict(stroke_dasharray=dash, **kw))
        self.items.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{r:.2f}" fill="{fill}" stroke="{stroke}" '
                          f'stroke-width="{width}" {extra}/>')

    def rect_px(self, x, y, w, h, fill="none", stroke=INK, width=2, **kw):
        extra = self._attrs(kw)
        self.items.append(f'<rect x="{x:.2f}" y="{y:.2f}" width="{w:.2f}" height="{h:.2f}" fill="{fill}" '
                          f'stroke="{stroke}" stroke-width="{width}" {extra}/>')

    def text(self, at, s, size=22, fill=INK, anchor="start", px=False, weight="normal", italic=False, **kw):
        """Text with real subscripts (d_b, w_{light}): each part its own <text>, placed by measured
        widths, since tspan shifts are not drawn alike everywhere (WeasyPrint)."""
        x, y = at if px else self.px(*at)
        extra = self._attrs(kw)
        style = ' font-style="italic"' if italic else ""
        parts = _segments(s)
        sub = round(size * 0.72)
        widths = [_width(t, sub if is_sub else size, weight) for t, is_sub in parts]
        total = sum(widths)
        x0 = x - (total if anchor == "end" else total / 2 if anchor == "middle" else 0)
        if len(parts) == 1:
            self.items.append(f'<text x="{x:.2f}" y="{y:.2f}" font-size="{size}" fill="{fill}" '
                              f'text-anchor="{anchor}" font-weight="{weight}"{style} {extra}>{escape(s)}</text>')
            return
        for (t, is_sub), w in zip(parts, widths):
            yy = y + (0.3 * size if is_sub else 0)
            self.items.append(f'<text x="{x0:.2f}" y="{yy:.2f}" font-size="{sub if is_sub else size}" '
                              f'fill="{fill}" text-anchor="start" font-weight="{weight}"{style} {extra}>'
                              f'{escape(t.replace(" ", chr(160)))}</text>')   # spaces kept at the ends
            x0 += w

    def svg(self):
        facts = " ".join(f'data-{k.replace("_", "-")}="{fmt(v)}"' for k, v in self.facts.items())
        head = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.w}" height="{self.h}" '
                f'viewBox="0 0 {self.w} {self.h}" font-family="{FONT}" '
                f'data-origin-x="{fmt(float(self.ox))}" data-origin-y="{fmt(float(self.oy))}" '
                f'data-scale="{fmt(float(self.s))}" {facts}>')
        defs = ""
        title = f"<title>{escape(self.title)}</title>" if self.title else ""
        return "\n".join([head, title, defs, '<rect width="100%" height="100%" fill="white"/>'] + self.items + ["</svg>"]) + "\n"

    def save(self, path):
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.svg())
