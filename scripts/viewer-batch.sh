# viewer-batch.sh: sourced by the scripts and tests that run the viewer headless many times, as one
# `shadowlab --batch` (one process: the image module and the GL drivers load once, not once a run).
#
#   viewer_batch_quote ARGS...       prints ARGS as one batch line (quoted as a shell would read them back)
#   viewer_batch_add NAME ARGS...    queues a run of the viewer with ARGS
#   viewer_batch_run VIEWER WORK_DIR runs the queue: each run's output (stdout and stderr) in WORK_DIR/NAME.log,
#                                    its exit status in WORK_DIR/NAME.exit (none: the viewer never ended it),
#                                    everything in WORK_DIR/batch.log; returns 1 if a run failed
#   viewer_batch_status WORK_DIR NAME returns the run's exit status (255: it never ended)
#
# The viewer marks where each line starts (`shadowlab: batch line N`, on stdout and stderr) and how it ended
# (`shadowlab: batch line N: exit S`, stdout); a line that kills the viewer's process ends with S = 128 + the
# signal and the lines after it run on in a new process (README.md, --batch).
viewer_batch_names=() viewer_batch_lines=()
viewer_batch_quote() {
  local w line=""
  for w in "$@"; do line+=" '${w//\'/\'\\\'\'}'"; done
  printf '%s\n' "${line# }"
}
viewer_batch_add() {
  local name=$1
  shift
  viewer_batch_names+=("$name") viewer_batch_lines+=("$(viewer_batch_quote "$@")")
}
viewer_batch_run() {
  local viewer=$1 work=$2 i status=0
  printf '%s\n' "${viewer_batch_lines[@]}" >"$work/batch.txt"
  rm -f "$work"/batch.*.log "$work"/batch.*.exit
  "$viewer" --batch "$work/batch.txt" >"$work/batch.log" 2>&1
  # line N's output (from its start marker to the next line's) in batch.N.log, its status in batch.N.exit
  awk -v dir="$work" '
    /^shadowlab: batch line [0-9]+: exit [0-9]+$/ { n = $4; sub(":", "", n); print $6 > (dir "/batch." n ".exit"); next }
    /^shadowlab: batch line [0-9]+$/ { n = $4; next }
    n { print > (dir "/batch." n ".log") }' "$work/batch.log"
  for i in "${!viewer_batch_names[@]}"; do
    touch "$work/batch.$((i + 1)).log"
    mv "$work/batch.$((i + 1)).log" "$work/${viewer_batch_names[$i]}.log"
    rm -f "$work/${viewer_batch_names[$i]}.exit"
    if [ -f "$work/batch.$((i + 1)).exit" ]; then
      mv "$work/batch.$((i + 1)).exit" "$work/${viewer_batch_names[$i]}.exit"
      [ "$(cat "$work/${viewer_batch_names[$i]}.exit")" = 0 ] || status=1
    else
      status=1
    fi
  done
  viewer_batch_names=() viewer_batch_lines=()
  return $status
}
viewer_batch_status() { [ -f "$1/$2.exit" ] && return "$(cat "$1/$2.exit")"; return 255; }
