#!/usr/bin/env bash
# viewer_screenshot.sh VIEWER IMAGE_COMPARE WORK_DIR
# The viewer in a real X window (Xvfb) renders frames, saves the last one, and
# exits; the picture must match the same view rendered headless with OSMesa.
set -u
viewer=$1 compare=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
fail=0
for mode in "" "--visibility"; do
  tag=${mode:+visibility}; tag=${tag:-shaded}
  bash "$(dirname "$0")/with_display.sh" -s "-screen 0 800x600x24" "$viewer" --lab 2 --size 320x240 --frames 5 $mode \
    --screenshot "$work/window-$tag.png" || { echo "the viewer failed in Xvfb" >&2; exit 1; }
  "$viewer" --headless --lab 2 --size 320x240 --frames 1 $mode --screenshot "$work/headless-$tag.png" || exit 1
  "$compare" "$work/window-$tag.png" "$work/headless-$tag.png" 0.1 0.5 || fail=1
done
exit $fail
