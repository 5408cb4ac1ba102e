#!/usr/bin/env bash
# no_headless.sh SOURCE_DIR TREE VIEWER IMAGE_COMPARE [GRADER ARGS...]
# A build with both headless backends switched off (-DSL_OSMESA=OFF
# -DSL_EGL=OFF), as on macOS and Windows, which have neither, and without
# the browser viewer (-DSL_SERVE=OFF): it configures
# and builds, and renders through hidden GLFW windows in a virtual display
# (Xvfb): the grader gives the solutions full marks on the cases GRADER ARGS choose (each
# lab's probes and one scene case: the staff suite grades every case through OSMesa),
# and the stubs (labs 1, 4) 0 with "not
# implemented", its header says that this is a self-check, and the viewer's
# --headless picture matches VIEWER's (the solutions' viewer of this build,
# through OSMesa or EGL).
# TREE is kept between runs, so a second run builds only what changed.
set -u
src=$1 tree=$2 viewer=$3 compare=$4
shift 4
solution_cases=("$@")
work="$tree/test-output"
fail=0
say() { echo "no_headless: $*"; }
check() { # check WHAT FILE REGEX: FILE must match REGEX
  if grep -Eq -- "$3" "$2"; then say "ok: $1"; else say "FAIL: $1 (no /$3/ in $2)"; fail=1; fi
}
mkdir -p "$tree"
rm -rf "$work"; mkdir -p "$work"

# Configure: neither backend, though this machine has both.
# Nor the browser viewer (as where libwebsockets is missing): the viewer still builds.
gen=() # a new tree uses Ninja, as bootstrap.sh makes one
[ -f "$tree/CMakeCache.txt" ] || ! command -v ninja >/dev/null || gen=(-G Ninja)
cmake "${gen[@]}" -S "$src" -B "$tree" -DSL_LABS=student -DSL_OSMESA=OFF -DSL_EGL=OFF -DSL_SERVE=OFF -DBUILD_TESTING=OFF \
  >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; say "FAIL: configure"; exit 1; }
check "configure says both backends are off and what stands in" "$work/configure.log" \
  "both headless backends switched off.*hidden window"
# Only what grading and the viewer need: the grader with its plain runners (no --isolate
# runners, no submission kit: this test uses neither) and the viewer.
# The stubs as committed (the tree's build/stubs/labs, from git) get a runner of their own, so
# the stubs' grade below holds whatever labs/ holds now (a student's finished labs).
cmake --build "$tree" -j2 --target shadowlab-grade-plain sl_stubs-runner shadowlab >"$work/build.log" 2>&1 ||
  { tail -40 "$work/build.log"; say "FAIL: build"; exit 1; }
if nm -D "$tree/bin/shadowlab-runner" 2>/dev/null | grep -Eq ' U (OSMesa|egl)[A-Z]'; then
  say "FAIL: the runner still links OSMesa or EGL"; fail=1
else
  say "ok: the runner links neither OSMesa nor EGL"
fi

# A headless backend asked for by name is refused, naming what the build has.
"$tree/bin/shadowlab-grade" --backend egl >"$work/egl.log" 2>&1
check "--backend egl is refused" "$work/egl.log" "not a backend of this build \(it has window"

# --serve, not built in, says so.
"$tree/bin/shadowlab" --serve 8080 >"$work/serve.log" 2>&1
check "--serve says it is not built in" "$work/serve.log" "--serve is not built in: libwebsockets"

# a display of its own, and the program's own exit status (tests/with_display.sh says why not xvfb-run)
x() { bash "$src/tests/with_display.sh" -s "-screen 0 640x480x24" "$@"; }

# The solutions, through hidden windows by default: full marks.
x "$tree/bin/shadowlab-grade" -j 2 --labs-dir "$src/solutions" --runners "$tree/bin/solutions" \
  "${solution_cases[@]}" >"$work/solutions.log" 2>&1
status=$?
[ $status -eq 0 ] && say "ok: the solutions grade exits 0" || { say "FAIL: the solutions grade exited $status"; fail=1; }
check "rendered with the hidden window" "$work/solutions.log" "^shadowlab-grade: rendered with window: "
check "the header says it is a self-check" "$work/solutions.log" "^shadowlab-grade: SELF-CHECK: .*course's own grader"
check "the solutions get full marks" "$work/solutions.log" "^Score: ([0-9.]+)/\1( |$)"
grep -E "^(Score|  Lab)" "$work/solutions.log"
# what a lost point said (kept whole, so a failure on another machine explains itself)
grep -A3 -E "^  FAIL " "$work/solutions.log" | sed 's/^/no_headless: solutions: /'

# The stubs: 0, each check saying what is not implemented (labs 1 and 4: the
# first stub and a lab resting on three others, their probes and scene cases;
# the solutions ran all seven).
x "$tree/bin/shadowlab-grade" -j 2 --labs-dir "$tree/stubs/labs" --runners "$tree/bin/stubs" --lab 1,4 --case lab1_probes --case lab1_depth_boxes \
  --case lab4_probes --case lab4_grid_3x3 >"$work/stubs.log" 2>&1
status=$?
[ $status -eq 1 ] && say "ok: the stubs' grade exits 1" || { say "FAIL: the stubs' grade exited $status"; fail=1; }
check "the stubs score 0" "$work/stubs.log" "^Score: 0/[0-9]+"
check "the stubs say not implemented" "$work/stubs.log" "not implemented: lab1_create_shadow_map\(\)"
if grep -Eq "crash|timed out|PROBLEM" "$work/stubs.log" "$work/solutions.log"; then
  say "FAIL: a case crashed, timed out or had a problem"; grep -E "crash|timed out|PROBLEM" "$work/"*.log | head; fail=1
fi

# The viewer: --headless is the hidden window here, and draws what the other backends draw.
x "$tree/bin/shadowlab" --headless --solutions --lab 4 --size 320x240 --frames 2 \
  --screenshot "$work/window.png" >"$work/viewer.log" 2>&1 || { cat "$work/viewer.log"; say "FAIL: viewer"; fail=1; }
check "the viewer's --headless is the hidden window" "$work/viewer.log" " through window, "
"$viewer" --headless --lab 4 --size 320x240 --frames 2 --screenshot "$work/headless.png" >/dev/null ||
  { say "FAIL: the headless viewer"; fail=1; }
"$compare" "$work/window.png" "$work/headless.png" 0.1 0.5 || fail=1

[ $fail -eq 0 ] && say "passed" || say "failed"
exit $fail
