#!/usr/bin/env bash
# gradebook_staff_fault.sh GRADER WORK_DIR
# A grade that stopped on the staff's side is never the student's grade in the
# gradebook (shadowlab-grade --gradebook, as grade-batch writes it): a report
# with a PROBLEM (its runners could not start) and exit status 2, and a grade
# that left no report, are "staff problem" with no scores; an
# honest report beside them keeps its row. gradebook.json lists both staff
# problems with their causes, and the class report names them and leaves them
# out of what the class got wrong.
set -u
grader=$1 work=$2
rm -rf "$work"
mkdir -p "$work/cannot_fork/report" "$work/no_report" "$work/honest/report"
echo 2 >"$work/cannot_fork/status"
cat >"$work/cannot_fork/report/results.json" <<'JSON'
{"score": 5, "max_score": 14, "bonus": 0, "complete": true, "built": true, "options": "", "labs": "other",
 "lab_scores": [{"lab": 1, "score": 5, "max_score": 14}],
 "problems": ["could not grade lab1_depth_spot: could not start the runner: cannot start a process: Resource temporarily unavailable"]}
JSON
echo 1 >"$work/no_report/status"
echo 1 >"$work/honest/status"
cat >"$work/honest/report/results.json" <<'JSON'
{"score": 9, "max_score": 14, "bonus": 0, "complete": true, "built": true, "options": "", "labs": "other",
 "lab_scores": [{"lab": 1, "score": 9, "max_score": 14}], "problems": []}
JSON
"$grader" --gradebook "$work" || { echo "gradebook_staff_fault: --gradebook failed" >&2; exit 1; }
csv="$work/gradebook.csv"
cat "$csv"
fail=0
problem() { echo "gradebook_staff_fault: $*" >&2; fail=1; }
row() { grep "^$1," "$csv"; }
# submission,student,student_id,late,status,lab1,bonus,total,max,...
[[ "$(row cannot_fork)" == 'cannot_fork,,,,staff problem,,,,,,,,'*'could not start the runner'* ]] ||
  problem "the grade whose runners could not start is not 'staff problem' without scores"
[[ "$(row no_report)" == 'no_report,,,,staff problem,,,,,,,,'* ]] ||
  problem "the grade with no report is not 'staff problem' without scores"
[[ "$(row honest)" == 'honest,,,,graded,9,0,9,14,'* ]] || problem "the honest grade lost its row"
json="$work/gradebook.json"
[ "$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["staff_problems"]))' "$json")" = 2 ] &&
  grep -q '"submission":.*"cannot_fork"' "$json" &&
  grep -q '"cause":.*"no report (grade exit status 1)' "$json" ||
  problem "gradebook.json does not list the two staff problems with their causes: $(cat "$json")"
grep -q '^staff problem,,cannot_fork,could not grade lab1_depth_spot' "$work/class-report.csv" &&
  grep -q '^staff problem,,no_report,' "$work/class-report.csv" && grep -q '<h2>Staff problems</h2>' "$work/class-report.html" ||
  problem "the class report does not name the staff problems"
! grep -q 'Resource temporarily' <(grep -E '^(mistake|follows),' "$work/class-report.csv") ||
  problem "a staff problem is counted among the class's mistakes"
exit $fail
