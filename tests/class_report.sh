#!/usr/bin/env bash
# A class of four generated submissions (tests/make_submissions.sh): two with
# the same lab 3 mistake (sin where tan belongs), one with a lab 2 mistake that
# lab 3 builds on, and the solutions.
# grade-batch writes the class report: per diagnosis the students who got it
# ("2 of 4: sin(theta) where tan(theta) belongs", counted once however many
# checks it failed), per check how many failed, each lab's score histogram;
# the gradebook row says which options made it. Then the same folder again:
#   - with other grader options: refused, naming both, nothing graded again;
#   - --regrade one student: that one alone graded again.
#   class_report.sh BUILD SOURCE WORK
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
subs="$work/submissions" out="$work/grades"
fail=0
problem() { echo "class_report: $*" >&2; fail=1; }

bash "$source/tests/make_submissions.sh" "$source" "$subs" amy=lab3_slope_sin ben=lab3_slope_sin \
  dan=lab2_inverted_compare eve=solutions
# a case or two per lab: each mistake shows, and the batch stays quick
options=(--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset --timeout 120)
batch=("$source/scripts/grade-batch" -j 2 --build "$build" --out "$out" "$subs" --)

# ---- 1. the class report ----
set +e
"${batch[@]}" "${options[@]}" >"$work/first.log" 2>&1
status=$?
set -e
cat "$work/first.log"
[ "$status" = 0 ] || problem "the batch exited with $status"
report=$out/class-report.csv html=$out/class-report.html
[ -s "$report" ] && [ -s "$html" ] || { problem "no class report"; exit 1; }
cat "$report"
[ "$(head -n 1 "$report")" = "kind,lab,name,text,students,of" ] || problem "the class report's columns: $(head -n 1 "$report")"
# kind,lab,name,text,students,of: the text may hold commas, so read the last two fields from the end
row_of() { grep -E "$1" "$report" | head -n 1; }
count_of() { awk -F, '{ print $(NF - 1) "/" $NF }' <<<"$1"; }
sin=$(row_of '^diagnosis,3,slope-scaled-bias-.*sin\(theta\) where tan\(theta\) belongs')
[ -n "$sin" ] || problem "no diagnosis 'sin(theta) where tan(theta) belongs'"
[ "$(count_of "$sin")" = 2/4 ] || problem "sin where tan: $(count_of "$sin") students, expected 2/4"
grep -qE '<td class="num">.*2 of 4</td><td>3</td><td>slope_scaled_bias\(\): sin\(theta\) where tan\(theta\) belongs' "$html" ||
  problem "class-report.html does not say '2 of 4: slope_scaled_bias(): sin(theta) where tan(theta) belongs'"
probe=$(row_of '^check,3,lab3_probes / slope_scaled_bias,')
[ "$(count_of "$probe")" = 2/4 ] || problem "lab3_probes / slope_scaled_bias failed by $(count_of "$probe"), expected 2/4"
# submissions are graded per lab: dan's lab 2 mistake costs lab 2 only, never
# lab 3 again as a failure that follows from it
! grep -qE '^diagnosis,3,follows-needs-lab-2-first' "$report" ||
  problem "dan's lab 2 mistake is charged in lab 3 too (a failure that follows from lab 2)"
lab2=$(row_of '^check,2,lab2_directional_manual / visibility,')
[ "$(count_of "$lab2")" = 1/4 ] || problem "lab2_directional_manual / visibility failed by $(count_of "$lab2"), expected 1/4"
for lab in 2 3 total; do
  students=$(awk -F, -v lab="$lab" '$1 == "score" && $2 == lab { n += $(NF - 1) } END { print n + 0 }' "$report")
  [ "$students" = 4 ] || problem "lab $lab's histogram holds $students students, not 4"
done
full=$(awk -F, '$1 == "score" && $2 == "total" && $3 == "100%" { print $(NF - 1) }' "$report")
[ "$full" = 1 ] || problem "$full students with full marks in all, expected 1 (the solutions)"
grep -q '<svg' "$html" || problem "class-report.html has no histogram"

# ---- 2. each gradebook row says what made it ----
gradebook=$out/gradebook.csv
header=$(head -n 1 "$gradebook")
column() { tr ',' '\n' <<<"$header" | grep -nx "$1" | cut -d: -f1; }
options_column=$(column options)
[ -n "$options_column" ] || problem "the gradebook has no options column: $header"
amy=$(grep '^amy,' "$gradebook")
# (grade-submission adds --isolate: each lab graded on its own)
grep -q -- "--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset .*--timeout 120" <<<"$amy" ||
  problem "amy's row does not say its options: $amy"

# ---- 3. another pass with other options into the same folder: refused, naming both ----
declare -A before=()
for d in "$out"/*/; do before[$(basename "$d")]=$(stat -c '%i %Y' "$d/report/results.json"); done
set +e
"${batch[@]}" --case lab3_probes >"$work/second.log" 2>&1
status=$?
set -e
cat "$work/second.log"
[ "$status" = 2 ] || problem "a pass with other options exited $status, not 2"
grep -q "graded with other grader options" "$work/second.log" || problem "the refusal does not say why"
grep -q -- "this run: --case lab3_probes$" "$work/second.log" || problem "the refusal does not name this run's options"
grep -q -- "--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset --timeout 120$" "$work/second.log" ||
  problem "the refusal does not name the folder's options"
for name in "${!before[@]}"; do
  [ "${before[$name]}" = "$(stat -c '%i %Y' "$out/$name/report/results.json")" ] || problem "$name was graded again"
done

# ---- 4. one student graded again ----
set +e
"$source/scripts/grade-batch" -j 2 --build "$build" --out "$out" --regrade ben "$subs" -- "${options[@]}" >"$work/third.log" 2>&1
status=$?
set -e
cat "$work/third.log"
[ "$status" = 0 ] || problem "--regrade ben exited $status"
grep -q "^grade-batch: 3 of 4 already graded" "$work/third.log" || problem "--regrade did not keep the other four"
for name in "${!before[@]}"; do
  now=$(stat -c '%i %Y' "$out/$name/report/results.json")
  if [ "$name" = ben ]; then [ "${before[$name]}" != "$now" ] || problem "ben was not graded again"
  else [ "${before[$name]}" = "$now" ] || problem "$name was graded again with ben"; fi
done
set +e
"$source/scripts/grade-batch" --build "$build" --out "$out" --regrade nobody "$subs" -- "${options[@]}" >"$work/fourth.log" 2>&1
status=$?
set -e
[ "$status" = 2 ] && grep -q -- "--regrade nobody: no such submission" "$work/fourth.log" ||
  problem "--regrade of an unknown name: exit $status, $(cat "$work/fourth.log")"
[ $fail = 0 ] && echo "class_report: the class report, the options of each row, a refused second pass and one regrade as expected"
exit $fail
