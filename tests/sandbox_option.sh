#!/usr/bin/env bash
# sandbox_option.sh SOURCE_DIR WORK_DIR
# -DSL_SANDBOX=fallback selects the fallback sandbox module (plain child
# processes) on Linux, and a name that is no module stops the configuration.
# Configures a second build tree once (later runs reuse it); builds nothing.
set -u
src=$1 work=$2
fail=0
problem() { echo "sandbox_option: $*" >&2; fail=1; }
gen=(); [ -f "$work/CMakeCache.txt" ] || gen=(-G "Unix Makefiles")
out=$(cmake "${gen[@]}" -S "$src" -B "$work" -DSL_SANDBOX=fallback -DSL_LABS=student 2>&1) || { echo "$out"; problem "configuring with SL_SANDBOX=fallback failed"; exit 1; }
grep -q "Runners' sandbox: fallback" <<<"$out" || problem "the configuration does not say it uses the fallback module"
rules=$(cat "$work"/grader/CMakeFiles/sl_sandbox.dir/build.make 2>/dev/null)
grep -q 'sl_sandbox_fallback\.c' <<<"$rules" || problem "the sandbox library does not compile sl_sandbox_fallback.c"
! grep -q 'sl_sandbox_linux\.c' <<<"$rules" || problem "the sandbox library still compiles sl_sandbox_linux.c"
if out=$(cmake -S "$src" -B "$work" -DSL_SANDBOX=none 2>&1); then
  problem "SL_SANDBOX=none was accepted"
else
  grep -q "SL_SANDBOX is linux or fallback" <<<"$out" || problem "SL_SANDBOX=none: no message says what it takes"
fi
# leave the tree configured for the next run
cmake -S "$src" -B "$work" -DSL_SANDBOX=fallback >/dev/null 2>&1
[ $fail = 0 ] && echo "sandbox_option: SL_SANDBOX=fallback selects sl_sandbox_fallback.c"
exit $fail
