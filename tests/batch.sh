#!/usr/bin/env bash
# scripts/grade-batch on five sample submissions, one in each accepted layout:
# the solutions, the stubs, two known mistakes and one that does not compile.
# The first run is interrupted as soon as a submission is graded; the second
# grades the rest without grading the finished ones again, and the gradebook
# is the expected one (tests/batch/expected-gradebook.csv). What is tested is
# the batch's bookkeeping, so two labs are graded (2 and 3, where the mistakes
# are), one case each: grade-submission builds those two labs only.
#   batch.sh BUILD SOURCE WORK LAB2_MISTAKE_TREE LAB3_MISTAKE_TREE
set -euo pipefail
build=$1 source=$2 work=$3 lab2_tree=$4 lab3_tree=$5
expected="$source/tests/batch/expected-gradebook.csv"
rm -rf "$work"
mkdir -p "$work/submissions"
subs="$work/submissions" out="$work/grades"
fail=0
problem() { echo "batch: $*" >&2; fail=1; }

# ---- the submissions ----
mkdir "$subs/solutions"                                      # 1. a labs/ folder
cp -R "$source/solutions" "$subs/solutions/labs"
cp -R "${SHADOWLAB_STUBS:-$source/labs}" "$subs/stubs"                           # 2. the lab folders
mkdir "$subs/lab2_inverted_compare"                          # 3. loose files
find "$lab2_tree" -type f \( -name 'lab[0-9].c' -o -path '*/shaders/*' \) -exec cp {} "$subs/lab2_inverted_compare/" \;
echo "my notes" >"$subs/lab2_inverted_compare/notes.txt"
mkdir -p "$subs/lab3_slope_sin/shadowlab-main"               # an unpacked archive: one folder
cp -R "$lab3_tree" "$subs/lab3_slope_sin/shadowlab-main/labs"
mkdir "$subs/does_not_build"
find "$source/solutions" -type f -exec cp {} "$subs/does_not_build/" \;
sed -i '0,/return SL_OK;/s//return SL_OK/' "$subs/does_not_build/lab3.c"

# One case in each of the two labs with a mistake: lab 2's scene and lab 3's probes.
# A generous time limit: the test machine may be busy.
cases=(--case lab2_directional_manual --case lab3_probes --timeout 120)
batch=("$source/scripts/grade-batch" -j 2 --build "$build" --out "$out" "$subs" -- "${cases[@]}")

# ---- 1. interrupted once a submission is graded ----
"${batch[@]}" >"$work/first.log" 2>&1 &
pid=$!
until compgen -G "$out/*/status" >/dev/null || ! kill -0 "$pid" 2>/dev/null; do sleep 0.2; done
kill -TERM "$pid" 2>/dev/null || true
set +e
wait "$pid"
status=$?
set -e
cat "$work/first.log"
[ "$status" = 130 ] || problem "the interrupted batch exited with $status, not 130"
grep -q "interrupted: [0-9] of 5 graded" "$work/first.log" || problem "the interrupted batch did not say so"
finished=()
for d in "$out"/*/; do [ -f "$d/status" ] && finished+=("$(basename "$d")"); done
[ ${#finished[@]} -ge 1 ] && [ ${#finished[@]} -lt 5 ] || problem "${#finished[@]} submissions finished before the interruption"
declare -A before=()
for name in "${finished[@]}"; do before[$name]=$(stat -c '%i %Y' "$out/$name/report/results.json" "$out/$name/status"); done
leftovers=$(pgrep -f -- "$out/" || true)
[ -z "$leftovers" ] || problem "processes left running after the interruption: $leftovers"

# ---- 2. resumed ----
set +e
"${batch[@]}" >"$work/second.log" 2>&1
status=$?
set -e
cat "$work/second.log"
[ "$status" = 0 ] || problem "the resumed batch exited with $status"
grep -q "^grade-batch: ${#finished[@]} of 5 already graded" "$work/second.log" || problem "the resumed batch did not keep the finished grades"
grep -q "^\[5/5 graded" "$work/second.log" || problem "no progress line reached 5/5"
for name in "${finished[@]}"; do
  [ "${before[$name]}" = "$(stat -c '%i %Y' "$out/$name/report/results.json" "$out/$name/status")" ] ||
    problem "$name was graded again"
  ! grep -q "started $name" "$work/second.log" || problem "$name was started again"
done
for name in does_not_build lab2_inverted_compare lab3_slope_sin solutions stubs; do
  [ -f "$out/$name/report/report.html" ] && [ -f "$out/$name/grade.log" ] || problem "$name has no report folder"
done
grep -q "layout: loose files" "$out/lab2_inverted_compare/grade.log" || problem "the loose files were not taken"
grep -q "layout: a labs/ folder" "$out/lab3_slope_sin/grade.log" || problem "the unpacked archive was not looked into"

# ---- 3. the gradebook ----
gradebook="$out/gradebook.csv"
cat "$gradebook"
header=$(head -n 1 "$gradebook")
[ "$header" = "submission,student,student_id,late,status,lab2,lab3,bonus,total,max,seed,options,content,note" ] ||
  problem "the gradebook's columns: $header"
# every column before the note is a name, a status, a number or options without a comma
column() { tr ',' '\n' <<<"$header" | grep -nx "$1" | cut -d: -f1; }
field() { cut -d, -f"$2" <<<"$1"; }
status_at=$(column status) total_at=$(column total) max_at=$(column max) note_at=$(column note)
lab_at=$(column lab2)
solutions_row=$(grep '^solutions,' "$gradebook")
# (the bonus is its own column, apart from the total: lab 3's probes have a bonus check)
awk -v t="$(field "$solutions_row" "$total_at")" -v b="$(field "$solutions_row" "$(column bonus)")" \
  -v m="$(field "$solutions_row" "$max_at")" 'BEGIN { exit !(t == m && b > 0) }' ||
  problem "the solutions' total is not the maximum, with their bonus apart"
grep -q -- "--case lab2_directional_manual --case lab3_probes" <<<"$solutions_row" ||
  problem "the solutions' row does not say its options"
rows=0
while IFS= read -r line; do
  [[ "$line" == \#* ]] && continue
  rows=$((rows + 1))
  IFS=, read -r name status l2 l3 note_re <<<"$line"
  row=$(grep "^$name," "$gradebook") || { problem "no row for $name"; continue; }
  [ "$(field "$row" "$status_at")" = "$status" ] || problem "$name: status '$(field "$row" "$status_at")', expected '$status'"
  want=("$l2" "$l3")
  for lab in 2 3; do
    at=$((lab_at + lab - 2))
    got=$(field "$row" $at) full=$(field "$solutions_row" $at) w=${want[$((lab - 2))]}
    case "$w" in
      any) ;;
      full) [ "$got" = "$full" ] || problem "$name: lab $lab scored $got, expected full marks ($full)" ;;
      lost) awk -v g="$got" -v f="$full" 'BEGIN { exit !(g < f) }' || problem "$name: lab $lab kept full marks ($got)" ;;
      *) [ "$got" = "$w" ] || problem "$name: lab $lab scored $got, expected $w" ;;
    esac
  done
  note=$(cut -d, -f"$note_at"- <<<"$row")
  grep -Eq -- "$note_re" <<<"$note" || problem "$name: note '$note' does not match $note_re"
  [ "$(field "$row" "$max_at")" = "$(field "$solutions_row" "$max_at")" ] || problem "$name: another maximum than the solutions'"
done <"$expected"
[ "$(($(wc -l <"$gradebook") - 1))" = "$rows" ] || problem "the gradebook has other rows than the expected ones"
[ -s "$out/class-report.html" ] && [ -s "$out/class-report.csv" ] || problem "no class report beside the gradebook"
exit $fail
