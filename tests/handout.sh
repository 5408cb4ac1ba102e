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
"$src/scripts/make-handout.sh" "$work/dist" || exit 1
tar -xzf "$work"/dist/shadowlab-*.tar.gz -C "$work" || exit 1
root=$(find "$work" -maxdepth 1 -type d -name 'shadowlab-*' | head -n 1)
[ ! -e "$root/solutions" ] || problem "solutions/ is in the handout"
[ ! -e "$root/tests/variants" ] || problem "tests/variants/ is in the handout"
[ ! -e "$root/tests/attacks" ] || problem "tests/attacks/ is in the handout"
cmake -S "$root" -B "$root/build" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$root/build" -j "$(nproc)" >"$work/build.log" 2>&1 || { tail -n 30 "$work/build.log"; exit 1; }
out=$("$root/build/bin/shadowlab-grade" 2>&1)
status=$?
echo "$out" | tail -n 5
[ "$status" = 1 ] || problem "the stubs graded with exit status $status, expected 1"
tail -n 1 <<<"$out" | grep -qE '^Score: 0/[0-9.]+$' || problem "the stubs do not score 0"
grep -q "not implemented: lab1_create_shadow_map" <<<"$out" || problem "no 'not implemented' message"
! grep -qE "PROBLEM|crash|protocol" <<<"$out" || problem "the handout's grade reports a problem"
out=$("$root/build/bin/shadowlab-grade" --update-references 2>&1)
status=$?
[ "$status" = 2 ] || problem "--update-references: exit status $status, expected 2"
grep -q "no solutions/" <<<"$out" || problem "--update-references is not refused with a reason: $out"
# A student who finished every lab: the handout's own tests pass, full marks.
for lab in "$src"/solutions/lab*; do cp -R "$lab"/. "$root/labs/$(basename "$lab")/"; done
cmake --build "$root/build" -j "$(nproc)" >>"$work/build.log" 2>&1 || { tail -n 30 "$work/build.log"; exit 1; }
ctest --test-dir "$root/build" --output-on-failure >"$work/ctest.log" 2>&1 || { cat "$work/ctest.log"; problem "the handout's own tests fail on finished labs"; }
grep -E "tests passed" "$work/ctest.log"
out=$("$root/build/bin/shadowlab-grade" 2>&1)
status=$?
[ "$status" = 0 ] || problem "finished labs graded with exit status $status, expected 0"
echo "$out" | tail -n 1
exit $fail
