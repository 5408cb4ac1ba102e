#!/usr/bin/env bash
# bad_input.sh GRADER GRADER_SOURCE_DIR WORK_DIR
# A corrupt case file, a case naming a missing scene, a missing and a corrupt
# reference: each is reported by name, the other cases are still graded, the
# report ends with its Score line, and the exit status is 2.
set -u
grader=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
cp -R "$src/cases" "$work/cases"
cp -R "$src/references" "$work/references"
printf '{"name": "corrupt", "lab": 1,\n  "scene": oops\n}\n' >"$work/cases/corrupt.json"
printf '{"name": "no_scene", "lab": 1, "scene": "no_such_scene", "checks": [{"kind": "fbo", "points": 1}]}\n' >"$work/cases/no_scene.json"
rm "$work/references/lab2_spot_manual/visibility.png"
printf 'not an EXR file' >"$work/references/lab1_depth_boxes/depth_map.exr"
out=$("$grader" --cases "$work/cases" --references "$work/references" 2>&1)
status=$?
echo "$out"
fail=0
want() { grep -qE -- "$1" <<<"$out" || { echo "bad_input: output does not match: $1" >&2; fail=1; }; }
[ "$status" = 2 ] || { echo "bad_input: exit status $status, expected 2" >&2; fail=1; }
want "PROBLEM .*corrupt\.json:2: invalid JSON"
want "PROBLEM .*no_scene\.json: scene .*no_such_scene\.json: cannot open scene file"
want "FAIL .*lab2_spot_manual / visibility"
want "reference missing: .*lab2_spot_manual/visibility\.png"
want "FAIL .*lab1_depth_boxes / depth"
want "reference corrupt: .*lab1_depth_boxes/depth_map\.exr"
want "PASS .*lab1_depth_boxes / framebuffer"
want "PASS .*lab2_directional_manual / visibility"
tail -n 1 <<<"$out" | grep -qE "^Score: [0-9.]+/[0-9.]+$" || { echo "bad_input: no Score line at the end" >&2; fail=1; }
exit $fail
