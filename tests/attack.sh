#!/usr/bin/env bash
# attack.sh NAME plain|isolate GRADER SOURCE_DIR WORK_DIR [GRADER ARGS...]
# Grades one attack's labs tree and checks that the attack got nothing and
# left nothing: the score is the stubs' 0 (exit 1, one Score line, reports
# agree), no line of a solution shows in the output or the reports, no file of
# the project, the build or the reports changed after the grader finished, no
# process the attack started is alive, and no marker file it tried to leave exists.
set -u
name=$1 mode=$2 grader=$3 src=$4 work=$5
shift 5
args=("$@")
[ "$mode" = isolate ] && args+=(--isolate)
runners=""
for ((i = 0; i < ${#args[@]}; i++)); do [ "${args[$i]}" = --runners ] && runners=${args[$((i + 1))]}; done
rm -rf "$work"; mkdir -p "$work"
# Processes of this run carry a tag in their environment: the runner's
# environment keeps MESA_* variables, and anything it starts inherits them.
tag="attack-$name-$mode-$$-$RANDOM"
export MESA_SL_TEST_TAG=$tag
tagged() {
  local p
  for p in /proc/[0-9]*; do
    tr '\0' '\n' 2>/dev/null <"$p/environ" | grep -qx "MESA_SL_TEST_TAG=$tag" && echo "${p#/proc/}"
  done
}
markers() { find /tmp "$src" "$runners" -maxdepth 4 -name 'shadowlab-attack-marker*' 2>/dev/null; }
snapshot() {
  # contents and times of everything an attack might rewrite
  find "$src/grader" "$src/solutions" "$src/labs" "$src/framework" "$runners" "$grader" -type f -print0 2>/dev/null |
    sort -z | xargs -0 stat -c '%n %s %Y' | sha256sum
  find "$src/grader" "$src/solutions" "$runners" "$grader" -type f -print0 2>/dev/null | sort -z | xargs -0 sha256sum | sha256sum
}
before=$(snapshot)
markers | xargs -r rm -f
out="$work/out.txt"
timeout -k 10 600 "$grader" "${args[@]}" --report "$work/report" --gradescope "$work/gradescope.json" >"$out" 2>&1
status=$?
cat "$out"
fail=0
problem() { echo "attack $name ($mode): $*" >&2; fail=1; }
[ "$status" != 124 ] && [ "$status" != 137 ] || problem "the grader did not finish (killed after 600 s)"
if ! grep -q "sandbox: namespaces" "$out"; then
  echo "attack $name ($mode): this machine gives the runners only a weaker sandbox:" >&2
  grep "sandbox:" "$out" >&2
  echo "the attack suite needs the namespaces sandbox (root, or unprivileged user namespaces)" >&2
  exit 77
fi
if grep -q "^shadowlab-grade: compiler: NOT fenced" "$out"; then
  echo "attack $name ($mode): this machine gives the compiler no fence: the attack's lab code was built where it could" >&2
  echo "read the answers (the build said why when it was configured)" >&2
  exit 77
fi
[ "$status" = 1 ] || problem "exit status $status, expected 1 (checks failed)"
[ "$(grep -c '^Score:' "$out")" = 1 ] || problem "more than one line starts with 'Score:' (forged output reached the report)"
tail -n 1 "$out" | grep -qE '^Score: 0/[0-9.]+$' || problem "the score is not 0: $(tail -n 1 "$out")"
grep -qE '"score":[[:space:]]*0([,.}[:space:]]|$)' "$work/report/results.json" || problem "results.json's score is not 0"
grep -qE '"score":[[:space:]]*0([,.}[:space:]]|$)' "$work/gradescope.json" || problem "gradescope.json's score is not 0"
leaks=$(bash "$src/tests/solution_leaks.sh" "$src" "$out" "$work/report/results.json" "$work/gradescope.json")
[ $? = 0 ] || problem "$leaks"
reports=$(sha256sum "$work/report/results.json" "$work/gradescope.json")
# Give anything the attack left running the time to act, then look.
sleep 2
[ "$(sha256sum "$work/report/results.json" "$work/gradescope.json")" = "$reports" ] || problem "a report changed after the grader exited"
survivors=$(tagged)
[ -z "$survivors" ] || { problem "processes outlived the grade: $survivors"; for p in $survivors; do kill -9 "$p" 2>/dev/null; done; }
[ "$(snapshot)" = "$before" ] || problem "files of the project, the build or the grader changed"
left=$(markers)
[ -z "$left" ] || { problem "the attack left files: $left"; rm -f $left; }
exit $fail
