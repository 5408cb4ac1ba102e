#!/usr/bin/env bash
# with_display.sh [-s "XVFB ARGS"] CMD...
# Runs CMD with a virtual X display of its own (Xvfb) and exits with CMD's own
# status, for the tests that open windows. Not xvfb-run -a: tests started at
# once all begin its search at display 99 and race for it, and its clean-up can
# end with a status of its own (5) that reads as the command's. Here each run
# starts its search at a number of its own, a display taken meanwhile is
# passed over (the server refuses it), the server says when it is ready
# (-displayfd), and whatever its clean-up meets, the status is CMD's; 125 when
# no display could be started (said on stderr).
set -u
server_args="-screen 0 1280x1024x24"
if [ "${1:-}" = -s ]; then server_args=$2; shift 2; fi
[ $# -gt 0 ] || { echo "with_display: give a command" >&2; exit 125; }
command -v Xvfb >/dev/null && command -v xauth >/dev/null ||
  { echo "with_display: Xvfb and xauth are needed (scripts/install-deps.sh installs them)" >&2; exit 125; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/sl-display-XXXXXX") || exit 125
auth="$dir/Xauthority"
: >"$auth"
server=""
stop() {
  if [ -n "$server" ]; then kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; fi
  rm -rf "$dir" 2>/dev/null
}
trap stop EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
cookie=$(mcookie 2>/dev/null || od -An -N16 -tx1 /dev/urandom | tr -d ' \n')
number=$(( 100 + ($$ * 7 + RANDOM) % 800 ))
for _ in $(seq 1 40); do
  while [ -e "/tmp/.X$number-lock" ]; do number=$(( number + 1 )); done
  xauth -f "$auth" add ":$number" . "$cookie" 2>/dev/null
  rm -f "$dir/ready"
  mkfifo "$dir/ready"
  # shellcheck disable=SC2086 # the server's arguments are words
  # -noreset: by default the server resets whenever its last client leaves, and refuses connections
  # meanwhile; runners come and go one after another, so a runner starting then would find no display
  Xvfb ":$number" $server_args -noreset -nolisten tcp -auth "$auth" -displayfd 3 3>"$dir/ready" 2>"$dir/server.log" &
  server=$!
  # the display's number arrives once the server accepts clients; nothing when it gave up
  shown=""
  read -r -t 30 shown <"$dir/ready" || true
  if [ "$shown" = "$number" ] && kill -0 "$server" 2>/dev/null; then break; fi
  kill "$server" 2>/dev/null; wait "$server" 2>/dev/null
  server=""
  number=$(( number + 1 ))
done
if [ -z "$server" ]; then
  echo "with_display: could not start a virtual display; the server's last words:" >&2
  tail -n 5 "$dir/server.log" >&2
  exit 125
fi
DISPLAY=":$number" XAUTHORITY="$auth" "$@"
status=$?
exit "$status"
