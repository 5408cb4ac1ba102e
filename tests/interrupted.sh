#!/usr/bin/env bash
# interrupted.sh GRADER WORK_DIR [GRADER ARGS...]
# SIGINT in the middle of a grade (GRADER ARGS: runners whose lab code hangs): the runners are killed, what was graded is
# printed with a Score line marked incomplete, exit 2, no runner is left and no
# temporary file stays beside the report.
set -u
grader=$1 work=$2
shift 2
rm -rf "$work"; mkdir -p "$work"
fail=0
# This run's runners carry a tag in their environment (MESA_* reaches them).
tag="interrupted-$$-$RANDOM"
export MESA_SL_TEST_TAG=$tag
tagged() {
  local p
  for p in /proc/[0-9]*; do
    tr '\0' '\n' 2>/dev/null <"$p/environ" | grep -qx "MESA_SL_TEST_TAG=$tag" && echo "${p#/proc/}"
  done
}
# -j1, no time limit to speak of, and a lab whose code never returns: once a
# case has ended (--progress says so), the grader is certainly still grading.
"$grader" "$@" -j1 --timeout 600 --progress --report "$work/report" >"$work/out.txt" 2>"$work/err.txt" &
pid=$!
until grep -q '^shadowlab-grade: \[1/' "$work/err.txt" 2>/dev/null; do
  kill -0 $pid 2>/dev/null || break
  sleep 0.1
done
kill -INT $pid
wait $pid
status=$?
cat "$work/err.txt" "$work/out.txt"
problem() { echo "interrupted: $*" >&2; fail=1; }
[ "$status" = 2 ] || problem "exit status $status, expected 2"
tail -n 1 "$work/out.txt" | grep -qE "^Score: [0-9.]+/[0-9.]+( \(\+[0-9.]+ bonus\))? \(incomplete: the grader was stopped; [0-9]+ of [0-9]+ cases graded\)$" ||
  problem "the last line is not an incomplete Score line"
grep -qE "; [1-9][0-9]* of [0-9]+ cases graded" "$work/out.txt" || problem "no case was graded before the interruption"
grep -q "not graded: the grader was stopped" "$work/out.txt" || problem "cases not run are not marked"
grep -q '"complete":[[:space:]]*false' "$work/report/results.json" || problem "results.json does not say it is incomplete"
sleep 0.5
left=$(tagged)
[ -z "$left" ] || problem "runners are still alive: $left"
leftovers=$(find "$work" -name '.*' -type f)
[ -z "$leftovers" ] || problem "temporary files left: $leftovers"
exit $fail
