#!/usr/bin/env bash
# experiments.sh MODE SOURCE_DIR BUILD_DIR WORK_DIR
# Blame by experiment (grader/sl_experiment.c), through scripts/grade-submission as staff grade. MODE:
# - blame: two mistakes in lab 5 (the blur's sigma halved, the light-bleeding cut at half the amount): the probes'
#   ranking blames blur_moments() for the bleeding picture, whose replacement alone does not fix it; the
#   experiment names blur_moments() for the blurred moments and the pair for the pictures, and the staff
#   line counts the runs for the three failed checks;
# - off: the same with --no-experiments: the probes' ranking, no experiment run;
# - budget: the same with a budget too small for one run: the probes' ranking, and the staff line says so;
# - correct: lab 5 as the solutions have it: full marks and no experiment run;
# - attack: an attack: the same mistakes, and a lab5.c that, in an experiment's runner, reads the solution's
#   function from its sandbox and sends it out through stdout, stderr, files, the channel, its exit
#   status and its time; and a lab2.c that calls the solution's lab2_shadow_matrix() it is linked beside
#   in a C experiment and sends its answer out the same ways: nothing reaches the output, the reports
#   or the disk, and the experiments answer "not fixed", the one bit.
set -uo pipefail
mode=$1 src=$2 build=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
fail=0
problem() { echo "FAIL: $*"; fail=1; }
expect() { grep -E -q -- "$2" "$1" || problem "$(basename "$1"): no line matches: $2"; }
reject() { ! grep -E -q -- "$2" "$1" || problem "$(basename "$1"): a line matches: $2 ($(grep -E -m1 -- "$2" "$1" | cut -c1-200))"; }

submission() { # submission NAME [attack]: lab 5 from the solutions, with the two mistakes unless NAME is "correct"
  local dir="$work/$1"
  mkdir -p "$dir"
  cp -R "$src/solutions/lab5_vsm" "$dir/"
  if [ "$1" != correct ]; then
    sed -i 's/return linstep(amount, 1.0, p_max);/return linstep(amount * 0.5, 1.0, p_max);/' "$dir/lab5_vsm/shaders/vsm.glsl"
    sed -i 's/float sigma = max(float(radius) \* 0.5, 0.5);/float sigma = max(float(radius) * 0.25, 0.5);/' \
      "$dir/lab5_vsm/shaders/blur.glsl"
    grep -q 'amount \* 0.5' "$dir/lab5_vsm/shaders/vsm.glsl" && grep -q 'radius) \* 0.25' "$dir/lab5_vsm/shaders/blur.glsl" ||
      problem "the mistakes were not written (the solutions changed?)"
  fi
  if [ "${2:-}" = attack ]; then
    cat >>"$dir/lab5_vsm/lab5.c" <<'ATTACK'

/* Attack: in a runner that holds a solution function (an experiment), carry it out. */
#include <fcntl.h>
#include <glob.h>
#include <string.h>
#include <unistd.h>
#include "sl_protocol.h"
static void _leak_write(int fd, const void *data, size_t n) {
    while (n > 0) {
        ssize_t w = write(fd, data, n);
        if (w <= 0) return;
        data = (const char *)data + w, n -= (size_t)w;
    }
}
__attribute__((constructor)) static void _leak(void) {
    static const char *const patterns[] = {"/labs/lab5_vsm/shaders/*.glsl",
                                           "/tmp/shadowlab-isolate-*/lab5-*/lab5_vsm/shaders/*.glsl"};
    static char text[1 << 16];
    char found[512] = "";
    for (int p = 0; p < 2; p++) {
        glob_t g;
        if (glob(patterns[p], 0, NULL, &g) != 0) continue;
        for (size_t i = 0; i < g.gl_pathc; i++) {
            int fd = open(g.gl_pathv[i], O_RDONLY);
            ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : -1;
            if (fd >= 0) close(fd);
            if (n <= 0) continue;
            text[n] = '\0';
            const char *at = strstr(text, "return linstep(amount, 1.0, p_max);");
            if (!at) at = strstr(text, "float sigma = max(float(radius) * 0.5, 0.5);");
            if (at) snprintf(found, sizeof found, "EXPERIMENT-LEAK %.*s", (int)strcspn(at, "\n"), at);
        }
        globfree(&g);
    }
    if (!found[0]) return; /* the student's own files: an ordinary run */
    _leak_write(1, found, strlen(found)), _leak_write(1, "\n", 1);
    _leak_write(2, found, strlen(found)), _leak_write(2, "\n", 1);
    int fd = open("/tmp/shadowlab-experiment-leak", O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) _leak_write(fd, found, strlen(found)), close(fd);
    fd = open("shadowlab-experiment-leak", O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) _leak_write(fd, found, strlen(found)), close(fd);
    sl_message_header h = {SL_MSG_ERROR, 0, strlen(found)};
    _leak_write(SL_CHANNEL_FD, &h, sizeof h), _leak_write(SL_CHANNEL_FD, found, strlen(found));
    sleep(1); /* its time */
    _exit(77); /* its exit status */
}
ATTACK
  fi
  chmod -R a+rX "$dir"
}

c_attack() { # c_attack NAME: lab 2 with a mistake in lab2_shadow_matrix() and code that, linked beside the
  # solution's lab2_shadow_matrix() (a C experiment), calls it and sends out what it answers
  local dir="$work/$1"
  mkdir -p "$dir"
  cp -R "$src/solutions/lab2_projective" "$dir/"
  sed -i 's/        {0.0f, 0.0f, 0.5f, 0.0f},/        {0.0f, 0.0f, 1.0f, 0.0f},/' "$dir/lab2_projective/lab2.c"
  grep -q '{0.0f, 0.0f, 1.0f, 0.0f},' "$dir/lab2_projective/lab2.c" || problem "the lab 2 mistake was not written"
  cat >>"$dir/lab2_projective/lab2.c" <<'ATTACK'

/* Attack: in a runner whose lab2_shadow_matrix() is the solution's (an experiment), carry its answer out. */
#include <fcntl.h>
#include <string.h>
#include <unistd.h>
#include "sl_protocol.h"
static void _leak_write(int fd, const void *data, size_t n) {
    while (n > 0) {
        ssize_t w = write(fd, data, n);
        if (w <= 0) return;
        data = (const char *)data + w, n -= (size_t)w;
    }
}
__attribute__((constructor)) static void _leak(void) {
    sl_status (*volatile answer)(mat4, mat4, mat4) = lab2_shadow_matrix; /* the linked one, not this file's */
    mat4 identity = GLM_MAT4_IDENTITY_INIT, other = GLM_MAT4_IDENTITY_INIT, dest;
    answer(identity, other, dest);
    if (dest[2][2] != 0.5f) return; /* this file's own: an ordinary run */
    char found[200];
    snprintf(found, sizeof found, "EXPERIMENT-LEAK-C the solution's W has %.3f on its diagonal", (double)dest[2][2]);
    _leak_write(1, found, strlen(found)), _leak_write(2, found, strlen(found));
    int fd = open("/tmp/shadowlab-experiment-leak", O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) _leak_write(fd, found, strlen(found)), close(fd);
    sl_message_header h = {SL_MSG_ERROR, 0, strlen(found)};
    _leak_write(SL_CHANNEL_FD, &h, sizeof h), _leak_write(SL_CHANNEL_FD, found, strlen(found));
    sleep(1);
    _exit(dest[0][0] == 0.5f ? 77 : 78);
}
ATTACK
  chmod -R a+rX "$dir"
}

grade() { # grade NAME OUT [grader options]
  local name=$1 out=$2
  shift 2
  local lab=5
  case $name in attack_c | c_two) lab=2 ;; esac
  bash "$src/scripts/grade-submission" --build "$build" --jobs 2 "$work/$name" -- --lab $lab --report "$work/report-$out" \
    --gradescope "$work/report-$out/gradescope.json" "$@" >"$work/$out.txt" 2>&1
  echo $? >"$work/$out.status"
}

case $mode in
blame)
  submission two
  grade two two
  [ "$(cat "$work/two.status")" = 1 ] || problem "two mistakes: exit $(cat "$work/two.status"), not 1"
  expect "$work/two.txt" 'moments_blurred$'
  expect "$work/two.txt" '^ +Replacing blur_moments\(\) with a correct one fixes this check \(an experiment'
  expect "$work/two.txt" '^ +Replacing blur_moments\(\) and reduce_light_bleeding\(\) together with correct ones fixes this check, and neither alone does'
  expect "$work/two.txt" '^shadowlab-grade: experiments \(staff only\): [1-9][0-9]* runs for 3 failed checks \(2 functions'
  reject "$work/two.txt" 'blur_moments\(\) is wrong on its own .*Here: shadows differ'
  reject "$work/two.txt" 'Candidates:'
  # the reports say what the text says, and nothing of the experiments' cost
  grep -q 'Replacing blur_moments() with a correct one' "$work/report-two/results.json" ||
    problem "results.json does not say the experiment's answer"
  reject "$work/report-two/results.json" 'experiments \(staff only\)'
  # a C function: the runner linked with the solution's lab2_shadow_matrix() in place of the student's
  c_attack c_two
  sed -i '/^\/\* Attack:/,$d' "$work/c_two/lab2_projective/lab2.c" # the mistake alone
  grade c_two c_two
  expect "$work/c_two.txt" '^ +Replacing lab2_shadow_matrix\(\) with a correct one fixes this check \(an experiment'
  reject "$work/c_two.txt" 'EXPERIMENT-LEAK|does not fix'
  ;;
off)
  submission two
  grade two plain --no-experiments
  [ "$(cat "$work/plain.status")" = 1 ] || problem "--no-experiments: exit $(cat "$work/plain.status"), not 1"
  expect "$work/plain.txt" 'lab5_bleeding / visibility'
  expect "$work/plain.txt" 'blur_moments\(\) is wrong on its own .*fix it first\. Here: '
  reject "$work/plain.txt" 'Replacing|an experiment|experiments \(staff only\)'
  ;;
budget)
  submission two
  grade two budget --experiment-budget 0.000001
  [ "$(cat "$work/budget.status")" = 1 ] || problem "a spent budget: exit $(cat "$work/budget.status"), not 1"
  expect "$work/budget.txt" '^shadowlab-grade: experiments \(staff only\): 0 runs for 3 failed checks .*the budget ran out: the checks not answered keep the probes. ranking'
  expect "$work/budget.txt" 'blur_moments\(\) is wrong on its own .*fix it first\. Here: '
  reject "$work/budget.txt" 'Replacing|an experiment\)'
  ;;
correct)
  submission correct
  grade correct correct
  [ "$(cat "$work/correct.status")" = 0 ] || problem "the solutions' lab 5: exit $(cat "$work/correct.status"), not 0"
  expect "$work/correct.txt" '^shadowlab-grade: experiments \(staff only\): 0 runs for 0 failed checks'
  ;;
attack)
  rm -f /tmp/shadowlab-experiment-leak
  submission attack attack
  grade attack attack
  [ "$(cat "$work/attack.status")" = 1 ] || problem "the attack: exit $(cat "$work/attack.status"), not 1"
  expect "$work/attack.txt" '^shadowlab-grade: experiments \(staff only\): [1-9][0-9]* runs'
  # the attack ran in every experiment (each exits): its one bit, "not fixed", is all that shows
  expect "$work/attack.txt" 'does not fix this check \(an experiment\)'
  reject "$work/attack.txt" 'Replacing blur_moments\(\) with a correct one fixes'
  for f in "$work/attack.txt" $(find "$work/report-attack" -type f); do
    reject "$f" 'EXPERIMENT-LEAK|return linstep\(amount, 1\.0, p_max\)|float sigma = max\(float\(radius\) \* 0\.5, 0\.5\);'
  done
  leaks=$(bash "$src/tests/solution_leaks.sh" "$src" "$work/attack.txt" "$work/report-attack/results.json") ||
    problem "solution text: $leaks"
  # the same through a C experiment: the runner linked with the solution's lab2_shadow_matrix()
  c_attack attack_c
  grade attack_c attack_c
  [ "$(cat "$work/attack_c.status")" = 1 ] || problem "the C attack: exit $(cat "$work/attack_c.status"), not 1"
  expect "$work/attack_c.txt" '^shadowlab-grade: experiments \(staff only\): [1-9][0-9]* runs'
  expect "$work/attack_c.txt" 'does not fix this check \(an experiment\)'
  reject "$work/attack_c.txt" 'Replacing lab2_shadow_matrix\(\) with a correct one fixes'
  for f in "$work/attack_c.txt" $(find "$work/report-attack_c" -type f); do
    reject "$f" 'EXPERIMENT-LEAK'
  done
  [ ! -e /tmp/shadowlab-experiment-leak ] || { problem "the attack left /tmp/shadowlab-experiment-leak"; rm -f /tmp/shadowlab-experiment-leak; }
  ! find "$work" "$build/bin" -name shadowlab-experiment-leak | grep -q . || problem "the attack left a file"
  ;;
*) echo "experiments.sh: MODE is blame, off, budget, correct or attack" >&2; exit 2 ;;
esac
[ $fail = 0 ] && echo "experiments $mode: every expectation met"
exit $fail
