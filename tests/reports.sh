#!/usr/bin/env bash
# reports.sh GRADER WORK_DIR [GRADER ARGS...]
# A grade with failing checks writes every report: results.json, report.html,
# student/reference/diff images of the failed image checks, JUnit XML, and
# Gradescope and PrairieLearn results whose scores agree with the Score line,
# each read by a strict reader (check_reports.py). No temporary file is left beside them.
set -u
grader=$1 work=$2
shift 2
rm -rf "$work"; mkdir -p "$work"
out=$("$grader" "$@" --lab 2 --report "$work/report" --junit "$work/junit.xml" --gradescope "$work/gradescope.json" \
      --prairielearn "$work/prairielearn.json" 2>&1)
status=$?
echo "$out"
printf '%s\n' "$out" >"$work/out.txt"
fail=0
problem() { echo "reports: $*" >&2; fail=1; }
[ "$status" = 1 ] || problem "exit status $status, expected 1"
score=$(tail -n 1 <<<"$out" | sed -E 's/^Score: ([0-9.]+)\/([0-9.]+)$/\1/')
for f in report/results.json report/report.html junit.xml gradescope.json prairielearn.json; do
  [ -s "$work/$f" ] || problem "$f was not written"
done
for role in student reference diff; do
  [ -s "$work/report/images/lab2_directional_manual.visibility.$role.png" ] || problem "no $role image of the failed check"
  grep -q "images/lab2_directional_manual.visibility.$role.png" "$work/report/report.html" || problem "report.html does not show the $role image"
done
grep -q '"passed":[[:space:]]*false' "$work/report/results.json" || problem "results.json has no failed check"
grep -q '"sandbox":' "$work/report/results.json" || problem "results.json does not say which sandbox the runners had"
grep -qE '"renderer":[[:space:]]*"[^"]+"' "$work/report/results.json" || problem "results.json does not name the renderer"
grep -qE "\"score\":[[:space:]]*$score([,.}[:space:]]|$)" "$work/gradescope.json" || problem "gradescope.json's score is not $score"
grep -q '<failure message=' "$work/junit.xml" || problem "junit.xml has no failure"
grep -qE 'comparison (is )?inverted' "$work/junit.xml" || problem "junit.xml lacks the failure's reason"
grep -q '"gradable":[[:space:]]*true' "$work/prairielearn.json" || problem "prairielearn.json is not gradable"
python3 "$(dirname "$0")/check_reports.py" --text "$work/out.txt" --json "$work/report/results.json" \
  --json "$work/gradescope.json" --json "$work/prairielearn.json" --junit "$work/junit.xml" \
  --html "$work/report/report.html" || problem "a report a strict reader refuses (above)"
leftovers=$(find "$work" -name '.*' -type f)
[ -z "$leftovers" ] || problem "temporary files left: $leftovers"
exit $fail
