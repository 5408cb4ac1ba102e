#!/usr/bin/env bash
# slides.sh WHAT BUILD_DIR IMAGE_CHECK SLIDES_SRC [VIEWER]
#   decks      builds the `slides` target: for every slides/labN_*.md an HTML and a PDF deck
#              for the lecturer (build/slides/) and for students (build/slides/student/),
#              every figure made, a PDF page per slide, no solution code in a students' deck
#   diagrams   every diagram drawn by slides/diagrams/*.py checked against its formula
#   figures    figures that the decks say differ do (bias sweep, PCF kernels, shimmer, ...)
#   keys       every key (<kbd>) a deck names is in the viewer's key table (`shadowlab --list-keys`,
#              which --help prints too) for that lab, and every option in `shadowlab --help`
#   browser    every HTML deck opened in headless Chromium and stepped through: no missing
#              image, blank slide, slide running over, or KaTeX error; a few slides kept as
#              PNGs in BUILD_DIR/tests/slides-review/
#   hall       every HTML deck at 1920x1080 in headless Chromium (tests/slides_hall.py): 16:9,
#              every text and diagram label >= 18 px, each figure a good share of its slide;
#              the lecturer's speaker view (key N) shows the slide's notes
#   pdf-pages  pages of the PDFs (a diagram, typeset math, a figure row) rendered by
#              pdftoppm and checked not blank; kept in BUILD_DIR/tests/slides-review/
#   no-solutions  the students' decks as a copy without solutions/ builds them: figures
#              the viewer draws become notes, or come from pre-rendered images
# Every test but `decks` and `keys` reads what `decks` made (CTest fixture slides_built).
# Exit 77 (skipped) where the slide tools are not installed (scripts/install-slides-deps.sh).
set -u
what=$1 build=$2 check=$3 src=$4 viewer=${5:-}
out="$build/slides"
here=$(dirname "$(realpath "$0")")
skip() { echo "slides: SKIPPED: $* (install them with scripts/install-slides-deps.sh)"; exit 77; }
fail=0
problem() { echo "slides: $*" >&2; fail=1; }
py=python3
for p in /usr/bin/python3 python3; do
  if command -v "$p" >/dev/null && "$p" -c 'import PIL' 2>/dev/null; then py=$p; break; fi
done
need_tools() {
  command -v pandoc >/dev/null || skip "pandoc is not installed"
  command -v weasyprint >/dev/null || skip "WeasyPrint is not installed, so no PDF decks"
  command -v node >/dev/null || skip "node is not installed (it typesets the math)"
  "$py" -c 'import PIL' 2>/dev/null || skip "Python's PIL (python3-pil) is not installed"
}
review="$build/tests/slides-review"
start=$SECONDS
case $what in
decks)
  need_tools
  log="$build/tests/slides-build.log"
  mkdir -p "$build/tests"
  cmake --build "$build" --target slides >"$log" 2>&1 || { cat "$log"; problem "the slides target failed"; exit 1; }
  grep -E "^render-figures: [0-9]+ made|^slides: (figures|done) in" "$log"
  n=0
  for deck in "$src"/lab[0-9]*.md; do
    n=$((n + 1))
    name=$(basename "$deck" .md)
    slides=$(($(grep -c '^# ' "$deck") + 1))   # the title page and one per "# "
    [ "$slides" -ge 25 ] || problem "$name has $slides slides: a lecture needs about 25-40"
    dirs=("$out/student")
    [ -d "$src/../solutions" ] && dirs=("$out" "$out/student")
    for d in "${dirs[@]}"; do
      for ext in html pdf; do [ -s "$d/$name.$ext" ] || problem "no $d/$name.$ext"; done
      grep -q 'src="data:image' "$d/$name.html" || problem "$d/$name.html does not embed its figures"
      grep -q 'class="katex' "$d/$name.html" || problem "$d/$name.html has no typeset math"
      if command -v pdfinfo >/dev/null && [ -s "$d/$name.pdf" ]; then
        pages=$(pdfinfo "$d/$name.pdf" | awk '/^Pages:/ {print $2}')
        [ "$pages" = "$slides" ] || problem "$d/$name.pdf has $pages pages for $slides slides: a slide runs over its page"
      fi
    done
    # A students' deck carries no solution code: no line of a function the lecturer's deck quotes.
    while read -r file func; do
      body=$(sed -n "/^[^ ].*\\b$func *(/,/^}/p" "$src/../$file" | sed -n '2,$p' | grep -vE '^\s*(//|\}|$)' | head -n 3)
      while IFS= read -r l; do
        l=$(sed -E 's/^ +//' <<<"$l")
        [ ${#l} -ge 12 ] || continue
        if "$py" - "$out/student/$name.html" "$l" <<'PY'; then problem "student/$name.html quotes the solution of $func: $l"; fi
import html, sys
text = html.unescape(open(sys.argv[1], encoding="utf-8").read())
sys.exit(0 if sys.argv[2] in text else 1)
PY
      done <<<"$body"
    done < <(sed -nE 's/^<!-- solution: *([^ ]+) +([^ ]+).*-->$/\1 \2/p' "$deck")
  done
  [ "$n" -eq 7 ] || problem "$n decks in slides/, expected 7"
  ;;
diagrams)
  need_tools
  "$py" "$here/slides_check.py" diagrams "$out" || fail=1
  ;;
figures)
  need_tools
  "$py" "$here/slides_check.py" figures "$out"
  rc=$?
  [ $rc = 77 ] && exit 77
  [ $rc = 0 ] || fail=1
  ;;
keys)
  [ -x "$viewer" ] || { problem "no viewer at '$viewer'"; exit 1; }
  mkdir -p "$build/tests"
  "$viewer" --help >"$build/tests/shadowlab-help.txt" 2>&1
  "$viewer" --list-keys >"$build/tests/shadowlab-keys.txt" 2>&1
  "$py" "$here/slides_check.py" keys "$src" "$build/tests/shadowlab-help.txt" "$build/tests/shadowlab-keys.txt" \
    "$src"/../grader/*.c || fail=1
  ;;
browser)
  need_tools
  command -v chromium >/dev/null || skip "chromium is not installed"
  rm -rf "$review/html"
  "$py" "$here/slides_check.py" browser "$out" "$review/html"
  rc=$?
  [ $rc = 77 ] && exit 77
  [ $rc = 0 ] || fail=1
  ;;
hall)
  # At 1920x1080: 16:9 slides, text and diagram labels >= 18 px, figures a good share of their slide.
  need_tools
  command -v chromium >/dev/null || skip "chromium is not installed"
  "$py" "$here/slides_hall.py" "$out"
  rc=$?
  [ $rc = 77 ] && exit 77
  [ $rc = 0 ] || fail=1
  ;;
pdf-pages)
  need_tools
  command -v pdftoppm >/dev/null || skip "pdftoppm (poppler-utils) is not installed"
  mkdir -p "$review/pdf"
  source "$here/image_checks.sh"
  start_image_check "$check"
  # lab 3: the title, the acne diagram, the bias sweep's row; lab 5: Chebyshev's bound.
  for spec in "lab3_bias 1" "lab3_bias 4" "lab3_bias 7" "lab5_vsm 5" "lab7_cube 6"; do
    set -- $spec
    pdf="$out/$1.pdf"
    [ -s "$pdf" ] || pdf="$out/student/$1.pdf"   # a copy without solutions has the students' decks only
    png="$review/pdf/$1-p$2"
    pdftoppm -png -r 60 -f "$2" -l "$2" -singlefile "$pdf" "$png" || { problem "pdftoppm failed on $pdf"; continue; }
    check_image not-blank "$png.png" || problem "page $2 of $pdf is blank"
  done
  echo "slides: PDF pages kept in $review/pdf"
  ;;
no-solutions)
  need_tools
  # A copy without solutions/: the viewer's figures cannot be drawn. Without pre-rendered
  # images each becomes a note; with them (staff's) every figure is there.
  for mode in none prerendered; do
    work="$build/tests/slides-$mode"
    rm -rf "$work"; mkdir -p "$work"
    pre=/nonexistent
    [ $mode = prerendered ] && pre="$out/figures"
    # Start from the build's diagrams and crops (cached), without the viewer's figures: those
    # must come from the pre-rendered ones, or be left out.
    cp -r "$out/figures" "$work/figures"
    "$py" - "$work/figures" <<'PY'
import json, os, sys
d = sys.argv[1]
for target, m in json.load(open(os.path.join(d, "manifest.json"))).items():
    if m["kind"] in ("figure", "animation", "truth"):
        for p in (os.path.join(d, os.path.basename(target)), os.path.join(d, ".stamps", target.replace("/", "_") + ".key")):
            if os.path.exists(p):
                os.remove(p)
PY
    "$py" "$src/tools/render_figures.py" --python "$py" --from none --prerendered "$pre" --out "$work" \
      "$src"/lab[0-9]*.md >"$work/render.log" 2>&1 || { cat "$work/render.log"; problem "figures ($mode) failed"; continue; }
    for deck in "$src"/lab[0-9]*.md; do
      name=$(basename "$deck" .md)
      "$py" "$src/tools/prepare_deck.py" --audience student --out-dir "$work" "$deck" >"$work/$name.md" ||
        { problem "prepare_deck failed on $name"; continue; }
      "$py" - "$work" "$work/$name.md" "$mode" <<'PY' || fail=1
import json, re, sys
work, md, mode = sys.argv[1:]
manifest = json.load(open(f"{work}/figures/manifest.json"))
text = open(md, encoding="utf-8").read()
bad = 0
for target in re.findall(r"\]\((figures/[^)\s]+)\)", text):
    st = manifest.get(target, {}).get("status")
    if st == "missing":
        print(f"slides: {md}: {target} is shown although it could not be made"); bad = 1
notes = text.count("Figure left out")
deck = md.split("/")[-1]
left_out = [t for t, m in manifest.items() if m["deck"] == deck and m["status"] == "missing"]
if mode == "prerendered" and (notes or left_out):
    print(f"slides: {md}: {notes} figures left out although pre-rendered ones were there"); bad = 1
if mode == "none" and left_out and notes == 0:
    print(f"slides: {md}: figures could not be made but no note says so"); bad = 1
sys.exit(bad)
PY
    done
    made=$(grep -E '^render-figures: [0-9]+ made' "$work/render.log")
    echo "slides: without solutions, $mode: $made"
  done
  # One students' deck through pandoc: the notes show, nothing else is missing.
  pandoc "$build/tests/slides-none/lab4_pcf.md" --from markdown --to html5 --filter "$src/tools/katex-filter.js" \
    --resource-path="$build/tests/slides-none" -o "$build/tests/slides-none/lab4_pcf.html" 2>"$build/tests/slides-none/pandoc.log" ||
    problem "pandoc failed on the students' lab 4 without solutions"
  grep -q 'left-out' "$build/tests/slides-none/lab4_pcf.html" || problem "the students' lab 4 shows no note for its left-out figures"
  ;;
*) echo "usage: slides.sh decks|diagrams|figures|keys|browser|hall|pdf-pages|no-solutions BUILD_DIR IMAGE_CHECK SLIDES_SRC [VIEWER]" >&2; exit 2 ;;
esac
echo "slides: $what took $((SECONDS - start)) s"
exit $fail
