#!/usr/bin/env bash
# render-readme-figures.sh VIEWER [OUT_DIR]
# render-readme-figures.sh --check IMAGE_COMPARE VIEWER WORK_DIR
#
# Renders the pictures each lab README opens with ("What a finished lab looks
# like"), from the commands written there: every README line of the form
#
#   ./build/bin/shadowlab ARGS --screenshot labN_NAME.png
#
# runs with VIEWER in place of ./build/bin/shadowlab, headless, one frame, and
# its picture goes to OUT_DIR (default docs/labs, where the READMEs show them).
# VIEWER must draw the solutions (a -DSL_LABS=solutions build's
# build/bin/shadowlab, or the tests' shadowlab-solutions).
#
# --check renders them into WORK_DIR and compares each with the one in
# docs/labs (IMAGE_COMPARE: the grader's neighbourhood compare, a small
# tolerance): a README command, a solution or the renderer changed without
# its picture. It also fails when a picture in docs/labs is named by no
# README, or a README names one that is not there.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
check=""
if [ "${1:-}" = "--check" ]; then check=$2; shift 2; fi
[ $# -ge 1 ] || { echo "usage: render-readme-figures.sh [--check IMAGE_COMPARE] VIEWER [OUT_DIR]" >&2; exit 2; }
viewer=$1
out=${2:-$here/docs/labs}
mkdir -p "$out"
pattern='^\./build/bin/shadowlab (.*) --screenshot (lab[0-9]_[a-z0-9_]+\.png)$'
fail=0 count=0
declare -A named=()
compare_image() { "$check" "$@"; }
if [ -n "$check" ]; then
  # Every compare in one image_compare (`IMAGE_COMPARE -`, a compare a line): loading the
  # image module costs more than a compare.
  coproc comparer { "$check" -; }
  compare_image() {
    local line
    local IFS=$'\t'
    echo "$*" >&"${comparer[1]}"
    while IFS= read -r line <&"${comparer[0]}"; do
      [[ $line =~ ^image_compare:\ exit\ ([0-9]+)$ ]] && return "${BASH_REMATCH[1]}"
      echo "$line"
    done
    echo "render-readme-figures: $check stopped" >&2
    return 2
  }
fi
# Every README command is a line of one `VIEWER --batch` (scripts/viewer-batch.sh: one process, the image
# module and the GL drivers load once); the arguments are the README's own words, split as a shell would,
# without running one. Each line's output goes to a folder of its own, removed at the end.
source "$here/scripts/viewer-batch.sh"
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
readmes=() lines=() names=()
for readme in "$here"/labs/lab*/README.md; do
  while IFS= read -r line; do
    [[ $line =~ $pattern ]] || continue
    args=${BASH_REMATCH[1]} name=${BASH_REMATCH[2]}
    named[$name]=1
    count=$((count + 1))
    read -r -a argv <<<"$args"
    viewer_batch_add "$count" --headless --frames 1 "${argv[@]}" --screenshot "$out/$name"
    readmes+=("$readme") lines+=("$line") names+=("$name")
  done <"$readme"
done
[ "$count" -gt 0 ] && viewer_batch_run "$viewer" "$logs"
for i in "${!names[@]}"; do
  readme=${readmes[$i]} line=${lines[$i]} name=${names[$i]} n=$((i + 1))
  if ! viewer_batch_status "$logs" "$n"; then
    echo "render-readme-figures: ${readme#"$here"/}: '$line' failed:" >&2
    if [ -f "$logs/$n.exit" ]; then cat "$logs/$n.log" >&2; else tail -n 20 "$logs/batch.log" >&2; fi
    fail=1
    continue
  fi
  if [ -n "$check" ]; then
    shipped=$here/docs/labs/$name
    if [ ! -f "$shipped" ]; then
      echo "render-readme-figures: ${readme#"$here"/} shows docs/labs/$name, which is not there" >&2
      fail=1
    elif ! compare_image "$out/$name" "$shipped" 0.05 0.2; then
      echo "render-readme-figures: docs/labs/$name does not match what '$line' renders" >&2
      fail=1
    fi
  fi
done
[ "$count" -gt 0 ] || { echo "render-readme-figures: no figure commands in labs/*/README.md" >&2; exit 1; }
if [ -n "$check" ]; then
  for shipped in "$here"/docs/labs/*.png; do
    [ -e "$shipped" ] || continue
    name=$(basename "$shipped")
    [ -n "${named[$name]:-}" ] || { echo "render-readme-figures: docs/labs/$name is shown by no lab README" >&2; fail=1; }
  done
fi
echo "render-readme-figures: $count pictures${check:+ checked}"
exit $fail
