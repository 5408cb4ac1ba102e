#!/usr/bin/env bash
# Installs every Debian 12 package shadowlab needs to build, run and test.
# Idempotent: packages already present are left alone. Run as root (or with sudo).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglfw3-dev          # viewer window (X11 build)
  libcglm-dev           # math (GLM for C)
  libosmesa6-dev        # headless GL for the grader (OSMesa, llvmpipe)
  libgl-dev             # GL headers: GL/glcorearb.h, KHR/khrplatform.h
  libopenimageio-dev    # PNG / OpenEXR capture and references
  libcjson-dev          # case files, reports
  xvfb xauth            # the viewer's tests run in a virtual X display
  libgl1-mesa-dri libglx-mesa0   # llvmpipe behind GLX: the viewer under Xvfb
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root (missing: ${missing[*]})" >&2; exit 2; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
