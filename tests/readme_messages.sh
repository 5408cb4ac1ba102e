#!/usr/bin/env bash
# Every message a lab README's table promises has a variant that makes it fire.
#   readme_messages.sh LABS_DIR VARIANTS_DIR PENDING [STUBS]
# Walks the message table of each labs/labN_*/README.md (the table headed "the grader says" or
# "message (abridged)"): the first `code` of each row is the message. A variant of lab N in
# VARIANTS_DIR shows it with "readme: MESSAGE", the same text; its test (variant.NAME) grades the
# mistake and expects the message (grade_expect.sh --expect-readme). A row no variant shows yet
# must be listed in PENDING as "N: MESSAGE"; a "readme:" line or a PENDING line that names no row
# of its lab's table fails, so neither can outlive a row that changed.
# A row the untouched stubs make fire ("not implemented: ...") may instead be listed in STUBS as
# "N: MESSAGE": grade.student_scores_zero grades the committed stubs and expects each listed
# message in lab N's section of their report (grade_expect.sh --expect-readme-rows).
set -euo pipefail
labs=$1 variants=$2 pending=$3 stubs=${4:-/dev/null}
fail=0 rows=0 shown=0 by_stubs=0 waiting=0
problem() { echo "readme_messages: $*" >&2; fail=1; }
# the messages of a README's table, one a line
messages() {
  awk '/^\| (the grader says|message \(abridged\)) \|/ {t = 1; next}
       t && !/^\|/ {t = 0}
       t && /^\|[-| ]+\|$/ {next}
       t {print}' "$1" | sed -n 's/^| `\([^`]*\)`.*/\1/p'
}
declare -A row_of claimed is_pending by_stub
for readme in "$labs"/lab[0-9]*_*/README.md; do
  lab=$(basename "$(dirname "$readme")"); lab=${lab#lab}; lab=${lab%%_*}
  while IFS= read -r m; do row_of["$lab: $m"]=1; done < <(messages "$readme")
done
# every "readme:" line of the variants, as NAME, LAB and MESSAGE (a variant's "lab:" comes first)
while IFS=$'\t' read -r spec lab m; do
  name=$(basename "$spec" .variant)
  [ -n "${row_of["$lab: $m"]+x}" ] || problem "$name: no row of lab $lab's README says: $m"
  claimed["$lab: $m"]=$name
done < <(awk 'FNR == 1 {lab = ""} /^lab: / {lab = substr($0, 6)} /^readme: / {print FILENAME "\t" lab "\t" substr($0, 9)}' \
           "$variants"/*.variant)
# "N: MESSAGE" lines of a list file into the set named $2, each naming a row of lab N's table
read_rows() {
  local -n into=$2; local line
  while IFS= read -r line; do
    case "$line" in "" | "#"*) continue ;; esac
    [ -n "${row_of["$line"]+x}" ] || problem "$(basename "$1"): no README row says: $line"
    into["$line"]=1
  done <"$1"
}
read_rows "$pending" is_pending
read_rows "$stubs" by_stub
for key in "${!row_of[@]}"; do
  rows=$((rows + 1))
  if [ -n "${claimed["$key"]+x}" ]; then
    shown=$((shown + 1))
    [ -z "${is_pending["$key"]+x}" ] || problem "lab ${key%%:*}: shown by ${claimed["$key"]}, still listed as pending: ${key#*: }"
  elif [ -n "${by_stub["$key"]+x}" ]; then
    by_stubs=$((by_stubs + 1))
    [ -z "${is_pending["$key"]+x}" ] || problem "lab ${key%%:*}: shown by the stubs' grade, still listed as pending: ${key#*: }"
  elif [ -n "${is_pending["$key"]+x}" ]; then
    waiting=$((waiting + 1))
  else
    problem "lab ${key%%:*}: no variant shows this README message (add one with \"readme:\"): ${key#*: }"
  fi
done
echo "readme_messages: $rows rows, $shown shown by a variant, $by_stubs by the stubs' grade, $waiting pending"
exit $fail
