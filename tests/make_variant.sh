#!/usr/bin/env bash
# make_variant.sh SPEC SOLUTIONS_DIR OUT_DIR
# Copies the solutions to OUT_DIR and makes the changes SPEC describes: each
# "find:" text is replaced by the "replace:" text after it, in the file named
# by the last "file:" line before them (a variant may change several files).
# "find+:" and "replace+:" lines continue the text above them on a new line,
# for a change that spans lines. Fails when a find text is no longer in its
# file, or is there more than once, so variants cannot rot or hit the wrong place.
# "function: NAME" stands for a whole definition in that file, from the line
# that starts it (a type at the line's start, then NAME and "(", no ";") to the
# first line that is only "}" after it: the next "replace:" text replaces it
# all (tests/external/'s adaptations write whole functions of their own).
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
      files+=("$file"); finds+=($'\x01'"${line#function: }"); last="" ;;
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
  if [ "${finds[$i]:0:1}" = $'\x01' ]; then
    # a whole definition: its lines, found by name
    name=${finds[$i]:1}
    span=$(awk -v name="$name" '
      BEGIN { pat = "^[A-Za-z_][A-Za-z0-9_ \\t\\*]*[ \\t\\*]" name "\\(" }
      start == 0 && $0 ~ pat && $0 !~ /;[ \t]*$/ { start = NR; count++; next }
      start > 0 && end == 0 && $0 == "}" { end = NR }
      $0 ~ pat && $0 !~ /;[ \t]*$/ && NR != start { count++ }
      END { print start, end, count }' "$target")
    read -r first last_line count <<<"$span"
    if [ "${count:-0}" != 1 ] || [ "${last_line:-0}" = 0 ]; then
      echo "$spec: the definition of ${name}() is not in ${files[$i]} exactly once: update the variant" >&2
      rm -rf "$out.tmp"; exit 1
    fi
    { head -n $((first - 1)) "$target"; printf '%s\n' "${replaces[$i]}"; tail -n +$((last_line + 1)) "$target"; } >"$target.new"
    mv "$target.new" "$target"
    continue
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
rm -rf "$out"
mv "$out.tmp" "$out"
