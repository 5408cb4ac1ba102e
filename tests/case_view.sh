#!/usr/bin/env bash
# case_view.sh SOLUTIONS_VIEWER STUDENT_VIEWER WORK_DIR
# The viewer's --case renders what the grader renders: with the solutions it
# matches the reference (0% of pixels differ), with the stubs it does not and
# names the stub; in a window (Xvfb) as headless, it saves the three panels;
# labs 5-7's moments, cascade index and cube faces likewise (--check).
set -u
solutions=$1 student=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "case_view: $*" >&2; fail=1; }
out=$("$solutions" --headless --case lab4_pcss --screenshot "$work/solutions.png" 2>&1)
echo "$out"
grep -q "lab4_pcss / visibility: 0.00% of pixels differ" <<<"$out" || problem "the solutions' render of lab4_pcss is not the reference"
out=$("$student" --headless --case lab2_spot_manual --screenshot "$work/student.png" 2>&1)
echo "$out"
grep -qE "lab2_spot_manual / visibility: [1-9][0-9.]*% of pixels differ.*not implemented: lab2_light_view" <<<"$out" ||
  problem "the stubs' render of lab2_spot_manual is not reported as differing, with the stub named"
for f in solutions student; do [ -s "$work/$f.png" ] || problem "no screenshot $f.png"; done
# Labs 5-7's own pictures (--check, key C): moments, cascade index, a cube face, as the runner takes them.
for spec in lab5_moments:moments lab5_moments:moments_blurred lab6_field:cascade_index lab7_cube_faces:face_ny; do
  c=${spec%%:*} k=${spec#*:}
  out=$("$solutions" --headless --case "$c" --check "$k" --screenshot "$work/$c-$k.png" 2>&1)
  grep -q "$c / $k: 0.00% of pixels differ" <<<"$out" || { echo "$out"; problem "the solutions' $c / $k is not the reference"; }
  [ -s "$work/$c-$k.png" ] || problem "no screenshot $c-$k.png"
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
if command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1600x900x24" "$solutions" --case lab1_depth_boxes --frames 3 --screenshot "$work/window.png" ||
    problem "the window view failed"
  [ -s "$work/window.png" ] || problem "no window screenshot"
fi
out=$("$solutions" --headless --case lab3_probes 2>&1)
grep -q "has no picture to show" <<<"$out" || problem "a probe-only case is not explained"
# Lab 6's flicker: the path's frames, what changed along them (the solutions: next to nothing).
out=$("$solutions" --headless --case lab6_stability_turn --screenshot "$work/flicker.png" 2>&1)
grep -qE "lab6_stability_turn / flicker: along the camera path 0\.0[0-4][0-9]% of pixels change from one frame to the next in yours, 0\.[0-9]+% in the reference" <<<"$out" ||
  { echo "$out"; problem "the solutions' flicker view of lab6_stability_turn is not still"; }
exit $fail
