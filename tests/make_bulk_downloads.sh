#!/usr/bin/env bash
# Mock bulk downloads, made from the solutions and the variants in
# tests/variants, named as the platforms name them:
#
#   canvas-submissions.zip   Canvas "Download Submissions": flat files
#                            <sortable name>_[LATE_]<user id>_<file id>_<file name>,
#                            a resubmitted file's name with -1, a text entry
#                            <name>_<user id>_text.html (lib/content_zipper.rb)
#   moodle-folders.zip       Moodle "Download all submissions", in folders:
#                            "<Full Name>_<id>_assignsubmission_file_/<the files as uploaded>",
#                            onlinetext as "<Full Name>_<id>_assignsubmission_onlinetext_/onlinetext.html"
#   moodle-flat.zip          the same without "Download submissions in folders":
#                            "<Full Name>_<id>_assignsubmission_file_<file name>"
#
# Who is in them (tests/bulk_downloads.sh expects their lab 1 grades):
#   smithbob 1002      Canvas, late, one archive (shadowlab.zip holding labs/): lab1_no_viewport
#   leeann 1003        Canvas, lab 1's files loose, lab1-1.c (uploaded again) and the first
#                      lab1.c (a stub) beside it: the solutions
#   nguyenan 1004      Canvas, a text entry only: no lab file
#   Jane Doe 2001      Moodle folders, labs/ as uploaded and an online text: the solutions
#   Zoë Müller 2002    Moodle folders, a Finder zip (__MACOSX, ._ files) of lab 1 saved by a
#                      Windows editor (BOM, CRLF): the solutions
#   Omar Haddad 2004   Moodle flat, lab 1's files: lab1_no_viewport
#
#   make_bulk_downloads.sh SOURCE OUT
set -euo pipefail
source=$1 out=$2
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=C.UTF-8 # names with accents go into the archives as UTF-8
zip_of() { # zip_of ARCHIVE DIR: DIR's entries at the archive's root
  (cd "$2" && shopt -s dotglob && cmake -E tar cf "$1" --format=zip -- *)
}
lab1="lab1_depth_fbo"
bash "$source/tests/make_variant.sh" "$source/tests/variants/lab1_no_viewport.variant" "$source/solutions" \
  "$work/no_viewport" >/dev/null
solutions="$source/solutions"

# ---- Canvas ----
c="$work/canvas"
mkdir -p "$c"
mkdir -p "$work/smithbob/labs"
cp -R "$work/no_viewport/$lab1" "$work/smithbob/labs/"
zip_of "$c/smithbob_LATE_1002_5004_shadowlab.zip" "$work/smithbob"
cp "${SHADOWLAB_STUBS:-$source/labs}/$lab1/lab1.c" "$c/leeann_1003_5001_lab1.c"
cp "$solutions/$lab1/lab1.c" "$c/leeann_1003_5005_lab1-1.c"
cp "$solutions/$lab1/shaders/depth.vert" "$c/leeann_1003_5006_depth.vert"
cp "$solutions/$lab1/shaders/depth.frag" "$c/leeann_1003_5007_depth.frag"
printf '<p>I could not upload my files, here is my answer.</p>\n' >"$c/nguyenan_1004_text.html"
zip_of "$out/canvas-submissions.zip" "$c"

# ---- Moodle, in folders ----
m="$work/moodle"
jane="$m/Jane Doe_2001_assignsubmission_file_"
mkdir -p "$jane/labs"
cp -R "$solutions/$lab1" "$jane/labs/"
zoe="$work/zoe"
mkdir -p "$zoe/shadowlab/$lab1/shaders" "$zoe/__MACOSX/shadowlab/$lab1"
for f in lab1.c shaders/depth.vert shaders/depth.frag; do   # a Windows editor: BOM and CRLF
  { printf '\xef\xbb\xbf'; sed 's/$/\r/' "$solutions/$lab1/$f"; } >"$zoe/shadowlab/$lab1/$f"
done
printf 'Mac OS X resource fork' >"$zoe/__MACOSX/shadowlab/$lab1/._lab1.c"
printf 'Finder' >"$zoe/shadowlab/.DS_Store"
mkdir -p "$m/Zoë Müller_2002_assignsubmission_file_"
zip_of "$m/Zoë Müller_2002_assignsubmission_file_/shadowlab.zip" "$zoe"
mkdir -p "$m/Jane Doe_2001_assignsubmission_onlinetext_"
printf '<p>See my lab report.</p>\n' >"$m/Jane Doe_2001_assignsubmission_onlinetext_/onlinetext.html"
zip_of "$out/moodle-folders.zip" "$m"

# ---- Moodle, flat ----
f="$work/moodle-flat"
mkdir -p "$f"
cp "$work/no_viewport/$lab1/lab1.c" "$f/Omar Haddad_2004_assignsubmission_file_lab1.c"
cp "$work/no_viewport/$lab1/shaders/depth.vert" "$f/Omar Haddad_2004_assignsubmission_file_depth.vert"
cp "$work/no_viewport/$lab1/shaders/depth.frag" "$f/Omar Haddad_2004_assignsubmission_file_depth.frag"
zip_of "$out/moodle-flat.zip" "$f"
