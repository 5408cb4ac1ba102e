#!/usr/bin/env bash
# references_reproduce.sh GRADER IMAGE_COMPARE GRADER_SOURCE_DIR WORK_DIR
# Renders the references again from the solutions and checks that the shipped
# ones match: a solution changed without its references would show up here.
# The fresh MANIFEST.json must list the same files as the shipped one.
set -u
grader=$1 compare=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
"$grader" --update-references --references "$work" || exit 1
fail=0
while IFS= read -r shipped; do
  rel=${shipped#"$src/references/"}
  fresh="$work/$rel"
  [ -f "$fresh" ] || { echo "no fresh render of $rel" >&2; fail=1; continue; }
  case "$rel" in
    MANIFEST.json)
      diff <(grep -oE '"[a-z_]+\.(exr|png|json)"' "$fresh" | sort) <(grep -oE '"[a-z_]+\.(exr|png|json)"' "$shipped" | sort) >/dev/null ||
        { echo "MANIFEST.json lists other files than the shipped one" >&2; fail=1; } ;;
    *.exr) "$compare" "$fresh" "$shipped" 0.002 0.5 || fail=1 ;;
    *.png) "$compare" "$fresh" "$shipped" 0.1 0.5 || fail=1 ;;
    *.probe.json) python3 "$(dirname "$0")/probe_references_agree.py" "$src/cases" "$fresh" "$shipped" || fail=1 ;;
    *.json)
      # matrices: every number within 1e-4 + 1e-4 of its size (floats computed by another compiler or
      # cglm version round differently)
      paste <(grep -oE -- '-?[0-9.]+(e-?[0-9]+)?' "$fresh") <(grep -oE -- '-?[0-9.]+(e-?[0-9]+)?' "$shipped") |
        awk -v f="$rel" '{d=$1-$2; if (d<0) d=-d; m=$2<0?-$2:$2; if (d>1e-4+1e-4*m) {print f ": " $1 " vs " $2; bad=1}} END {exit bad}' || fail=1 ;;
  esac
done < <(find "$src/references" -type f | sort)
[ "$(find "$work" -type f | wc -l)" = "$(find "$src/references" -type f | wc -l)" ] ||
  { echo "the cases need other references than the ones shipped" >&2; fail=1; }
exit $fail
