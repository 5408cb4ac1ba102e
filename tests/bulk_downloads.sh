#!/usr/bin/env bash
# grade-batch on mock Canvas and Moodle bulk downloads (tests/make_bulk_downloads.sh,
# made from the solutions and a variant): each split into one submission per
# student, named after them, graded, and the gradebook keeps the student's name
# and id as the platform wrote them and Canvas's late mark; a text entry alone
# is "no lab file". A damaged download is named, and what could be read of it
# is listed.
#   bulk_downloads.sh BUILD SOURCE WORK
set -euo pipefail
build=$1 source=$2 work=$3
if [ ! -x "$build/bin/shadowlab-stage" ]; then
  echo "bulk_downloads: no $build/bin/shadowlab-stage to unpack the downloads with: skipped"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
out="$work/grades"
fail=0
problem() { echo "bulk_downloads: $*" >&2; fail=1; }
bash "$source/tests/make_bulk_downloads.sh" "$source" "$work/downloads"
downloads=("$work/downloads/canvas-submissions.zip" "$work/downloads/moodle-folders.zip" "$work/downloads/moodle-flat.zip")
batch=("$source/scripts/grade-batch" -j 2 --build "$build" --out "$out")

# ---- 1. split: what would be graded ----
"${batch[@]}" --list "${downloads[@]}" >"$work/list.txt" 2>"$work/list.log"
cat "$work/list.log" "$work/list.txt"
expect_listed() { # NAME STUDENT ID LATE FILES
  local line
  line=$(grep "^$1"$'\t' "$work/list.txt") || { problem "no submission $1"; return; }
  # (read would join empty fields: a tab is white space to it)
  student=$(cut -f2 <<<"$line") id=$(cut -f3 <<<"$line") late=$(cut -f4 <<<"$line") files=$(cut -f6 <<<"$line")
  [ "$student" = "$2" ] && [ "$id" = "$3" ] && [ "$late" = "$4" ] || problem "$1: '$student' '$id' '$late', expected '$2' '$3' '$4'"
  [ "$files" = "$5" ] || problem "$1's files: '$files', expected '$5'"
}
expect_listed smithbob_1002 smithbob 1002 late "shadowlab.zip"
expect_listed leeann_1003 leeann 1003 "" "depth.frag depth.vert lab1.c"
expect_listed nguyenan_1004 nguyenan 1004 "" "text.html"
expect_listed Jane_Doe_2001 "Jane Doe" 2001 "" \
  "labs/lab1_depth_fbo/lab1.c labs/lab1_depth_fbo/shaders/depth.frag labs/lab1_depth_fbo/shaders/depth.vert onlinetext.html"
expect_listed Zoe_Muller_2002 "Zoë Müller" 2002 "" "shadowlab.zip"
expect_listed Omar_Haddad_2004 "Omar Haddad" 2004 "" "depth.frag depth.vert lab1.c"
[ "$(wc -l <"$work/list.txt")" = 6 ] || problem "$(wc -l <"$work/list.txt") submissions listed, expected 6"
grep -q "canvas-submissions.zip: a Canvas download" "$work/list.log" || problem "the Canvas download was not named as one"
grep -q "moodle-flat.zip: a Moodle download" "$work/list.log" || problem "the flat Moodle download was not named as one"
# the resubmitted lab1-1.c is the lab1.c graded (the first upload was the stub)
"$build/bin/shadowlab-stage" --extract "${downloads[0]}" "$work/canvas-unpacked"
cmp -s "$work/canvas-unpacked/leeann_1003_5005_lab1-1.c" "$source/solutions/lab1_depth_fbo/lab1.c" ||
  problem "the fixture's lab1-1.c is not the solutions'"

# ---- 2. a damaged download: named, and what could be read is listed ----
size=$(stat -c %s "${downloads[0]}")
head -c $((size * 2 / 3)) "${downloads[0]}" >"$work/damaged.zip"
set +e
"${batch[@]}" --list "$work/damaged.zip" >"$work/damaged.txt" 2>"$work/damaged.log"
status=$?
set -e
cat "$work/damaged.log" "$work/damaged.txt"
grep -q "damaged.zip" "$work/damaged.log" || problem "the damaged download was not named"

# ---- 3. graded ----
set +e
"${batch[@]}" "${downloads[@]}" -- --case lab1_depth_boxes --timeout 120 >"$work/grade.log" 2>&1
status=$?
set -e
cat "$work/grade.log"
[ "$status" = 0 ] || problem "grade-batch exited $status"
gradebook=$out/gradebook.csv
cat "$gradebook"
header=$(head -n 1 "$gradebook")
column() { tr ',' '\n' <<<"$header" | grep -nx "$1" | cut -d: -f1; }
field() { cut -d, -f"$2" <<<"$1"; }
expect_row() { # NAME STUDENT ID LATE STATUS LAB1 (full, lost or none) [NOTE]
  local row
  row=$(grep "^$1," "$gradebook") || { problem "no gradebook row for $1"; return; }
  [ "$(field "$row" "$(column student)")" = "$2" ] || problem "$1: student '$(field "$row" "$(column student)")', expected '$2'"
  [ "$(field "$row" "$(column student_id)")" = "$3" ] || problem "$1: id '$(field "$row" "$(column student_id)")', expected '$3'"
  [ "$(field "$row" "$(column late)")" = "$4" ] || problem "$1: late '$(field "$row" "$(column late)")', expected '$4'"
  [ "$(field "$row" "$(column status)")" = "$5" ] || problem "$1: status '$(field "$row" "$(column status)")', expected '$5'"
  local lab1 max
  lab1=$(field "$row" "$(column lab1)") max=$(field "$row" "$(column max)")
  case $6 in
    full) [ "$lab1" = "$max" ] || problem "$1: lab 1 scored $lab1 of $max, expected full marks" ;;
    lost) awk -v g="$lab1" -v m="$max" 'BEGIN { exit !(g < m) }' || problem "$1: lab 1 kept full marks ($lab1)" ;;
    none) [ "$lab1" = 0 ] || problem "$1: lab 1 scored $lab1 with no lab file" ;;
  esac
  [ -z "${7:-}" ] || grep -q -- "$7" <<<"$row" || problem "$1: the note does not say '$7': $row"
}
expect_row smithbob_1002 smithbob 1002 late graded lost
expect_row leeann_1003 leeann 1003 "" graded full
expect_row nguyenan_1004 nguyenan 1004 "" "no lab file" none "text.html"
expect_row Jane_Doe_2001 "Jane Doe" 2001 "" graded full
expect_row Zoe_Muller_2002 "Zoë Müller" 2002 "" graded full
expect_row Omar_Haddad_2004 "Omar Haddad" 2004 "" graded lost
[ "$(($(wc -l <"$gradebook") - 1))" = 6 ] || problem "the gradebook has $(($(wc -l <"$gradebook") - 1)) rows, expected 6"
grep -q "no lab file" "$out/class-report.html" || problem "the class report does not name the submissions without a lab file"
[ $fail = 0 ] && echo "bulk_downloads: Canvas and Moodle downloads split per student and graded as expected"
exit $fail
