#!/usr/bin/env bash
# sandbox_option.sh SOURCE_DIR WORK_DIR
# -DSL_SANDBOX=fallback selects the fallback sandbox module (plain child
# processes) on Linux, and a name that is no module stops the configuration.
# Configures a second build tree, without its tests (-DBUILD_TESTING=OFF: the
# option is the grader's, and the tests' folder is most of a configuration);
# builds nothing. The refused name comes first: it stops before the grader's
# folder, and the tree it leaves is the one the accepted name configures.
set -u
src=$1 work=$2
fail=0
problem() { echo "sandbox_option: $*" >&2; fail=1; }
rm -rf "$work"
gen=(); ! command -v ninja >/dev/null || gen=(-G Ninja)
if out=$(cmake "${gen[@]}" -S "$src" -B "$work" -DSL_SANDBOX=none -DBUILD_TESTING=OFF 2>&1); then
  problem "SL_SANDBOX=none was accepted"
else
  grep -q "SL_SANDBOX is linux or fallback" <<<"$out" || problem "SL_SANDBOX=none: no message says what it takes: $out"
fi
out=$(cmake -S "$src" -B "$work" -DSL_SANDBOX=fallback -DSL_LABS=student -DBUILD_TESTING=OFF 2>&1) ||
  { echo "$out"; problem "configuring with SL_SANDBOX=fallback failed"; exit 1; }
grep -q "Runners' sandbox: fallback" <<<"$out" || problem "the configuration does not say it uses the fallback module"
# what the sandbox library compiles, in either generator's rules
if [ -f "$work/build.ninja" ]; then
  rules=$(grep -E '^build [^:]*sl_sandbox\.dir/' "$work/build.ninja")
else
  rules=$(cat "$work"/grader/CMakeFiles/sl_sandbox.dir/build.make 2>/dev/null)
fi
grep -q 'sl_sandbox_fallback\.c' <<<"$rules" || problem "the sandbox library does not compile sl_sandbox_fallback.c"
! grep -q 'sl_sandbox_linux\.c' <<<"$rules" || problem "the sandbox library still compiles sl_sandbox_linux.c"
[ $fail = 0 ] && echo "sandbox_option: SL_SANDBOX=fallback selects sl_sandbox_fallback.c"
exit $fail
