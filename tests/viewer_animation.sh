#!/usr/bin/env bash
# viewer_animation.sh VIEWER SOLUTIONS_VIEWER IMAGE_CHECK WORK_DIR
# Lab 6's shimmer demo, as the slides use it: with the cascades fitted to a
# camera that turns or slides while the picture stays, the solutions' snapping
# keeps every shadow still, and --no-snap (the viewer undoing the snapping)
# makes the edges crawl; --mark-changes measures it. --screenshot FILE.gif
# writes every frame into one looping GIF. The student build runs the same
# commands with its stubs without failing.
set -u
viewer=$1 solutions=$2 check=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_animation: $*" >&2; fail=1; }
source "$(dirname "$0")/image_checks.sh"   # check_image: the picture checks in one image_check
start_image_check "$check"
shimmer=(--headless --lab 6 --scene cascade_field --map-size 256 --path-fits-cascades --frames 12 --size 480x300)

# The share of pixels --mark-changes says changed, in percent (its last line).
changed() { sed -nE 's/^shadowlab: saved .*\(([0-9.]+)%\) changed over [0-9]+ frames.*/\1/p' "$1" | tail -n 1; }
for path in turn slide; do
  for snap in snapped unsnapped; do
    extra=(); [ $snap = unsnapped ] && extra=(--no-snap)
    if ! "$solutions" "${shimmer[@]}" --camera-path $path "${extra[@]}" --mark-changes \
         --screenshot "$work/$path-$snap.png" >"$work/$path-$snap.log" 2>&1; then
      cat "$work/$path-$snap.log"; problem "--camera-path $path ${extra[*]} --mark-changes failed"; continue
    fi
    pct=$(changed "$work/$path-$snap.log")
    [ -n "$pct" ] || { cat "$work/$path-$snap.log"; problem "--mark-changes did not say how much changed"; continue; }
    echo "viewer_animation: $path, $snap: $pct% of the pixels changed"
    # Measured: snapped 0-0.003%, unsnapped about 0.9% (every shadow edge).
    if [ $snap = snapped ]; then
      awk -v p="$pct" 'BEGIN { exit !(p <= 0.05) }' || problem "$path: the snapped shadows moved ($pct% changed)"
    else
      awk -v p="$pct" 'BEGIN { exit !(p >= 0.3) }' ||
        problem "$path: --no-snap did not make the shadows shimmer ($pct% changed, expected 0.3% or more)"
    fi
  done
done
# With the overlay, the marks are the scene's: its pass times change every frame, and count for nothing.
if "$solutions" "${shimmer[@]}" --camera-path turn --overlay --mark-changes --screenshot "$work/turn-overlay.png" \
     >"$work/turn-overlay.log" 2>&1; then
  [ "$(changed "$work/turn-overlay.log")" = "$(changed "$work/turn-snapped.log")" ] ||
    problem "with the overlay --mark-changes counts $(changed "$work/turn-overlay.log")%, without it $(changed "$work/turn-snapped.log")%"
  check_image label "$work/turn-overlay.png" 8 8 150 40 || problem "--mark-changes with --overlay saved no overlay"
else
  cat "$work/turn-overlay.log"; problem "--mark-changes with --overlay failed"
fi
# The red marks are in the picture: it differs from a still frame where the edges are.
"$solutions" --headless --lab 6 --scene cascade_field --map-size 256 --frames 1 --size 480x300 \
  --screenshot "$work/still.png" >/dev/null 2>&1 || problem "a still frame failed"
[ -f "$work/turn-unsnapped.png" ] && ! cmp -s "$work/still.png" "$work/turn-unsnapped.png" ||
  problem "--mark-changes saved the plain frame"
# Sliding, snapped: nothing changed, so the picture is the still frame itself.
[ "$(changed "$work/slide-snapped.log")" = 0.000 ] && ! cmp -s "$work/still.png" "$work/slide-snapped.png" &&
  problem "--mark-changes with nothing changed did not save the plain frame"

# An animated GIF: six frames (a graphic control block before each image), looping. The delay
# is printed, not judged: OpenImageIO 2.5 (Debian 13) writes 1 s whatever it is asked.
"$solutions" "${shimmer[@]}" --frames 6 --camera-path turn --no-snap --screenshot "$work/anim.gif" >"$work/gif.log" 2>&1 ||
  { cat "$work/gif.log"; problem "--screenshot FILE.gif failed"; }
if [ -f "$work/anim.gif" ]; then
  bytes=$(od -An -tx1 -v "$work/anim.gif" | tr -s ' \n' ' ')
  blocks=$(grep -oE "21 f9 04 [0-9a-f]{2} [0-9a-f]{2} [0-9a-f]{2} [0-9a-f]{2} 00 2c" <<<"$bytes")
  frames=$(grep -c . <<<"$blocks")
  [ "$frames" -eq 6 ] || problem "anim.gif holds $frames frames, not 6"
  delays=$(while read -r _ _ _ _ lo hi _; do echo $((16#$hi$lo)); done <<<"$blocks" | sort -u | tr '\n' ' ')
  echo "viewer_animation: anim.gif: $frames frames, delay (1/100 s): $delays"
  grep -q "4e 45 54 53 43 41 50 45 32 2e 30" <<<"$bytes" || problem "anim.gif does not loop (no NETSCAPE2.0 block)"
  check_image not-blank "$work/anim.gif" >/dev/null || problem "anim.gif's first frame is blank or unreadable"
else
  problem "no anim.gif"
fi

# Usage mistakes are refused with a message, not a crash.
for bad in "--camera-path wobble" "--mark-changes --frames 1 --screenshot x.png" "--mark-changes --frames 4"; do
  # shellcheck disable=SC2086
  "$solutions" --headless --lab 6 $bad >"$work/bad.log" 2>&1
  rc=$?
  [ $rc -eq 2 ] && grep -q "^shadowlab: " "$work/bad.log" || { cat "$work/bad.log"; problem "'$bad' gave $rc, not 2 with a message"; }
done

# The student build: stubs, the same commands, no failure (no shadows to shimmer).
"$viewer" "${shimmer[@]}" --camera-path slide --no-snap --mark-changes --screenshot "$work/student.png" \
  >"$work/student.log" 2>&1 || { cat "$work/student.log"; problem "the student build failed the shimmer demo"; }
grep -q "not implemented yet" "$work/student.log" || problem "the student build did not say what is not implemented"
exit $fail
