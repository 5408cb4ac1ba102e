#!/usr/bin/env bash
# readme-criteria.sh [--check] CASE_CRITERIA [CASES_DIR]
#
# Writes, into each labs/labN_*/README.md, the criteria the grader applies to
# that lab's checks, in words, made from what the lab's case files apply:
# CASE_CRITERIA is the build's tests/bin/case_criteria, which reads the case
# files as the grader does (a case's own numbers over the defaults of
# framework/sl_case.c's table; the shared rules of framework/sl_compare.h).
# The list stands between these two lines of the README, which this script
# replaces with what it makes:
#
#   <!-- criteria: ... -->
#   <!-- end of criteria -->
#
# Change a tolerance in a case file or the table, then run this script.
# --check: writes nothing; exit 1 naming every README whose list is not what
# the cases apply, and every grading figure a README states outside its list
# (a "within 0.1 of", an "at most 0.5% of pixels": the list says those, once).
# Either way, grader/cases/README.md's table of check kinds must state the
# defaults of framework/sl_case.c's table (it is checked, never written).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
check=false
if [ "${1:-}" = "--check" ]; then check=true; shift; fi
tool=${1:-}
cases=${2:-$here/grader/cases}
[ -x "$tool" ] || { echo "readme-criteria: give the built case_criteria (tests/bin/case_criteria), not '$tool'" >&2; exit 2; }
begin='<!-- criteria: scripts/readme-criteria.sh writes this list from the case files (grader/cases); change them, then run it -->'
end='<!-- end of criteria -->'

applied=$("$tool" "$cases"/lab[0-9]*_*.json) || { echo "readme-criteria: the case files do not load" >&2; exit 2; }

# The list for lab $1: one line per group of checks that apply the same numbers.
criteria_of() {
  awk -F'\t' -v lab="$1" '
    function num(x,   s) {             # 0.05, 0.0001, 0.00002: no exponents in a student text
      if (x == 0) return "0"
      s = sprintf("%.4g", x)
      if (s ~ /e/) { s = sprintf("%.10f", x); sub(/0+$/, "", s) }
      return s
    }
    function pct(x) { return num(100 * x) "%" }
    function compared(what, k,   s) {   # the neighbourhood compare, a pass/fail share and a mean
      s = "a " what " passes when some " what " of the reference'"'"'s " n "×" n " neighbourhood is within " \
          num(threshold[k]) " of it, and the other way round; at most " pct(fail[k]) " of " what "s may fail, none may be NaN"
      if (mean[k] > 0) s = s ", and the mean difference may be at most " num(mean[k])
      return s
    }
    /^rule / { split($0, r, " "); rule[r[2]] = r[3]; next }
    $1 != "check" || $2 != lab { next }
    {
      key = $5 SUBSEP $6 SUBSEP $7 SUBSEP $8 SUBSEP $9 SUBSEP $10
      if (!(key in cases)) { order[++groups] = key; kind[key] = $5; threshold[key] = $6; fail[key] = $7
                              mean[key] = $8; epsilon[key] = $9; binarise[key] = $10; cases[key] = "" }
      name = "`" $3 "`" ($11 == 1 ? " (bonus)" : "")
      if (index(cases[key], name) == 0) cases[key] = cases[key] (cases[key] == "" ? "" : ", ") name
    }
    END {
      n = rule["neighbourhood"]
      for (g = 1; g <= groups; g++) {
        k = order[g]; t = kind[k]
        if (t == "fbo") continue                          # complete or not: no figure
        if (t == "depth_map") s = "**depth map**: " compared("texel", k) "."
        else if (t == "cube_face") s = "**cube faces**, each on its own: " compared("texel", k) ". A face stores distance / far."
        else if (t == "moments" || t == "moments_blurred")
          s = "**" (t == "moments" ? "moments before the blur" : "moments after the blur") "**, each channel (depth, depth squared) on its own: " \
              compared("texel", k) ". The target must be 32-bit float in red and green."
        else if (t == "matrices") s = "**matrices**: every entry within " num(epsilon[k]) " of the reference'"'"'s (relative to its largest entry, where that is over 1)."
        else if (t == "visibility" || t == "image") {
          s = "**" (t == "image" ? "shaded image" : "visibility") "**: "
          if (binarise[k] > 0) s = s "both pictures are first read as lit (1) from " num(binarise[k]) " on and shadowed (0) below it; then "
          s = s compared("pixel", k) "."
          if (t == "visibility")
            s = s " It also fails when more than " pct(rule["visibility_max_shadow_lost"]) " of the reference'"'"'s shadow on surfaces facing the light (where it has " \
                rule["visibility_min_shadow_pixels"] " pixels or more) is lit in yours with no shadowed pixel within one pixel."
        } else if (t == "penumbra")
          s = "**penumbra**: along each of the case'"'"'s probe lines, your penumbra may be wider or narrower than the reference'"'"'s by at most " \
              pct(threshold[k]) " of its width (2 pixels where that is more); and at most " pct(rule["lit_max_lost"]) \
              " of the surfaces the reference shows lit (where it has " rule["lit_min_pixels"] " or more) may be dark in yours."
        else if (t == "bleeding")
          s = "**bleeding**: in the reference'"'"'s umbra (its visibility at most " num(rule["bleeding_umbra"]) " on surfaces facing the light), the share of pixels lit above " \
              num(threshold[k]) " with your reduction may be at most " pct(rule["bleeding_max_kept"]) " of the share without it, or under " pct(rule["bleeding_negligible"]) \
              " (an umbra of fewer than " rule["bleeding_min_umbra_pixels"] " pixels passes); and at most " pct(rule["lit_max_lost"]) " of the surfaces the reference shows lit (where it has " \
              rule["lit_min_pixels"] " or more) may be dark in yours."
        else if (t == "cascade_index")
          s = "**cascade index**: " compared("pixel", k) ". Indices are whole numbers: within " num(threshold[k]) " means the same cascade."
        else if (t == "flicker")
          s = "**flicker**: along the camera path, at most " pct(threshold[k]) " of the world-fixed receiver pixels (surfaces facing the light) may change between lit and shadowed " \
              "from one frame to the next, averaged over the frames; your frames must be in shadow at least " pct(rule["flicker_min_shadow_kept"]) \
              " as often as the reference'"'"'s (where it shadows " pct(rule["flicker_min_reference_shadow"]) " of them or more), and at most " pct(rule["lit_max_lost"]) \
              " of the surfaces the reference shows lit (where it has " rule["lit_min_pixels"] " or more) may be dark in yours."
        else s = "**" t "**: the threshold " num(threshold[k]) ", at most " pct(fail[k]) " failing."
        sub(/\*\*: /, "** (" cases[k] "): ", s)             # the check, its cases, then what it applies
        sub(/\*\*, each on its own: /, "** (" cases[k] "), each on its own: ", s)
        sub(/\*\*, each channel /, "** (" cases[k] "), each channel ", s)
        print "- " s
      }
    }' <<<"$applied"
}

# The README with its list replaced by $2 (a file); the README as it is when it has no markers.
with_list() {
  awk -v begin="$begin" -v end="$end" -v list="$2" '
    $0 == begin { print; while ((getline line < list) > 0) print line; skip = 1; next }
    $0 == end { skip = 0 }
    !skip { print }' "$1"
}

# Grading figures outside the list: "within 0.1 of", "at most 0.5% of pixels", "0.5% of texels fail", "allowed 0.5%",
# "mean difference at most 0.002".
# The grader's messages quoted in a table row or between backticks are its own words, checked by the variants.
stray_figures() {
  awk -v begin="$begin" -v end="$end" '
    $0 == begin { skip = 1; next }
    $0 == end { skip = 0; next }
    skip || /^\| `/ { next }
    { line = $0; gsub(/`[^`]*`/, "", line)
      if (line ~ /within [0-9.]+ of (some|the|it)|[0-9.]+% of (the )?(pixels|texels) (may )?fail|allowed [0-9.]+%|mean difference at most [0-9]|at most [0-9.]+% of (the )?(pixels|texels)/)
        print FILENAME ":" FNR ": " $0 }' "$1"
}

# grader/cases/README.md's table of check kinds: the defaults each row states are sl_case.c's.
same() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-9 * (b < 0 ? -b : b) + 1e-15) }'; }
defaults_stated() {
  local doc=$1 kind col t f m e said
  declare -A thr fail_of mean_of eps
  while IFS=$'\t' read -r _ kind t f m e; do thr[$kind]=$t fail_of[$kind]=$f mean_of[$kind]=$m eps[$kind]=$e; done < <(grep '^default' <<<"$applied")
  while IFS=$'\t' read -r kind col; do
    [ -n "${thr[$kind]+x}" ] || { echo "  $kind: no such check kind"; continue; }
    said=""
    if [[ $col =~ threshold\ ([0-9.e-]+)(\ \([^\)]*\))?,\ ([0-9.]+)%\ of\ (pixels|texels),\ mean\ ([0-9.e-]+) ]]; then
      said="threshold ${BASH_REMATCH[1]}, ${BASH_REMATCH[3]}%, mean ${BASH_REMATCH[5]}"
      same "${BASH_REMATCH[1]}" "${thr[$kind]}" && same "$(awk -v p="${BASH_REMATCH[3]}" 'BEGIN { print p / 100 }')" "${fail_of[$kind]}" &&
        same "${BASH_REMATCH[5]}" "${mean_of[$kind]}" && continue
    elif [[ $col =~ ^\ *as\ \`([a-z_]+)\` ]]; then
      said="as ${BASH_REMATCH[1]}"; local o=${BASH_REMATCH[1]}
      [ "${thr[$o]:-}" = "${thr[$kind]}" ] && [ "${fail_of[$o]:-}" = "${fail_of[$kind]}" ] && [ "${mean_of[$o]:-}" = "${mean_of[$kind]}" ] && continue
    elif [[ $kind = matrices && $col =~ ([0-9.e-]+)\ of\ the\ largest ]]; then
      said="${BASH_REMATCH[1]}"; same "${BASH_REMATCH[1]}" "${eps[$kind]}" && continue
    elif [[ $kind = penumbra && $col =~ within\ ([0-9.]+)% ]]; then
      said="${BASH_REMATCH[1]}%"; same "$(awk -v p="${BASH_REMATCH[1]}" 'BEGIN { print p / 100 }')" "${thr[$kind]}" && continue
    elif [[ $kind = bleeding && $col =~ \`threshold\`\ \(([0-9.e-]+)\) ]] || [[ $kind = flicker && $col =~ ([0-9.e-]+)\ by\ default ]]; then
      said="${BASH_REMATCH[1]}"; same "${BASH_REMATCH[1]}" "${thr[$kind]}" && continue
    elif [ "${thr[$kind]}${fail_of[$kind]}${mean_of[$kind]}${eps[$kind]}" = 0000 ] || [ "$kind" = probe ]; then
      continue                                   # no default of the table to state (a probe's are its own)
    fi
    echo "  $kind: says ${said:-no default}; the table in framework/sl_case.c: threshold ${thr[$kind]}, fail fraction ${fail_of[$kind]}, mean ${mean_of[$kind]}, epsilon ${eps[$kind]}"
  done < <(awk -F'|' '/^## / { kinds = ($0 == "## Check kinds") }   # the table of that section alone
                      kinds && /^\| `[a-z_]+` \|/ { k = $2; gsub(/[ `]/, "", k); print k "\t" $5 }' "$doc")
}

fail=0
list=$(mktemp); trap 'rm -f "$list" "$list.new"' EXIT
for readme in "$here"/labs/lab[0-9]*_*/README.md; do
  folder=$(basename "$(dirname "$readme")")
  n=${folder#lab}; n=${n%%_*}
  [ "$n" = 0 ] && continue
  criteria_of "$n" >"$list"
  [ -s "$list" ] || continue
  if ! grep -qxF -- "$begin" "$readme" || ! grep -qxF -- "$end" "$readme"; then
    echo "readme-criteria: labs/$folder/README.md has no list of criteria (the lines $begin and $end)" >&2
    fail=1
    continue
  fi
  with_list "$readme" "$list" >"$list.new"
  if $check; then
    if ! cmp -s "$readme" "$list.new"; then
      echo "readme-criteria: labs/$folder/README.md does not state what lab $n's cases apply:" >&2
      diff "$readme" "$list.new" | sed 's/^/  /' >&2
      fail=1
    fi
  elif ! cmp -s "$readme" "$list.new"; then
    cp "$list.new" "$readme"
    echo "readme-criteria: wrote lab $n's criteria into labs/$folder/README.md"
  fi
done
for doc in "$here"/labs/lab[0-9]*_*/README.md "$here"/README.md "$here"/grader/README.md; do
  [ -f "$doc" ] || continue
  stray=$(stray_figures "$doc")
  if [ -n "$stray" ]; then
    echo "readme-criteria: a grading figure outside the list of criteria (say it there, from the cases, or not at all):" >&2
    sed "s|^$here/|  |" <<<"$stray" >&2
    fail=1
  fi
done
wrong=$(defaults_stated "$here/grader/cases/README.md")
if [ -n "$wrong" ]; then
  echo "readme-criteria: grader/cases/README.md's table of check kinds does not state the defaults the grader applies:" >&2
  echo "$wrong" >&2
  fail=1
fi
$check && [ $fail = 0 ] && echo "readme-criteria: every lab README states the criteria its cases apply, and no other figure; grader/cases/README.md the defaults"
exit $fail
