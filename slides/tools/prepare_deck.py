#!/usr/bin/env python3
"""prepare_deck.py: a deck as the lecturer or a student gets it.

  prepare_deck.py --audience lecturer|student --out-dir OUT DECK.md > DECK.for-pandoc.md

- `<!-- solution: PATH NAME -->` becomes, for the lecturer, a code block with
  the function NAME as the solutions' file PATH has it (the slide and the code
  cannot disagree, and the deck's Markdown holds no solution code: the
  students' handout ships the Markdown). For students it becomes a note
  naming the TODO where they write it.
- `::: lecturer` ... `:::` blocks are the lecturer's only, and so are `::: notes` ... `:::`
  blocks, the lecturer's notes: hidden on the HTML slide (the speaker view, key N, shows
  them), printed under the slide in the lecturer's PDF. The questions' answers go there.
- An image whose figure was left out (OUT/figures/manifest.json: no solutions
  to draw it with and none pre-rendered) becomes a note saying so: never a
  shadowless picture under a shadow caption.
- Every figure carries its real aspect ratio (`style="aspect-ratio: W / H"`, read
  from the file), so a browser lays the slide out at the right size before the
  image is decoded, and an SVG diagram is given to pandoc as a data: URI. Given
  the file, pandoc 3 (Debian 13) puts the SVG inline as an <svg> element whose
  width and height attributes (960x500) size it, past the slide's bottom, where
  the styles' rules for <img> do not reach; every pandoc keeps a data: URI an
  <img>, so the HTML decks are the same whichever pandoc made them.
"""
import argparse
import base64
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SOLUTION = re.compile(r"^<!-- solution: *(\S+) +(\S+)(?: +(TODO\([^)]*\)))? *-->$")
IMAGE = re.compile(r"!\[([^\]]*)\]\((figures/[^)\s]+)\)(\{[^}]*\})?")
SVG_SIZE = re.compile(r"<svg\b[^>]*?\swidth=\"([0-9.]+)(?:px)?\"[^>]*?\sheight=\"([0-9.]+)(?:px)?\"", re.S)
SVG_VIEWBOX = re.compile(r"<svg\b[^>]*?\sviewBox=\"\s*[-0-9.]+[\s,]+[-0-9.]+[\s,]+([0-9.]+)[\s,]+([0-9.]+)\s*\"", re.S)


def figure_size(path):
    """(width, height) of a PNG, GIF or SVG file as it declares them, or None."""
    with open(path, "rb") as f:
        head = f.read(4096)
    if head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR":
        return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    if head[:6] in (b"GIF87a", b"GIF89a"):
        return int.from_bytes(head[6:8], "little"), int.from_bytes(head[8:10], "little")
    if path.endswith(".svg"):
        text = head.decode("utf-8", "replace")
        m = SVG_SIZE.search(text) or SVG_VIEWBOX.search(text)
        if m:
            return float(m.group(1)), float(m.group(2))
    return None


def function_text(path, name):
    """The function NAME in a C or GLSL file: from its signature's line to its closing brace."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    sig = re.compile(r"^\S.*\b" + re.escape(name) + r"\s*\(")
    for i, line in enumerate(lines):
        if sig.match(line) and not line.rstrip().endswith(";"):
            depth, out = 0, []
            for line2 in lines[i:]:
                out.append(line2)
                depth += line2.count("{") - line2.count("}")
                if "{" in "".join(out) and depth == 0:
                    return "\n".join(out)
    raise SystemExit(f"prepare-deck: no function {name} in {path}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--audience", choices=["lecturer", "student"], required=True)
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("deck")
    a = ap.parse_args()
    manifest = {}
    mpath = os.path.join(a.out_dir, "figures", "manifest.json")
    if os.path.isfile(mpath):
        with open(mpath) as f:
            manifest = json.load(f)
    out = []
    skipping = False
    with open(a.deck, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for line in lines:
        s = line.strip()
        if s in ("::: lecturer", "::: {.lecturer}", "::: notes", "::: {.notes}"):
            if a.audience == "student":
                skipping = True
                continue
            out.append("::: {.notes}" if "notes" in s else "::: {.lecturer}")
            continue
        if skipping:
            if s == ":::":
                skipping = False
            continue
        m = SOLUTION.match(s)
        if m:
            path, name, todo = m.group(1), m.group(2), m.group(3)
            lang = "glsl" if path.endswith((".glsl", ".vert", ".frag", ".geom")) else "c"
            if a.audience == "lecturer":
                full = os.path.join(ROOT, path)
                if not os.path.isfile(full):
                    sys.exit(f"prepare-deck: {a.deck}: {path} is not here (a lecturer's deck needs solutions/)")
                out += ["```" + lang, function_text(full, name), "```"]
            else:
                where = f" ({todo})" if todo else ""
                out.append(f"[The lecturer's deck shows the solution's `{name}` here; "
                           f"it is yours to write{where}.]{{.left-out}}")
            continue

        def swap(mm):
            target = mm.group(2)
            if manifest.get(target, {}).get("status") == "missing":
                cap = mm.group(1).strip()
                what = f" ({cap})" if cap else ""
                return (f"[Figure left out{what}: it is drawn with the solutions' code, which this copy does "
                        f"not have; the course's pre-rendered figures fill it in.]{{.left-out}}")
            path = os.path.join(a.out_dir, target)
            if not os.path.isfile(path):
                return mm.group(0)   # pandoc names the missing file
            attrs = (mm.group(3) or "{}")[1:-1].strip()
            size = figure_size(path)
            if size and size[0] > 0 and size[1] > 0 and "style=" not in attrs:
                # One style attribute: pandoc 2.17 writes a second for `width=84%` (browsers read the first).
                style = [f"aspect-ratio: {size[0]:g} / {size[1]:g}"]
                width = re.search(r"(?:^|\s)width=([0-9.]+%)", attrs)
                if width:
                    style.insert(0, f"width: {width.group(1)}")
                    attrs = attrs.replace(width.group(0), "")
                attrs = (attrs + f' style="{"; ".join(style)}"').strip()
            if target.endswith(".svg"):
                with open(path, "rb") as f:
                    target = "data:image/svg+xml;base64," + base64.b64encode(f.read()).decode("ascii")
            return f"![{mm.group(1)}]({target})" + (f"{{{attrs}}}" if attrs else "")
        out.append(IMAGE.sub(swap, line))
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main()
