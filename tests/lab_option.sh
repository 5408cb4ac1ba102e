#!/usr/bin/env bash
# shadowlab-grade --lab takes a number, a range or a list (1-2, 1,3-4), and
# several --lab add up; anything else is refused with exit 2 and says what
# it takes (it once graded lab 1 alone for "--lab 1-2").
#   lab_option.sh GRADER
set -uo pipefail
grader=$1
fail=0
labs_listed() { "$grader" --list "$@" | sed -n 's/^lab \([0-9]\) .*/\1/p' | sort -u | tr '\n' ' '; }
expect_labs() { # expect_labs "LABS" ARGS...
  local want=$1 got
  shift
  got=$(labs_listed "$@")
  [ "$got" = "$want" ] || { echo "lab_option: $* listed labs '$got', expected '$want'" >&2; fail=1; }
}
expect_labs "2 " --lab 2
expect_labs "1 2 " --lab 1-2
expect_labs "1 3 4 " --lab 1,3-4
expect_labs "1 3 4 " --lab '1, 3 - 4'
expect_labs "2 5 6 " --lab 2 --lab 5-6
for bad in 1-x 0 8 3-1 1, ,2 -1 1-2-3 two ''; do
  out=$("$grader" --list --lab "$bad" 2>&1)
  status=$?
  [ "$status" = 2 ] || { echo "lab_option: --lab '$bad' exited $status, not 2" >&2; fail=1; }
  grep -q -- "--lab '$bad'" <<<"$out" || { echo "lab_option: --lab '$bad' said: $out" >&2; fail=1; }
done
[ $fail = 0 ] && echo "lab_option: ranges, lists and mistakes as expected"
exit $fail
