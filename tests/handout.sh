#!/usr/bin/env bash
# handout.sh SOURCE_DIR WORK_DIR [GRADER ARGS...]
# The student handout, unpacked where nothing else is: it holds every public
# case and reference, it builds on its own, its lab 1 grades 0 with "not
# implemented", it refuses --update-references, and once its labs are finished
# (the solutions' files copied in, as a student's finished work) its own tests
# pass and the cases GRADER ARGS choose (each lab's probes and one scene case)
# get full marks. The staff suite grades every case of the same code on the
# same references (grade.student_scores_zero, grade.solutions_full_marks):
# here a grade proves that the handout's build grades, not every case again.
set -u
src=$1 work=$2
shift 2
finished_cases=("$@")
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
# The lecturer's notes (the answers to the questions for the room) stay out of the decks' Markdown:
# every line of a `::: notes` or `::: lecturer` block that is not also elsewhere in its deck.
for deck in "$src"/slides/lab*.md; do
  shipped="$root/slides/$(basename "$deck")"
  [ -f "$shipped" ] || { problem "slides/$(basename "$deck") is not in the handout"; continue; }
  while IFS= read -r line; do
    [ "$(grep -cxF -- "$line" "$deck")" = 1 ] || continue # a line the slides say too
    ! grep -qxF -- "$line" "$shipped" || problem "slides/$(basename "$deck") ships the lecturer's notes: $line"
  done < <(awk '/^::: *(notes|lecturer) *$/ {on = 1; next} on && /^::: *$/ {on = 0} on && NF' "$deck")
done
# Every public case and its references (the grades below run a few of them)
while IFS= read -r f; do
  [ -e "$root/$f" ] || problem "$f is not in the handout"
done < <(git -C "$src" ls-files -- grader/cases grader/references)
# Its test command installs only what its own tests use: no slide tools, no browser, no fuzzer's clang.
plan=$("$root/scripts/run-tests.sh" --plan 2>&1)
grep -q "a student's tree" <<<"$plan" || problem "run-tests.sh does not say it runs a student's tests: $plan"
[ "$(grep '^run-tests: would run' <<<"$plan")" = "run-tests: would run scripts/install-deps.sh" ] ||
  problem "run-tests.sh in the handout would install more than its tests use: $plan"
gen=(); ! command -v ninja >/dev/null || gen=(-G Ninja) # as bootstrap.sh makes a new build folder
cmake "${gen[@]}" -S "$root" -B "$root/build" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
# the grader (with its runner) and the viewer: all the handout's default build holds
cmake --build "$root/build" -j "$(nproc)" --target shadowlab-grade shadowlab >"$work/build.log" 2>&1 ||
  { tail -n 30 "$work/build.log"; exit 1; }
out=$("$root/build/bin/shadowlab-grade" --lab 1 2>&1)
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
cmake --build "$root/build" -j "$(nproc)" --target shadowlab-grade test-programs >>"$work/build.log" 2>&1 ||
  { tail -n 30 "$work/build.log"; exit 1; }
# Its own suite builds (test-programs: every test program is in the handout) and runs: the tests
# that read the handout's own files (its case format, its scenes) and the one that lists this
# build's GL backends. Left out: the other unit tests and the backends' drawing tests, the same
# sources on the same machine as the staff suite's unit.* and context.*; and grade.report_is_complete,
# a grade of every case, where the full-marks grade below checks more on fewer cases.
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -R '^(unit\.(case_files|scenes)|context\.names)$' \
  >"$work/ctest.log" 2>&1 || { cat "$work/ctest.log"; problem "the handout's own tests fail on finished labs"; }
grep -q "100% tests passed, 0 tests failed out of 3" "$work/ctest.log" ||
  { cat "$work/ctest.log"; problem "the handout's suite did not run its three tests"; }
grep -E "tests passed" "$work/ctest.log"
out=$("$root/build/bin/shadowlab-grade" "${finished_cases[@]}" 2>&1)
status=$?
[ "$status" = 0 ] || problem "finished labs graded with exit status $status, expected 0"
tail -n 1 <<<"$out" | grep -qE '^Score: ([0-9.]+)/\1( |$)' || problem "finished labs do not get full marks: $(tail -n 1 <<<"$out")"
! grep -qE "PROBLEM|crash|protocol" <<<"$out" || problem "the finished labs' grade reports a problem"
echo "$out" | tail -n 1
exit $fail
