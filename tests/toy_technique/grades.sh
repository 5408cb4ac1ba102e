#!/usr/bin/env bash
# The test technique graded by the real grader (technique.toy_lab0_grades): its one case, lab 0, run
# through the sandboxed runner path of labs 1-7. The correct build's runners render the references
# (--update-references --runners) and then get full marks; the wrong build (toy_visibility() answers
# 0.25) loses the case, its failing checks named.
#   grades.sh GRADER TOY_DIR CORRECT_RUNNERS WRONG_RUNNERS OUT
set -uo pipefail
grader=$1 toy=$2 correct=$3 wrong=$4 out=$5
rm -rf "$out" && mkdir -p "$out"
cd "$toy" || exit 1 # the case names its scene, plane.json, beside it
common=(--cases "$toy/cases" --references "$out/references" --technique-dir "$toy" -j 1)
fail() { echo "toy grades: FAIL: $*"; exit 1; }

"$grader" --update-references --runners "$correct" "${common[@]}" > "$out/update.txt" 2>&1 ||
  { cat "$out/update.txt"; fail "the correct build did not render the references"; }
"$grader" --runners "$correct" "${common[@]}" --report "$out/correct" --junit "$out/correct.xml" > "$out/correct.txt" 2>&1
status=$?
cat "$out/correct.txt"
[ $status -eq 0 ] || fail "the correct build exits $status, not 0 (full marks)"
grep -qE '^Score: 2/2' "$out/correct.txt" || fail "the correct build does not score 2/2"
python3 - "$out/correct/results.json" <<'PY' || fail "results.json does not list lab 0's score"
import json, sys
labs = json.load(open(sys.argv[1]))["lab_scores"]
assert any(l["lab"] == 0 and l["score"] == 2 and l["max_score"] == 2 for l in labs), labs
PY
grep -q '<testsuite name="lab0 the build.s added technique" tests="2" failures="0" skipped="0">' "$out/correct.xml" ||
  fail "the JUnit report has no lab 0 suite"
echo "toy grades: ok: the correct build gets full marks, in the text, JSON and JUnit reports"

"$grader" --runners "$wrong" "${common[@]}" > "$out/wrong.txt" 2>&1
status=$?
cat "$out/wrong.txt"
[ $status -eq 1 ] || fail "the wrong build exits $status, not 1 (points lost)"
grep -qE '^Score: 0/2' "$out/wrong.txt" || fail "the wrong build does not score 0/2"
grep -qE 'FAIL.*image' "$out/wrong.txt" || fail "the report does not name the failing image check"
grep -qE 'FAIL.*visibility' "$out/wrong.txt" || fail "the report does not name the failing probe check"
echo "toy grades: ok: the wrong build loses the case, its failing checks named"
