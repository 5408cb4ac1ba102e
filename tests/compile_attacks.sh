#!/usr/bin/env bash
# compile_attacks.sh SOURCE BUILD WORK
# The compile-time attacks (tests/attacks/compile_*: #include of a solution by
# its absolute and its relative path, .incbin of a solution shader, a read
# through /proc/self/cwd, __has_include probing), graded as course staff grade
# a submission: one submission holding them all (each attacks another lab),
# through scripts/grade-submission, each lab built on its own behind the
# compile fence. Every lab scores 0, no solution text reaches the report, and
# the build says it was fenced. Graded: the attacked labs only (the others are
# the stubs, nothing to see), each through its probes (every function a lab
# writes, called: an #include of the solution would score there) and lab 1's
# scene (the lab 1 attack prints what it embedded when the shadow map is made).
set -uo pipefail
src=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work/submission/labs"
fail=0
problem() { echo "compile_attacks: $*" >&2; fail=1; }
# the handout's stubs as committed (the build's copy, from git), never labs/ as it is now
stubs=${SHADOWLAB_STUBS:-$build/stubs/labs}
[ -d "$stubs" ] || { echo "compile_attacks: no committed stubs at $stubs" >&2; exit 1; }
fence=$("$build/bin/shadowlab-fence" --probe)
case "$fence" in
  namespaces|uid) ;;
  *) echo "compile_attacks: this machine gives the compiler no fence ($fence): skipped"; exit 77 ;;
esac
# each attack's lab files over the stubs, as the attack suite lays them, then their lab folders into one submission
attacked=""
for attack in "$src"/tests/attacks/compile_*/; do
  name=$(basename "$attack")
  bash "$src/tests/make_attack.sh" "$attack" "$src" "$work/trees/$name" "$stubs" || exit 1
  for lab in "$attack"lab*/; do
    folder=$(basename "$lab")
    [ ! -e "$work/submission/labs/$folder" ] || { problem "two attacks on $folder: give each its own lab"; continue; }
    cp -R "$work/trees/$name/$folder" "$work/submission/labs/$folder"
    n=${folder#lab}; attacked+="${attacked:+,}${n%%_*}"
  done
done
set +e
"$src/scripts/grade-submission" --build "$build" --jobs 2 "$work/submission" -- --report "$work/report" \
  --lab "$attacked" --case '*_probes' --case lab1_depth_boxes --timeout 120 >"$work/out.txt" 2>&1
status=$?
set -e
cat "$work/out.txt"
[ "$status" = 1 ] || problem "exit status $status, expected 1 (checks failed)"
tail -n 1 "$work/out.txt" | grep -qE '^Score: 0/[0-9.]+$' || problem "the score is not 0: $(tail -n 1 "$work/out.txt")"
grep -q "each lab isolated" "$work/out.txt" || problem "the submission was not graded per lab"
grep -q "^shadowlab-grade: compiler: fenced" "$work/out.txt" || problem "the grade does not say the compiler was fenced"
! grep -q "did not build" "$work/out.txt" || problem "an attack's lab did not build: the attacks must build either way"
leaks=$(bash "$src/tests/solution_leaks.sh" "$src" "$work/out.txt" "$work/report/results.json") || problem "$leaks"
exit $fail
