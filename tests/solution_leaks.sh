#!/usr/bin/env bash
# solution_leaks.sh SOURCE_DIR FILE...
# Whether any of FILE (a grade's output, its reports) shows a line of the
# solutions: a line of code (24 characters or more, comments left out) that
# the solutions have and neither the stubs nor the framework's shaders have.
# Prints the lines found and exits 1; exits 0 when there is none.
set -uo pipefail
src=$1
shift
code_lines() { # the trimmed code lines of the files given, one per line, sorted and unique
  sed -e 's|//.*||' -e 's|/\*.*\*/||' -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' "$@" 2>/dev/null |
    grep -vE '^(\*|/\*|#include|#version)' | awk 'length($0) >= 24' | LC_ALL=C sort -u
}
solutions=$(find "$src/solutions" -type f \( -name '*.c' -o -name '*.glsl' -o -name '*.vert' -o -name '*.frag' -o -name '*.geom' \))
# the stubs as committed (SHADOWLAB_STUBS, set by ctest), not a working labs/ that may hold finished labs
others=$(find "${SHADOWLAB_STUBS:-$src/labs}" "$src/framework/shaders" -type f)
# shellcheck disable=SC2086
distinctive=$(LC_ALL=C comm -23 <(code_lines $solutions) <(code_lines $others))
[ -n "$distinctive" ] || { echo "solution_leaks: no distinctive solution line found (is $src the project?)" >&2; exit 2; }
found=$(grep -F -h -o -f <(printf '%s\n' "$distinctive") "$@" 2>/dev/null | LC_ALL=C sort -u)
if [ -n "$found" ]; then
  echo "solution text in the grade's output or reports:"
  sed 's/^/  /' <<<"$found" | head -n 10
  exit 1
fi
exit 0
