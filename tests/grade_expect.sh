#!/usr/bin/env bash
# Runs the grader and checks what it reports.
#   grade_expect.sh --exe GRADER --exit N [--loses LAB] [--full LAB]... [--expect REGEX]... [-- GRADER ARGS]
#   --exit N       the exit status the grader must return; --exit-in 0,1: one of these
#   --loses LAB    a check of lab LAB (not a bonus one) must fail
#   --full LAB     every check of lab LAB but bonus ones must pass
#   --expect RE    the output must match RE (grep -E); --reject RE: must not
#   --expect-readme SPEC  each "readme:" line of the variant SPEC, a message as a lab README's
#                  table writes it, must be in the output ("…" and the spaces around it stand for any text, a trailing one for nothing, a number
#                  or N, M, X, K, LINE, COL for any number)
#   --expect-readme-rows FILE  each "N: MESSAGE" line of FILE, a row of lab N's README table, must
#                  be in lab N's section of the output (matched as for --expect-readme)
set -u
exe="" want_exit="" loses=() full=() expect=() reject=() readme_specs=() readme_rows=()
while [ $# -gt 0 ]; do
  case "$1" in
    --exe) exe=$2; shift 2 ;;
    --exit) want_exit=$2; shift 2 ;;
    --exit-in) want_exit=$2; shift 2 ;;
    --loses) loses+=("$2"); shift 2 ;;
    --full) full+=("$2"); shift 2 ;;
    --expect) expect+=("$2"); shift 2 ;;
    --reject) reject+=("$2"); shift 2 ;;
    --expect-readme) readme_specs+=("$2"); shift 2 ;;
    --expect-readme-rows) readme_rows+=("$2"); shift 2 ;;
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
# A README row's message as a regular expression: its example numbers and placeholders match any number.
readme_regex() {
  printf '%s' "$1" | perl -CSD -Mutf8 -pe '
    s/ ?[:;,—]? ?…$//;
    s/WxH/\x01NUMx\x01NUM/g;
    s/(?<![A-Za-z_0-9.])[0-9]+(?:\.[0-9]+)?(?![A-Za-z_0-9])/\x01NUM/g;
    s/(?<![A-Za-z_+\-])(?:N|M|X|K|LINE|COL)(?![A-Za-z_(]|\.[A-Za-z])/\x01NUM/g;
    s/([\\.^\$*+?()\[\]{}|])/\\$1/g;
    s/ ?… ?/\x01ANY/g;
    s/\x01NUM/[-+0-9.e]+/g;
    s/\x01ANY/.*/g;'
}
for spec in "${readme_specs[@]+"${readme_specs[@]}"}"; do
  while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in
      "readme: "*)
        text=${line#readme: }
        grep -qE -- "$(readme_regex "$text")" "$out" || problem "the README's message does not fire: $text" ;;
    esac
  done <"$spec"
done
# The output of lab N's section alone.
lab_section() { awk -v lab="$1" '/^Lab [0-9]+:/ {in_lab = ($2 == lab ":")} /^Score:/ {in_lab = 0} in_lab' "$out"; }
for rows in "${readme_rows[@]+"${readme_rows[@]}"}"; do
  while IFS= read -r line || [ -n "$line" ]; do
    case "$line" in "" | "#"*) continue ;; esac
    lab=${line%%: *} text=${line#*: }
    lab_section "$lab" | grep -qE -- "$(readme_regex "$text")" ||
      problem "the README's message does not fire in lab $lab's section: $text"
  done <"$rows"
done
exit $fail
