#!/usr/bin/env bash
# attack.sh NAME MODE GRADER SOURCE_DIR WORK_DIR [GRADER ARGS...] [--beside HONEST GRADER ARGS...]
# Grades one attack's labs tree and checks that the attack got nothing and
# left nothing: the score is the stubs' 0 (exit 1, one Score line, reports
# agree), every report reads with a strict reader and no line of the text report
# is lab code's (check_reports.py), no line of a solution shows in the output or the reports, no file of
# the project, the build or the reports changed after the grader finished, no
# process the attack started is alive, and no marker file it tried to leave exists.
#   MODE plain, isolate   in the namespaces sandbox (skipped where there is none), plainly or with --isolate
#   MODE hidden           plainly, on the hidden cases of seed 1 (--hidden --seed 1)
#   MODE beside-LEVEL     with --sandbox LEVEL (namespaces, uid or basic), and, while the attack's runners
#                         run, a grade of an honest submission (the arguments after --beside) at the same
#                         level beside it, as grade-batch or a server grading two submissions at once: the
#                         attack must also cost that grade nothing (exit 0, full marks). `uid` needs root; as
#                         root, `basic` runs both graders as a user of their own (uid 61100), as a grader
#                         without root would be. Where the test may make a pids cgroup (root), both grades
#                         run in one of at most 600 tasks: a small machine, and today's shared test machine
#                         spared whatever an attack that is not stopped would take.
set -u
name=$1 mode=$2 grader=$3 src=$4 work=$5
shift 5
args=() honest=()
while [ $# -gt 0 ] && [ "$1" != --beside ]; do args+=("$1"); shift; done
[ $# -gt 0 ] && { shift; honest=("$@"); }
level=namespaces
case "$mode" in
  plain) ;;
  isolate) args+=(--isolate) ;;
  hidden) args+=(--hidden --seed 1) ;;
  beside-namespaces | beside-uid | beside-basic)
    level=${mode#beside-}
    args+=(--sandbox "$level")
    honest+=(--sandbox "$level") ;;
  *) echo "attack.sh: unknown mode $mode" >&2; exit 2 ;;
esac
runners=""
for ((i = 0; i < ${#args[@]}; i++)); do [ "${args[$i]}" = --runners ] && runners=${args[$((i + 1))]}; done
rm -rf "$work"; mkdir -p "$work"
# Processes of this run carry a tag in their environment: the runner's
# environment keeps MESA_* variables, and anything it starts inherits them.
tag="attack-$name-$mode-$$-$RANDOM"
export MESA_SL_TEST_TAG=$tag
tagged() { # (grep and sed without the tag, or they would find themselves)
  env -u MESA_SL_TEST_TAG grep -lzxE "MESA_SL_TEST_TAG=$tag(-honest)?" /proc/[0-9]*/environ 2>/dev/null |
    env -u MESA_SL_TEST_TAG sed 's|^/proc/\([0-9]*\)/environ$|\1|'
}
markers() { find /tmp "$src" "$runners" -maxdepth 4 -name 'shadowlab-attack-marker*' 2>/dev/null; }
snapshot() {
  # contents and times of everything an attack might rewrite
  find "$src/grader" "$src/solutions" "$src/labs" "$src/framework" "$runners" "$grader" -type f -print0 2>/dev/null |
    sort -z | xargs -0 stat -c '%n %s %Y' | sha256sum
  find "$src/grader" "$src/solutions" "$runners" "$grader" -type f -print0 2>/dev/null | sort -z | xargs -0 sha256sum | sha256sum
}

# ---- beside another grade: who runs the graders, and in which cgroup ----
as_user=() cgroup=""
if [ "${mode%%-*}" = beside ]; then
  if [ "$(id -u)" != 0 ]; then
    [ "$level" != uid ] || { echo "attack $name ($mode): the uid sandbox needs a grader running as root" >&2; exit 77; }
  else
    if [ "$level" = uid ]; then
      # the runners' uids must reach the system and the runner: where a folder on the way is closed
      # to other users (a root folder of mode 0700, as under a chroot) the grader falls back to
      # basic, and the attack would run as root: skip before it runs at all
      runner=""
      for ((i = 0; i < ${#args[@]}; i++)); do [ "${args[$i]}" = --runners ] && runner=${args[$((i + 1))]}/shadowlab-runner; done
      setpriv --reuid=60800 --regid=60800 --clear-groups -- /bin/sh -c "test -x '$runner'" 2>/dev/null ||
        { echo "attack $name ($mode): a runner's uid cannot run $runner here (a folder on its path is closed to others)" >&2; exit 77; }
    fi
    if [ "$level" = basic ]; then
      as_user=(setpriv --reuid=61100 --regid=61100 --clear-groups --)
      # a user of its own must reach the system and the grader: not where a folder on the way is
      # closed to other users (a clone under /root, a root folder of mode 0700)
      "${as_user[@]}" /bin/sh -c "test -x '$grader'" 2>/dev/null ||
        { echo "attack $name ($mode): a user of its own cannot run $grader here (a folder on its path is closed to others)" >&2; exit 77; }
      chown 61100:61100 "$work"
    fi
    # this process's pids cgroup (v1's pids hierarchy, or v2 where it has the controller)
    own=$(awk -F: '$2 ~ /(^|,)pids(,|$)/ {print $3}' /proc/self/cgroup)
    if [ -n "$own" ] && [ -d "/sys/fs/cgroup/pids$own" ]; then parent="/sys/fs/cgroup/pids$own"
    else parent="/sys/fs/cgroup$(awk -F: '$1 == 0 {print $3}' /proc/self/cgroup)"; fi
    cgroup="$parent/shadowlab-test-$$"
    if ! { mkdir "$cgroup" && echo 600 >"$cgroup/pids.max"; } 2>/dev/null; then rmdir "$cgroup" 2>/dev/null; cgroup=""; fi
  fi
fi
remove_cgroup() {
  [ -n "$cgroup" ] && [ -d "$cgroup" ] || return 0
  local p
  for p in $(cat "$cgroup"/cgroup.procs "$cgroup"/*/cgroup.procs 2>/dev/null); do kill -9 "$p" 2>/dev/null; done
  sleep 0.5
  rmdir "$cgroup"/*/ "$cgroup" 2>/dev/null
}
trap remove_cgroup EXIT
# Runs a grader as the test's user, in the test's cgroup.
run_grader() {
  if [ -n "$cgroup" ]; then
    bash -c 'echo $$ >"$1/cgroup.procs" && shift && exec "$@"' _ "$cgroup" "${as_user[@]+"${as_user[@]}"}" "$@"
  else
    "${as_user[@]+"${as_user[@]}"}" "$@"
  fi
}

before=$(snapshot)
markers | xargs -r rm -f
out="$work/out.txt" honest_out="$work/honest.txt"
run_grader timeout -k 10 600 "$grader" "${args[@]}" --report "$work/report" --gradescope "$work/gradescope.json" \
  --prairielearn "$work/prairielearn.json" --junit "$work/junit.xml" >"$out" 2>&1 &
attack_pid=$!
honest_status=""
if [ ${#honest[@]} -gt 0 ]; then
  # the honest grade starts once the attack's first runner does
  for _ in $(seq 300); do
    for p in $(tagged); do
      [ "$(tr '\0' '\n' 2>/dev/null <"/proc/$p/cmdline" | head -n 1)" = shadowlab-runner ] && break 2
    done
    kill -0 "$attack_pid" 2>/dev/null || break
    sleep 0.1
  done
  MESA_SL_TEST_TAG=$tag-honest run_grader timeout -k 10 600 "$grader" "${honest[@]}" >"$honest_out" 2>&1
  honest_status=$?
fi
wait "$attack_pid"
status=$?
cat "$out"
fail=0
problem() { echo "attack $name ($mode): $*" >&2; fail=1; }
[ "$status" != 124 ] && [ "$status" != 137 ] || problem "the grader did not finish (killed after 600 s)"
if ! grep -q "sandbox:" "$out"; then
  problem "the grader graded nothing (exit status $status)"
  exit 1
fi
# A run skipped below still must not leave the attack's marker files behind (in the project
# they would be read as case files by every later grade).
skip() { markers | xargs -r rm -f; exit 77; }
if ! grep -q "sandbox: $level" "$out"; then
  echo "attack $name ($mode): this machine gives the runners another sandbox than $level:" >&2
  grep "sandbox:" "$out" >&2
  echo "the attack suite needs the namespaces sandbox (root, or unprivileged user namespaces)" >&2
  skip
fi
if grep -q "^shadowlab-grade: compiler: NOT fenced" "$out"; then
  echo "attack $name ($mode): this machine gives the compiler no fence: the attack's lab code was built where it could" >&2
  echo "read the answers (the build said why when it was configured)" >&2
  skip
fi
[ "$status" = 1 ] || problem "exit status $status, expected 1 (checks failed)"
[ "$(grep -c '^Score:' "$out")" = 1 ] || problem "more than one line starts with 'Score:' (forged output reached the report)"
tail -n 1 "$out" | grep -qE '^Score: 0/[0-9.]+$' || problem "the score is not 0: $(tail -n 1 "$out")"
grep -qE '"score":[[:space:]]*0([,.}[:space:]]|$)' "$work/report/results.json" || problem "results.json's score is not 0"
grep -qE '"score":[[:space:]]*0([,.}[:space:]]|$)' "$work/gradescope.json" || problem "gradescope.json's score is not 0"
# Whatever lab code printed or sent: every report parses, and no line of the text is one it drew.
python3 "$src/tests/check_reports.py" --text "$out" --json "$work/report/results.json" --json "$work/gradescope.json" \
  --json "$work/prairielearn.json" --junit "$work/junit.xml" --html "$work/report/report.html" \
  --forged "every check passed" --forged "  PASS" --forged "shadowlab-grade: the submission did not build" ||
  problem "a report a strict reader refuses, or a line lab code wrote (above)"
if [ -n "$honest_status" ]; then
  # what an attack on its neighbours says it got (its output, kept in the report): where
  # its marker files cannot tell (at `uid`, what a runner's uid left in /tmp is removed)
  reached=$(grep -o 'reached process [0-9]*: [a-z-]*' "$work/report/results.json" | sort -u | head -n 5)
  [ -z "$reached" ] || problem "the attack reached its neighbours: $(echo $reached)"
  echo "---- the honest grade beside it ----"
  cat "$honest_out"
  honest_problem() { problem "the honest grade beside it: $*"; }
  grep -q "sandbox: $level" "$honest_out" || honest_problem "not in the $level sandbox"
  [ "$honest_status" = 0 ] || honest_problem "exit status $honest_status, expected 0 (full marks)"
  last=$(tail -n 1 "$honest_out")
  [[ "$last" =~ ^Score:\ ([0-9.]+)/([0-9.]+) ]] && [ "${BASH_REMATCH[1]}" = "${BASH_REMATCH[2]}" ] ||
    honest_problem "not full marks: $last"
  ! grep -q '^  FAIL' "$honest_out" || honest_problem "checks failed: $(grep -c '^  FAIL' "$honest_out")"
fi
leaks=$(bash "$src/tests/solution_leaks.sh" "$src" "$out" "$work/report/results.json" "$work/gradescope.json")
[ $? = 0 ] || problem "$leaks"
reports=$(sha256sum "$work/report/results.json" "$work/gradescope.json")
# Give anything the attack left running the time to act, then look.
sleep 2
[ "$(sha256sum "$work/report/results.json" "$work/gradescope.json")" = "$reports" ] || problem "a report changed after the grader exited"
survivors=$(tagged)
# A process still on its way out (the kernel kills what is left in a runner's PID namespace when
# the runner ends, and on a loaded machine that takes a moment) is not one the attack left
# running: give the tagged ones up to 10 s more before blaming them.
for ((wait_left = 20; wait_left > 0 && ${#survivors} > 0; wait_left--)); do sleep 0.5; survivors=$(tagged); done
[ -z "$survivors" ] || {
  problem "processes outlived the grade: $survivors"
  for p in $survivors; do
    echo "  $p: $(tr '\0' ' ' <"/proc/$p/cmdline" 2>/dev/null) ($(grep -E '^(State|PPid|Uid):' "/proc/$p/status" 2>/dev/null | tr -s '\t\n' '  '))" >&2
    kill -9 "$p" 2>/dev/null
  done
}
[ "$(snapshot)" = "$before" ] || problem "files of the project, the build or the grader changed"
left=$(markers)
[ -z "$left" ] || { problem "the attack left files: $left"; rm -f $left; }
exit $fail
