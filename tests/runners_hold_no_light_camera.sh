#!/usr/bin/env bash
# runners_hold_no_light_camera.sh NM BUILD_DIR
# Lab 1's light camera for any light (solutions/framework/sl_light_camera.c,
# sl_light_camera_compute) is lab 2's answer: the grader computes it and sends
# it in a lab 1 case's job, and no runner may hold it, or lab 2's code linked
# beside it could call it. Every runner of the build (bin/, bin/solutions/, the
# per-lab ones, and the tests' runners where they are built) must not define it
# (lab code may name it, as tests/attacks/framework_light_camera does by a weak
# reference: it stays undefined), nor may the submission kit a submission's
# runners are linked from (a submission naming it would pull it from an archive).
# The grader must define it: that shows nm reads these files (not stripped).
set -u
nm=$1 build=$2
symbol=sl_light_camera_compute
fail=0
problem() { echo "runners_hold_no_light_camera: $*" >&2; fail=1; }
# the symbol's definitions in `nm -P -A` (file and member, name, type; U, w and v are references), for
# every file given at once
symbols() { [ $# -gt 0 ] || return 0; "$nm" -P -A "$@" 2>/dev/null | awk -v s="$symbol" '$2 == s && $3 !~ /^[Uwv]$/'; }

grader="$build/bin/shadowlab-grade"
[ -x "$grader" ] || { problem "no grader at $grader (build the default targets first)"; exit 1; }
[ -x "$build/bin/shadowlab-runner" ] || problem "no runner at $build/bin/shadowlab-runner (build the default targets first)"
symbols "$grader" | grep -q " T " || problem "nm finds no $symbol in the grader, which computes lab 1's light cameras"

mapfile -d '' runners < <(find "$build/bin" "$build/tests/runners" -type f -name 'shadowlab-runner*' -print0 2>/dev/null)
found=$(symbols "${runners[@]}")
[ -z "$found" ] || problem "runners hold lab 2's answer:"$'\n'"$found"
mapfile -d '' kit < <(find "$build/submission-kit" -type f \( -name '*.a' -o -name '*.o' \) -print0 2>/dev/null)
found=$(symbols "${kit[@]}")
[ -z "$found" ] || problem "the submission kit defines lab 2's answer:"$'\n'"$found"
echo "${#runners[@]} runners and ${#kit[@]} files of the submission kit checked"
exit $fail
