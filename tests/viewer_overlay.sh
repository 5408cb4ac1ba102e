#!/usr/bin/env bash
# viewer_overlay.sh VIEWER SOLUTIONS_VIEWER IMAGE_CHECK WORK_DIR
# The overlay is drawn in headless runs when asked (--overlay), with readable
# text where the panel is and the scene untouched elsewhere; by default with
# --frames it is off, so screenshots and figures keep their pictures; the
# light's frustum draws lines into the scene; and where the viewer carries the
# solutions, --solutions draws exactly what the solutions' own viewer draws;
# the keys O, G and U do what their options do.
set -u
viewer=$1 solutions=$2 check=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_overlay: $*" >&2; fail=1; }
run() { "$@" >"$work/log" 2>&1 || { cat "$work/log"; problem "failed: $*"; }; }
common=(--headless --lab 4 --scene spot_on_floor --size 640x400 --frames 2)
run "$solutions" "${common[@]}" --screenshot "$work/plain.png"
run "$solutions" "${common[@]}" --no-overlay --screenshot "$work/no-overlay.png"
run "$solutions" "${common[@]}" --overlay --screenshot "$work/overlay.png"
# What it says: the lab and its settings, and the pass times, with what they measure on llvmpipe.
for line in "\[top left\] lab 4: PCF & PCSS" "\[top left\] filter: PCF grid 3x3" "\[top left\] shadow map: 1024x1024" \
            "\[top right\] depth +[0-9]+\.[0-9]{2}" "\[top right\] camera +[0-9]+\.[0-9]{2}"; do
  grep -qE "$line" "$work/log" || problem "the overlay does not say: $line"
done
if grep -q llvmpipe "$work/log"; then
  grep -q "\[top right\] llvmpipe: rasteriser CPU time" "$work/log" || problem "the overlay does not say what llvmpipe's times are"
fi
# Labs 5-7 say their own settings: the moments, the cascades and their splits, the cube map.
run "$solutions" --headless --lab 5 --scene stacked_occluders --size 640x400 --frames 1 --overlay --blur 3
for line in "\[top left\] VSM: moments 512x512, blur radius 3" "\[top left\] bleeding reduction 0\.30"; do
  grep -qE "$line" "$work/log" || problem "the lab 5 overlay does not say: $line"
done
run "$solutions" --headless --lab 6 --scene cascade_field --size 640x400 --frames 1 --overlay --cascades 3 --no-snap
for line in "\[top left\] shadow maps: 3 layers of 1024x1024" "\[top left\] cascades: 3, lambda 0\.80" \
            "\[top left\] splits \(view depth\): [0-9.]+ [0-9.]+ [0-9.]+ [0-9.]+$" "\[top left\] texel snapping: off"; do
  grep -qE "$line" "$work/log" || problem "the lab 6 overlay does not say: $line"
done
run "$solutions" --headless --lab 7 --scene closed_room --size 640x400 --frames 1 --overlay --soft
for line in "\[top left\] cube map: 6 faces of 512x512" "\[top left\] lookup: soft, 20 directions" \
            "\[top left\] faces: (one layered pass|six passes)"; do
  grep -qE "$line" "$work/log" || problem "the lab 7 overlay does not say: $line"
done
grep -q "shadow map: 1024x1024" "$work/log" && problem "the lab 7 overlay names the 2D map's size"
run "$solutions" "${common[@]}" --frustum --screenshot "$work/frustum.png"
cmp -s "$work/plain.png" "$work/no-overlay.png" || problem "--frames without --overlay does not give the plain picture"
# The top-left panel (lab, scene, code, light, map, bias, filter) at scale 1 (400 px high).
"$check" text "$work/overlay.png" "$work/plain.png" 8 8 150 50 || problem "no text in the overlay's panel"
# Below the panels, the scene is as it was.
"$check" text "$work/overlay.png" "$work/plain.png" 8 300 300 90 >/dev/null && problem "the overlay changed the scene below its panels"
cmp -s "$work/plain.png" "$work/frustum.png" && problem "--frustum drew nothing"
# The keys do what the options do (--keys presses them before the first frame).
run "$solutions" "${common[@]}" --keys G --screenshot "$work/key-l.png"
cmp -s "$work/key-l.png" "$work/frustum.png" || problem "key G does not draw what --frustum draws"
run "$solutions" "${common[@]}" --keys O --screenshot "$work/key-o.png"
"$check" text "$work/key-o.png" "$work/plain.png" 8 8 150 50 >/dev/null || problem "key O does not show the overlay"
run "$solutions" "${common[@]}" --keys OO --screenshot "$work/key-oo.png"
cmp -s "$work/key-oo.png" "$work/plain.png" || problem "key O twice does not hide the overlay again"
if "$viewer" --help | grep -q -- "--solutions"; then
  if "$viewer" "${common[@]}" --solutions --screenshot "$work/ab.png" >"$work/log" 2>&1; then
    cmp -s "$work/ab.png" "$work/plain.png" || problem "--solutions does not draw what the solutions' viewer draws"
    run "$viewer" "${common[@]}" --keys U --screenshot "$work/key-a.png"
    cmp -s "$work/key-a.png" "$work/plain.png" || problem "key U does not switch to the solutions' code"
  elif grep -q "no solutions beside" "$work/log"; then
    echo "viewer_overlay: this build has no second lab code (a solutions build or a handout): A/B not checked"
  else
    cat "$work/log"; problem "--solutions failed"
  fi
fi
exit $fail
