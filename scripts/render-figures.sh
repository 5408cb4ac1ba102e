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
# it renders, drop the mark, so that a broken command fails the build. An animation (frames joined into a GIF where
# ffmpeg is installed; otherwise its last frame) is named the same way with
# "animation", --frames N and a --screenshot path ending in .gif: the viewer
# saves each frame (--frame-dir), then the script joins them.
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

placeholder() { # PATH KIND TEXT
  local png=$1
  # The viewer writes PNG only; browsers and WeasyPrint go by the content, not the name.
  [ "$2" = animation ] && png=${1%.*}.png
  "$viewer" --headless --frames 1 --lab 1 --size 640x400 --caption "placeholder: $3" --screenshot "$png" >/dev/null &&
    { [ "$png" = "$1" ] || mv "$png" "$1"; }
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
    if [ "$kind" = animation ]; then
      # Every frame of the run, then one animated GIF (ffmpeg) or the last frame alone.
      frames_dir=${shot%.*}-frames; rm -rf "$frames_dir"; mkdir -p "$frames_dir"
      n=0
      for ((i = 0; i < ${#args[@]}; i++)); do [ "${args[$i]}" = "--frames" ] && n=${args[$((i + 1))]}; done
      # The viewer saves every frame into the folder; the .gif path is not its to write.
      a=()
      for ((i = 0; i < ${#args[@]}; i++)); do
        if [ "${args[$i]}" = "--screenshot" ]; then i=$((i + 1)); else a+=("${args[$i]}"); fi
      done
      echo "render-figures: shadowlab $cmd"
      if ! "$viewer" --headless "${a[@]}" --frame-dir "$frames_dir" >/dev/null 2>"$errors"; then
        head -n 3 "$errors" >&2
        if [ -n "$needs" ]; then pending_failed "$shot" "$kind" "$needs"; else failed=$((failed + 1)); fi
        continue
      fi
      if command -v ffmpeg >/dev/null; then
        ffmpeg -loglevel error -y -framerate 10 -i "$frames_dir/%03d.png" "$shot" || failed=$((failed + 1))
      else
        # Without ffmpeg the deck shows the last frame (PNG data under the animation's name).
        echo "render-figures: no ffmpeg: $shot is its last frame; the frames are in $frames_dir"
        cp "$(printf '%s/%03d.png' "$frames_dir" "$n")" "$shot" || failed=$((failed + 1))
      fi
      made=$((made + 1))
      continue
    fi
    echo "render-figures: shadowlab $cmd"
    if "$viewer" --headless --frames 1 "${args[@]}" >/dev/null 2>"$errors"; then
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
