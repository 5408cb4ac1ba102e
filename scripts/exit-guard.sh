# Sourced by the staff's scripts (grade-submission, grade-batch, bootstrap.sh,
# the Gradescope and PrairieLearn entry points):
#
#   source "$root/scripts/exit-guard.sh" NAME STATUS...
#
# Whatever ends the script (a command failing under set -e, an unexpected status
# of a program it passes on), it exits with one of the STATUS its header
# documents; any other becomes 2, "a problem on the staff's side", said with the
# command and line that ended it, so that a batch or a platform never reads a
# status it does not know (an xvfb-run's 5, a crash's 139). A script with its own
# clean-up defines sl_on_exit; the guard runs it first.
_sl_guard_name=$1
shift
_sl_guard_allowed=" $* "
_sl_guard_cause=""
# the last command that failed, for the message (set -E: functions' too)
set -E
trap '_sl_guard_cause="\"$BASH_COMMAND\" (line $LINENO, status $?)"' ERR
_sl_guard_exit() {
  local status=$?
  trap - ERR
  if declare -F sl_on_exit >/dev/null; then sl_on_exit || true; fi
  case "$_sl_guard_allowed" in *" $status "*) exit "$status" ;; esac
  echo "$_sl_guard_name: internal error: exit status $status${_sl_guard_cause:+ after $_sl_guard_cause}" \
    "(a problem on the staff's side, not the submission's)" >&2
  exit 2
}
trap _sl_guard_exit EXIT
