#!/usr/bin/env bash
# measure-grade-batch.sh [BUILD_DIR] [-j N]
# measure-grade-batch.sh --lms-class [BUILD_DIR]
# The README's "Grading at scale" figures: grade-batch on 20 submissions made
# from the solutions and 19 wrong variants (tests/make_submissions.sh), every
# lab's public cases, -j 2 by default; prints the wall time and the CPU time of
# every process it started (user + sys), in all and per submission, and the
# load average before and after (the wall time follows it; the CPU time hardly).
# --lms-class: Canvas's download of a twelve-student class as it comes
# (tests/make_lms_class.sh: complete, partial, one mistake, macOS and Windows
# shapes, tar.gz, a text entry, a build folder, a compile error, the wrong file,
# an empty zip) graded at -j 2, then again with hidden cases, then one empty
# upload and one of the handout's stubs on their own.
set -euo pipefail
cd "$(dirname "$0")/.."
lms_class=false
[ "${1:-}" != --lms-class ] || { lms_class=true; shift; }
build=${1:-build}
[ $# -lt 1 ] || shift
work=$(mktemp -d /tmp/shadowlab-measure-XXXXXX)
trap 'rm -rf "$work"' EXIT
TIMEFORMAT='%R %U %S'
# timed LABEL N COMMAND...: runs COMMAND, prints its wall and CPU time (every process it started)
timed() {
  local label=$1 n=$2 times
  shift 2
  times=$( { time "$@" >"$work/log" 2>&1; } 2>&1 ) || true
  read -r wall user sys <<<"$(tail -n 1 <<<"$times")"
  awk -v l="$label" -v w="$wall" -v u="$user" -v s="$sys" -v n="$n" -v load="$(cut -d' ' -f1 /proc/loadavg)" 'BEGIN {
    printf "%s: %.1f s wall, %.1f s CPU (user %.1f + sys %.1f)", l, w, u + s, u, s
    if (n > 1) printf "; per submission %.1f s wall, %.1f s CPU", w / n, (u + s) / n
    printf " (load average after: %s)\n", load }'
}
if $lms_class; then
  [ -d "$build/stubs/labs" ] || { echo "measure-grade-batch: no $build/stubs/labs (build the project first)" >&2; exit 2; }
  bash tests/make_lms_class.sh . "$build/stubs/labs" "$work/downloads" >/dev/null
  timed "Canvas class of 12, -j 2" 12 scripts/grade-batch -j 2 --build "$build" --out "$work/public" "$work/downloads/canvas-v1.zip"
  grep -E "^grade-batch: [0-9]+ (graded|submissions)" "$work/log" | tail -n 2 || true
  timed "the same, hidden cases (--hidden --seed 4711)" 12 scripts/grade-batch -j 2 --build "$build" --out "$work/hidden" \
    "$work/downloads/canvas-v1.zip" -- --hidden --seed 4711
  timed "the same download again, nothing changed" 12 scripts/grade-batch -j 2 --build "$build" --out "$work/public" \
    "$work/downloads/canvas-v1.zip"
  mkdir -p "$work/empty" "$work/stubs"
  # a complete upload beside them: what the two save
  cp -R "$build/stubs/labs" "$work/stubs/"
  timed "one empty upload" 1 scripts/grade-submission --build "$build" "$work/empty"
  timed "one upload of the handout's stubs" 1 scripts/grade-submission --build "$build" "$work/stubs"
  mkdir -p "$work/complete/labs"
  cp -R solutions/. "$work/complete/labs/"
  timed "one complete upload (the solutions)" 1 scripts/grade-submission --build "$build" "$work/complete"
  exit 0
fi
submissions=(solutions lab1_no_viewport lab1_no_clear lab2_inverted_compare lab2_no_bias lab2_wrong_order
             lab2_fov_not_doubled lab3_slope_sin lab3_no_polygon_offset lab3_cull_back_faces
             lab4_grid_radius_ignored lab4_pcss_inverted lab4_not_normalised lab5_depth_not_squared
             lab5_one_blur_direction lab6_no_snapping lab6_lambda_ignored lab7_up_vector_y lab7_fov_45 lab7_no_bias)
bash tests/make_submissions.sh . "$work/submissions" "${submissions[@]}"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
TIMEFORMAT='%R %U %S'
times=$( { time scripts/grade-batch -j 2 "$@" --build "$build" --out "$work/grades" "$work/submissions" >"$work/log" 2>&1; } 2>&1 ) ||
  { cat "$work/log"; echo "measure-grade-batch: grade-batch failed" >&2; exit 1; }
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
read -r wall user sys <<<"$times"
n=${#submissions[@]}
awk -v w="$wall" -v u="$user" -v s="$sys" -v n="$n" 'BEGIN {
  printf "grade-batch on %d submissions: %.0f s wall, %.0f s CPU (user %.0f + sys %.0f): %.0f s wall and %.0f s CPU per submission\n",
         n, w, u + s, u, s, w / n, (u + s) / n }'
