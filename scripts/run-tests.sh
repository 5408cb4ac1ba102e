#!/usr/bin/env bash
# The whole test suite in one command: installs what is missing (Debian),
# builds every grader the tests need (student, solutions, wrong variants), and
# runs ctest. In a student's tree (no solutions/) it runs the tests that tree
# has and installs only what they use. --plan says which, and changes nothing.
# CI runs exactly this (.ci/run). The tests' programs (the variants', attacks'
# and per-lab runners) are a target of their own, test-programs, outside the
# default build: a lab edit never relinks them.
# The tests that need untouched stubs take them as committed (build/stubs/labs,
# from git), so this passes whatever labs/ holds.
set -euo pipefail
cd "$(dirname "$0")/.."
plan=0
case "${1:-}" in
  --plan) plan=1 ;; # say what would be installed and run, change nothing
  "") ;;
  -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  *) echo "run-tests: unknown option $1 (--plan says what would run)" >&2; exit 2 ;;
esac
installs=()
if [ -d solutions ]; then
  installs=("install-deps.sh --tests") # and the suite's own tools (the fuzzer's clang)
  # The lecture decks' tools (pandoc, WeasyPrint, KaTeX and node, pdftoppm, Chromium), so the slides' tests
  # run here and in CI; SL_SLIDES=0 leaves them out (those tests are then skipped).
  [ "${SL_SLIDES:-1}" = 0 ] || installs+=(install-slides-deps.sh)
  # Chromium and its chromedriver, for the browser viewer's test (shadowlab
  # --serve); SL_BROWSER=0 leaves them out (that test is then skipped).
  [ "${SL_BROWSER:-1}" = 0 ] || installs+=(install-browser-deps.sh)
  echo "run-tests: the staff suite (solutions/ is here): every test"
else
  # A student's tree: the tests that need solutions/ (grades of variants, attacks, slides, the
  # browser) are not configured, so neither their tools nor the fuzzer's clang are installed.
  installs=(install-deps.sh)
  echo "run-tests: a student's tree (no solutions/): the unit tests, the headless contexts and a grade" \
       "of your labs whose report must be complete; the staff tests (they need solutions/) are left out"
fi
if [ $plan = 1 ]; then
  for i in "${installs[@]}"; do echo "run-tests: would run scripts/$i"; done
  exit 0
fi
for i in "${installs[@]}"; do
  read -r -a cmd <<<"$i"
  "./scripts/${cmd[0]}" "${cmd[@]:1}"
done
generator=() # as bootstrap.sh: Ninja for a new build folder
[ -f build/CMakeCache.txt ] || ! command -v ninja >/dev/null || generator=(-G Ninja)
cmake -S . -B build "${generator[@]+"${generator[@]}"}" -DSL_LABS="${SL_LABS:-student}"
cmake --build build -j "$(nproc)"
cmake --build build -j "$(nproc)" --target test-programs
# Two tests per core: many of them spend much of their time waiting (a virtual display or a
# browser starting, a time limit running out, a grade's pause before it looks for leftovers).
ctest --test-dir build --output-on-failure -j "$((2 * $(nproc)))" --timeout 900
