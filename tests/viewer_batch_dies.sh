#!/usr/bin/env bash
# viewer_batch_dies.sh VIEWER WORK_DIR
# A --batch line that kills the viewer's process costs that line only: the viewer marks its end with
# 128 + the signal, says so, and runs the lines after it in a new process. The line is killed for real:
# the viewer runs under a file size limit (ulimit -f) its small pictures stay under and one larger
# picture exceeds, so writing that one raises SIGXFSZ, whose default is to end the process.
set -u
viewer=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "viewer_batch_dies: $*" >&2; fail=1; }
source "$(dirname "$0")/../scripts/viewer-batch.sh"
# 8 KiB: a 32x20 picture is some 600 bytes, a 640x400 one (even flat, without shadows) well over 8 KiB. The
# GL driver's shader cache is off: its files are no picture of a line's.
cat >"$work/limited-viewer" <<END
#!/usr/bin/env bash
ulimit -f 8
MESA_SHADER_CACHE_DISABLE=true MESA_GLSL_CACHE_DISABLE=true exec "$viewer" "\$@"
END
chmod +x "$work/limited-viewer"
small=(--headless --lab 4 --scene spot_on_floor --size 32x20 --frames 1)
viewer_batch_add before "${small[@]}" --screenshot "$work/before.png"
viewer_batch_add dies --headless --lab 4 --scene spot_on_floor --size 640x400 --frames 1 --screenshot "$work/large.png"
viewer_batch_add after "${small[@]}" --screenshot "$work/after.png"
viewer_batch_run "$work/limited-viewer" "$work" && problem "a batch with a line that died did not fail"
killed=$((128 + $(kill -l XFSZ)))
viewer_batch_status "$work" before || problem "the line before the one that died failed: $(cat "$work/before.log")"
viewer_batch_status "$work" dies
[ $? = "$killed" ] || problem "the line that died does not end with exit $killed (SIGXFSZ): $(cat "$work/dies.log")"
grep -q "line 2: the viewer was killed by signal $(kill -l XFSZ).*the lines after it run in a new process" "$work/dies.log" ||
  problem "the viewer does not say line 2 killed it: $(cat "$work/dies.log")"
viewer_batch_status "$work" after || problem "the line after the one that died failed: $(cat "$work/after.log")"
[ -s "$work/before.png" ] && [ -s "$work/after.png" ] || problem "the lines before and after the one that died drew no picture"
[ "$(grep -c '^shadowlab: batch line [0-9]*: exit [0-9]*$' "$work/batch.log")" = 3 ] || problem "not one end marked a line"
[ $fail = 0 ] && echo "viewer_batch_dies: line 2 died (SIGXFSZ) and cost that line only"
exit $fail
