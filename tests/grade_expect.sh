#!/usr/bin/env bash
# Runs the grader and checks what it reports.
#   grade_expect.sh --exe GRADER --exit N [--loses LAB] [--full LAB]... [--expect REGEX]... [-- GRADER ARGS]
#   --exit N       the exit status the grader must return; --exit-in 0,1: one of these
#   --loses LAB    a check of lab LAB (not a bonus one) must fail
#   --full LAB     every check of lab LAB but bonus ones must pass
#   --expect RE    the output must match RE (grep -E); --reject RE: must not
set -u
exe="" want_exit="" loses=() full=() expect=() reject=()
while [ $# -gt 0 ]; do
  case "$1" in
    --exe) exe=$2; shift 2 ;;
    --exit) want_exit=$2; shift 2 ;;
    --exit-in) want_exit=$2; shift 2 ;;
    --loses) loses+=("$2"); shift 2 ;;
    --full) full+=("$2"); shift 2 ;;
    --expect) expect+=("$2"); shift 2 ;;
    --reject) reject+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "grade_expect: unknown argument $1" >&2; exit 2 ;;
  esac
done
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$exe" "$@" >"$out" 2>&1
status=$?
cat "$out"
fail=0
problem() { echo "grade_expect: $*" >&2; fail=1; }
[ -z "$want_exit" ] || [[ ",$want_exit," == *",$status,"* ]] || problem "exit status $status, expected $want_exit"
last=$(tail -n 1 "$out")
[[ "$last" =~ ^Score:\ [0-9.]+/[0-9.]+(\ \(\+[0-9.]+\ bonus\))?$ ]] || problem "the last line is not 'Score: X/Y': $last"
[ "$(grep -c '^Score:' "$out")" = 1 ] || problem "more than one line starts with 'Score:'"
# The FAIL lines of lab N's section that are not bonus checks.
lab_failures() { awk -v lab="$1" '/^Lab [0-9]+:/ {in_lab = ($2 == lab ":")} in_lab && /^  FAIL / && !/\(bonus\)$/' "$out"; }
lab_present() { grep -qE "^Lab $1:" "$out"; }
for lab in "${loses[@]+"${loses[@]}"}"; do
  lab_present "$lab" || { problem "no section for lab $lab"; continue; }
  [ -n "$(lab_failures "$lab")" ] || problem "lab $lab kept full marks, expected it to lose points"
done
for lab in "${full[@]+"${full[@]}"}"; do
  lab_present "$lab" || { problem "no section for lab $lab"; continue; }
  [ -z "$(lab_failures "$lab")" ] || problem "lab $lab lost points, expected full marks"
done
for re in "${expect[@]+"${expect[@]}"}"; do grep -qE -- "$re" "$out" || problem "output does not match: $re"; done
for re in "${reject[@]+"${reject[@]}"}"; do ! grep -qE -- "$re" "$out" || problem "output matches what it must not: $re"; done
exit $fail
