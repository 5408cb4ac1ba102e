#!/usr/bin/env bash
# bad_input.sh GRADER GRADER_SOURCE_DIR WORK_DIR [GRADER ARGS...]
# Staff-side problems are reported by name and exit 2, and the rest is still
# graded, ending with its Score line: a corrupt case file, a case naming a
# missing scene, a case name that is not a folder name, two cases with one
# name, a missing, a corrupt, a changed and a misfitting reference, and a
# labs folder that is not one.
set -u
grader=$1 src=$2 work=$3
shift 3
rm -rf "$work"; mkdir -p "$work"
cp -R "$src/cases" "$work/cases"
cp -R "$src/references" "$work/references"
printf '{"name": "corrupt", "lab": 1,\n  "scene": oops\n}\n' >"$work/cases/corrupt.json"
printf '{"name": "no_scene", "lab": 1, "scene": "no_such_scene", "checks": [{"kind": "fbo", "points": 1}]}\n' >"$work/cases/no_scene.json"
printf '{"name": "../escape", "lab": 1, "scene": "boxes_on_floor", "checks": [{"kind": "fbo", "points": 1}]}\n' >"$work/cases/bad_name.json"
sed 's/"title": "[^"]*"/"title": "a second case of that name"/' "$src/cases/lab1_depth_spot.json" >"$work/cases/zz_duplicate.json"
rm "$work/references/lab2_spot_manual/visibility.exr"
printf 'not an EXR file' >"$work/references/lab1_depth_boxes/depth_map.exr"
# changed: a valid image, but not the one the manifest records
cp "$src/references/lab3_contact/visibility.exr" "$work/references/lab3_front_culling/visibility.exr"
# misfitting: the case renders 256x256 (it now asks for 128x128)
sed 's/"lab": 2,/"lab": 2, "width": 128, "height": 128,/' "$src/cases/lab2_directional_hardware.json" \
  >"$work/cases/lab2_directional_hardware.json"
# labs 1-3 hold every planted fault (the case files of lab 1 and the references of labs 1-3):
# grading the other labs too would only repeat their clean cases
out=$("$grader" --cases "$work/cases" --references "$work/references" "$@" --lab 1-3 2>&1)
status=$?
echo "$out"
fail=0
want() { grep -qE -- "$1" <<<"$out" || { echo "bad_input: output does not match: $1" >&2; fail=1; }; }
[ "$status" = 2 ] || { echo "bad_input: exit status $status, expected 2" >&2; fail=1; }
want "PROBLEM .*corrupt\.json:2: invalid JSON"
want "PROBLEM .*no_scene\.json: scene .*no_such_scene\.json: cannot open scene file"
want "PROBLEM .*bad_name\.json: \"name\" must be letters, digits"
want "PROBLEM .*zz_duplicate\.json: the name \"lab1_depth_spot\" is taken by .*lab1_depth_spot\.json"
want "FAIL .*lab2_spot_manual / visibility"
want "reference missing: .*lab2_spot_manual/visibility\.exr"
want "FAIL .*lab1_depth_boxes / depth"
want "reference corrupt: .*lab1_depth_boxes/depth_map\.exr.*; reference changed since it was made: .*lab1_depth_boxes/depth_map\.exr"
want "reference changed since it was made: .*lab3_front_culling/visibility\.exr"
want "reference does not fit its case: .*lab2_directional_hardware/visibility\.exr is 256x256x1, the case makes 128x128x1"
# a state check whose picture has a broken reference is not graded either, and says why (a staff problem)
grep -A1 -E "FAIL .*lab1_depth_boxes / framebuffer" <<<"$out" |
  grep -qE "not graded: .*lab1_depth_boxes / depth, has a reference problem" ||
  { echo "bad_input: the framebuffer check does not say its picture's reference is broken" >&2; fail=1; }
want "PASS .*lab2_directional_manual / visibility"
tail -n 1 <<<"$out" | grep -qE "^Score: [0-9.]+/[0-9.]+( \(\+[0-9.]+ bonus\))?$" || { echo "bad_input: no Score line at the end" >&2; fail=1; }
# no manifest at all: nothing can be verified, said once per reference, exit 2
rm "$work/references/MANIFEST.json"
out=$("$grader" --cases "$src/cases" --references "$work/references" --lab 2 "$@" 2>&1)
status=$?
[ "$status" = 2 ] || { echo "bad_input: without a manifest, exit status $status, expected 2" >&2; fail=1; }
grep -qE "references cannot be verified: .*MANIFEST\.json" <<<"$out" || { echo "bad_input: a missing manifest is not named" >&2; fail=1; }
# a labs folder that is not one: exit 2 before anything runs
out=$("$grader" "$@" --labs-dir "$work" 2>&1)
status=$?
[ "$status" = 2 ] || { echo "bad_input: with a wrong --labs-dir, exit status $status, expected 2" >&2; fail=1; }
grep -qE -- "--labs-dir: .* is not a labs tree: .*lab1_depth_fbo/shaders is missing" <<<"$out" ||
  { echo "bad_input: a wrong --labs-dir is not named: $out" >&2; fail=1; }
# an unwritable report: exit 2, and the score is still printed
out=$("$grader" "$@" --lab 1 --report /proc/no-such-folder 2>&1)
status=$?
[ "$status" = 2 ] || { echo "bad_input: with an unwritable report, exit status $status, expected 2" >&2; fail=1; }
grep -qE "shadowlab-grade: .*/proc/no-such-folder.*cannot" <<<"$out" || { echo "bad_input: the unwritable report is not named" >&2; fail=1; }
tail -n 1 <<<"$out" | grep -qE "^Score: " || { echo "bad_input: no Score line after a report failure" >&2; fail=1; }
exit $fail
