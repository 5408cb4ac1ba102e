#!/usr/bin/env bash
# measure-serve.sh [BUILD] [SIZE]: how the browser viewer (shadowlab --serve)
# compares with the window, on this machine: the frames per second Chromium
# receives at SIZE (default 960x540) against the windowed viewer's under Xvfb,
# and the time from a key press in Chromium to the first frame that shows it
# (median of 20). Printed for the README (docs), never asserted by a test.
# Needs scripts/install-browser-deps.sh (chromium, chromium-driver) and xvfb-run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
size=${2:-960x540}
viewer=$build/tests/bin/shadowlab-solutions
[ -x "$viewer" ] || viewer=$build/bin/shadowlab
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
view=(--lab 4 --scene boxes_on_floor --size "$size" --no-overlay)
echo "measure-serve: $(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg); $("$viewer" --headless --frames 1 "${view[@]}" | head -1)"

# The window: K frames and K+100 frames, so start-up cancels out.
seconds() {
  local start end
  start=$(date +%s.%N)
  xvfb-run -a -s "-screen 0 1280x1024x24" "$viewer" "${view[@]}" --frames "$1" >/dev/null
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'
}
short=$(seconds 20)
long=$(seconds 120)
echo "window: $size: $(awk -v s="$short" -v l="$long" 'BEGIN { printf "%.1f", 100 / (l - s) }') frames/s (the windowed viewer under Xvfb, GLX llvmpipe)"

python3 "$root/tests/serve_browser.py" measure "$viewer" "$work" "$size"
