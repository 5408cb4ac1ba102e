#!/usr/bin/env bash
# viewer_lecture.sh VIEWER IMAGE_CHECK WORK_DIR
# --lecture's overlay leaves the picture to the hall: in labs 3, 4 (with the light's frustum), 6 and 7, at
# 1280x720 and 1920x1080, the overlay (its status line, the frustum) changes at most 10% of the pixels of
# the same frame drawn without it. Its status line names the lab, the technique, the setting the last key
# changed and the frame time; key I brings the panels (the parameters, the legend) and takes them away
# again; a font that cannot be read gives the bitmap font and one warning, never a failed run.
set -u
viewer=$1 check=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_lecture: $*" >&2; fail=1; }
source "$(dirname "$0")/image_checks.sh"
start_image_check "$check"
source "$(dirname "$0")/../scripts/viewer-batch.sh"
names=()
run() { viewer_batch_add "$@"; names+=("$1"); }

declare -A scene=([3]=boxes_on_floor [4]=boxes_on_floor [6]=cascade_field [7]=closed_room)
for size in 1280x720 1920x1080; do
  for lab in 3 4 6 7; do
    common=(--headless --lab "$lab" --scene "${scene[$lab]}" --size "$size" --frames 2)
    extra=()
    [ "$lab" = 4 ] && extra=(--frustum) # the frustum's lines were the widest thing a lecture drew
    run "plain-$lab-$size" "${common[@]}" --no-overlay --screenshot "$work/plain-$lab-$size.png"
    run "lecture-$lab-$size" "${common[@]}" --lecture --overlay "${extra[@]}" --screenshot "$work/lecture-$lab-$size.png"
  done
done
run panels --headless --lab 6 --scene cascade_field --size 1280x720 --frames 1 --lecture --overlay --show-cascades \
  --keys I
run panels-again --headless --lab 6 --scene cascade_field --size 1280x720 --frames 1 --lecture --overlay \
  --show-cascades --keys II
run changed --headless --lab 4 --size 1280x720 --frames 1 --lecture --overlay --keys F
run no-font --headless --lab 4 --size 1280x720 --frames 1 --lecture --overlay --font "$work/no-such-font.ttf" \
  --screenshot "$work/no-font.png"
run plain-viewer --headless --lab 4 --size 1280x720 --frames 1 --overlay
viewer_batch_run "$viewer" "$work"
for name in "${names[@]}"; do
  viewer_batch_status "$work" "$name" || { cat "$work/$name.log"; problem "failed: $name"; }
done

for size in 1280x720 1920x1080; do
  for lab in 3 4 6 7; do
    covered=$(check_image changed "$work/lecture-$lab-$size.png" "$work/plain-$lab-$size.png")
    echo "viewer_lecture: lab $lab at $size: the overlay changes $covered% of the pixels"
    awk -v c="$covered" 'BEGIN { exit !(c > 0.5 && c <= 10) }' ||
      problem "lab $lab at $size: the overlay changes ${covered:-?}% of the pixels (more than 0.5%, at most 10% expected)"
    grep -qE "^\[status\] lab $lab  .*  [0-9]+\.[0-9] ms$" "$work/lecture-$lab-$size.log" ||
      problem "lab $lab at $size: no status line with the lab and a frame time"
    grep -qE "^\[(top|bottom) (left|right)\]" "$work/lecture-$lab-$size.log" &&
      problem "lab $lab at $size: --lecture shows panels before key I"
  done
done
grep -qF "[status] lab 4  PCF & PCSS   filter: poisson" "$work/changed.log" ||
  problem "the status line does not name the setting F changed (filter: poisson)"
grep -qF "[top left] lab 6: cascaded shadow maps" "$work/panels.log" || problem "key I does not bring the panels"
grep -qF "[top right] cascades (K), view depth" "$work/panels.log" || problem "key I does not bring lab 6's legend"
grep -q "^\[status\]" "$work/panels.log" && problem "with the panels on, the status line is still drawn"
grep -qE "^\[(top|bottom) (left|right)\]|^\[label\]" "$work/panels-again.log" && problem "key I twice does not take the panels away"
grep -q "^\[status\] lab 6" "$work/panels-again.log" || problem "key I twice does not give the status line back"
[ "$(grep -c "warning: no font file $work/no-such-font.ttf" "$work/no-font.log")" = 1 ] ||
  problem "a missing font is not said in one warning"
grep -q "^\[status\] lab 4" "$work/no-font.log" || problem "without its font the status line is not drawn"
grep -qF "[top left] lab 4: PCF & PCSS" "$work/plain-viewer.log" || problem "the plain viewer's overlay lost its panels"
grep -q "^\[status\]" "$work/plain-viewer.log" && problem "the plain viewer's overlay shows a status line"
exit $fail
