#!/usr/bin/env bash
# handout.sh SOURCE_DIR WORK_DIR
# The student handout, unpacked where nothing else is: it builds on its own,
# its labs grade 0 with "not implemented", it refuses --update-references,
# and once its labs are finished (the solutions' files copied in, as a
# student's finished work) its own test suite passes and it grades full marks.
set -u
src=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "handout: $*" >&2; fail=1; }
"$src/scripts/make-handout.sh" --committed "$work/dist" || exit 1
tar -xzf "$work"/dist/shadowlab-*.tar.gz -C "$work" || exit 1
root=$(find "$work" -maxdepth 1 -type d -name 'shadowlab-*' | head -n 1)
[ ! -e "$root/solutions" ] || problem "solutions/ is in the handout"
[ ! -e "$root/tests/variants" ] || problem "tests/variants/ is in the handout"
[ ! -e "$root/tests/attacks" ] || problem "tests/attacks/ is in the handout"
[ ! -e "$root/solutions/bench" ] && [ ! -e "$root/framework/sl_bench_baseline.c" ] ||
  problem "the benchmark's plain-GL program (an answer to labs 1-4) is in the handout"
# No implementation of a lab step: each lab's key calls, as patterns that match
# the solutions, match nothing in the handout's code (a stub's comment may say
# what to call). Lab 1's light camera is a table there (framework/sl_light_cameras.inc; the
# grader sends a lab 1 case's in its job),
# and the grader reads lab 6's splits and lab 7's faces from the solutions' probe outputs.
answers=$(bash "$src/tests/handout_answers.sh" "$src/solutions" "$root")
case $? in
  0|1) ;;
  *) problem "the key-call patterns no longer match the solutions (tests/handout_answers.sh)" ;;
esac
while IFS= read -r line; do
  [ -n "$line" ] || continue
  problem "an implementation of a lab step is in the handout: $line"
done <<<"$answers"
cmake -S "$root" -B "$root/build" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$root/build" -j "$(nproc)" >"$work/build.log" 2>&1 || { tail -n 30 "$work/build.log"; exit 1; }
out=$("$root/build/bin/shadowlab-grade" 2>&1)
status=$?
echo "$out" | tail -n 5
[ "$status" = 1 ] || problem "the stubs graded with exit status $status, expected 1"
tail -n 1 <<<"$out" | grep -qE '^Score: 0/[0-9.]+$' || problem "the stubs do not score 0"
grep -q "not implemented: lab1_create_shadow_map" <<<"$out" || problem "no 'not implemented' message"
! grep -qE "PROBLEM|crash|protocol" <<<"$out" || problem "the handout's grade reports a problem"
# the benchmark runs without its plain-GL row (a staff build's only)
bench=$("$root/build/bin/shadowlab" --bench --list 2>&1)
grep -q '^lab4-grid-3x3 ' <<<"$bench" || problem "shadowlab --bench --list does not list the labs' rows: $bench"
! grep -q 'plain-gl' <<<"$bench" || problem "the handout's benchmark has the plain-GL row"
"$root/build/bin/shadowlab" --bench --only lab2 --size 64x36 --frames 2 --warmup 1 >"$work/bench.log" 2>&1 ||
  { cat "$work/bench.log"; problem "shadowlab --bench fails in the handout"; }
out=$("$root/build/bin/shadowlab-grade" --update-references 2>&1)
status=$?
[ "$status" = 2 ] || problem "--update-references: exit status $status, expected 2"
grep -q "no solutions/" <<<"$out" || problem "--update-references is not refused with a reason: $out"
# A student who finished every lab: the handout's own tests pass, full marks.
for lab in "$src"/solutions/lab*; do cp -R "$lab"/. "$root/labs/$(basename "$lab")/"; done
cmake --build "$root/build" -j "$(nproc)" >>"$work/build.log" 2>&1 || { tail -n 30 "$work/build.log"; exit 1; }
cmake --build "$root/build" -j "$(nproc)" --target test-programs >>"$work/build.log" 2>&1 ||
  { tail -n 30 "$work/build.log"; exit 1; }
# Its grading, staging and unit tests: the ones a student runs after a lab. (The viewer's, the
# slides', the browser's and the second build trees' run as the staff suite's own tests; its
# complete-report test grades the labs as the full-marks grade below does, which checks more.)
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -R '^(unit|grade|stage|context|fallback)\.' -E '^grade\.report_is_complete$' \
  >"$work/ctest.log" 2>&1 || { cat "$work/ctest.log"; problem "the handout's own tests fail on finished labs"; }
grep -E "tests passed" "$work/ctest.log"
out=$("$root/build/bin/shadowlab-grade" 2>&1)
status=$?
[ "$status" = 0 ] || problem "finished labs graded with exit status $status, expected 0"
echo "$out" | tail -n 1
exit $fail
