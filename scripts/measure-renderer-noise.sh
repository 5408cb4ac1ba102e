#!/usr/bin/env bash
# measure-renderer-noise.sh [BUILD_DIR]
# How much the solutions' captures move when the software renderer changes
# (DESIGN.md: thread count, vector width, CPU features, softpipe): renders
# every reference again under each variation and compares it with the
# shipped one. The figures set the tolerances in grader/cases/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
compare=$build/tests/bin/image_compare
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-36s %-24s %8s %10s %10s %10s %10s\n' variation file largest mean "fail@0.02" "fail@0.05" "fail@0.1"
for variation in LP_NUM_THREADS=0 LP_NATIVE_VECTOR_WIDTH=128 GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 \
                 GALLIUM_OVERRIDE_CPU_CAPS=nosse GALLIUM_DRIVER=softpipe; do
  rm -rf "$work/refs"
  env "$variation" "$build/bin/shadowlab-grade" --update-references --references "$work/refs" --timeout 600 >/dev/null 2>&1 || true
  while IFS= read -r shipped; do
    rel=${shipped#grader/references/}
    fresh=$work/refs/$rel
    [ -f "$fresh" ] || { printf '%-36s %-28s %s\n' "$variation" "$rel" "not rendered"; continue; }
    line=""
    for t in 0.02 0.05 0.1; do
      out=$("$compare" "$fresh" "$shipped" "$t" 100 || true)
      pct=$(sed -E 's/.*: ([0-9.]+)% of pixels differ.*/\1/' <<<"$out")
      largest=$(sed -E 's/.*largest difference ([0-9.]+).*/\1/' <<<"$out")
      mean=$(sed -E 's/.*mean ([0-9.]+).*/\1/' <<<"$out")
      line="$line $(printf '%9s%%' "$pct")"
    done
    printf '%-36s %-24s %8s %10s%s\n' "$variation" "${rel%/*}" "$largest" "$mean" "$line"
  done < <(find grader/references -name '*.exr' | sort)
done
