# apt-common.sh: what install-deps.sh and install-slides-deps.sh share, sourced
# by both after they set `packages` and define `say`: the check that this is a
# Debian-like system, the release's name, whether a package is installed or
# offered, sudo when not root, and one `apt-get update` at the most.
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
