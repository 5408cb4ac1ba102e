#!/usr/bin/env bash
# gradebook_staff_fault.sh GRADER WORK_DIR
# A grade that stopped on the staff's side is never the student's grade in the
# gradebook (shadowlab-grade --gradebook, as grade-batch writes it): a report
# with a PROBLEM (its runners could not start) and exit status 2, and a grade
# that left no report, are "not graded (staff fault)" with no scores; an
# honest report beside them keeps its row.
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
[[ "$(row cannot_fork)" == 'cannot_fork,,,,not graded (staff fault),,,,,,,'*'could not start the runner'* ]] ||
  problem "the grade whose runners could not start is not 'not graded (staff fault)' without scores"
[[ "$(row no_report)" == 'no_report,,,,not graded (staff fault),,,,,,,'* ]] ||
  problem "the grade with no report is not 'not graded (staff fault)' without scores"
[[ "$(row honest)" == 'honest,,,,graded,9,0,9,14,'* ]] || problem "the honest grade lost its row"
exit $fail
