#!/usr/bin/env bash
# render-figures.sh VIEWER OUT_DIR DECK.md...
#
# Renders every figure the decks name, headless, with the viewer itself: no
# figure is drawn by hand or kept as a binary. A deck names the command that
# makes each figure in a comment just above where it shows it:
#
#   <!-- figure: shadowlab --lab 3 --bias-mode none --screenshot figures/acne.png -->
#
# The command runs from OUT_DIR (so figures/... lands in OUT_DIR/figures) with
# `shadowlab` meaning VIEWER and `--headless --frames 1` added in front (a
# command may ask for more frames). A figure of a lab the viewer does not
# have yet is marked with the lab it needs:
#
#   <!-- figure (needs lab 5): shadowlab --lab 5 ... --screenshot figures/x.png -->
#
# While the viewer refuses that lab, the figure is a clearly labelled
# placeholder (the plain lab 1 scene with "placeholder" written on it), so the
# deck still builds; once the lab is in the viewer the real figure is made,
# with no change to the deck. If its command then fails (options the lab's
# viewer does not take), the figure stays a placeholder with a warning; once
# it renders, drop the mark, so that a broken command fails the build. An
# animation is named the same way with "animation", --frames N and a
# --screenshot path ending in .gif: the viewer writes every frame into one
# looping GIF (browsers play it; a PDF shows its first frame).
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: render-figures.sh VIEWER OUT_DIR DECK.md..." >&2; exit 2; }
viewer=$(realpath "$1") out=$2
shift 2
decks=()
for deck in "$@"; do decks+=("$(realpath -m "$deck")"); done
mkdir -p "$out/figures"
cd "$out"
made=0 placeholders=0 failed=0
errors=$(mktemp)
trap 'rm -f "$errors"' EXIT

# Does the viewer take --lab N? It says "--lab must be 1..K" when it does not.
viewer_has_lab() {
  local said
  said=$("$viewer" --lab "$1" --headless 2>&1 || true)
  ! grep -q -- "--lab must be" <<<"$said"
}

placeholder() { # PATH KIND TEXT (a .gif path gets a one-frame GIF)
  "$viewer" --headless --frames 1 --lab 1 --size 640x400 --caption "placeholder: $3" --screenshot "$1" >/dev/null
}
warned=0
# A figure marked as needing a lab whose command fails (the lab is in, but the
# deck's options are not what its viewer took): a placeholder and a warning,
# not a failed build. Drop the "(needs lab N)" mark once the figure renders.
pending_failed() { # SHOT KIND LAB
  echo "render-figures: WARNING: the command for $1 (needs lab $3) failed: check its options against" \
    "'shadowlab --help'; placeholder for now" >&2
  placeholder "$1" "$2" "the command for this figure failed (lab $3's options?)" || failed=$((failed + 1))
  warned=$((warned + 1))
}

for deck in "${decks[@]}"; do
  [ -f "$deck" ] || { echo "render-figures: no deck $deck" >&2; failed=$((failed + 1)); continue; }
  while IFS= read -r line; do
    kind=$(sed -E 's/^<!-- (figure|animation).*/\1/' <<<"$line")
    needs=$(sed -nE 's/^<!-- (figure|animation) \(needs lab ([0-9]+)\):.*/\2/p' <<<"$line")
    cmd=$(sed -E 's/^<!-- (figure|animation)( \(needs lab [0-9]+\))?: *shadowlab (.*) -->$/\3/' <<<"$line")
    eval "args=($cmd)"
    shot=""
    for ((i = 0; i < ${#args[@]}; i++)); do
      [ "${args[$i]}" = "--screenshot" ] && shot=${args[$((i + 1))]:-}
    done
    [ -n "$shot" ] || { echo "render-figures: no --screenshot in: $line" >&2; failed=$((failed + 1)); continue; }
    mkdir -p "$(dirname "$shot")"
    if [ -n "$needs" ] && ! viewer_has_lab "$needs"; then
      echo "render-figures: $shot needs lab $needs, which this viewer does not have: placeholder"
      placeholder "$shot" "$kind" "this figure needs lab $needs in the viewer" || failed=$((failed + 1))
      placeholders=$((placeholders + 1))
      continue
    fi
    echo "render-figures: shadowlab $cmd"
    # A figure is one frame unless its command asks for more; an animation names its --frames.
    first=(--frames 1)
    [ "$kind" = animation ] && first=()
    if "$viewer" --headless "${first[@]}" "${args[@]}" >/dev/null 2>"$errors"; then
      made=$((made + 1))
    else
      head -n 3 "$errors" >&2
      if [ -n "$needs" ]; then pending_failed "$shot" "$kind" "$needs"; else failed=$((failed + 1)); fi
    fi
  done < <(grep -E '^<!-- (figure|animation)( \(needs lab [0-9]+\))?: *shadowlab .* -->$' "$deck" || true)
done
echo "render-figures: $made rendered, $placeholders placeholders, $warned pending commands failed (warnings)," \
  "$failed failed, in $out/figures"
[ "$failed" -eq 0 ]
