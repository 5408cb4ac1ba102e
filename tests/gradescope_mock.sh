#!/usr/bin/env bash
# The Gradescope bundle end to end, in a mock of Gradescope's layout under a
# temporary folder: make the bundle, run its setup.sh as the image build does,
# then run_autograder on a submission uploaded as loose files (the solutions:
# full marks), and on one whose lab file includes the solution's (it must not
# build: the compiler cannot read the solutions). The bundle's grades take the
# uid sandbox, as in a container that refuses namespaces: the header must not
# say that lab code can read the references, the cases or the solutions.
# run_prairielearn in a mock of PrairieLearn's /grade, likewise.
#   gradescope_mock.sh SOURCE WORK
set -euo pipefail
source=$1 work=$2
[ "$(id -u)" = 0 ] || { echo "gradescope_mock: needs root (the uid sandbox): skipped"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
chmod 711 "$work"   # the runners (uid 65534) go through it to their files, as through /autograder
fail=0
problem() { echo "gradescope_mock: $*" >&2; fail=1; }
nobody() { setpriv --reuid=65534 --regid=65534 --clear-groups -- "$@"; }
nobody true 2>/dev/null || {
  echo "gradescope_mock: uid 65534 cannot run programs on this machine (the root folder is closed to other users,"
  echo "as in a chroot made with mktemp -d): the uid sandbox this test is about cannot exist here: skipped"
  exit 77
}

# ---- the bundle ----
# (a generous time limit: the test machine may be busy)
"$source/scripts/make-gradescope-bundle" --out "$work/bundle" -- --sandbox uid --lab 2 --timeout 120
for f in setup.sh run_autograder run_prairielearn grader/references/MANIFEST.json solutions labs; do
  [ -e "$work/bundle/$f" ] || problem "the bundle has no $f"
done
if command -v unzip >/dev/null && [ -f "$work/bundle.zip" ]; then
  # grep reads the whole listing (no -q): under pipefail, unzip killed by SIGPIPE would fail the pipe
  unzip -l "$work/bundle.zip" | grep -E ' setup\.sh$' >/dev/null || problem "setup.sh is not at the zip's root"
fi

# ---- the image: /autograder/source, and setup.sh ----
ag="$work/autograder"
mkdir -p "$ag/source" "$ag/submission"
cp -a "$work/bundle/." "$ag/source/"
cp "$ag/source/run_autograder" "$ag/run_autograder"
SHADOWLAB_AUTOGRADER="$ag" bash "$ag/source/setup.sh" >"$work/setup.log" 2>&1 || { cat "$work/setup.log"; problem "setup.sh failed"; exit 1; }
tail -n 3 "$work/setup.log"
grep -Eq '^setup.sh: self-check: Score: ([0-9.]+)/\1( |$)' "$work/setup.log" || problem "no full-marks self-check in setup.sh"
for secret in grader/references/MANIFEST.json grader/cases solutions/lab2_projective/lab2.c build/bin/shadowlab-grade; do
  ! nobody test -r "$ag/source/$secret" || problem "uid 65534 can read $secret"
done
nobody test -r "$ag/source/framework/shaders/scene.vert" || problem "uid 65534 cannot read the framework's shaders"

# ---- a submission: the solutions' files, uploaded loose (labs build on each other: all of them) ----
find "$source/solutions" -type f -exec cp {} "$ag/submission/" \;
set +e
SHADOWLAB_AUTOGRADER="$ag" "$ag/run_autograder" >"$work/full.log" 2>&1
status=$?
set -e
cat "$work/full.log"
results="$ag/results/results.json"
[ "$status" = 0 ] || problem "run_autograder exited with $status"
[ -s "$results" ] || problem "no results.json"
grep -q 'sandbox: uid' "$work/full.log" || problem "the grade did not take the uid sandbox"
! grep -q 'lab code can read' "$work/full.log" || problem "the header says lab code can read the answers"
grep -q '"status":[[:space:]]*"passed"' "$results" || problem "no test passed"
! grep -q '"status":[[:space:]]*"failed"' "$results" || problem "the solutions failed a test"
grep -Eq '^Score: ([0-9.]+)/\1$' "$work/full.log" || problem "the solutions did not get full marks"

# ---- a submission that includes the solution's file ----
rm -rf "$ag/submission" "$ag/results"
mkdir "$ag/submission"
printf '#include "%s"\n' "$ag/source/solutions/lab2_projective/lab2.c" >"$ag/submission/lab2.c"
set +e
SHADOWLAB_AUTOGRADER="$ag" "$ag/run_autograder" >"$work/include.log" 2>&1
status=$?
set -e
cat "$work/include.log"
[ "$status" = 0 ] || problem "run_autograder exited with $status on a submission that does not build"
grep -q '"output":[[:space:]]*"The submission did not build: lab2_projective/lab2.c:1:[0-9]*: fatal error: ' "$results" ||
  problem "results.json does not say the submission did not build, and where"
grep -Eq '"score":[[:space:]]*0,' "$results" || problem "a submission that does not build scored points"

# ---- PrairieLearn: /grade/student -> /grade/results/results.json ----
mkdir -p "$work/grade/student"
cp "$ag/submission/lab2.c" "$work/grade/student/"
SHADOWLAB_AUTOGRADER="$ag" SHADOWLAB_GRADE="$work/grade" "$ag/source/run_prairielearn" >"$work/prairielearn.log" 2>&1 ||
  problem "run_prairielearn failed"
grep -q '"gradable":[[:space:]]*false' "$work/grade/results/results.json" ||
  problem "PrairieLearn's results do not say the submission is not gradable"
exit $fail
