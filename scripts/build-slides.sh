#!/usr/bin/env bash
# build-slides.sh VIEWER SLIDES_DIR OUT_DIR
# build-slides.sh --handout-figures VIEWER SLIDES_DIR DEST
#
# The lecture decks (the `slides` build target runs this). First every figure
# the decks name (slides/tools/render_figures.py: the viewer's renders, the
# diagrams drawn by slides/diagrams/*.py, crops and insets), then each
# SLIDES_DIR/labN_*.md twice:
#   OUT_DIR/labN_*.html, .pdf           the lecturer's deck: the solutions' code
#                                       where a slide quotes it (only where solutions/ exists),
#                                       the notes (HTML: a speaker view, key N; PDF: under
#                                       each slide)
#   OUT_DIR/student/labN_*.html, .pdf   the students' deck: no solution code; figures the
#                                       viewer draws come from the solutions, or pre-rendered
#                                       (SHADOWLAB_PRERENDERED, default SLIDES_DIR/figures),
#                                       or are left out with a note
# HTML: pandoc's dzslides, one self-contained file. PDF: pandoc's HTML printed by
# WeasyPrint (slides/tools/print_decks.py, every deck in one process), a 16:9 page per slide. Math is typeset by KaTeX at build time
# (slides/tools/katex-filter.js), so both show real equations without a script.
# Where pandoc is missing it says so and stops without failing the build;
# without WeasyPrint it makes the HTML decks only.
#
# Environment: SHADOWLAB_FIGURE_ARGS (options in front of every viewer command,
# e.g. --solutions), SHADOWLAB_FIGURES_FROM (solutions: the viewer draws with the
# solutions' code; none: it cannot), SHADOWLAB_PRERENDERED, SL_FIGURE_JOBS,
# SL_SLIDES_PDF=0 (HTML decks only), SL_SLIDES_CACHE (--handout-figures: render in this
# build output, e.g. build/slides, to reuse its figures instead of a temporary folder).
#
# --handout-figures renders the figures the viewer draws (with the solutions)
# and copies them, flat, into DEST: what a students' copy without solutions/
# needs in slides/figures/ to show every figure.
set -euo pipefail
handout=0
if [ "${1:-}" = --handout-figures ]; then handout=1; shift; fi
[ $# -eq 3 ] || { echo "usage: build-slides.sh [--handout-figures] VIEWER SLIDES_DIR OUT_DIR" >&2; exit 2; }
viewer=$1 src=$(realpath "$2") out=$3
say() { echo "slides: $*"; }
# The Python WeasyPrint runs with has Pillow (crops and insets); another python3 first in PATH may not.
py=python3
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null && "$p" -c 'import PIL' 2>/dev/null; then py=$p; break; fi
done
from=${SHADOWLAB_FIGURES_FROM:-solutions}
decks=("$src"/${SL_SLIDES_DECKS:-lab[0-9]*}.md)   # SL_SLIDES_DECKS=lab3*: some decks only

if [ $handout = 1 ]; then
  [ "$from" = solutions ] || { echo "build-slides: --handout-figures needs a viewer that draws with the solutions" >&2; exit 2; }
  work=${SL_SLIDES_CACHE:-}
  if [ -z "$work" ]; then work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; fi
  "$py" "$src/tools/render_figures.py" --python "$py" --viewer "$(realpath "$viewer")" \
    --viewer-args="${SHADOWLAB_FIGURE_ARGS:-}" --out "$work" "${decks[@]}"
  mkdir -p "$out"
  # The viewer's figures only: the diagrams and crops are made from them or from scripts the copy has.
  "$py" - "$work/figures/manifest.json" "$work" "$out" <<'PY'
import json, os, shutil, sys
manifest, work, dest = sys.argv[1:]
n = 0
for target, m in json.load(open(manifest)).items():
    if m["kind"] in ("figure", "animation", "truth"):
        shutil.copyfile(os.path.join(work, target), os.path.join(dest, os.path.basename(target)))
        n += 1
print(f"slides: {n} pre-rendered figures in {dest}")
PY
  exit 0
fi

if ! command -v pandoc >/dev/null; then
  say "pandoc is not installed, so the decks are not built (nothing else is affected)."
  say "Install the slide tools with scripts/install-slides-deps.sh (Debian: pandoc, weasyprint, libjs-katex, nodejs)."
  exit 0
fi
command -v node >/dev/null || { say "node is not installed: it typesets the decks' math (scripts/install-slides-deps.sh)" >&2; exit 1; }
mkdir -p "$out/student"
out=$(realpath "$out")

start=$SECONDS
"$py" "$src/tools/render_figures.py" --python "$py" --viewer "$(realpath "$viewer")" \
  --viewer-args="${SHADOWLAB_FIGURE_ARGS:-}" --from "$from" \
  --prerendered "${SHADOWLAB_PRERENDERED:-$src/figures}" --out "$out" "${decks[@]}"
say "figures in $((SECONDS - start)) s"

# KaTeX's stylesheet with its fonts: woff2 for the browsers, ttf for WeasyPrint.
mkdir -p "$out/.katex"
node "$src/tools/katex-filter.js" --css woff2 >"$out/.katex/katex-woff2.css"
node "$src/tools/katex-filter.js" --css ttf >"$out/.katex/katex-ttf.css"

# pandoc 2.19 and later embed with --embed-resources; 2.17 (Debian 12) with --self-contained.
embed=(--self-contained)
if pandoc --help 2>/dev/null | grep -- --embed-resources >/dev/null; then embed=(--embed-resources --standalone); fi
pdf=${SL_SLIDES_PDF:-1}
[ "$pdf" = 1 ] || say "SL_SLIDES_PDF=$pdf: HTML decks only"
[ "$pdf" = 0 ] || command -v weasyprint >/dev/null || { pdf=0; say "WeasyPrint is not installed: HTML decks only (scripts/install-slides-deps.sh)"; }
audiences=(student)
[ "$from" = solutions ] && [ -d "$src/../solutions" ] && audiences=(lecturer student)
# One deck for one audience: HTML, then PDF.
build_deck() { # DECK WHO
  local deck=$1 who=$2 name dest md print
  name=$(basename "$deck" .md)
  dest=$out
  [ "$who" = student ] && dest=$out/student
  md="$out/.$name.$who.md"   # made by prepare_deck.py (below)
  # Unchanged since the last build (the deck, its figures, the styles, the tools): nothing to do.
  local key stamp="$out/.$name.$who.key"
  key=$( { cat "$md" "$src/slides.css" "$src/print.css" "$src/tools/katex-filter.js" "$src/tools/speaker-view.html" \
             "$out/.katex/"*.css;
           grep -oE '\(figures/[^) ]+\)' "$md" | tr -d '()' | sort -u | (cd "$out" && xargs -r cat 2>/dev/null);
           echo "pdf=$pdf"; } | sha256sum | cut -d' ' -f1)
  if [ -s "$dest/$name.html" ] && { [ "$pdf" != 1 ] || [ -s "$dest/$name.pdf" ]; } &&
     [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$key" ]; then
    say "$dest/$name.html: unchanged"
    return 0
  fi
  rm -f "$stamp"
  # The lecturer's HTML has a speaker view (key N) for its notes; the students' has no notes.
  local speaker=()
  [ "$who" = lecturer ] && speaker=(--include-after-body="$src/tools/speaker-view.html")
  SL_DECK="$name ($who)" pandoc "$md" --from markdown --to dzslides "${embed[@]}" --resource-path="$out:$src" \
    --filter "$src/tools/katex-filter.js" --metadata pagetitle="$name" "${speaker[@]}" \
    --css="$out/.katex/katex-woff2.css" --css="$src/slides.css" --output="$dest/$name.html" || return 1
  if [ "$pdf" = 1 ]; then
    # Not self-contained: WeasyPrint reads the figures and fonts from disk, which is faster.
    print="$out/.$name.$who.print.html"
    SL_DECK="$name ($who)" pandoc "$md" --from markdown --to html5 --standalone --section-divs \
      --filter "$src/tools/katex-filter.js" \
      --css="$out/.katex/katex-ttf.css" --css="$src/print.css" --output="$print" || return 1
    if [ "$print_in_one" = 1 ]; then
      # Printed after every deck's HTML, all in one WeasyPrint (below); the stamp comes with the PDF.
      rm -f "$dest/$name.pdf"
      printf '%s\n' "$print" "$dest/$name.pdf" "$key" "$stamp" >"$out/.$name.$who.to-print"
      say "$dest/$name.html"
      return 0
    fi
    # WeasyPrint warns about CSS it does not use (KaTeX's and pandoc's); keep those out of the way.
    weasyprint --base-url "$out/" "$print" "$dest/$name.pdf" 2>"$out/.$name.$who.weasyprint.log" ||
      { cat "$out/.$name.$who.weasyprint.log" >&2; return 1; }
  fi
  echo "$key" >"$stamp"
  say "$dest/$name.html$([ "$pdf" = 1 ] && echo " and $name.pdf")"
}
# The PDFs are printed by one Python process (or SL_FIGURE_JOBS of them) for all decks: starting
# Python and importing WeasyPrint costs more than half of printing a deck. Where this Python
# cannot import WeasyPrint (it came with another one), each deck runs the weasyprint command.
print_in_one=0
[ "$pdf" = 1 ] && "$py" -c 'import weasyprint' 2>/dev/null && print_in_one=1
rm -f "$out"/.*.to-print
# Two decks at a time (SL_FIGURE_JOBS): pandoc and WeasyPrint use one core each.
jobs=${SL_FIGURE_JOBS:-2}
pids=()
failed=0
# A students' deck whose Markdown is the lecturer's (no slide quotes a solution) is the
# lecturer's deck: built once, copied after (same_as_lecturer).
same_as_lecturer=()
for deck in "${decks[@]}"; do
  name=$(basename "$deck" .md)
  for who in "${audiences[@]}"; do
    "$py" "$src/tools/prepare_deck.py" --audience "$who" --out-dir "$out" "$deck" >"$out/.$name.$who.md" ||
      { say "prepare_deck.py failed on $name ($who)" >&2; failed=1; continue 2; }
  done
  for who in "${audiences[@]}"; do
    if [ "$who" = student ] && [ ${#audiences[@]} = 2 ] && cmp -s "$out/.$name.lecturer.md" "$out/.$name.student.md"; then
      same_as_lecturer+=("$name")
      continue
    fi
    build_deck "$deck" "$who" &
    pids+=($!)
    if [ ${#pids[@]} -ge "$jobs" ]; then
      wait "${pids[0]}" || failed=1
      pids=("${pids[@]:1}")
    fi
  done
done
for p in "${pids[@]}"; do wait "$p" || failed=1; done
if [ "$print_in_one" = 1 ]; then
  to_print=("$out"/.*.to-print)
  [ -e "${to_print[0]}" ] || to_print=()
  pids=()
  for ((i = 0; i < jobs && i < ${#to_print[@]}; i++)); do
    pairs=()
    for ((j = i; j < ${#to_print[@]}; j += jobs)); do
      mapfile -t job <"${to_print[j]}"
      pairs+=("${job[0]}" "${job[1]}")
    done
    # WeasyPrint warns about CSS it does not use (KaTeX's and pandoc's); keep those out of the way.
    "$py" "$src/tools/print_decks.py" "$out/" "${pairs[@]}" 2>"$out/.print-decks.$i.log" &
    pids+=($!)
  done
  for ((i = 0; i < ${#pids[@]}; i++)); do
    wait "${pids[i]}" || { cat "$out/.print-decks.$i.log" >&2; failed=1; }
  done
  for t in "${to_print[@]}"; do
    mapfile -t job <"$t"
    rm -f "$t"
    if [ -s "${job[1]}" ]; then
      echo "${job[2]}" >"${job[3]}"
      say "${job[1]}"
    else
      say "no ${job[1]}: printing it failed (above)" >&2
      failed=1
    fi
  done
fi
for name in "${same_as_lecturer[@]}"; do
  [ -f "$out/.$name.lecturer.key" ] || continue   # the lecturer's failed (above)
  cp "$out/$name.html" "$out/student/$name.html"
  [ "$pdf" = 1 ] && cp "$out/$name.pdf" "$out/student/$name.pdf"
  cp "$out/.$name.lecturer.key" "$out/.$name.student.key"
  say "$out/student/$name.html$([ "$pdf" = 1 ] && echo " and $name.pdf"): the lecturer's (no slide quotes a solution)"
done
[ $failed = 0 ] || { say "a deck failed to build (above)" >&2; exit 1; }
say "done in $((SECONDS - start)) s"
