#!/usr/bin/env bash
# make-handout.sh [--committed | --from-working-tree] [OUT_DIR]
# The student distribution: one archive with the framework, the labs with
# their stubs, the public cases and their references, the grader, the
# slides, the scripts, the tests a student's copy runs, and the README. No
# solutions/, no wrong variants, no attack suite, nothing of the build, no
# lecturer's notes in the decks' Markdown (the answers to the room's questions).
# Made from the files git tracks, as they are in the working tree, except
# labs/: the stubs as committed (HEAD). Where labs/ differs from HEAD (edits,
# finished labs, new files) it refuses and names what differs, unless told:
#   --committed          pack HEAD's stubs, whatever labs/ holds
#   --from-working-tree  pack labs/ as it is (stubs edited and not yet committed)
set -euo pipefail
cd "$(dirname "$0")/.."
labs_from=""
while [ $# -gt 0 ]; do
  case "$1" in
    --committed) labs_from=committed; shift ;;
    --from-working-tree) labs_from=working; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "make-handout: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
out=${1:-dist}
has_git=0
git rev-parse --verify -q HEAD:labs >/dev/null 2>&1 && has_git=1
if [ $has_git = 1 ] && [ -z "$labs_from" ]; then
  differs=$(git status --porcelain --untracked-files=all -- labs | head -n 10)
  if [ -n "$differs" ]; then
    echo "make-handout: labs/ differs from the committed stubs (HEAD):" >&2
    sed 's/^/  /' <<<"$differs" >&2
    echo "make-handout: the handout takes the stubs as committed. Commit the stubs you mean to ship, or give" >&2
    echo "  --committed (pack HEAD's stubs, leave labs/ alone) or --from-working-tree (pack labs/ as it is)" >&2
    exit 2
  fi
fi
[ -n "$labs_from" ] || labs_from=committed
[ $has_git = 1 ] || labs_from=working
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
staff+='|make_attack\.sh|make_variant\.sh|any_tree\.sh|compile_attacks\.sh|solution_leaks\.sh|handout_answers\.sh|handout\.sh|experiments\.sh)$)'
git ls-files -z | grep -zvE "$staff" | grep -zvE '^labs/' |
  tar --null -T - -cf - | tar -xf - -C "$stage/$name"
if [ $labs_from = committed ]; then
  git archive --format=tar HEAD labs | tar -xf - -C "$stage/$name"
else
  git ls-files -z -- labs | tar --null -T - -cf - | tar -xf - -C "$stage/$name"
fi
# The decks' Markdown without the lecturer's blocks: `::: notes` (the lecturer's notes, which hold the
# answers to the questions for the room) and `::: lecturer`, as the students' decks are built
# (slides/tools/prepare_deck.py). Neither holds a `:::` of its own (slides/README.md).
for deck in "$stage/$name"/slides/*.md; do
  [ "$(basename "$deck")" != README.md ] || continue
  awk '/^::: *(notes|lecturer) *$/ {skip = 1; next} skip && /^::: *$/ {skip = 0; next} !skip' "$deck" >"$deck.tmp"
  mv "$deck.tmp" "$deck"
done
if grep -lE '^::: *(notes|lecturer) *$' "$stage/$name"/slides/*.md 2>/dev/null | grep -v '/README\.md$'; then
  echo "make-handout: the lecturer's notes are still in the decks above" >&2
  exit 1
fi
if [ -e "$stage/$name/solutions" ] || grep -rqs "sl_solution" "$stage/$name/labs"; then
  echo "make-handout: solutions leaked into the handout" >&2
  exit 1
fi
tar -C "$stage" -czf "$out/$name.tar.gz" "$name"
echo "make-handout: $out/$name.tar.gz ($(du -h "$out/$name.tar.gz" | cut -f1))"
