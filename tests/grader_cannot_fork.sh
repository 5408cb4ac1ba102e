#!/usr/bin/env bash
# grader_cannot_fork.sh GRADER WORK_DIR [GRADER ARGS...]
# The machine runs out of processes in the middle of a grade (what a thread
# bomb beside it would do to a machine that let it): the grader, which can
# start no more runners, must say so and exit 2, and never grade the cases it
# could not run as failures of the submission ("timed out", "crashed"). The
# grade runs in a pids cgroup of the test's own, whose limit drops below what
# it holds as soon as the first runner is up. Needs root (to make the cgroup).
set -u
grader=$1 work=$2
shift 2
[ "$(id -u)" = 0 ] || { echo "grader_cannot_fork: needs root, to make a pids cgroup" >&2; exit 77; }
own=$(awk -F: '$2 ~ /(^|,)pids(,|$)/ {print $3}' /proc/self/cgroup)
if [ -n "$own" ] && [ -d "/sys/fs/cgroup/pids$own" ]; then parent="/sys/fs/cgroup/pids$own"
else parent="/sys/fs/cgroup$(awk -F: '$1 == 0 {print $3}' /proc/self/cgroup)"; fi
cgroup="$parent/shadowlab-test-$$"
if ! { mkdir "$cgroup" && echo 1000 >"$cgroup/pids.max"; } 2>/dev/null; then
  rmdir "$cgroup" 2>/dev/null
  echo "grader_cannot_fork: no pids cgroup to make under $parent" >&2
  exit 77
fi
cleanup() {
  local p
  echo max >"$cgroup/pids.max" 2>/dev/null
  for p in $(cat "$cgroup"/cgroup.procs "$cgroup"/*/cgroup.procs 2>/dev/null); do kill -9 "$p" 2>/dev/null; done
  sleep 0.5
  rmdir "$cgroup"/*/ "$cgroup" 2>/dev/null
}
trap cleanup EXIT
rm -rf "$work"
mkdir -p "$work"
out="$work/out.txt"
bash -c 'echo $$ >"$1/cgroup.procs" && shift && exec "$@"' _ "$cgroup" timeout -k 10 300 "$grader" "$@" >"$out" 2>&1 &
pid=$!
runner_up() {
  local p
  for p in $(cat "$cgroup"/cgroup.procs "$cgroup"/*/cgroup.procs 2>/dev/null); do
    [ "$(tr '\0' '\n' 2>/dev/null <"/proc/$p/cmdline" | head -n 1)" = shadowlab-runner ] && return 0
  done
  return 1
}
for _ in $(seq 600); do runner_up && break; kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
runner_up || echo "grader_cannot_fork: no runner was seen: the limit drops now anyway" >&2
echo 1 >"$cgroup/pids.max"
wait "$pid"
status=$?
cat "$out"
fail=0
problem() { echo "grader_cannot_fork: $*" >&2; fail=1; }
[ "$status" = 2 ] || problem "exit status $status, expected 2 (could not grade)"
grep -q '^PROBLEM could not grade' "$out" || problem "no PROBLEM line says what could not be graded"
grep -q 'not graded: could not start the runner' "$out" || problem "no check says its runner could not start"
! grep -qE 'timed out|crashed|shader loop' "$out" || problem "a case the machine stopped is graded as the submission's fault"
[[ "$(tail -n 1 "$out")" =~ ^Score:\ [0-9.]+/[0-9.]+ ]] || problem "the report is not complete: $(tail -n 1 "$out")"
exit $fail
