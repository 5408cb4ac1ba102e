#!/usr/bin/env bash
# build-slides.sh VIEWER SLIDES_DIR OUT_DIR
# The lecture decks (the `slides` build target runs this): renders every
# figure the decks name with the viewer (scripts/render-figures.sh), then
# turns each SLIDES_DIR/labN_*.md into OUT_DIR/labN_*.html (dzslides, one
# self-contained file: figures, styles and script inside) and OUT_DIR/labN_*.pdf
# (pandoc's HTML printed by WeasyPrint, a page per slide). Where pandoc is not
# installed it says so and stops without failing the build; without
# WeasyPrint it makes the HTML decks only. Options for the viewer's figure
# runs (e.g. --solutions) come in SHADOWLAB_FIGURE_ARGS.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: build-slides.sh VIEWER SLIDES_DIR OUT_DIR" >&2; exit 2; }
viewer=$1 src=$(realpath "$2") out=$3
here=$(dirname "$(realpath "$0")")
say() { echo "slides: $*"; }
if ! command -v pandoc >/dev/null; then
  say "pandoc is not installed, so the decks are not built (nothing else is affected)."
  say "Install the slide tools with scripts/install-slides-deps.sh (Debian: pandoc, weasyprint, poppler-utils)."
  exit 0
fi
mkdir -p "$out"
out=$(realpath "$out")
decks=("$src"/lab[0-9]*.md)

# The viewer with the figure options in front (the solutions' code, where a student build carries it).
wrapper="$out/.figure-viewer"
printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$(realpath "$viewer")" "${SHADOWLAB_FIGURE_ARGS:-}" >"$wrapper"
chmod +x "$wrapper"
"$here/render-figures.sh" "$wrapper" "$out" "${decks[@]}"

# pandoc 2.19 and later embed with --embed-resources; 2.17 (Debian 12) with --self-contained.
embed=(--self-contained)
if pandoc --help 2>/dev/null | grep -- --embed-resources >/dev/null; then embed=(--embed-resources --standalone); fi
pdf=1
command -v weasyprint >/dev/null || { pdf=0; say "WeasyPrint is not installed: HTML decks only (scripts/install-slides-deps.sh)"; }
for deck in "${decks[@]}"; do
  name=$(basename "$deck" .md)
  pandoc "$deck" --from markdown --to dzslides "${embed[@]}" --resource-path="$out:$src" \
    --css="$src/slides.css" --output="$out/$name.html"
  if [ $pdf = 1 ]; then
    pandoc "$deck" --from markdown --to html5 "${embed[@]}" --section-divs --resource-path="$out:$src" \
      --css="$src/print.css" --output="$out/$name.print.html"
    # WeasyPrint warns about CSS it does not use (pandoc's own styles); keep those out of the way.
    weasyprint "$out/$name.print.html" "$out/$name.pdf" 2>"$out/$name.weasyprint.log" ||
      { cat "$out/$name.weasyprint.log" >&2; exit 1; }
    rm -f "$out/$name.print.html"
  fi
  say "$out/$name.html$([ $pdf = 1 ] && echo " and $name.pdf")"
done
