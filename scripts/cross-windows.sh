#!/usr/bin/env bash
# cross-windows.sh [OUT] [student|solutions]: the viewer built for Windows on Debian with
# mingw-w64, then run under Wine in a virtual display (Xvfb) to its first
# frame. A check that the viewer stays portable, not a way to ship it.
#
#   1. Debian's packages: mingw-w64's C compiler, Wine, Xvfb, dpkg-dev (apt-get source).
#   2. GLFW and cJSON from Debian's own source packages: a deb-src line is added
#      beside the system's deb lines (/etc/apt/sources.list.d/shadowlab-deb-src.sources)
#      and `apt-get source glfw3 cjson` fetches them. Nothing else is downloaded.
#      cglm is headers only: Debian's libcglm-dev (install-deps.sh) serves both.
#   3. GLFW built with mingw-w64 (its own CMake, static); cJSON compiled in.
#   4. The viewer (student labs, or solutions) compiled and linked with the same sources and
#      warnings as on Linux: no OSMesa, no EGL (offscreen is the hidden
#      window), no --serve, no image module (OpenImageIO is not cross-built:
#      screenshots say the module is missing). The grader is not built: its
#      runners' sandbox is Linux's.
#   5. Run under Wine (its OpenGL goes to the host's, Mesa's llvmpipe in Xvfb):
#      `shadowlab.exe --headless --lab 4 --frames 30` (a hidden window) must end with 0 (OUT/run.log), then
#      the viewer is left running in its window while xwd saves Xvfb's screen
#      (OUT/first-frame.png, made from it with Python's standard library).
# OUT defaults to build/windows. Run as root (or with sudo): it installs
# packages and adds the deb-src line.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/windows}
kind=${2:-student}
case $kind in student) labs="$root/labs" ;; solutions) labs="$root/solutions" ;; *) echo "usage: $0 [OUT] [student|solutions]" >&2; exit 2 ;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)
say() { echo "cross-windows: $*"; }
sudo=""
[ "$(id -u)" = 0 ] || sudo=sudo
export DEBIAN_FRONTEND=noninteractive

# 1. packages
packages=(gcc-mingw-w64-x86-64-posix mingw-w64-tools cmake make dpkg-dev wine64 xvfb xauth x11-apps libglx-mesa0
          libcglm-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
wine=$(command -v wine64 || echo /usr/lib/wine/wine64)
[ -x "$wine" ] || { say "no wine64 after installing it"; exit 1; }

# 2. sources: a deb-src line for each of the system's deb lines, once
src_list=/etc/apt/sources.list.d/shadowlab-deb-src.sources
if ! grep -rqs '^Types:.*deb-src\|^deb-src ' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $sudo tee "$src_list" >/dev/null
  else
    grep -h '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | $sudo tee "${src_list%.sources}.list" >/dev/null
  fi
  say "added deb-src lines ($src_list)"
  $sudo apt-get update -q
fi
mkdir -p "$out/src"
for package in glfw3 cjson; do
  if ! ls -d "$out/src/$package"-*/ >/dev/null 2>&1; then
    say "apt-get source $package"
    (cd "$out/src" && apt-get source -q "$package" >"$out/src/$package.log" 2>&1) ||
      { tail -20 "$out/src/$package.log"; say "apt-get source $package failed"; exit 1; }
  fi
done
glfw_src=$(ls -d "$out/src"/glfw3-*/ | head -1)
cjson_src=$(ls -d "$out/src"/cjson-*/ | head -1)
say "GLFW from $(basename "$glfw_src"), cJSON from $(basename "$cjson_src")"

cc=x86_64-w64-mingw32-gcc-posix
command -v $cc >/dev/null || cc=x86_64-w64-mingw32-gcc

# 3. GLFW for Windows (static), through its own CMake and mingw-w64
toolchain="$out/mingw-w64.cmake"
cat >"$toolchain" <<EOF
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_C_COMPILER $cc)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
EOF
prefix="$out/prefix"
if [ ! -f "$prefix/lib/libglfw3.a" ]; then
  say "building GLFW with mingw-w64"
  cmake -S "$glfw_src" -B "$out/glfw-build" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF \
    -DGLFW_BUILD_DOCS=OFF >"$out/glfw.log" 2>&1 &&
    cmake --build "$out/glfw-build" -j2 >>"$out/glfw.log" 2>&1 &&
    cmake --install "$out/glfw-build" >>"$out/glfw.log" 2>&1 || { tail -30 "$out/glfw.log"; say "GLFW failed"; exit 1; }
fi
mkdir -p "$prefix/include/cjson"
cp "$cjson_src/cJSON.h" "$prefix/include/cjson/"
# cglm: headers only, the same for every target (not /usr/include itself: glibc's headers are there)
rm -rf "$prefix/include/cglm" && cp -r /usr/include/cglm "$prefix/include/"

# 4. the viewer: the sources CMake gives bin/shadowlab on Linux (sl_core,
# sl_framework, sl_cases, the student labs), without the image module
obj="$out/obj-$kind"
mkdir -p "$obj" "$out/bin"
cat >"$obj/build_info.c" <<EOF
/* Generated by cross-windows.sh: which lab sources this program uses. */
const char sl_build_labs_dir[] = "$(cd "$labs" && pwd)";
const char sl_build_labs_kind[] = "$kind";
EOF
strict=(-std=c11 -O2 -Wall -Wextra -Wshadow -Wno-unused-parameter -Wno-format-truncation -Werror)
common=(-I"$root/framework" -I"$prefix/include")
core=(sl_backend sl_case sl_compare sl_gl sl_image sl_json sl_log sl_params sl_platform sl_probe sl_protocol sl_scene
      sl_text)
# sl_framework's sources as framework/CMakeLists.txt lists them, so a module added there is built here too
mapfile -t framework < <(awk '/^add_library\(sl_framework STATIC/ { inside = 1; next }
  inside { for (i = 1; i <= NF; i++) { s = $i; sub(/\)$/, "", s); if (s ~ /\.c$/) { sub(/\.c$/, "", s); print s } }
           if (/\)/) inside = 0 }' "$root/framework/CMakeLists.txt")
[ ${#framework[@]} -gt 0 ] || { say "no sl_framework sources found in framework/CMakeLists.txt"; exit 1; }
objects=()
: >"$out/compile.log"
# an object older than its source or than any of the project's headers is made again
newest_header=$(ls -t "$root"/framework/*.h | head -1)
compile() { # compile SOURCE OBJECT FLAGS...
  local s=$1 o=$2; shift 2
  if [ ! -f "$o" ] || [ "$s" -nt "$o" ] || [ "$newest_header" -nt "$o" ]; then
    $cc -c "$s" -o "$o" "${common[@]}" "$@" 2>>"$out/compile.log" ||
      { cat "$out/compile.log"; say "FAIL: compiling $s"; exit 1; }
  fi
  objects+=("$o")
}
say "compiling the viewer with $cc"
for f in "${core[@]}"; do
  compile "$root/framework/$f.c" "$obj/$f.o" "${strict[@]}" -DSL_SCENES_DIR="\"$root/framework/scenes\"" \
    -DSL_IMAGE_IO_BUILD_DIR="\"$out/lib\""
done
for f in "${framework[@]}"; do
  compile "$root/framework/$f.c" "$obj/$f.o" "${strict[@]}" -DSL_FRAMEWORK_DIR="\"$root/framework\"" \
    -DSL_GRADER_DIR="\"$root/grader\""
done
for d in "$labs"/lab*_*/; do
  n=$(basename "$d" | sed 's/^lab\([0-9]*\)_.*/\1/')
  # student files: warnings, never errors
  compile "$d/lab$n.c" "$obj/lab$n.o" -std=c11 -O2 -Wall -Wextra -Wno-unused-parameter
done
compile "$root/framework/viewer_main.c" "$obj/viewer_main.o" "${strict[@]}"
compile "$obj/build_info.c" "$obj/build_info.o" "${strict[@]}"
compile "$cjson_src/cJSON.c" "$obj/cJSON.o" -std=c89 -O2
say "linking bin/shadowlab.exe"
$cc -o "$out/bin/shadowlab.exe" "${objects[@]}" -L"$prefix/lib" -lglfw3 -lgdi32 -lm -static -lwinpthread \
  2>"$out/link.log" || { cat "$out/link.log"; say "FAIL: linking"; exit 1; }
file "$out/bin/shadowlab.exe" 2>/dev/null | sed 's/^/cross-windows: /' || true

# 5. under Wine, in a virtual display, to the first frame
export WINEPREFIX="$out/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
rm -f "$out/first-frame.xwd" "$out/first-frame.png"
say "running it under Wine in Xvfb (the first run makes the Wine prefix: a minute)"
cat >"$out/run-in-display.sh" <<'EOF'
#!/bin/sh
# In the virtual display: 30 frames offscreen (a hidden window) that must end well, then the
# viewer left running in its window while the screen is saved.
out=$1 wine=$2
"$wine" wineboot -i >/dev/null 2>&1
"$wine" "$out/bin/shadowlab.exe" --headless --lab 4 --size 640x360 --frames 30 >"$out/run.log" 2>&1
echo "exit $?" >>"$out/run.log"
"$wine" "$out/bin/shadowlab.exe" --lab 4 --size 640x360 >"$out/window.log" 2>&1 &
viewer=$!
for i in $(seq 120); do
  sleep 1
  grep -q ' through ' "$out/window.log" 2>/dev/null && break
  kill -0 $viewer 2>/dev/null || break
done
sleep 10
xwd -root -silent >"$out/first-frame.xwd" 2>/dev/null
kill $viewer 2>/dev/null
"$(dirname "$wine")/wineserver" -k 2>/dev/null || true
EOF
chmod +x "$out/run-in-display.sh"
timeout 600 xvfb-run -a -s "-screen 0 800x480x24" "$out/run-in-display.sh" "$out" "$wine" || true
cat "$out/run.log"
[ -s "$out/first-frame.xwd" ] || { say "FAIL: no picture of the screen"; exit 1; }
# XWD (TrueColor ZPixmap, as Xvfb's) to PNG with Python's standard library alone
if ! python3 - "$out/first-frame.xwd" "$out/first-frame.png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
f = struct.unpack(">25I", data[:100])
header_size, fmt, width, height, byte_order, bpp, line = f[0], f[2], f[4], f[5], f[7], f[11], f[12]
masks, ncolours = f[14:17], f[19]
assert fmt == 2 and bpp in (24, 32), f"not a 24- or 32-bit ZPixmap (format {fmt}, {bpp} bits)"
step = bpp // 8
pixels = data[header_size + 12 * ncolours:]
shifts = [(m & -m).bit_length() - 1 for m in masks]
rows = []
for y in range(height):
    row = pixels[y * line:y * line + width * step]
    out = bytearray()
    for x in range(width):
        v = int.from_bytes(row[step * x:step * x + step], "little" if byte_order == 0 else "big")
        out += bytes(((v & m) >> s) & 255 for m, s in zip(masks, shifts))
    rows.append(b"\0" + bytes(out))
chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"".join(rows), 6)) + chunk(b"IEND", b"")
open(sys.argv[2], "wb").write(png)
lit = sum(1 for r in rows for i in range(1, len(r), 3) if r[i] or r[i + 1] or r[i + 2])
print(f"cross-windows: {lit} of {width * height} screen pixels not black")
sys.exit(0 if lit > width * height // 10 else 1)
PY
then
  say "FAIL: the screen was black while the viewer ran ($out/first-frame.png)"; exit 1
fi
grep -q '^exit 0' "$out/run.log" || { say "FAIL: the viewer did not exit 0 under Wine"; exit 1; }
say "passed: the screen while the Windows viewer ran under Wine: $out/first-frame.png"
