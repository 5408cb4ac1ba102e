#!/usr/bin/env bash
# slides.sh decks|first-page BUILD_DIR IMAGE_CHECK SLIDES_SRC
#   decks       builds the `slides` target: an HTML and a PDF deck per
#               slides/labN_*.md, every figure the decks name rendered, and
#               placeholders only for figures of labs the viewer lacks
#   first-page  renders the first page of one PDF deck (and the bias sweep's
#               page) with pdftoppm and checks they are not blank
# Exit 77 (skipped) where the slide tools are not installed
# (scripts/install-slides-deps.sh).
set -u
what=$1 build=$2 check=$3 src=$4
out="$build/slides"
skip() { echo "slides: SKIPPED: $* (install them with scripts/install-slides-deps.sh)"; exit 77; }
fail=0
problem() { echo "slides: $*" >&2; fail=1; }
command -v pandoc >/dev/null || skip "pandoc is not installed"
command -v weasyprint >/dev/null || skip "WeasyPrint is not installed, so no PDF decks"
case $what in
decks)
  log="$build/tests/slides-build.log"
  mkdir -p "$build/tests"
  cmake --build "$build" --target slides >"$log" 2>&1 || { cat "$log"; problem "the slides target failed"; exit 1; }
  for deck in "$src"/lab[0-9]*.md; do
    name=$(basename "$deck" .md)
    for ext in html pdf; do [ -s "$out/$name.$ext" ] || problem "no $name.$ext"; done
    # Each figure the deck names exists, and is inside the HTML deck (self-contained).
    while read -r shot; do
      [ -s "$out/$shot" ] || problem "$name: figure $shot was not rendered"
    done < <(sed -nE 's/^<!-- (figure|animation).*--screenshot ([^ ]+) -->$/\2/p' "$deck")
    grep -q 'src="data:image' "$out/$name.html" || problem "$name.html does not embed its figures"
    # A slide a page: a slide that runs over its page would add one (title page + one per "# ").
    if command -v pdfinfo >/dev/null && [ -s "$out/$name.pdf" ]; then
      pages=$(pdfinfo "$out/$name.pdf" | awk '/^Pages:/ {print $2}')
      slides=$(($(grep -c '^# ' "$deck") + 1))
      [ "$pages" = "$slides" ] || problem "$name.pdf has $pages pages for $slides slides: a slide runs over its page"
    fi
  done
  n=$(ls "$src"/lab[0-9]*.md | wc -l)
  [ "$n" -eq 7 ] || problem "$n decks in slides/, expected 7"
  # Placeholders only where a figure is marked as needing a lab the viewer lacks.
  grep -E ": placeholder$" "$log" | grep -vE "needs lab [5-9]" && problem "a placeholder for a lab the viewer has"
  grep -lE "^<!-- (figure|animation) \(needs lab [1-4]\)" "$src"/*.md && problem "a figure of labs 1-4 marked as pending"
  grep -E "^render-figures: [0-9]+ rendered" "$log"
  ;;
first-page)
  command -v pdftoppm >/dev/null || skip "pdftoppm (poppler-utils) is not installed"
  pdf="$out/lab3_bias.pdf"
  [ -s "$pdf" ] || { cmake --build "$build" --target slides >/dev/null 2>&1 || problem "the slides target failed"; }
  work="$build/tests/slides-pages"
  rm -rf "$work"; mkdir -p "$work"
  pdftoppm -png -r 60 -f 1 -l 1 -singlefile "$pdf" "$work/page1" || problem "pdftoppm failed on $pdf"
  pdftoppm -png -r 60 -f 3 -l 3 -singlefile "$pdf" "$work/page3" || problem "pdftoppm failed on $pdf"
  "$check" not-blank "$work/page1.png" || problem "the first page of $pdf is blank"
  "$check" not-blank "$work/page3.png" || problem "page 3 of $pdf (the bias sweep) is blank"
  ;;
*) echo "usage: slides.sh decks|first-page BUILD_DIR IMAGE_CHECK SLIDES_SRC" >&2; exit 2 ;;
esac
exit $fail
