#!/usr/bin/env bash
# measure-grade-batch.sh [BUILD_DIR] [-j N]
# The README's "Grading at scale" figure: grade-batch on 20 submissions made
# from the solutions and 19 wrong variants (tests/make_submissions.sh), every
# lab's public cases, -j 2 by default; prints the wall time and the CPU time of
# every process it started (user + sys), in all and per submission, and the
# load average before and after (the wall time follows it; the CPU time hardly).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ $# -lt 1 ] || shift
work=$(mktemp -d /tmp/shadowlab-measure-XXXXXX)
trap 'rm -rf "$work"' EXIT
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
