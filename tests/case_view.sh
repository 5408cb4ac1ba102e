#!/usr/bin/env bash
# case_view.sh SOLUTIONS_VIEWER STUDENT_VIEWER WORK_DIR
# The viewer's --case renders what the grader renders: with the solutions it
# matches the reference (0% of pixels differ), with the stubs it does not and
# names the stub; in a window (Xvfb) as headless, it saves the three panels.
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
if command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1600x900x24" "$solutions" --case lab1_depth_boxes --frames 3 --screenshot "$work/window.png" ||
    problem "the window view failed"
  [ -s "$work/window.png" ] || problem "no window screenshot"
fi
out=$("$solutions" --headless --case lab3_probes 2>&1)
grep -q "has no picture to show" <<<"$out" || problem "a probe-only case is not explained"
exit $fail
