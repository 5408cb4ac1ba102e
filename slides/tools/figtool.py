#!/usr/bin/env python3
"""figtool.py: figures made from other figures, so a deck can show the place that matters.

  figtool.py crop SRC X,Y WxH [--scale S] --out DST
      the region (pixels of SRC) alone, magnified S times (nearest: pixels stay pixels)
  figtool.py inset SRC X,Y WxH [--scale S] [--corner tl|tr|bl|br] --out DST
      the whole picture with the region framed, and the region magnified in a corner
  figtool.py stats SRC X,Y WxH
      prints the region's mean grey level and how many of its pixels are neither
      black nor white (a penumbra's width in pixels, for the figure tests)

Runs with the Python WeasyPrint brings (python3-pil); used by the decks'
`<!-- derive: ... -->` lines (scripts/render-figures.sh).
"""
import argparse
import os
import sys

from PIL import Image, ImageDraw

FRAME = (240, 140, 20)


def region(s):
    xy, wh = s
    x, y = (int(v) for v in xy.split(","))
    w, h = (int(v) for v in wh.lower().split("x"))
    return x, y, w, h


def main(argv=None, cwd="."):
    """argv as the command line's (default sys.argv[1:]); relative paths are read from cwd.
    render_figures.py calls this in its own process (a Python and PIL less to start a figure)."""
    ap = argparse.ArgumentParser(prog="figtool.py")
    ap.add_argument("op", choices=["crop", "inset", "stats"])
    ap.add_argument("src")
    ap.add_argument("xy")
    ap.add_argument("wh")
    ap.add_argument("--scale", type=int, default=2)
    ap.add_argument("--corner", default="tr")
    ap.add_argument("--out")
    a = ap.parse_args(argv)
    img = Image.open(os.path.join(cwd, a.src)).convert("RGB")
    x, y, w, h = region((a.xy, a.wh))
    if x < 0 or y < 0 or x + w > img.width or y + h > img.height:
        sys.exit(f"figtool: region {a.xy} {a.wh} is outside {a.src} ({img.width}x{img.height})")
    part = img.crop((x, y, x + w, y + h))
    if a.op == "stats":
        grey = part.convert("L")
        px = list(grey.getdata())
        partial = sum(1 for v in px if 40 < v < 215)
        print(f"mean {sum(px) / len(px):.2f} partial {partial} pixels {len(px)}")
        return
    if not a.out:
        sys.exit("figtool: --out is needed")
    big = part.resize((w * a.scale, h * a.scale), Image.NEAREST)
    if a.op == "crop":
        big.save(os.path.join(cwd, a.out))
        return
    out = img.copy()
    d = ImageDraw.Draw(out)
    d.rectangle((x - 2, y - 2, x + w + 1, y + h + 1), outline=FRAME, width=4)
    margin = 8
    bx = out.width - big.width - margin if "r" in a.corner else margin
    by = out.height - big.height - margin if "b" in a.corner else margin
    out.paste(big, (bx, by))
    d.rectangle((bx - 3, by - 3, bx + big.width + 2, by + big.height + 2), outline=FRAME, width=5)
    out.save(os.path.join(cwd, a.out))


if __name__ == "__main__":
    main()
