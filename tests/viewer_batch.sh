# Sourced by the tests that run the viewer many times headless: viewer_batch_add NAME ARGS... queues a
# run, viewer_batch_run VIEWER WORK_DIR runs the queue as one `VIEWER --batch` (one process: the image
# module and the GL drivers load once, not once a run) and leaves each run's output (stdout and stderr)
# in WORK_DIR/NAME.log and its exit status in WORK_DIR/NAME.exit (none: the viewer stopped before it).
viewer_batch_names=() viewer_batch_lines=()
viewer_batch_add() {
  local name=$1 w line=""
  shift
  for w in "$@"; do line+=" '${w//\'/\'\\\'\'}'"; done
  viewer_batch_names+=("$name") viewer_batch_lines+=("${line# }")
}
viewer_batch_run() {
  local viewer=$1 work=$2 i
  printf '%s\n' "${viewer_batch_lines[@]}" >"$work/batch.txt"
  rm -f "$work"/batch.*.log "$work"/batch.*.exit
  "$viewer" --batch "$work/batch.txt" >"$work/batch.log" 2>&1
  # the viewer marks where each line starts (stdout and stderr) and how it ended (stdout)
  awk -v dir="$work" '
    /^shadowlab: batch line [0-9]+: exit [0-9]+$/ { n = $4; sub(":", "", n); print $6 > (dir "/batch." n ".exit"); next }
    /^shadowlab: batch line [0-9]+$/ { n = $4; next }
    n { print > (dir "/batch." n ".log") }' "$work/batch.log"
  for i in "${!viewer_batch_names[@]}"; do
    touch "$work/batch.$((i + 1)).log"
    mv "$work/batch.$((i + 1)).log" "$work/${viewer_batch_names[$i]}.log"
    rm -f "$work/${viewer_batch_names[$i]}.exit"
    [ -f "$work/batch.$((i + 1)).exit" ] && mv "$work/batch.$((i + 1)).exit" "$work/${viewer_batch_names[$i]}.exit"
  done
  viewer_batch_names=() viewer_batch_lines=()
}
# viewer_batch_status WORK_DIR NAME: the run's exit status (255: it never ended)
viewer_batch_status() { [ -f "$1/$2.exit" ] && return "$(cat "$1/$2.exit")"; return 255; }
