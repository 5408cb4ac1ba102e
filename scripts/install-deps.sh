#!/usr/bin/env bash
# Installs the Debian packages shadowlab needs to build, run and test, as the
# running release offers them (Debian 12 bookworm, 13 trixie, testing).
# --tests adds what only the project's own test suite uses (the archive
# fuzzer's clang): scripts/run-tests.sh passes it; a student's set-up does not.
# Idempotent: packages already present are left alone, and nothing is fetched
# when all are there. Run as root (or with sudo).
set -euo pipefail

# The one package list. A name ending in '?' is installed where the release has
# it and skipped where it does not.
packages=(
  build-essential cmake pkg-config
  ninja-build           # the build tool: a lab edit rebuilds in seconds (make's checks took most of them)
  libglfw3-dev          # viewer window
  libcglm-dev           # math (GLM for C)
  libgl-dev             # GL headers: GL/glcorearb.h, KHR/khrplatform.h
  libegl-dev            # headless GL through EGL (every release)
  libegl-mesa0 libgbm1  # Mesa's EGL driver: surfaceless EGL and the software device
  libgl1-mesa-dri       # llvmpipe, the software renderer (Debian 12: swrast_dri.so)
  mesa-libgallium?      # llvmpipe's home from Mesa 24.2 on (Debian 13 and later)
  libosmesa6-dev?       # headless GL through OSMesa, the references' backend; gone from Mesa 25.1 on
  libopenimageio-dev    # PNG / OpenEXR capture and references
  libcjson-dev          # case files, reports
  libarchive-dev        # submissions uploaded as .zip / .tar.gz (shadowlab-stage)
  libfreetype-dev       # the lecture overlay's TrueType text (shadowlab --lecture)
  fonts-dejavu-core     # its font, DejaVu Sans
  libwebsockets-dev     # the viewer in a browser (shadowlab --serve); optional at build time
  xvfb xauth            # the viewer's tests run in a virtual X display
  libglx-mesa0          # llvmpipe behind GLX: the viewer under Xvfb
  python3               # the handout test's scan for lab answers, the README checks (tests/*.py)
)
if [ "${1:-}" = --tests ]; then
  packages+=(
    clang libclang-rt-dev # the archive fuzzer (clang -fsanitize=fuzzer,address): Debian's default clang and its
                          # runtime, clang-14 and libclang-rt-14-dev on 12, -19 on 13, the newest on testing
  )
fi

say() { echo "install-deps: $*"; }

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=apt-common.sh
. "$here/apt-common.sh" "Install the equivalents of: ${packages[*]//\?/} (see README.md, 'Supported systems')"

required=() optional=()
for p in "${packages[@]}"; do
  case $p in *\?) optional+=("${p%\?}") ;; *) required+=("$p") ;; esac
done

missing=()
for p in "${required[@]}"; do installed "$p" || missing+=("$p"); done
# Only a machine that lacks something is asked to refresh apt's lists.
[ ${#missing[@]} -eq 0 ] || update
not_offered=()
for p in "${optional[@]}"; do
  installed "$p" && continue
  if offered "$p"; then missing+=("$p"); else not_offered+=("$p"); fi
done

if [ ${#not_offered[@]} -gt 0 ]; then
  say "not offered by $release, so skipped: ${not_offered[*]}"
  case " ${not_offered[*]} " in
    *" libosmesa6-dev "*) say "no OSMesa here (Mesa 25.1 removed it): shadowlab renders headless through EGL" ;;
  esac
fi

install_missing "${missing[@]+"${missing[@]}"}"
