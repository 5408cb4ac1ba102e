#!/usr/bin/env bash
# The whole test suite in one command: installs what is missing (Debian),
# builds every grader the tests need (student, solutions, wrong variants), and
# runs ctest. CI runs exactly this (.ci/run). The tests' programs (the
# variants', attacks' and per-lab runners) are a target of their own,
# test-programs, outside the default build: a lab edit never relinks them.
# The tests that need untouched stubs take them as committed (build/stubs/labs,
# from git), so this passes whatever labs/ holds.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --tests # and the suite's own tools (the fuzzer's clang)
# The lecture decks' tools (pandoc, WeasyPrint, KaTeX and node, pdftoppm, Chromium), so the slides' tests
# run here and in CI; SL_SLIDES=0 leaves them out (those tests are then skipped).
[ "${SL_SLIDES:-1}" = 0 ] || ./scripts/install-slides-deps.sh
# Chromium and its chromedriver, for the browser viewer's test (shadowlab
# --serve); SL_BROWSER=0 leaves them out (that test is then skipped).
[ "${SL_BROWSER:-1}" = 0 ] || ./scripts/install-browser-deps.sh
generator=() # as bootstrap.sh: Ninja for a new build folder
[ -f build/CMakeCache.txt ] || ! command -v ninja >/dev/null || generator=(-G Ninja)
cmake -S . -B build "${generator[@]+"${generator[@]}"}" -DSL_LABS="${SL_LABS:-student}"
cmake --build build -j "$(nproc)"
cmake --build build -j "$(nproc)" --target test-programs
# Two tests per core: many of them spend much of their time waiting (a virtual display or a
# browser starting, a time limit running out, a grade's pause before it looks for leftovers).
ctest --test-dir build --output-on-failure -j "$((2 * $(nproc)))" --timeout 900
