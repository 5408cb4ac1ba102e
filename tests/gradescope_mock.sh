#!/usr/bin/env bash
# The Gradescope bundle end to end, in a mock of Gradescope's layout under a
# temporary folder: make the bundle of an assignment of one lab (--lab 3), run
# its setup.sh as the image build does, then run_autograder on a submission of
# that lab alone, uploaded as loose files (the solution's lab 3: full marks,
# the solutions standing in for labs 1 and 2, its bonus said in words and the
# score at the maximum), on one whose lab file includes the solution's (it
# must not build: the compiler cannot read the solutions), and with hidden
# cases (their tests shown after the due date). The bundle's grades take the
# uid sandbox, as in a container that refuses namespaces: the header must not
# say that lab code can read the references, the cases or the solutions.
# run_prairielearn in a mock of PrairieLearn's /grade, likewise: a score in
# [0, 1], and a failed picture's diff image in its test.
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
"$source/scripts/make-gradescope-bundle" --out "$work/bundle" --lab 3 -- --sandbox uid --timeout 120
for f in setup.sh run_autograder run_prairielearn grader/references/MANIFEST.json solutions labs; do
  [ -e "$work/bundle/$f" ] || problem "the bundle has no $f"
done
grep -qx -- '--lab' "$work/bundle/grader-options" && grep -qx 3 "$work/bundle/grader-options" ||
  problem "the bundle of lab 3 does not grade lab 3 alone"
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

# ---- a submission of lab 3 alone: the solution's files, uploaded loose ----
find "$source/solutions/lab3_bias" -type f -exec cp {} "$ag/submission/" \;
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
grep -Eq '^Score: ([0-9.]+)/\1 \(\+[0-9.]+ bonus\)$' "$work/full.log" ||
  problem "lab 3 alone did not get full marks and its bonus"
grep -q 'each lab isolated' "$work/full.log" || problem "the submission was not graded per lab"
! grep -q 'Lab [1245-7] (' "$results" || problem "the assignment of lab 3 graded other labs"
# the score is the maximum (the bonus kept apart: the default --bonus policy); the bonus is said in words
max=$(sed -nE 's/^Score: [0-9.]+\/([0-9.]+).*/\1/p' "$work/full.log")
score=$(grep -Eo '"score":[[:space:]]*[0-9.]+' "$results" | head -n 1 | grep -Eo '[0-9.]+$')
[ "$score" = "$max" ] || problem "Gradescope's score is $score, not the maximum $max"
grep -q '"output":[[:space:]]*"Bonus: [0-9.]* points earned on extension checks, kept apart from the score' "$results" ||
  problem "Gradescope's output does not say the bonus in words"

# ---- a submission that includes the solution's file ----
rm -rf "$ag/submission" "$ag/results"
mkdir "$ag/submission"
printf '#include "%s"\n' "$ag/source/solutions/lab3_bias/lab3.c" >"$ag/submission/lab3.c"
set +e
SHADOWLAB_AUTOGRADER="$ag" "$ag/run_autograder" >"$work/include.log" 2>&1
status=$?
set -e
cat "$work/include.log"
[ "$status" = 0 ] || problem "run_autograder exited with $status on a submission that does not build"
grep -q '"output":[[:space:]]*"The submission did not build: lab3_bias/lab3.c:1:[0-9]*: fatal error: ' "$results" ||
  problem "results.json does not say the submission did not build, and where"
grep -Eq '"score":[[:space:]]*0,' "$results" || problem "a submission that does not build scored points"

# ---- hidden cases: their tests show after the due date ----
rm -rf "$ag/submission" "$ag/results"
mkdir "$ag/submission"
find "$source/solutions/lab3_bias" -type f -exec cp {} "$ag/submission/" \;
cp "$ag/source/grader-options" "$work/grader-options.public"
printf -- '--hidden\n--seed\n7\n--case\nlab3_contact\n' >>"$ag/source/grader-options"
set +e
SHADOWLAB_AUTOGRADER="$ag" "$ag/run_autograder" >"$work/hidden.log" 2>&1
status=$?
set -e
cp "$work/grader-options.public" "$ag/source/grader-options"
[ "$status" = 0 ] || { cat "$work/hidden.log"; problem "run_autograder exited with $status on hidden cases"; }
grep -q 'hidden cases: variants' "$work/hidden.log" || problem "the hidden run did not grade hidden cases"
tests=$(grep -o '"name":' "$results" | wc -l)
after=$(grep -o '"visibility":[[:space:]]*"after_due_date"' "$results" | wc -l)
[ "$tests" -gt 0 ] && [ "$tests" = "$after" ] || problem "$after of $tests hidden tests show after the due date"

# ---- PrairieLearn: /grade/student -> /grade/results/results.json ----
pl_results="$work/grade/results/results.json"
mkdir -p "$work/grade/student"
printf '#include "%s"\n' "$ag/source/solutions/lab3_bias/lab3.c" >"$work/grade/student/lab3.c"
SHADOWLAB_AUTOGRADER="$ag" SHADOWLAB_GRADE="$work/grade" "$ag/source/run_prairielearn" >"$work/prairielearn.log" 2>&1 ||
  problem "run_prairielearn failed"
grep -q '"gradable":[[:space:]]*false' "$pl_results" ||
  problem "PrairieLearn's results do not say the submission is not gradable"
# an upload without a lab file: not gradable, and never also told how its labs were graded
rm -rf "$work/grade/student" "$work/grade/results"
mkdir -p "$work/grade/student"
echo "see attached" >"$work/grade/student/notes.txt"
SHADOWLAB_AUTOGRADER="$ag" SHADOWLAB_GRADE="$work/grade" "$ag/source/run_prairielearn" >"$work/prairielearn-empty.log" 2>&1 ||
  problem "run_prairielearn failed on an upload without a lab file"
python3 - "$pl_results" <<'PY' || problem "PrairieLearn's verdict on an upload without a lab file (above)"
import json, sys
r = json.load(open(sys.argv[1], encoding="utf-8"))
said = " ".join([r.get("message", "")] + r.get("format_errors", []))
bad = [w for w, ok in [("gradable is not false", r.get("gradable") is False),
                       ("no format error names the missing lab file", any("No lab file found" in e for e in r.get("format_errors", []))),
                       ("it is told its labs were graded", "graded as the handout's stub" not in said),
                       ("it is not told nothing was graded", "Nothing was graded" in said)] if not ok]
for b in bad: print("PrairieLearn:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
# the solution's lab 3: a score of 1 (not above), the bonus in words
rm -rf "$work/grade/student" "$work/grade/results"
mkdir -p "$work/grade/student"
find "$source/solutions/lab3_bias" -type f -exec cp {} "$work/grade/student/" \;
SHADOWLAB_AUTOGRADER="$ag" SHADOWLAB_GRADE="$work/grade" "$ag/source/run_prairielearn" >"$work/prairielearn-full.log" 2>&1 ||
  problem "run_prairielearn failed on the solution's lab 3"
grep -Eq '"score":[[:space:]]*1[,}[:space:]]' "$pl_results" ||
  problem "PrairieLearn's score is not 1: $(grep -o '"score":[^,]*' "$pl_results" | head -n 1)"
grep -q '"message":[[:space:]]*"Bonus: ' "$pl_results" || problem "PrairieLearn's message does not say the bonus in words"
# a mistake in a picture (lab 3's slope-scaled bias without its slope term: acne in the pictures, more
# points than the bonus gives back): the test carries its diff image
rm -rf "$work/grade/student" "$work/grade/results"
bash "$source/tests/make_variant.sh" "$source/tests/variants/lab3_no_slope_term.variant" "$source/solutions" \
  "$work/variant" >/dev/null
mkdir -p "$work/grade/student"
cp -R "$work/variant/lab3_bias" "$work/grade/student/"
SHADOWLAB_AUTOGRADER="$ag" SHADOWLAB_GRADE="$work/grade" "$ag/source/run_prairielearn" >"$work/prairielearn-mistake.log" 2>&1 ||
  problem "run_prairielearn failed on a mistake"
grep -Eq '"score":[[:space:]]*0\.[0-9]' "$pl_results" || problem "a mistake's PrairieLearn score is not below 1"
grep -q '"url":[[:space:]]*"data:image/png;base64,iVBOR' "$pl_results" || problem "no diff image in PrairieLearn's results"
[ "$(stat -c %s "$pl_results")" -lt 1000000 ] || problem "PrairieLearn's results are 1 MB or more"
exit $fail
