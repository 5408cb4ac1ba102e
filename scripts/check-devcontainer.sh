#!/usr/bin/env bash
# check-devcontainer.sh ROOT: runs the dev container's steps on a fresh
# Debian 12 without a container engine: debootstrap makes a minimal bookworm
# file system in ROOT (kept, so a second run starts from it), then, inside it
# (chroot), the COPY and RUN lines of .devcontainer/Dockerfile in order, the
# postCreateCommand of .devcontainer/devcontainer.json in a copy of this
# commit, and a smoke test: the grader grades lab 1 and `shadowlab --serve
# 8080` serves its page. Run as root; downloads Debian's packages.
set -euo pipefail
root=${1:?usage: check-devcontainer.sh ROOT}
src=$(cd "$(dirname "$0")/.." && pwd)
say() { echo "check-devcontainer: $*"; }
[ "$(id -u)" = 0 ] || { say "run as root (debootstrap, chroot)"; exit 2; }
command -v debootstrap >/dev/null || { apt-get update -q && apt-get install -y -q debootstrap; }

if [ ! -e "$root/.shadowlab-fresh" ]; then
  rm -rf "$root"
  say "a fresh Debian 12 in $root (debootstrap --variant=minbase bookworm)"
  debootstrap --variant=minbase bookworm "$root" >"$root.debootstrap.log" 2>&1 ||
    { tail -20 "$root.debootstrap.log"; exit 1; }
  touch "$root/.shadowlab-fresh"
  # the pristine system, to start every run from
  tar -C "$root" -cf "$root.tar" .
else
  say "back to the pristine Debian 12 in $root"
  rm -rf "$root"; mkdir -p "$root"; tar -C "$root" -xf "$root.tar"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
mounted=()
cleanup() { for m in "${mounted[@]}"; do umount -l "$m" 2>/dev/null || true; done; }
trap cleanup EXIT
for m in proc dev dev/pts sys; do
  mount --bind "/$m" "$root/$m"; mounted=("$root/$m" "${mounted[@]}")
done
# The build context: this commit's files, where a dev container has them.
work=/workspaces/shadowlab
mkdir -p "$root$work"
git -C "$src" archive HEAD | tar -x -C "$root$work"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  LANG=C.UTF-8 /bin/sh -c "$1"; }

# The Dockerfile, line by line (continuations joined): COPY and RUN.
python3 - "$src/.devcontainer/Dockerfile" >"$root/.steps" <<'PY'
import sys
text = open(sys.argv[1]).read().replace("\\\n", " ")
for line in text.splitlines():
    line = line.strip()
    if line.startswith(("COPY ", "RUN ")):
        print(line)
PY
while IFS= read -r step; do
  case $step in
    COPY\ *)
      set -- ${step#COPY }
      dest=${!#}
      mkdir -p "$root$dest"
      for f in "${@:1:$#-1}"; do cp "$src/$f" "$root$dest"; done
      say "COPY ${*:1:$#-1} -> $dest" ;;
    RUN\ *)
      say "RUN ${step#RUN }"
      in_root "${step#RUN }" ;;
  esac
done <"$root/.steps"

command=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["postCreateCommand"])' \
  "$src/.devcontainer/devcontainer.json")
say "postCreateCommand: $command"
in_root "cd $work && $command" >"$root.build.log" 2>&1 || { tail -30 "$root.build.log"; say "FAIL: the build"; exit 1; }

say "smoke test: the grader on lab 1 (the stubs: exit 1 and a score)"
status=0
in_root "cd $work && ./build/bin/shadowlab-grade --lab 1" >"$root.grade.log" 2>&1 || status=$?
tail -3 "$root.grade.log"
[ $status -eq 1 ] && grep -q '^Score: 0/' "$root.grade.log" || { say "FAIL: grade exited $status"; exit 1; }

say "smoke test: shadowlab --serve 8080 serves the page"
# chroot, env and sh each exec the next: $! is the viewer itself
chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root /bin/sh -c \
  "cd $work && exec ./build/bin/shadowlab --serve 8080 --size 320x180" >"$root.serve.log" 2>&1 &
viewer=$!
served=""
for _ in $(seq 60); do
  if grep -q "serving the viewer at http://127.0.0.1:8080/" "$root.serve.log" &&
     curl -sf http://127.0.0.1:8080/ | grep -q "<title>shadowlab</title>"; then served=1; break; fi
  sleep 1
done
kill "$viewer" 2>/dev/null || true
wait "$viewer" 2>/dev/null || true
[ -n "$served" ] || { cat "$root.serve.log"; say "FAIL: no page at port 8080"; exit 1; }
say "passed: the dev container's steps work on a fresh Debian 12"
