#!/usr/bin/env bash
# Makes a folder of student submissions from the solutions and the variants in
# tests/variants: one submission folder per name, holding a labs/ tree with
# the lab files alone (labN.c and shaders/), as a student would hand it in.
#
#   make_submissions.sh SOURCE OUT [STUDENT=]WHAT...
#
# WHAT is a variant (tests/variants/WHAT.variant: that mistake in the
# solutions), "solutions" (full marks) or "stubs" (the handout untouched); the
# submission's folder is named STUDENT, or WHAT (two students may make one mistake).
# Used by the batch tests and the batch-grading measure (scripts and README).
set -euo pipefail
source=$1 out=$2
shift 2
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for item in "$@"; do
  name=${item%%=*} what=${item#*=}
  case "$what" in
    solutions) tree="$source/solutions" ;;
    stubs) tree="${SHADOWLAB_STUBS:-$source/labs}" ;;
    *) spec="$source/tests/variants/$what.variant"
       [ -f "$spec" ] || { echo "make_submissions: no variant $what" >&2; exit 1; }
       [ -d "$work/$what" ] || bash "$source/tests/make_variant.sh" "$spec" "$source/solutions" "$work/$what" >/dev/null
       tree="$work/$what" ;;
  esac
  rm -rf "$out/$name"
  mkdir -p "$out/$name/labs"
  for lab in "$tree"/lab[0-9]*_*/; do
    folder=$(basename "$lab")
    mkdir -p "$out/$name/labs/$folder"
    cp "$lab"/lab[0-9].c "$out/$name/labs/$folder/"
    cp -R "$lab/shaders" "$out/$name/labs/$folder/shaders"
  done
done
