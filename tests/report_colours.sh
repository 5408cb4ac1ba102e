#!/usr/bin/env bash
# The HTML report's pictures of checks that are not plain grey: lab 6's
# cascade index in the viewer's cascade colours (cascade 0 red, no cascade
# grey: as grey levels cascade 0 was as black as the background), lab 5's two
# moments as red (depth) and green (depth², a PNG made it alpha), each with a
# legend under the pictures (a mistake in each, so that the pictures are shown).
#   report_colours.sh GRADER COLOUR_CHECK WORK CASCADE_MISTAKE_ARGS -- MOMENTS_MISTAKE_ARGS
set -u
grader=$1 colour_check=$2 work=$3
shift 3
cascade_args=() moments_args=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do cascade_args+=("$1"); shift; done
shift
moments_args=("$@")
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "report_colours: $*" >&2; fail=1; }
"$grader" "${cascade_args[@]}" --case lab6_field --exclude lab6_field_ --report "$work/cascades" >"$work/cascades.log" 2>&1
"$grader" "${moments_args[@]}" --case lab5_moments --report "$work/moments" >"$work/moments.log" 2>&1
cat "$work/cascades.log" "$work/moments.log"
images=$work/cascades/images
for role in student reference; do
  [ -s "$images/lab6_field.cascade_index.$role.png" ] || { problem "no $role picture of the cascade index"; continue; }
  "$colour_check" colour "$images/lab6_field.cascade_index.$role.png" 0.3 0.3 0.3 5 || problem "no grey background in the $role's cascades"
done
# the reference's near ground is cascade 0 (red), the mistake's cascade 1 (green)
"$colour_check" colour "$images/lab6_field.cascade_index.reference.png" 1 0.3 0.25 5 || problem "the reference's cascade 0 is not red"
"$colour_check" colour "$images/lab6_field.cascade_index.student.png" 0.2 0.9 0.3 5 || problem "the off-by-one cascade 1 is not green"
grep -q 'class="legend".*cascade 0.*no cascade' "$work/cascades/report.html" || problem "no cascade legend in report.html"
# the reference's depth² (green) is below its depth (red) wherever depth < 1; the
# mistake stores depth twice (yellow); the far background is yellow in both
for check in moments moments_blurred; do
  f=$work/moments/images/lab5_moments.$check
  [ -s "$f.reference.png" ] && [ -s "$f.student.png" ] || { problem "no pictures of $check"; continue; }
  "$colour_check" red-green "$f.reference.png" || problem "the reference's $check is not red and green"
  "$colour_check" colour "$f.student.png" 1 1 0 5 || problem "the mistake's $check has no yellow background"
done
grep -q 'class="legend".*red: depth.*green: depth' "$work/moments/report.html" || problem "no moments legend in report.html"
[ $fail = 0 ] && echo "report_colours: cascades and moments in colour, with legends"
exit $fail
