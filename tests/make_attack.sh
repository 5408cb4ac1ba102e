#!/usr/bin/env bash
# make_attack.sh ATTACK_DIR SOURCE_DIR OUT_DIR [STUBS_DIR]
# A labs tree for one attack: the untouched stubs (STUBS_DIR: the build's
# stubs as committed; SOURCE_DIR/labs without it) with the
# attack's files laid over them. In those files, @SOURCE_DIR@ becomes the
# project's absolute path and @RELATIVE_SOURCE_DIR@ its path relative to the
# file's own folder, as a student who knows the layout would write them. The
# attacks' shared helpers (tests/attack_util.h) are copied beside the file that
# includes them: the compile fence shows the compiler a lab's own folder only.
set -euo pipefail
attack=${1%/} src=$2 out=$3 stubs=${4:-$2/labs} # (a folder given as dir/ is the same folder)
rm -rf "$out.tmp"
mkdir -p "$(dirname "$out")"
cp -R "$stubs" "$out.tmp"
while IFS= read -r file; do
  rel=${file#"$attack/"}
  case "$rel" in README.md) continue ;; esac
  target="$out.tmp/$rel"
  mkdir -p "$(dirname "$target")"
  folder=$(dirname "$out/$rel")
  relative=$(realpath -m --relative-to="$folder" "$src")
  if grep -q '@SOURCE_DIR@/tests/attack_util.h' "$file"; then cp "$src/tests/attack_util.h" "$(dirname "$target")/"; fi
  sed -e 's|"@SOURCE_DIR@/tests/attack_util.h"|"attack_util.h"|' \
      -e "s|@SOURCE_DIR@|$src|g" -e "s|@RELATIVE_SOURCE_DIR@|$relative|g" "$file" >"$target"
done < <(find "$attack" -type f | sort)
rm -rf "$out"
mv "$out.tmp" "$out"
