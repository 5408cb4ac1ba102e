#!/usr/bin/env bash
# Hidden cases for one seed: the same seed derives the same cases and another
# seed other ones; the solutions keep full marks on them; every known mistake
# given still loses points in its lab.
#   hidden_seeds.sh GRADER GRADE_EXPECT SEED [--solutions-case PATTERN]... SOLUTIONS GRADER ARGS...
#                   [-- LAB MISTAKE GRADER ARGS...]...
# With --solutions-case the solutions are graded on those cases only (every case on one
# seed is enough to show all of them fair; other seeds check a few more draws of each lab).
set -euo pipefail
grader=$1 expect=$2 seed=$3
shift 3
solutions_cases=()
while [ "${1:-}" = --solutions-case ]; do solutions_cases+=(--case "$2"); shift 2; done
groups=() current=()
for a in "$@"; do
  if [ "$a" = "--" ]; then groups+=("${current[*]}"); current=(); else current+=("$a"); fi
done
groups+=("${current[*]}")
fail=0
problem() { echo "hidden_seeds: $*" >&2; fail=1; }

# read -a splits on spaces: the test paths have none
read -r -a solutions <<<"${groups[0]}"
list() { "$grader" "${solutions[@]}" --hidden --seed "$1" --list; }
limit=(--timeout 120)   # the test machine may be busy: pixels are checked here, not speed
first=$(list "$seed")
[ "$first" = "$(list "$seed")" ] || problem "seed $seed gave other cases the second time"
[ "$first" != "$(list $((seed + 1000)))" ] || problem "seeds $seed and $((seed + 1000)) gave the same cases"
grep -q 'hidden: light turned' <<<"$first" || problem "no case of seed $seed turned its light"
grep -q 'probe lines carried' <<<"$first" || problem "the penumbra case of seed $seed kept its camera"
grep -q 'function tables varied' <<<"$first" || problem "no probe's inputs varied with seed $seed"

echo "== the solutions, seed $seed${solutions_cases[*]:+ (${solutions_cases[*]})}"
"$expect" --exe "$grader" --exit 0 --full 1 --full 2 --full 3 --full 4 --full 5 --full 6 --full 7 --reject FAIL \
  --expect "hidden cases: variants of the public ones drawn from seed $seed" \
  -- "${solutions[@]}" --hidden --seed "$seed" "${limit[@]}" "${solutions_cases[@]+"${solutions_cases[@]}"}" ||
  problem "the solutions lost points on seed $seed"

for group in "${groups[@]:1}"; do
  read -r -a mistake <<<"$group"
  lab=${mistake[0]}
  echo "== ${mistake[*]:1}, seed $seed"
  "$expect" --exe "$grader" --exit 1 --loses "$lab" -- "${mistake[@]:1}" --lab "$lab" --hidden --seed "$seed" "${limit[@]}" \
    || problem "a known mistake in lab $lab was not caught on seed $seed"
done
exit $fail
