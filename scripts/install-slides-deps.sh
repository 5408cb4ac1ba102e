#!/usr/bin/env bash
# Installs what `cmake --build build --target slides` needs to build the
# lecture decks, as Debian packages (Debian 12 bookworm, 13 trixie, testing):
#   pandoc         Markdown -> HTML slides (dzslides: one self-contained file)
#                  and -> the HTML the PDF is printed from
#   weasyprint     HTML + CSS -> PDF (no LaTeX: a fraction of TeX Live's size); brings
#                  python3 and python3-pil, which draw the diagrams and crop the figures
#   libjs-katex, fonts-katex, nodejs
#                  KaTeX (Debian 12: 0.16.4, 13 and testing: 0.16.10) run by node at build
#                  time: the math is typeset in the HTML and the PDF, no script needed
#   poppler-utils  pdftoppm, which the slides' tests use to look at PDF pages
#   chromium       the slides' test opens every HTML deck in it, headless
#   fonts-dejavu-core  the fonts the decks are set in
# Kept apart from install-deps.sh: the grader and the labs need none of it.
# scripts/run-tests.sh (CI) runs it; without these tools the slides target
# says what is missing and the slides' tests are skipped.
# Idempotent; run as root (or with sudo).
set -euo pipefail

# A name ending in '?' is installed where the release has it.
packages=(
  pandoc
  # Debian 12's python3-fonttools (weasyprint's) needs python3-scipy OR
  # python3-munkres: naming the small one keeps SciPy, Pythran and the Boost
  # headers (about 250 MB) off the machine.
  python3-munkres?
  weasyprint
  python3-pil
  libjs-katex
  fonts-katex
  nodejs
  poppler-utils
  chromium
  fonts-dejavu-core
)

say() { echo "install-slides-deps: $*"; }

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=apt-common.sh
. "$here/apt-common.sh" "Install pandoc, WeasyPrint, KaTeX with node, pdftoppm and Chromium by other means; see slides/README.md."

missing=()
for p in "${packages[@]}"; do
  name=${p%\?}
  installed "$name" && continue
  [ "$name" = "$p" ] && { missing+=("$name"); continue; }
  # An optional package is only worth it while weasyprint still has to come.
  installed weasyprint && continue
  update
  offered "$name" && missing+=("$name")
done
install_missing "${missing[@]+"${missing[@]}"}"
