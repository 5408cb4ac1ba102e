#!/usr/bin/env bash
# A grade of lab 1 reads its references from the build's reference cache:
# a grade with the cache filled maps no image module into the grader's process
# (SHADOWLAB_GRADE_DEBUG's line, from /proc/self/maps), reads every image
# reference from the cache, and says what a grade without the cache says; a
# grade at the basic sandbox level does not use the cache.
#   reference_cache.sh GRADER GRADER-ARGS...
# Exit 77 (skipped) where the cache is off: the basic sandbox, a build folder
# that is not the grader's.
set -uo pipefail
grader=$1
shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
problem() { echo "reference_cache: $*" >&2; fail=1; }
grade() { # grade NAME [OPTIONS]: the report without its timings, and the debug line
  local name=$1
  shift
  SHADOWLAB_GRADE_DEBUG=1 "$grader" "$@" --lab 1 >"$tmp/$name.out" 2>"$tmp/$name.err"
  echo $? >"$tmp/$name.status"
  sed -E 's/[0-9]+(\.[0-9]+)? s\b/T s/g' "$tmp/$name.out" >"$tmp/$name.text"
  grep 'debug: reference cache' "$tmp/$name.err" >"$tmp/$name.debug" || problem "$name: no debug line: $(cat "$tmp/$name.err")"
}
grade plain "$@" --no-reference-cache
grep -q 'image module loaded: yes' "$tmp/plain.debug" || problem "without the cache the module was not loaded?"
grade first "$@"
if grep -q 'reference cache off' "$tmp/first.debug"; then
  echo "reference_cache: skipped: $(cat "$tmp/first.debug")"
  exit 77
fi
# the suite's other grades usually filled the cache already: a third grade only when this one did
if grep -qE ': [0-9]+ read, 0 stored, 0 ignored;' "$tmp/first.debug"; then
  cp "$tmp/first.out" "$tmp/second.out"
  cp "$tmp/first.text" "$tmp/second.text"
  cp "$tmp/first.debug" "$tmp/second.debug"
  cp "$tmp/first.status" "$tmp/second.status"
else
  grade second "$@"
fi
cat "$tmp/second.debug"
grep -q 'image module loaded: no' "$tmp/second.debug" || problem "the second grade loaded the image module"
grep -qE ': [1-9][0-9]* read, 0 stored, 0 ignored;' "$tmp/second.debug" || problem "the second grade did not read every reference from the cache"
for run in first second; do
  [ "$(cat "$tmp/$run.status")" = "$(cat "$tmp/plain.status")" ] || problem "$run grade exited $(cat "$tmp/$run.status"), without the cache $(cat "$tmp/plain.status")"
  diff -u "$tmp/plain.text" "$tmp/$run.text" >&2 || problem "the $run grade's report differs from one without the cache"
done
grep -q '^Score: ' "$tmp/second.out" || problem "no score in the report"
# at the basic level runners run as the grader's user, who owns the cache: it is not used
grade basic "$@" --sandbox basic --case lab1_depth_boxes
grep -q 'reference cache off (the basic sandbox' "$tmp/basic.debug" || problem "at the basic level the cache was used: $(cat "$tmp/basic.debug")"
[ $fail = 0 ] && echo "reference_cache: a grade with the cache filled kept the image module out and said the same; basic used no cache"
exit $fail
