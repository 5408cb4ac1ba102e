#!/usr/bin/env bash
# case_view.sh SOLUTIONS_VIEWER STUDENT_VIEWER WORK_DIR [IMAGE_CHECK]
# The viewer's --case renders what the grader renders: with the solutions it
# matches the reference (0% of pixels differ), with the stubs it does not and
# names the stub; in a window (Xvfb) as headless, it saves the three panels;
# labs 5-7's moments, cascade index and cube faces likewise (--check). Each
# panel is labelled, depths and distances are stretched to their own range
# (printed), and the summary states the check's criterion from the case.
set -u
solutions=$1 student=$2 work=$3 check=${4:-}
[ -n "$check" ] || check=$(dirname "$solutions")/image_check
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "case_view: $*" >&2; fail=1; }
out=$("$solutions" --headless --case lab4_pcss --screenshot "$work/solutions.png" 2>&1)
echo "$out"
grep -q "lab4_pcss / visibility: 0.00% of pixels differ" <<<"$out" || problem "the solutions' render of lab4_pcss is not the reference"
out=$("$student" --headless --case lab2_spot_manual --screenshot "$work/student.png" 2>&1)
echo "$out"
# A visibility check's criterion: the case's threshold, the compare's neighbourhood, the lost-shadow rule.
grep -qE "criterion: a pixel differs when no pixel of the other picture's 3x3 neighbourhood is within 0\.05 of it \(both ways\); no NaN.*at most 50% of the reference's shadow lost, where it has 25 or more pixels \(here [0-9.]+% of [0-9]+ lost\)" <<<"$out" ||
  problem "lab2_spot_manual's criterion is not stated with the lost-shadow rule"
grep -qE "lab2_spot_manual / visibility: [1-9][0-9.]*% of pixels differ.*not implemented: lab2_light_view" <<<"$out" ||
  problem "the stubs' render of lab2_spot_manual is not reported as differing, with the stub named"
for f in solutions student; do [ -s "$work/$f.png" ] || problem "no screenshot $f.png"; done
# Labs 5-7's own pictures (--check, key C): moments, cascade index, a cube face, as the runner takes them.
for spec in lab5_moments:moments lab5_moments:moments_blurred lab6_field:cascade_index lab7_cube_faces:face_ny; do
  c=${spec%%:*} k=${spec#*:}
  out=$("$solutions" --headless --case "$c" --check "$k" --screenshot "$work/$c-$k.png" 2>&1)
  echo "$out" >"$work/$k.log"
  grep -q "$c / $k: 0.00% of pixels differ" <<<"$out" || { echo "$out"; problem "the solutions' $c / $k is not the reference"; }
  [ -s "$work/$c-$k.png" ] || problem "no screenshot $c-$k.png"
  case $k in
    moments) # judged per channel, as the grader does
      grep -qE "moments: 0\.00% of pixels differ \(depth 0\.00%, depth squared 0\.00%; allowed [0-9.]+% each\): passes" <<<"$out" &&
        grep -qE "criterion: .*, per channel \(both ways\)" <<<"$out" || { echo "$out"; problem "the moments are not judged per channel"; } ;;
    face_ny) # the case's threshold and mean bound; each picture's range
      for line in "criterion: a pixel differs when no pixel of the other picture's 3x3 neighbourhood is within 0\.002 of it \(both ways\); no NaN; mean difference at most 0\.0005" \
                  "each picture stretched black to white over its own range: yours (0\.[0-9]{4}) - (0\.[0-9]{4}), the reference \1 - \2"; do
        grep -qE "$line" <<<"$out" || { echo "$out"; problem "$c / $k does not say: $line"; }
      done ;;
  esac
done
out=$("$student" --headless --case lab6_field --check cascade_index 2>&1)
grep -qE "lab6_field / cascade_index: [1-9][0-9.]*% of pixels differ.*not implemented: lab6_" <<<"$out" ||
  { echo "$out"; problem "the stubs' cascade index of lab6_field is not reported as differing, with the stub named"; }
out=$("$student" --headless --case lab7_cube_faces --check face_px 2>&1)
grep -qE "lab7_cube_faces / face_px: [1-9][0-9.]*% of pixels differ.*not implemented: lab7_" <<<"$out" ||
  { echo "$out"; problem "the stubs' cube face is not reported as differing, with the stub named"; }
out=$("$solutions" --headless --case lab5_moments --check visibility 2>&1)
grep -q "has no check with a picture named visibility (it has: moments, moments_blurred)" <<<"$out" ||
  { echo "$out"; problem "an unknown --check is not explained with the case's checks"; }
if command -v Xvfb >/dev/null; then
  bash "$(dirname "$0")/with_display.sh" -s "-screen 0 1600x900x24" "$solutions" --case lab1_depth_boxes --frames 3 --screenshot "$work/window.png" ||
    problem "the window view failed"
  [ -s "$work/window.png" ] || problem "no window screenshot"
fi
# A penumbra check says the grade is not this pixel count.
out=$("$solutions" --headless --case lab4_pcss --check contact_hardening 2>&1)
grep -qE "for the eye, not the grade" <<<"$out" && grep -qE "criterion: the penumbra widths along the case's [0-9] probe lines" <<<"$out" ||
  { echo "$out"; problem "the penumbra check does not say what the grader measures"; }
# The pictures: labels on a dark backing at each panel's top left; a cube face stretched, no longer nearly black.
face=$work/lab7_cube_faces-face_ny.png
if [ ! -x "$check" ]; then
  problem "no image_check beside the viewer ($check): build it"
elif [ -s "$face" ]; then
  source "$(dirname "$0")/image_checks.sh"
  start_image_check "$check"
  # 1536 wide: three 512-px panels; the labels' text is at scale 2 (12 px a character)
  for x in 8 520 1032; do check_image label "$face" $x 8 60 18 || problem "no label on the panel at x=$x"; done
  check_image label "$face" 8 40 140 18 || problem "no range under the label of yours"
  mean=$(check_image mean "$face" 0 80 512 420)
  # unstretched, no pixel could be brighter than the top of its range: the mean grey is above it
  top=$(sed -nE 's/^shadowlab: each picture stretched .*: yours [0-9.]+ - ([0-9.]+),.*/\1/p' "$work/face_ny.log")
  echo "case_view: face_ny, yours: mean grey $mean, values up to $top"
  awk -v m="$mean" -v t="$top" 'BEGIN { exit !(t != "" && m > t + 0.05) }' || problem "the cube face is not stretched (mean $mean)"
fi
out=$("$solutions" --headless --case lab3_probes 2>&1)
grep -q "has no picture to show" <<<"$out" || problem "a probe-only case is not explained"
# Lab 6's flicker: the path's frames, what changed along them (the solutions: next to nothing),
# measured as the grader measures it: of the world-fixed receivers, per frame, against the case's bound.
out=$("$solutions" --headless --case lab6_stability_turn --screenshot "$work/flicker.png" 2>&1)
grep -qE "lab6_stability_turn / flicker: 0\.0[0-4][0-9]% of the world-fixed receiver pixels change per frame \(allowed [0-9.]+%, the reference 0\.[0-9]+%\): passes" <<<"$out" ||
  { echo "$out"; problem "the solutions' flicker view of lab6_stability_turn is not still, or not the grader's measure"; }
allowed=$(sed -nE 's/.*"kind": "flicker".*"threshold": ([0-9.e-]+).*/\1/p' "$(dirname "$0")/../grader/cases/lab6_stability_turn.json")
grep -qE "allowed $(awk -v t="$allowed" 'BEGIN { printf "%.4g", 100 * t }')%," <<<"$out" ||
  { echo "$out"; problem "the flicker view does not allow the case's threshold ($allowed)"; }
grep -qE "criterion: at most [0-9.]+% of the receivers \(surfaces facing the light\) change per frame" <<<"$out" ||
  { echo "$out"; problem "the flicker view's criterion is not the grader's"; }
# The stubs' frames lose the reference's shadows: no flicker, and still a fail.
stub_out=$("$student" --headless --case lab6_stability_move --screenshot "$work/flicker-stubs.png" 2>&1)
grep -qE "lab6_stability_move / flicker: .*: fails; not implemented: lab6_" <<<"$stub_out" ||
  { echo "$stub_out"; problem "the stubs' flicker view does not fail"; }
# Every summary and criterion fits the band under its panels (the longest: flicker's, with a stub named).
grep -h "cut short" "$work"/*.log <(echo "$out") <(echo "$stub_out") && problem "a summary or criterion is cut short under the panels"
exit $fail
