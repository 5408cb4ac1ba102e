#!/usr/bin/env bash
# exit_statuses.sh SOURCE_DIR BUILD_DIR TEARDOWN_FAULT_LIBRARY WORK
# No exit status escapes that the grader and the staff's scripts do not
# document (README "Exit statuses"): a crash of the grader's own, mid-grade or in
# a library's exit-time clean-up, and a command failing inside grade-submission
# or grade-batch, each end with the documented status and say why.
set -u
src=$1 build=$2 fault_library=$3 work=$4
grader="$build/bin/shadowlab-grade"
stubs=${SHADOWLAB_STUBS:-$build/stubs/labs}
rm -rf "$work"; mkdir -p "$work"
fail=0
say() { echo "exit_statuses: $*"; }
expect() { # expect WHAT STATUS WANT LOG [REGEX]
  if [ "$2" != "$3" ]; then say "FAIL: $1: exit $2, expected $3"; tail -n 5 "$4"; fail=1; return; fi
  if [ -n "${5:-}" ] && ! grep -Eq -- "$5" "$4"; then say "FAIL: $1: no /$5/ in its output"; tail -n 5 "$4"; fail=1; return; fi
  say "ok: $1 (exit $2)"
}

# 1. The exit guard itself: documented statuses pass, the rest become 2 with their cause.
guarded() { # guarded ALLOWED BODY: a script that sources the guard
  printf '%s\n' "set -euo pipefail" "source \"$src/scripts/exit-guard.sh\" demo $1" \
    "sl_on_exit() { touch \"$work/cleaned\"; }" "$2" >"$work/guarded.sh"
  rm -f "$work/cleaned"
  bash "$work/guarded.sh" >"$work/guarded.log" 2>&1
}
guarded "0 1" "exit 1"; expect "a documented status passes" $? 1 "$work/guarded.log"
[ -e "$work/cleaned" ] || { say "FAIL: the script's own clean-up did not run"; fail=1; }
guarded "0 1" "exit 5"; expect "an undocumented status becomes 2" $? 2 "$work/guarded.log" \
  "demo: internal error: exit status 5 .*staff's side"
guarded "0" $'true\nfalse\ntrue'; expect "a failing command becomes 2, named" $? 2 "$work/guarded.log" \
  'internal error: exit status 1 after "false" \(line [0-9]+, status 1\)'
[ -e "$work/cleaned" ] || { say "FAIL: the clean-up did not run after a failing command"; fail=1; }

# 2. The grader: a crash of its own mid-grade is a staff problem, said, exit 2.
"$grader" -j 1 --progress --labs-dir "$stubs" --lab 1-7 >"$work/segv.log" 2>&1 &
pid=$!
# once the first case has ended (a progress line), in the middle of the grade
for _ in $(seq 1 200); do [ -s "$work/segv.log" ] && break; sleep 0.05; done
kill -SEGV "$pid"
wait "$pid"; expect "the grader crashing mid-grade" $? 2 "$work/segv.log" \
  "^shadowlab-grade: internal error: SIGSEGV .* while .*staff's side"
# ... and a library crashing at exit, after the reports, leaves the grade's own status (the stubs: 1).
LD_PRELOAD="$fault_library" "$grader" -j 1 --labs-dir "$stubs" --lab 1 --case lab1_probes >"$work/teardown.log" 2>&1
expect "a library crashing in the grader's teardown" $? 1 "$work/teardown.log" "^Score: 0/"
# the preloaded crash is real: it ends a program that exits through libc
crashed=$(bash -c 'LD_PRELOAD="$0" bash -c "exit 0"; echo $?' "$fault_library" 2>/dev/null)
[ "$crashed" = 139 ] || { say "FAIL: the teardown fault does not fire (the test would prove nothing)"; fail=1; }
# A runner that cannot make its GL context (here: a hidden window with no display) is the
# machine's fault: not graded, exit 2, and no check failed as if the submission were wrong.
env -u DISPLAY -u WAYLAND_DISPLAY "$grader" -j 1 --backend window --labs-dir "$stubs" --lab 1 --case lab1_probes \
  >"$work/no-context.log" 2>&1
expect "a runner without a GL context" $? 2 "$work/no-context.log" \
  "^PROBLEM could not grade lab1_probes: the runner could not make its OpenGL context on this machine"
! grep -A1 "^  FAIL " "$work/no-context.log" | grep -vE "^  FAIL |^--|not graded: .*the grading machine's fault" ||
  { say "FAIL: a check was failed as the submission's for want of a GL context"; fail=1; }
# every status the grader's --help documents, and no other
"$grader" --help >"$work/help.log" 2>&1
grep -q "Exit status: 0 full marks, 1 some checks failed, 2 grading could not run properly" "$work/help.log" ||
  { say "FAIL: the grader's --help does not document its exit statuses"; fail=1; }

# 3. A command failing inside the scripts: exit 2, with the command named, never its own status.
mkdir -p "$work/shim"
printf '#!/bin/sh\nexit 5\n' >"$work/shim/cp"
chmod +x "$work/shim/cp"
mkdir -p "$work/submission/lab1_depth_fbo"
cp "$stubs/lab1_depth_fbo/lab1.c" "$work/submission/lab1_depth_fbo/"
PATH="$work/shim:$PATH" "$src/scripts/grade-submission" --build "$build" "$work/submission" -- --lab 1 \
  --case lab1_probes >"$work/submission.log" 2>&1
expect "grade-submission with a failing cp" $? 2 "$work/submission.log" \
  'grade-submission: internal error: exit status 5 after "cp '
mkdir -p "$work/canvas"
printf 'int x;\n' >"$work/canvas/doejane_12345_678901_lab1.c"
PATH="$work/shim:$PATH" "$src/scripts/grade-batch" --build "$build" --list "$work/canvas" >"$work/batch.log" 2>&1
expect "grade-batch with a failing cp" $? 2 "$work/batch.log" 'grade-batch: internal error: exit status 5 after "cp '

[ $fail = 0 ] && say "passed" || say "failed"
exit $fail
