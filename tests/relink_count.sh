#!/usr/bin/env bash
# relink_count.sh BUILD_DIR README
# The top README says which programs a student's edit to labs/labN_*/labN.c links
# again ("the viewer, the runner, lab N's own runner: 3 programs"). This reads
# Ninja's own graph of the default build (what `cmake --build build` makes) and
# checks, for every lab, that exactly those programs link that lab's object.
# 77 (skipped) where the build was not made by Ninja.
set -euo pipefail
build=$1 readme=$2
[ -f "$build/build.ninja" ] || { echo "relink_count: $build is not a Ninja build: skipped"; exit 77; }
sentence=$(tr '\n' ' ' <"$readme" | grep -o 'the programs that *hold lab N.s code ([^)]*)' | head -n 1) ||
  { echo "relink_count: $readme no longer says which programs a lab edit links again" >&2; exit 1; }
said=$(grep -o '[0-9]* programs)' <<<"$sentence" | grep -o '^[0-9]*')
echo "relink_count: the README says: $sentence"
default=$(ninja -C "$build" -t query all | awk '/^  input:/ {on = 1; next} /^  [a-z]/ {on = 0} on {print $1}' |
          grep '^bin/' | LC_ALL=C sort)
status=0
for n in 1 2 3 4 5 6 7; do
  object=$(ninja -C "$build" -t targets all | grep -o "^CMakeFiles/sl_labs_lab$n\.dir/[^:]*/lab$n\.c\.o" | head -n 1)
  [ -n "$object" ] || { echo "relink_count: no object for lab $n's labN.c in $build" >&2; exit 1; }
  linked=$(ninja -C "$build" -t query "$object" | awk '/^  outputs:/ {on = 1; next} on {print $1}' |
           grep '^bin/' | LC_ALL=C sort)
  relinked=$(LC_ALL=C comm -12 <(printf '%s\n' "$default") <(printf '%s\n' "$linked"))
  expected=$(printf '%s\n' bin/shadowlab bin/shadowlab-runner "bin/shadowlab-runner-isolate-lab$n" | LC_ALL=C sort)
  count=$(grep -c . <<<"$relinked" || true)
  echo "relink_count: lab $n: $count programs:" $relinked
  if [ "$relinked" != "$expected" ] || [ "$count" != "$said" ]; then
    echo "relink_count: lab $n's edit links again $count programs ($(echo $relinked)), the README says $said" \
         "(the viewer, the runner, lab $n's own runner)" >&2
    status=1
  fi
done
exit $status
