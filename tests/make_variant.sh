#!/usr/bin/env bash
# make_variant.sh SPEC SOLUTIONS_DIR OUT_DIR
# Copies the solutions to OUT_DIR and makes the changes SPEC describes: each
# "find:" text is replaced by the "replace:" text after it, in the file named
# by the last "file:" line before them (a variant may change several files).
# "find+:" and "replace+:" lines continue the text above them on a new line,
# for a change that spans lines. "function: NAME" stands for a find text that
# is the whole definition of NAME in that file (from the line that declares it,
# at the start of a line, to the next line that is just "}"), for a change that
# rewrites a function (tests/external). Fails when a find text is no longer in
# its file, or is there more than once, so variants cannot rot or hit the wrong place.
set -euo pipefail
spec=$1 solutions=$2 out=$3
file="" files=() finds=() replaces=() last=""
while IFS= read -r line || [ -n "$line" ]; do
  case "$line" in
    "file: "*) file=${line#file: }; last="" ;;
    "find: "*)
      [ -n "$file" ] || { echo "$spec: a find: before any file:" >&2; exit 1; }
      files+=("$file"); finds+=("${line#find: }"); last=find ;;
    "function: "*)
      [ -n "$file" ] || { echo "$spec: a function: before any file:" >&2; exit 1; }
      files+=("$file"); finds+=($'\001'"${line#function: }"); last=function ;;
    "find+: "* | "find+:")
      [ "$last" = find ] || { echo "$spec: find+: must follow a find: line" >&2; exit 1; }
      r=${line#find+:}; finds[${#finds[@]}-1]+=$'\n'"${r# }" ;;
    "replace:"*) r=${line#replace:}; replaces+=("${r# }"); last=replace ;;
    "replace+:"*)
      [ "$last" = replace ] || { echo "$spec: replace+: must follow a replace: line" >&2; exit 1; }
      r=${line#replace+:}; replaces[${#replaces[@]}-1]+=$'\n'"${r# }" ;;
  esac
done <"$spec"
[ ${#finds[@]} -gt 0 ] && [ ${#finds[@]} = ${#replaces[@]} ] \
  || { echo "$spec: needs file:, and find:/replace: pairs" >&2; exit 1; }
rm -rf "$out.tmp"
mkdir -p "$(dirname "$out")"
cp -R "$solutions" "$out.tmp"
for i in "${!finds[@]}"; do
  target="$out.tmp/${files[$i]}"
  [ -f "$target" ] || { echo "$spec: no file ${files[$i]} in the solutions" >&2; rm -rf "$out.tmp"; exit 1; }
  content=$(cat "$target"; printf x); content=${content%x}
  if [[ "${finds[$i]}" == $'\001'* ]]; then
    # the whole definition of a function: its declaring line, up to the first line that is "}"
    fn=${finds[$i]#$'\001'}
    if ! block=$(awk -v fn="$fn" '
      !inside && $0 ~ ("^[A-Za-z_][A-Za-z0-9_ *]*[ *]" fn "[(]") { inside = 1; n++ }
      inside { print }
      inside && $0 == "}" { inside = 0 }
      END { if (n != 1) exit 1 }' "$target"); then
      echo "$spec: function $fn is not defined once in ${files[$i]}" >&2; rm -rf "$out.tmp"; exit 1
    fi
    finds[$i]=$block
  fi
  case "$content" in
    *"${finds[$i]}"*) ;;
    *) echo "$spec: '${finds[$i]}' is not in ${files[$i]} any more: update the variant" >&2; rm -rf "$out.tmp"; exit 1 ;;
  esac
  rest=${content#*"${finds[$i]}"}
  case "$rest" in
    *"${finds[$i]}"*) echo "$spec: '${finds[$i]}' is in ${files[$i]} more than once: make it unique" >&2; rm -rf "$out.tmp"; exit 1 ;;
  esac
  content=${content/"${finds[$i]}"/"${replaces[$i]}"}
  printf '%s' "$content" >"$target"
done
# A file that comes out as it was keeps its time stamp, so a change to a variant's comments or
# expectations recompiles nothing.
if [ -d "$out" ]; then
  (cd "$out.tmp" && find . -type f) | while IFS= read -r f; do
    if cmp -s "$out.tmp/$f" "$out/$f"; then cp -p "$out/$f" "$out.tmp/$f"; fi
  done
fi
rm -rf "$out"
mv "$out.tmp" "$out"
