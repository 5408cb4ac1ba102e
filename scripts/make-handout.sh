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
# staff-only material: solutions, wrong variants, attacks, the handout maker itself
git ls-files -z | grep -zvE '^(solutions/|tests/variants/|tests/attacks/|tests/attack_util\.h$|tests/attack\.sh$|tests/make_attack\.sh$|tests/make_variant\.sh$|scripts/make-handout\.sh$|tests/handout\.sh$|\.ci/)' |
  tar --null -T - -cf - | tar -xf - -C "$stage/$name"
if [ -e "$stage/$name/solutions" ] || grep -rqs "sl_solution" "$stage/$name/labs"; then
  echo "make-handout: solutions leaked into the handout" >&2
  exit 1
fi
tar -C "$stage" -czf "$out/$name.tar.gz" "$name"
echo "make-handout: $out/$name.tar.gz ($(du -h "$out/$name.tar.gz" | cut -f1))"
