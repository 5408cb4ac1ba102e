#!/usr/bin/env bash
# lab-dependencies.sh [--check] [DECLARATION]
#
# Prints, for each lab, the sentence its README states about the earlier labs
# it runs, made from the one declaration of lab dependencies
# (framework/lab_dependencies.cmake: SL_LAB<N>_BUILDS_ON, the labs whose code
# the framework calls when it draws lab N; SL_LAB<N>_SHOWS, those whose
# results show in lab N's pictures, which the grader names: "needs lab K first").
#
# --check: each labs/labN_*/README.md must hold its sentence word for word, on
# a line of its own, and the top README.md its list line for each lab
# ("- **Lab N:** ..."); exit 1 naming every README that does not.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
check=false
if [ "${1:-}" = "--check" ]; then check=true; shift; fi
declaration=${1:-$here/framework/lab_dependencies.cmake}
[ -f "$declaration" ] || { echo "lab-dependencies: no $declaration" >&2; exit 2; }

# The labs listed by set(SL_LAB<N>_<WHAT> ...), space-separated, ascending.
labs_of() {
  sed -n "s/^[[:space:]]*set(SL_LAB$1_$2[[:space:]]*\(.*\))[[:space:]]*\$/\1/p" "$declaration" |
    tr -d '"' | tr ' ' '\n' | grep -E '^[0-9]+$' | sort -n | tr '\n' ' ' | sed 's/ $//'
}

# "lab 1", "labs 1 and 2", "labs 1, 2 and 3"
named() {
  local -a l=($1)
  case ${#l[@]} in
    1) echo "lab ${l[0]}" ;;
    *) local last=${l[-1]}; unset 'l[-1]'; local IFS=,; echo "labs ${l[*]// /} and $last" | sed 's/,/, /g' ;;
  esac
}

sentence() {
  local n=$1 builds shows quiet="" k
  builds=$(labs_of "$n" BUILDS_ON)
  shows=$(labs_of "$n" SHOWS)
  for k in $builds; do [[ " $shows " == *" $k "* ]] || quiet="$quiet $k"; done
  quiet=${quiet# }
  if [ -z "$builds" ]; then
    if [ "$n" = 1 ]; then echo "**Earlier labs it runs:** none; lab 1 is where the chain starts."
    else echo "**Earlier labs it runs:** none; lab $n draws with its own code only, so you can do it before the others."
    fi
    return
  fi
  local out="**Earlier labs it runs:**"
  [ -n "$shows" ] && out="$out $(named "$shows"), whose mistakes show in this lab's pictures (the grader says \"needs lab K first\")"
  for k in $quiet; do
    # who brings it: the labs this one builds on that build on it
    local by="" m
    for m in $builds; do [[ " $(labs_of "$m" BUILDS_ON) " == *" $k "* ]] && by="$by $m"; done
    [ -n "$shows" ] && out="$out; lab $k is there too" || out="$out lab $k"
    by=${by# }
    [ -n "$by" ] && { [[ $by == *" "* ]] && out="$out ($(named "$by") build on it)" || out="$out (lab $by builds on it)"; }
    out="$out, but its results do not show here"
  done
  echo "$out."
}

# The top README's line for lab N: the same facts, in its list of labs.
list_line() {
  local s
  s=$(sentence "$1")
  s=${s#"**Earlier labs it runs:** "}
  echo "- **Lab $1:** $s"
}

fail=0
top=$here/README.md
for readme in "$here"/labs/lab[0-9]*_*/README.md; do
  folder=$(basename "$(dirname "$readme")")
  n=${folder#lab}; n=${n%%_*}
  s=$(sentence "$n")
  if $check; then
    grep -qxF -- "$s" "$readme" ||
      { echo "lab-dependencies: labs/$folder/README.md does not say, on a line of its own: $s" >&2; fail=1; }
    [ "$n" = 0 ] || grep -qxF -- "$(list_line "$n")" "$top" ||
      { echo "lab-dependencies: README.md does not say, on a line of its own: $(list_line "$n")" >&2; fail=1; }
  else
    printf 'lab %s: %s\n' "$n" "$s"
    [ "$n" = 0 ] || printf '  README.md: %s\n' "$(list_line "$n")"
  fi
done
$check && [ $fail = 0 ] && echo "lab-dependencies: every lab README states what $(basename "$declaration") declares"
exit $fail
