#!/usr/bin/env bash
# render-figures.sh VIEWER OUT_DIR DECK.md...
# Renders every figure the decks name into OUT_DIR/figures: the viewer's
# renders (headless, with the options in SHADOWLAB_FIGURE_ARGS in front), the
# diagrams slides/diagrams/*.py draw, and crops and insets of them. The work
# is done by slides/tools/render_figures.py (see its header and
# slides/README.md); build-slides.sh calls it directly.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: render-figures.sh VIEWER OUT_DIR DECK.md..." >&2; exit 2; }
here=$(dirname "$(realpath "$0")")
py=python3
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null && "$p" -c 'import PIL' 2>/dev/null; then py=$p; break; fi
done
viewer=$1 out=$2
shift 2
exec "$py" "$here/../slides/tools/render_figures.py" --python "$py" --viewer "$(realpath "$viewer")" \
  --viewer-args="${SHADOWLAB_FIGURE_ARGS:-}" --from "${SHADOWLAB_FIGURES_FROM:-solutions}" --out "$out" "$@"
