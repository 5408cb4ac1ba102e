#!/usr/bin/env bash
# measure-student-rebuild.sh [LAB] [BUILD_DIR]
# A student's everyday loop: touch labs/labN_*/labN.c (default lab 3), run
# the default build (`cmake --build BUILD_DIR`, what bootstrap.sh makes), and
# print how many programs were linked again, which, and the seconds it took.
# A benchmark, not a test: the figure depends on the machine and its load.
set -euo pipefail
cd "$(dirname "$0")/.."
lab=${1:-3}
build=${2:-build}
[[ "$lab" =~ ^[1-9]$ ]] || { echo "measure-student-rebuild: LAB is a lab's number (1-7)" >&2; exit 2; }
file=$(compgen -G "labs/lab${lab}_*/lab${lab}.c" | head -n 1) ||
  { echo "measure-student-rebuild: no labs/lab${lab}_*/lab${lab}.c" >&2; exit 2; }
[ -f "$build/CMakeCache.txt" ] || { echo "measure-student-rebuild: $build is not configured (run scripts/bootstrap.sh)" >&2; exit 2; }
jobs=$(nproc)

programs() { # every program the build made: path and modification time
  find "$build" -path "$build/CMakeFiles" -prune -o -type f -perm -u+x ! -name '*.so*' ! -name '*.sh' \
    -newer "$build/CMakeCache.txt" -printf '%p %T@\n' 2>/dev/null | LC_ALL=C sort
}
echo "measure-student-rebuild: bringing $build up to date first (not timed)"
cmake --build "$build" -j "$jobs" >/dev/null
before=$(programs)
sleep 1 # a relinked program gets a later time even on coarse clocks
touch "$file"
# wall-clock seconds, and the CPU seconds of the build's processes (user + system),
# which a busy machine does not inflate
cpu_before=$(awk '{print $14 + $15 + $16 + $17}' /proc/$$/stat)
start=$(date +%s.%N)
cmake --build "$build" -j "$jobs" >/dev/null
end=$(date +%s.%N)
cpu_after=$(awk '{print $14 + $15 + $16 + $17}' /proc/$$/stat)
cpu=$(awk -v a="$cpu_before" -v b="$cpu_after" -v hz="$(getconf CLK_TCK)" 'BEGIN {printf "%.1f", (b - a) / hz}')
after=$(programs)
relinked=$(LC_ALL=C comm -13 <(printf '%s\n' "$before") <(printf '%s\n' "$after") | awk 'NF {print $1}')
count=$(grep -c . <<<"$relinked" || true)
seconds=$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}')
echo "measure-student-rebuild: touched $file; cmake --build $build -j $jobs relinked $count programs in $seconds s" \
     "($cpu s of CPU; $(nproc) CPUs, load $(cut -d' ' -f1 /proc/loadavg))"
sed "s|^$build/|  |" <<<"$relinked"
