#!/usr/bin/env bash
# End to end through scripts/grade-submission: the solutions, saved by a
# Windows editor (CRLF, a byte-order mark in every lab file) and zipped by
# macOS Finder (a top folder beside __MACOSX/ and ._ files), get full marks
# in every lab, and the grade says the line ends were normalised.
#   stage_submission.sh FIXTURES_TOOL SOURCE BUILD WORK GRADE_EXPECT
set -euo pipefail
fixtures=$1 source=$2 build=$3 work=$4 grade_expect=$5
rm -rf "$work"
mkdir -p "$work/tree"
cp -R "$source/solutions" "$work/tree/labs"
while IFS= read -r f; do
  { printf '\xef\xbb\xbf'; sed 's/$/\r/' "$f"; } >"$f.new" && mv "$f.new" "$f"
done < <(find "$work/tree/labs" -type f \( -name 'lab[0-9].c' -o -path '*/shaders/*' \))
"$fixtures" archive "$work/Shadowlab.zip" zip "tree:Shadowlab=$work/tree" file:Shadowlab/.DS_Store=x \
  dir:__MACOSX dir:__MACOSX/Shadowlab file:__MACOSX/Shadowlab/._labs=x
chmod -R a+rX "$work"
checks=(--exit 0 --reject FAIL --expect "layout: a labs/ folder \(in Shadowlab/\)"
        --expect "^Submission: Line ends and byte-order marks made plain before compiling .*lab1_depth_fbo/lab1.c")
for lab in 1 2 3 4 5 6 7; do checks+=(--full "$lab"); done
# The suite's one grade of a whole submission end to end: every lab staged, built and
# graded, one picture per lab (it runs that lab's C code and shaders as staged): a
# shorter grade than every case.
cases=(--case lab1_depth_boxes --case lab2_directional_manual --case lab3_contact --case lab4_grid_3x3
       --case lab5_visibility --case lab6_field_three --case lab7_room_front)
exec "$grade_expect" --exe "$source/scripts/grade-submission" "${checks[@]}" \
  -- --build "$build" --jobs 2 "$work/Shadowlab.zip" -- --timeout 120 "${cases[@]}"
