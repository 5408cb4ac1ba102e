#!/usr/bin/env bash
# viewer_split.sh VIEWER SOLUTIONS_VIEWER IMAGE_CHECK WORK_DIR
# --split A,B: at 1280x720, each half of the split frame is the single view's picture of its setting over
# that half (same camera, light and options), pixel for pixel but for the labels along the bottom and the
# divider in the middle, which must be there: two labs (2,4), two of lab 4's filters (4:grid,4:pcss) and,
# where VIEWER carries the solutions beside a student build, the student's code and the solutions'. The
# labels name what each half draws; key Y shows the left half's setting alone; a --split that sets nothing
# apart, or names what is not a setting, is refused.
set -u
viewer=$1 solutions=$2 check=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_split: $*" >&2; fail=1; }
source "$(dirname "$0")/image_checks.sh"
start_image_check "$check"
source "$(dirname "$0")/../scripts/viewer-batch.sh"

# The labels sit in the bottom tenth of the frame; the divider is 2 pixels wide at 720 lines.
band=72 divider=1
common=(--headless --size 1280x720 --frames 1)
names=()
run() { local name=$1; shift; viewer_batch_add "$name" "${common[@]}" "$@"; names+=("$name"); }
run labs --split 2,4 --screenshot "$work/labs.png"
run lab2 --lab 2 --screenshot "$work/lab2.png"
run lab4 --lab 4 --screenshot "$work/lab4.png"
run filters --split 4:grid,4:pcss --screenshot "$work/filters.png"
run grid --lab 4 --filter grid --screenshot "$work/grid.png"
run pcss --lab 4 --filter pcss --screenshot "$work/pcss.png"
run key-y --split 2,4 --keys Y --screenshot "$work/key-y.png"
run words --split 2,4 --overlay
viewer_batch_run "$solutions" "$work"
for name in "${names[@]}"; do
  viewer_batch_status "$work" "$name" || { cat "$work/$name.log"; problem "failed: $name"; }
done

halves() { # SPLIT LEFT RIGHT WHAT
  check_image halves "$work/$1.png" "$work/$2.png" "$work/$3.png" "$band" "$divider" ||
    problem "$4: the halves are not the single pictures of $2 and $3 (or lack labels or the divider)"
}
halves labs lab2 lab4 "--split 2,4"
halves filters grid pcss "--split 4:grid,4:pcss"

changed=$(check_image changed "$work/key-y.png" "$work/lab2.png")
[ "$changed" = 0.000 ] || problem "key Y does not show the left half's setting alone (${changed:-?}% of the pixels differ from --lab 2)"
grep -qxF "[label] lab 2's hard shadows" "$work/words.log" || problem "the left half's label does not say lab 2's hard shadows"
grep -qxF "[label] lab 4's PCF grid 3x3" "$work/words.log" || problem "the right half's label does not say lab 4's PCF grid 3x3"

# Student vs solutions, in a build that carries both.
if "$viewer" --help | grep -q -- "--solutions"; then
  run code --split 4:student,4:solutions --screenshot "$work/code.png"
  run student --lab 4 --screenshot "$work/student.png"
  run solution --lab 4 --solutions --screenshot "$work/solution.png"
  viewer_batch_run "$viewer" "$work"
  for name in code student solution; do
    viewer_batch_status "$work" "$name" || { cat "$work/$name.log"; problem "failed: $name"; }
  done
  halves code student solution "--split 4:student,4:solutions"
fi

# Refused, with a reason and exit status 2.
for bad in 2,2 2 2,4,5 2,nonsense 4:pcss,; do
  "$solutions" --headless --frames 1 --split "$bad" >"$work/bad.log" 2>&1
  status=$?
  [ "$status" = 2 ] && grep -q "^shadowlab: --split" "$work/bad.log" ||
    problem "--split $bad: exit $status, not refused with a reason: $(cat "$work/bad.log")"
done

[ "$fail" = 0 ] && echo "viewer_split: ok"
exit "$fail"
