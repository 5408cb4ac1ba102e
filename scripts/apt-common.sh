# apt-common.sh: what the install-*-deps.sh scripts share, sourced by each after
# it defines `say`: the check that this is a Debian-like system, the release's
# name, whether a package is installed or offered, sudo when not root, one
# `apt-get update` at the most, and the install of what is missing.
# Usage: . apt-common.sh "what to do without apt-get" (a line said on stderr).

if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
  say "this script knows Debian's packages only (no apt-get here). $1" >&2
  exit 2
fi
release=$( (. /etc/os-release 2>/dev/null && echo "${PRETTY_NAME:-unknown}") || echo unknown)

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
# Whether apt's current package lists offer the package at all.
offered() {
  local candidate
  candidate=$(apt-cache policy "$1" 2>/dev/null | awk '/Candidate:/ {print $2; exit}')
  [ -n "$candidate" ] && [ "$candidate" != "(none)" ]
}

sudo=""
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { say "run as root (or install sudo)" >&2; exit 2; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
updated=""
update() { [ -n "$updated" ] || { $sudo apt-get update -q; updated=1; }; }

# install_missing PACKAGE...: installs the packages named (those found missing), or says
# that nothing is missing; on failure names the ones this release does not offer. Ends
# the script either way.
install_missing() {
  if [ $# -eq 0 ]; then
    say "all packages already installed ($release)"
    exit 0
  fi
  say "installing on $release: $*"
  update
  if ! $sudo apt-get install -y -q --no-install-recommends "$@"; then
    say "apt-get could not install: $*" >&2
    local p
    for p in "$@"; do offered "$p" || say "  $p: not offered by $release's package lists" >&2; done
    exit 1
  fi
  say "done"
  exit 0
}
