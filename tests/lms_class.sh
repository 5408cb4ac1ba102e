#!/usr/bin/env bash
# grade-batch on a class as Canvas and Moodle really export it (tests/make_lms_class.sh):
#   1. each download, given exactly as downloaded, is split as the same files unzipped
#      by hand are: the same students, files and content hashes; a file a student
#      named like another student's never reaches that student; GitHub Classroom's
#      folders are one submission per user;
#   2. graded (lab 1, one case), every student gets the grade their files deserve, one
#      row each; names that reduce to '..', '.split' or the batch's own files neither
#      stop the batch nor touch its files; an empty upload and an unchanged stub are
#      neither built nor run;
#   3. a re-download a day later (one student uploaded again), given with the earlier
#      download unzipped by hand, regrades that student alone and keeps one row per id.
# PART "split" does 1 (nothing graded), "grade" does 2 and 3.
#   lms_class.sh BUILD SOURCE WORK PART
set -euo pipefail
build=$1 source=$2 work=$3 part=$4
[ -x "$build/bin/shadowlab-stage" ] || { echo "lms_class: no $build/bin/shadowlab-stage: skipped"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
out="$work/grades" downloads="$work/downloads"
fail=0
problem() { echo "lms_class: $*" >&2; fail=1; }
bash "$source/tests/make_lms_class.sh" "$source" "$build/stubs/labs" "$downloads"
batch=("$source/scripts/grade-batch" -j 2 --build "$build" --out "$out")
options=(-- --case lab1_depth_boxes --timeout 120)

# ---- 1. as downloaded, as unzipped by hand: the same split ----
if [ "$part" = split ]; then
for d in canvas-v1 moodle; do
  mkdir -p "$work/unzipped/$d"
  (cd "$work/unzipped/$d" && cmake -E tar xf "$downloads/$d.zip")
  "${batch[@]}" --list "$downloads/$d.zip" >"$work/$d.zip.list" 2>"$work/$d.zip.log"
  "${batch[@]}" --list "$work/unzipped/$d" >"$work/$d.dir.list" 2>"$work/$d.dir.log"
  # name, student, id, late, files, content hash: all but where from
  if ! diff <(cut -f1-4,6,7 "$work/$d.zip.list" | sort) <(cut -f1-4,6,7 "$work/$d.dir.list" | sort); then
    problem "$d: the download as downloaded and unzipped by hand are split differently"
  fi
done
cat "$work/canvas-v1.zip.list" "$work/moodle.zip.list" | cut -f1-6
[ "$(wc -l <"$work/canvas-v1.zip.list")" = 12 ] || problem "Canvas: $(wc -l <"$work/canvas-v1.zip.list") students, expected 12"
[ "$(wc -l <"$work/moodle.zip.list")" = 6 ] || problem "Moodle: $(wc -l <"$work/moodle.zip.list") students, expected 6"
amy=$(grep $'^Amy_Adams_2001\t' "$work/moodle.zip.list") || problem "no Amy Adams"
[ "$(cut -f6 <<<"${amy:-}")" = shadowlab.zip ] || problem "Amy Adams' files are not her own upload: ${amy:-}"
grep -q $'^Jay_Jones_2010\t.*Amy Adams_2001_assignsubmission_file_lab1.c' "$work/moodle.zip.list" ||
  problem "the file Jay Jones named like Amy Adams' is not his"
grep -q $'^2011\t\.\.\t2011\t' "$work/moodle.zip.list" || problem "the student whose name is '..' is not listed"
"${batch[@]}" --list "$downloads/classroom" >"$work/classroom.list" 2>"$work/classroom.log"
cat "$work/classroom.log" "$work/classroom.list"
grep -q "classroom: a GitHub Classroom download (shadowlab)" "$work/classroom.log" &&
  grep -q $'^alice\talice\talice\t' "$work/classroom.list" && grep -q $'^bob-smith\tbob-smith\tbob-smith\t' "$work/classroom.list" ||
  problem "the GitHub Classroom folders are not one submission per user"
[ $fail = 0 ] && echo "lms_class: each download is split as the same files unzipped by hand"
exit $fail
fi

# ---- 2. graded as downloaded ----
set +e
"${batch[@]}" "$downloads/canvas-v1.zip" "$downloads/moodle.zip" "$downloads/by-hand" "${options[@]}" >"$work/first.log" 2>&1
status=$?
set -e
cat "$work/first.log"
[ "$status" = 0 ] || problem "the batch exited $status"
gradebook=$out/gradebook.csv
cat "$gradebook"
header=$(head -n 1 "$gradebook")
column() { tr ',' '\n' <<<"$header" | grep -nx "$1" | cut -d: -f1; }
field() { cut -d, -f"$2" <<<"$1"; }
expect() { # NAME STATUS LAB1 (full, lost, 0) [NOTE]
  local row lab1 max
  row=$(tail -n +2 "$gradebook" | grep "^$1,") || { problem "no gradebook row for $1"; return; }
  [ "$(field "$row" "$(column status)")" = "$2" ] || problem "$1: status '$(field "$row" "$(column status)")', expected '$2'"
  lab1=$(field "$row" "$(column lab1)") max=$(field "$row" "$(column max)")
  case $3 in
    full) [ "$lab1" = "$max" ] || problem "$1: lab 1 scored $lab1 of $max, expected full marks" ;;
    lost) awk -v g="$lab1" -v m="$max" 'BEGIN { exit !(g > 0 && g < m) }' || problem "$1: lab 1 scored $lab1 of $max, expected some lost" ;;
    0) [ "$lab1" = 0 ] || problem "$1: lab 1 scored $lab1, expected 0" ;;
  esac
  [ -z "${4:-}" ] || grep -Eq -- "$4" <<<"$(cut -d, -f"$(column note)"- <<<"$row")" || problem "$1: the note does not say '$4': $row"
}
expect adamsamy_101 graded full
expect brownben_102 graded full
expect clarkcat_103 graded lost
expect davisdan_104 graded full
expect evanseve_105 graded full
expect fosterfay_106 graded full
expect garciagus_107 "no lab file" 0 "text.html"
expect harrishal_108 graded full
expect ivanovivy_109 "did not build" 0 "lab1\.c:[0-9]+:[0-9]+: error"
expect jonesjay_110 graded 0
expect kingkim_111 "no lab file" 0 "report\.pdf"
expect leelou_112 "no lab file" 0
expect Amy_Adams_2001 graded full
expect Ben_Brown_2002 graded 0
expect Jay_Jones_2010 graded full
expect Gus_Garcia_2007 "no lab file" 0
expect 2011 graded 0
expect gradebook_csv_2013 "no lab file" 0
expect submission "no lab file" 0 "named submission: '_\.\.' has no letter or digit"
expect split graded 0
expect gradebook_csv graded 0
expect grader-options "no lab file" 0
[ "$(($(wc -l <"$gradebook") - 1))" = 22 ] || problem "the gradebook has $(($(wc -l <"$gradebook") - 1)) rows, expected 22"
dups=$(tail -n +2 "$gradebook" | cut -d, -f1 | sort | uniq -d)
[ -z "$dups" ] || problem "rows given twice: $dups"
ids=$(tail -n +2 "$gradebook" | cut -d, -f"$(column student_id)" | grep . | sort | uniq -d)
[ -z "$ids" ] || problem "ids with two rows: $ids"
grep -q '^clarkcat_103,clarkcat,103,late,' "$gradebook" || problem "clarkcat's late mark is lost"
[ -f "$out/.batch/grader-options" ] && [ -f "$gradebook" ] && [ -s "$out/class-report.html" ] ||
  problem "the batch's own files are not where they belong"
# nothing to build: neither built nor run
for name in garciagus_107 jonesjay_110 split Ben_Brown_2002; do
  grep -q "nothing to build or run" "$out/$name/grade.log" || problem "$name was built (its files are the stubs or none)"
done
# every row keeps what it was graded from
[ "$(grep -c ',[0-9a-f]\{64\},' "$gradebook")" = 22 ] || problem "not every row has its content hash"

# ---- 3. a day later: clarkcat uploaded again ----
mkdir -p "$work/unzipped-again/canvas-v1"
(cd "$work/unzipped-again/canvas-v1" && cmake -E tar xf "$downloads/canvas-v1.zip")
declare -A before=()
for d in "$out"/*/; do
  n=$(basename "$d")
  [ ! -f "$d/report/results.json" ] || before[$n]=$(stat -c '%i %Y' "$d/report/results.json")
done
set +e
"${batch[@]}" "$downloads/canvas-v2.zip" "$work/unzipped-again/canvas-v1" "${options[@]}" >"$work/second.log" 2>&1
status=$?
set -e
cat "$work/second.log"
cat "$gradebook"
[ "$status" = 0 ] || problem "the batch of the re-download exited $status"
grep -q "^grade-batch: changed since their last grade, graded again: clarkcat_103$" "$work/second.log" ||
  problem "the re-download does not say that clarkcat_103 alone changed"
for n in "${!before[@]}"; do
  now=$(stat -c '%i %Y' "$out/$n/report/results.json")
  if [ "$n" = clarkcat_103 ]; then [ "$now" != "${before[$n]}" ] || problem "clarkcat_103 was not graded again"
  else [ "$now" = "${before[$n]}" ] || problem "$n was graded again though their files did not change"; fi
done
expect clarkcat_103 graded full "also in Canvas \(canvas-v1\): an older upload, not graded"
expect adamsamy_101 graded full "also in Canvas \(canvas-v2.zip\): the same upload"
[ "$(($(wc -l <"$gradebook") - 1))" = 22 ] || problem "after the re-download the gradebook has $(($(wc -l <"$gradebook") - 1)) rows, expected 22"
[ "$(grep -c ',103,' "$gradebook")" = 1 ] || problem "clarkcat (103) has more than one row"
[ $fail = 0 ] && echo "lms_class: the Canvas and Moodle class graded as downloaded, one row per student, the re-download regraded one"
exit $fail
