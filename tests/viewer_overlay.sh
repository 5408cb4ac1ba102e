#!/usr/bin/env bash
# viewer_overlay.sh VIEWER SOLUTIONS_VIEWER IMAGE_CHECK WORK_DIR
# The overlay is drawn in headless runs when asked (--overlay), with readable
# text where the panel is and the scene untouched elsewhere; by default with
# --frames it is off, so screenshots and figures keep their pictures; the
# light's frustum draws lines into the scene; and where the viewer carries the
# solutions, --solutions draws exactly what the solutions' own viewer draws;
# the keys O, G and U do what their options do. The overlay says what really
# draws when the asked lab is off (as the renderer noted it); --labels names the
# cascade colours, the cube faces and the light; --lecture draws the frustum
# thin and translucent and one status line for the panels; in a window the key panel lists the lab's own keys with their
# state; --help's keys are the key table's; --batch refuses what is not a headless run.
set -u
viewer=$1 solutions=$2 check=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_overlay: $*" >&2; fail=1; }
# Every picture check in one image_check process (check_image).
source "$(dirname "$0")/image_checks.sh"
start_image_check "$check"
# The headless runs are independent: each viewer's runs are one process (scripts/viewer-batch.sh), NAME's
# output in $work/NAME.log. A run that fails is a problem, except the ones named try-*, looked at below.
source "$(dirname "$0")/../scripts/viewer-batch.sh"
run() { viewer_batch_add "$@"; }
run_all() {
  local name
  viewer_batch_run "$1" "$work"
  for name in "${@:2}"; do
    [[ $name == try-* ]] && continue
    viewer_batch_status "$work" "$name" || { cat "$work/$name.log"; problem "failed: $name ($1)"; }
  done
}
common=(--headless --lab 4 --scene spot_on_floor --size 640x400 --frames 2)
run plain "${common[@]}" --screenshot "$work/plain.png"
run no-overlay "${common[@]}" --no-overlay --screenshot "$work/no-overlay.png"
run overlay "${common[@]}" --overlay --screenshot "$work/overlay.png"
# Labs 5-7 say their own settings: the moments, the cascades and their splits, the cube map.
run lab5 --headless --lab 5 --scene stacked_occluders --size 640x400 --frames 1 --overlay --blur 3
run lab6 --headless --lab 6 --scene cascade_field --size 640x400 --frames 1 --overlay --cascades 3 --no-snap
run lab7 --headless --lab 7 --scene closed_room --size 640x400 --frames 1 --overlay --soft
run frustum "${common[@]}" --frustum --screenshot "$work/frustum.png"
# The keys do what the options do (--keys presses them before the first frame).
run key-l "${common[@]}" --keys G --screenshot "$work/key-l.png"
run key-o "${common[@]}" --keys O --screenshot "$work/key-o.png"
run key-oo "${common[@]}" --keys OO --screenshot "$work/key-oo.png"
run lab5-pcf --headless --lab 5 --scene stacked_occluders --size 320x200 --frames 1 --overlay --pcf
run lab7-sun --headless --lab 7 --scene boxes_on_floor --size 320x200 --frames 1 --overlay
run l6-labels --headless --lab 6 --scene cascade_field --size 640x400 --frames 1 --show-cascades --labels \
  --screenshot "$work/l6-labels.png"
run l7-labels --headless --lab 7 --scene closed_room --size 640x400 --frames 1 --show-map --labels \
  --screenshot "$work/l7-labels.png"
# the frustum alone, without the spot light's marker (whose label a lecture draws larger)
sun=(--headless --lab 4 --scene boxes_on_floor --size 640x400 --frames 2)
run sun "${sun[@]}" --screenshot "$work/sun.png"
run sun-frustum "${sun[@]}" --frustum --screenshot "$work/sun-frustum.png"
run lecture-frustum "${sun[@]}" --frustum --lecture --no-overlay --screenshot "$work/lecture-frustum.png"
run lecture-overlay "${common[@]}" --overlay --lecture --screenshot "$work/lecture-overlay.png"
run_all "$solutions" plain no-overlay overlay lab5 lab6 lab7 frustum key-l key-o key-oo lab5-pcf lab7-sun l6-labels \
  l7-labels sun sun-frustum lecture-frustum lecture-overlay
run try-ab "${common[@]}" --solutions --screenshot "$work/ab.png"
run try-key-a "${common[@]}" --keys U --screenshot "$work/key-a.png"
run own-lab5 --headless --lab 5 --scene stacked_occluders --size 320x200 --frames 1 --overlay
run_all "$viewer" try-ab try-key-a own-lab5
# What it says: the lab and its settings, and the pass times, with what they measure on llvmpipe.
for line in "\[top left\] lab 4: PCF & PCSS" "\[top left\] filter: PCF grid 3x3" "\[top left\] shadow map: 1024x1024" \
            "\[top right\] depth +[0-9]+\.[0-9]{2}" "\[top right\] camera +[0-9]+\.[0-9]{2}"; do
  grep -qE "$line" "$work/overlay.log" || problem "the overlay does not say: $line"
done
if grep -q llvmpipe "$work/overlay.log"; then
  grep -q "\[top right\] llvmpipe: rasteriser CPU time" "$work/overlay.log" || problem "the overlay does not say what llvmpipe's times are"
fi
for line in "\[top left\] VSM: moments 512x512, blur radius 3" "\[top left\] bleeding reduction 0\.30"; do
  grep -qE "$line" "$work/lab5.log" || problem "the lab 5 overlay does not say: $line"
done
for line in "\[top left\] shadow maps: 3 layers of 1024x1024" "\[top left\] cascades: 3, lambda 0\.80" \
            "\[top left\] splits \(view depth\): [0-9.]+ [0-9.]+ [0-9.]+ [0-9.]+$" "\[top left\] texel snapping: off"; do
  grep -qE "$line" "$work/lab6.log" || problem "the lab 6 overlay does not say: $line"
done
for line in "\[top left\] cube map: 6 faces of 512x512" "\[top left\] lookup: soft, 20 directions" \
            "\[top left\] faces: (one layered pass|six passes)"; do
  grep -qE "$line" "$work/lab7.log" || problem "the lab 7 overlay does not say: $line"
done
grep -q "shadow map: 1024x1024" "$work/lab7.log" && problem "the lab 7 overlay names the 2D map's size"
cmp -s "$work/plain.png" "$work/no-overlay.png" || problem "--frames without --overlay does not give the plain picture"
# The top-left panel (lab, scene, code, light, map, bias, filter) at scale 1 (400 px high).
check_image text "$work/overlay.png" "$work/plain.png" 8 8 150 50 || problem "no text in the overlay's panel"
# Below the panels, the scene is as it was.
check_image text "$work/overlay.png" "$work/plain.png" 8 300 300 90 >/dev/null && problem "the overlay changed the scene below its panels"
cmp -s "$work/plain.png" "$work/frustum.png" && problem "--frustum drew nothing"
cmp -s "$work/key-l.png" "$work/frustum.png" || problem "key G does not draw what --frustum draws"
check_image text "$work/key-o.png" "$work/plain.png" 8 8 150 50 >/dev/null || problem "key O does not show the overlay"
cmp -s "$work/key-oo.png" "$work/plain.png" || problem "key O twice does not hide the overlay again"
if "$viewer" --help | grep -q -- "--solutions"; then
  if viewer_batch_status "$work" try-ab; then
    cmp -s "$work/ab.png" "$work/plain.png" || problem "--solutions does not draw what the solutions' viewer draws"
    viewer_batch_status "$work" try-key-a || { cat "$work/try-key-a.log"; problem "failed: --keys U"; }
    cmp -s "$work/key-a.png" "$work/plain.png" || problem "key U does not switch to the solutions' code"
  elif grep -q "no solutions beside" "$work/try-ab.log"; then
    echo "viewer_overlay: this build has no second lab code (a solutions build or a handout): A/B not checked"
  else
    cat "$work/try-ab.log"; problem "--solutions failed"
  fi
fi

# What really draws, as the renderer noted it: a setting (lab 5's P), the scene (lab 7 needs a point
# light), a lab's shaders (a copy of the solutions with lab 5's GLSL broken).
status() { grep -E "^shadowlab: lab [0-9] .* is off: " "$work/${1:-log}"; }
status lab5-pcf.log | grep -qF "lab 5 VSM is off: switched off with P; drawing lab 4's PCF grid 3x3" ||
  problem "lab 5 with VSM switched off does not say it draws lab 4's filter"
grep -q "\[top left\] VSM: moments" "$work/lab5-pcf.log" && problem "lab 5's overlay gives VSM's settings while lab 4's filter draws"
grep -q "\[top left\] filter: PCF grid 3x3" "$work/lab5-pcf.log" || problem "lab 5 with VSM off does not give lab 4's filter settings"
status lab7-sun.log | grep -qF "lab 7 cube maps is off: boxes_on_floor has no point light (closed_room has one); drawing lab 4's PCF grid 3x3" ||
  problem "lab 7 without a point light does not say what draws"
labs=$(sed -nE 's/^shadowlab: .* labs from (.*)$/\1/p' "$work/lab7-sun.log" | head -n 1)
if [ -d "$labs/lab5_vsm/shaders" ]; then
  cp -r "$labs" "$work/broken-labs" && echo "this is not GLSL;" >>"$work/broken-labs/lab5_vsm/shaders/vsm.glsl"
  "$solutions" --headless --lab 5 --scene stacked_occluders --size 320x200 --frames 1 --overlay \
    --labs-dir "$work/broken-labs" >"$work/log" 2>&1
  status | grep -qF "lab 5 VSM is off: lab 5's shaders do not compile; drawing lab 4's PCF grid 3x3" ||
    { cat "$work/log"; problem "lab 5 with broken shaders does not say lab 4's filter draws"; }
  grep -qE "\[top left\] lab 5 VSM is off: lab 5's shaders do not compile" "$work/log" ||
    problem "the overlay does not say lab 5's shaders stop VSM"
else
  problem "cannot find the solutions' labs folder in the viewer's first line"
fi
# This build's own labs, stubs or not: every function the status line blames is one the same frame reports
# as not implemented, and a lab that is not off shows its own settings.
while read -r n fn; do
  grep -qF "not implemented yet: lab${n}_${fn}()" "$work/own-lab5.log" || problem "the status blames lab${n}_${fn}, which is not reported as not implemented"
done < <(status own-lab5.log | grep -oE "lab [0-9]'s [a-z0-9_]+ is not implemented" | sed -E "s/lab ([0-9])'s ([a-z0-9_]+) .*/\1 \2/")
status own-lab5.log >/dev/null || grep -q "\[top left\] VSM: moments" "$work/own-lab5.log" || problem "lab 5 draws but its overlay does not say VSM"

# --labels: the cascade colours' legend (split depths from the frame), the cube faces named in the cross, the
# light's marker; in the picture, text on a dark backing where they are.
for line in "\[top right\] cascades \(K\), view depth" "\[top right\] ## 0: [0-9.]+ - [0-9.]+" "\[top right\] ## 3: [0-9.]+ - [0-9.]+"; do
  grep -qE "$line" "$work/l6-labels.log" || problem "the cascade legend does not say: $line"
done
check_image label "$work/l6-labels.png" 490 6 140 50 || problem "no cascade legend in the top right corner"
for face in +X -X +Y -Y +Z -Z; do grep -qF "[label] $face" "$work/l7-labels.log" || problem "the cube face $face is not labelled"; done
grep -qF "[marker] point light" "$work/l7-labels.log" || problem "no marker at the point light"
# The cross's cells are 66 px (half what fits 4 x 3 in 640x400), 8 px off the lower right: +Y's top left is
# at 434,194, +X's at 500,260; the labels sit just inside.
check_image label "$work/l7-labels.png" 436 196 16 13 || problem "no +Y label on the cross"
check_image label "$work/l7-labels.png" 502 262 16 13 || problem "no +X label on the cross"

# --lecture: the frustum's lines are no wider and translucent (no more pixels change, and those that do
# change less), and one status line stands for the panels (viewer_lecture.sh measures how much it covers).
normal=$(check_image changed "$work/sun.png" "$work/sun-frustum.png") lecture=$(check_image changed "$work/sun.png" "$work/lecture-frustum.png")
echo "viewer_overlay: the frustum changes $normal% of the pixels, $lecture% with --lecture"
awk -v a="$normal" -v b="$lecture" 'BEGIN { exit !(b > 0 && b <= a) }' || problem "--lecture's frustum lines are wider than the plain viewer's"
grep -q "^\[status\] lab 4  PCF & PCSS" "$work/lecture-overlay.log" || problem "--lecture's overlay has no status line"
grep -q "^\[top left\]" "$work/lecture-overlay.log" && problem "--lecture's overlay shows its panels before key I"
check_image text "$work/overlay.png" "$work/plain.png" 8 100 280 60 >/dev/null && problem "the plain overlay's panel reaches below its parameters"

# --batch runs headless runs only, says which line it refuses and why, and fails when a line does (no picture
# is drawn here: each line is refused before a context is made).
printf '%s\n' "# a comment, then a blank line" "" "--lab 4 --frames 1" "--headless --serve 8123" \
  "--headless --batch x" "--headless --caption 'not closed" >"$work/refused.txt"
"$solutions" --batch "$work/refused.txt" >"$work/refused.out" 2>"$work/refused.err" && problem "--batch with failing lines exits 0"
for line in "line 3 opens a window" "line 4 serves (--serve)" "line 5 has --batch" "line 6: a ' is not closed"; do
  grep -qF -- "$line" "$work/refused.err" || problem "--batch does not say: $line"
done
[ "$(grep -c '^shadowlab: batch line [0-9]*: exit 2$' "$work/refused.out")" = 4 ] || problem "--batch does not mark each line's end"
"$solutions" --headless --batch "$work/refused.txt" >"$work/log" 2>&1 && problem "--batch with other options is not refused"
grep -qF "takes no other options" "$work/log" || problem "--batch with other options does not say why it is refused"

# --help lists the key table (--list-keys, for scripts) and nothing says the solutions key is A.
"$viewer" --help >"$work/help" 2>&1 || problem "--help failed"
"$viewer" --list-keys >"$work/keys" 2>&1 || problem "--list-keys failed"
[ "$(wc -l <"$work/keys")" -ge 30 ] || problem "--list-keys lists $(wc -l <"$work/keys") keys"
while IFS=$'\t' read -r lab keys what; do
  grep -qF -- "$keys" "$work/help" && grep -qF -- "$what" "$work/help" || problem "--help does not list $keys ($what), lab $lab"
done <"$work/keys"
grep -qE "^all	U	student or solutions code" "$work/keys" || problem "U is not the solutions key"
grep -qE "key A\b|^ +A +[a-z]" "$work/help" && problem "--help still names A for the solutions"

# In a window the key panel lists the lab's own keys and what they set now: K colours the cascades, U
# switches to the solutions' code (where the build has them), and the panel says so.
if command -v Xvfb >/dev/null; then
  bash "$(dirname "$0")/with_display.sh" -s "-screen 0 800x600x24" "$viewer" --lab 6 --scene cascade_field --size 640x400 --frames 2 --overlay \
    --keys KU --screenshot "$work/keys-window.png" >"$work/log" 2>&1 || { cat "$work/log"; problem "the viewer failed in a window"; }
  for line in "\[bottom left\] keys, lab 6" "\[bottom left\] K +cascade colours: on" "\[bottom left\] , \. +lambda: 0\.80" \
              "\[bottom left\] .*W A S D Q E fly" "\[bottom left\] .*G frustum: off"; do
    grep -qE "$line" "$work/log" || problem "the key panel does not say: $line"
  done
  grep -qE "\[bottom left\] (B|F|C) " "$work/log" && problem "lab 6's key panel lists keys of labs 2-4"
  check_image label "$work/keys-window.png" 8 330 120 60 || problem "no key panel in the lower left corner"
  # At 800x450 with lab 6's layers shown (M), the key panel moves up above them: layer 0 (112 px square at
  # 326,330; its number in the corner) is the same with the overlay as without.
  bash "$(dirname "$0")/with_display.sh" -s "-screen 0 800x600x24" bash -c 'for o in --overlay --no-overlay; do
      "$1" --lab 6 --scene cascade_field --size 800x450 --frames 2 --show-map $o --screenshot "$2/layers$o.png" || exit
    done' layers "$solutions" "$work" >"$work/log-layers" 2>&1 || { cat "$work/log-layers"; problem "the viewer failed in a window"; }
  check_image text "$work/layers--overlay.png" "$work/layers--no-overlay.png" 326 350 112 90 >"$work/layers.txt"
  covered=$(sed -nE 's/.*: ([0-9.]+)% of pixels differ.*/\1/p' "$work/layers.txt")
  [ "$covered" = 0.0 ] || problem "at 800x450 the overlay covers lab 6's layer 0 (${covered:-?}% of it changes)"
  if grep -q "drawing with the solutions code" "$work/log"; then
    grep -qF "U code: solutions" "$work/log" || problem "after U the key panel does not say the solutions' code draws"
  else
    grep -qF "U code" "$work/log" && problem "the key panel offers U in a build without the solutions' code"
  fi
fi
exit $fail
