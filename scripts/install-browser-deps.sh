#!/usr/bin/env bash
# Installs what the test of the browser viewer (shadowlab --serve) drives it
# with, as Debian packages (Debian 12 bookworm, 13 trixie, testing):
#   chromium         a real browser, run headless
#   chromium-driver  chromedriver: the W3C WebDriver protocol over HTTP on
#                    this machine, which tests/serve_browser.py speaks
#   python3          tests/serve_browser.py (standard library only)
# Kept apart from install-deps.sh: the labs, the viewer and the grader need
# none of it (and a grading image should not carry a browser).
# scripts/run-tests.sh (CI) runs it; without these the test is skipped.
# Idempotent; run as root (or with sudo).
set -euo pipefail

packages=(chromium chromium-driver python3)

say() { echo "install-browser-deps: $*"; }

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=apt-common.sh
. "$here/apt-common.sh" "Install Chromium, its chromedriver and Python 3 by other means to run the --serve test."

missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
install_missing "${missing[@]+"${missing[@]}"}"
