#!/usr/bin/env bash
# compile_error_text.sh SOURCE BUILD WORK
# A submission whose lab 1 does not compile, with a compiler error that quotes
# bytes no report can hold: a #error line with bytes that are not UTF-8, an
# overlong form, a terminal escape, and a long tail (the first error is cut to
# 300 bytes; the compiler, run with LANG=C, writes the tail's accents as \U...
# escapes). Graded through scripts/grade-submission (lab 1's probes): lab 1 did
# not build, every report reads with a strict reader (check_reports.py), and
# the error's bad bytes are U+FFFD. About 10 s.
set -uo pipefail
src=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work/submission"
fail=0
problem() { echo "compile_error_text: $*" >&2; fail=1; }
fence=$("$build/bin/shadowlab-fence" --probe)
case "$fence" in
  namespaces|uid) ;;
  *) echo "compile_error_text: this machine gives the compiler no fence ($fence): skipped"; exit 77 ;;
esac
stubs=${SHADOWLAB_STUBS:-$src/labs}
{
  printf '#error bad \377\376 bytes \300\257 overlong \033[2J escape '
  for _ in $(seq 300); do printf '\303\251'; done
  printf '\n'
  cat "$stubs/lab1_depth_fbo/lab1.c"
} >"$work/submission/lab1.c"
set +e
"$src/scripts/grade-submission" --build "$build" --jobs 2 "$work/submission" -- --lab 1 --case lab1_probes \
  --report "$work/report" --junit "$work/junit.xml" --gradescope "$work/gradescope.json" \
  --prairielearn "$work/prairielearn.json" >"$work/out.txt" 2>&1
status=$?
set -e
cat "$work/out.txt"
[ "$status" = 1 ] || problem "exit status $status, expected 1 (checks failed)"
grep -q "^shadowlab-grade: lab 1 did not build: .*#error bad" "$work/out.txt" || problem "the grade does not say lab 1 did not build"
python3 "$src/tests/check_reports.py" --text "$work/out.txt" --json "$work/report/results.json" \
  --json "$work/gradescope.json" --json "$work/prairielearn.json" --junit "$work/junit.xml" \
  --html "$work/report/report.html" || problem "a report a strict reader refuses (above)"
# the error as the reports hold it: bad bytes as U+FFFD, the escape gone, cut at its limit
python3 - "$work/report/results.json" <<'PY' || problem "results.json's build error is not the cleaned first error"
import json, sys
error = json.load(open(sys.argv[1], encoding="utf-8"))["build_error"]
assert "#error bad \ufffd bytes \ufffd overlong  escape " in error, error
assert error.endswith("...") and len(error.encode()) <= len("lab 1 did not build: ") + 300, error
PY
exit $fail
