#!/usr/bin/env bash
# make-handout.sh [OUT_DIR]
# The student distribution: one archive with the framework, the labs with
# their stubs, the public cases and their references, the grader, the
# slides, the scripts, the tests a student's copy runs, and the README. No
# solutions/, no wrong variants, no attack suite, nothing of the build.
# Made from the files git tracks, as they are in the working tree.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-dist}
version=$(sed -nE 's/^project\(shadowlab VERSION ([0-9.]+).*/\1/p' CMakeLists.txt)
name=shadowlab-$version
mkdir -p "$out"
out=$(cd "$out" && pwd)
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir "$stage/$name"
# staff-only material: solutions (with the benchmark's plain-GL program), wrong
# variants, attacks, the tests that read the solutions, the handout maker itself
staff='^(solutions/|tests/variants/|tests/attacks/|\.ci/|scripts/make-handout\.sh$|tests/(attack_util\.h|attack\.sh'
staff+='|make_attack\.sh|make_variant\.sh|compile_attacks\.sh|solution_leaks\.sh|handout_answers\.sh|handout\.sh)$)'
git ls-files -z | grep -zvE "$staff" |
  tar --null -T - -cf - | tar -xf - -C "$stage/$name"
if [ -e "$stage/$name/solutions" ] || grep -rqs "sl_solution" "$stage/$name/labs"; then
  echo "make-handout: solutions leaked into the handout" >&2
  exit 1
fi
tar -C "$stage" -czf "$out/$name.tar.gz" "$name"
echo "make-handout: $out/$name.tar.gz ($(du -h "$out/$name.tar.gz" | cut -f1))"
