#!/usr/bin/env bash
# make_variant.sh SPEC SOLUTIONS_DIR OUT_DIR
# Copies the solutions to OUT_DIR and puts in the one mistake SPEC describes:
# each "find:" line is replaced by the "replace:" line after it, in "file:".
# Fails when a find line is no longer in the solution, or is there more than
# once, so variants cannot rot or hit the wrong place.
set -euo pipefail
spec=$1 solutions=$2 out=$3
file="" finds=() replaces=()
while IFS= read -r line || [ -n "$line" ]; do
  case "$line" in
    "file: "*) file=${line#file: } ;;
    "find: "*) finds+=("${line#find: }") ;;
    "replace:"*) r=${line#replace:}; replaces+=("${r# }") ;;
  esac
done <"$spec"
[ -n "$file" ] && [ ${#finds[@]} -gt 0 ] && [ ${#finds[@]} = ${#replaces[@]} ] \
  || { echo "$spec: needs file:, and find:/replace: pairs" >&2; exit 1; }
rm -rf "$out.tmp"
mkdir -p "$(dirname "$out")"
cp -R "$solutions" "$out.tmp"
target="$out.tmp/$file"
content=$(cat "$target"; printf x); content=${content%x}
for i in "${!finds[@]}"; do
  case "$content" in
    *"${finds[$i]}"*) ;;
    *) echo "$spec: '${finds[$i]}' is not in $file any more: update the variant" >&2; rm -rf "$out.tmp"; exit 1 ;;
  esac
  rest=${content#*"${finds[$i]}"}
  case "$rest" in
    *"${finds[$i]}"*) echo "$spec: '${finds[$i]}' is in $file more than once: make it unique" >&2; rm -rf "$out.tmp"; exit 1 ;;
  esac
  content=${content/"${finds[$i]}"/"${replaces[$i]}"}
done
printf '%s' "$content" >"$target"
rm -rf "$out"
mv "$out.tmp" "$out"
