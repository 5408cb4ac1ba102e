#!/usr/bin/env bash
# A small class as the platforms really export it, made from the solutions,
# the handout's stubs and one known mistake (lab1_no_draw_buffer_none: only the
# framebuffer check fails, so some points of lab1_depth_boxes are lost):
#
#   canvas-v1.zip   Canvas "Download Submissions": flat files
#                   <name>[_LATE]_<user id>_<attachment id>_<file name>, twelve students:
#     adamsamy 101   complete: shadowlab.zip holding labs/ (every lab of the solutions)
#     brownben 102   partial: lab1.zip holding labs/lab1_depth_fbo only
#     clarkcat 103   late, one mistake: lab 1's files loose, glDrawBuffer(GL_NONE) left out
#     davisdan 104   a Finder zip: shadowlab/lab1_depth_fbo/..., __MACOSX/, ._ files, .DS_Store
#     evanseve 105   Windows: files loose with a BOM and CRLF, Thumbs.db, desktop.ini; lab1.c
#                    uploaded twice (the first the stub, the second "lab1-1.c", a later attachment)
#     fosterfay 106  labs.tar.gz
#     garciagus 107  a text entry only
#     harrishal 108  project.zip: shadowlab-main/labs/... beside a build/ folder of 1500 files
#     ivanovivy 109  lab 1 that does not compile
#     jonesjay 110   the handout's lab1.c unchanged, and a file named like another student's
#                    Canvas file (adamsamy_101_999_lab1.c, an #error)
#     kingkim 111    the wrong file: report.pdf
#     leelou 112     an empty zip (only what macOS adds)
#   canvas-v2.zip   the same download a day later: clarkcat fixed lab 1 (new attachments)
#   moodle.zip      Moodle "Download all submissions" (not in folders): files
#                   "<Full Name>_<id>_assignsubmission_file_<file name>", six students:
#     Amy Adams 2001      complete: shadowlab.zip holding labs/
#     Ben Brown 2002      the handout's labs/, unchanged, in labs.zip
#     Jay Jones 2010      lab 1 loose, and a file he named "Amy Adams_2001_assignsubmission_file_lab1.c"
#                         (an #error): it is his, never Amy's
#     Gus Garcia 2007     online text only
#     ".." 2011           (a full name of dots) the handout's lab1.c, unchanged
#     gradebook.csv 2013  (a full name like the batch's own file) an empty zip
#   classroom/      GitHub Classroom's folders "<assignment>-<username>/": shadowlab-alice
#                   (labs/), shadowlab-bob-smith (lab1.c loose)
#   by-hand/        a folder of submissions named "_..", "_.split", "gradebook.csv", "grader-options"
#                   (the stubs, or nothing): names that reduce to the batch's own
#
#   make_lms_class.sh SOURCE STUBS OUT
set -euo pipefail
source=$1 stubs=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export LC_ALL=C.UTF-8
zip_of() { # zip_of ARCHIVE DIR: DIR's entries at the archive's root
  (cd "$2" && shopt -s dotglob && cmake -E tar cf "$1" --format=zip -- *)
}
lab1=lab1_depth_fbo
sol="$source/solutions/$lab1"
bash "$source/tests/make_variant.sh" "$source/tests/variants/lab1_no_draw_buffer_none.variant" "$source/solutions" \
  "$work/no_draw_buffer" >/dev/null
mistake="$work/no_draw_buffer/$lab1"
windows() { { printf '\xef\xbb\xbf'; sed 's/$/\r/' "$1"; } >"$2"; } # a Windows editor: BOM and CRLF

# ---- Canvas ----
c="$work/canvas"
mkdir -p "$c" "$work/adams/labs" "$work/brown/labs" "$work/davis/shadowlab/$lab1" "$work/davis/__MACOSX/shadowlab/$lab1"
cp -R "$source/solutions/." "$work/adams/labs/"
zip_of "$c/adamsamy_101_5001_shadowlab.zip" "$work/adams"
cp -R "$sol" "$work/brown/labs/"
zip_of "$c/brownben_102_5002_lab1.zip" "$work/brown"
cp "$mistake/lab1.c" "$c/clarkcat_LATE_103_5003_lab1.c"
cp "$mistake/shaders/depth.vert" "$c/clarkcat_LATE_103_5004_depth.vert"
cp "$mistake/shaders/depth.frag" "$c/clarkcat_LATE_103_5005_depth.frag"
cp -R "$sol/." "$work/davis/shadowlab/$lab1/"
printf 'resource fork' >"$work/davis/__MACOSX/shadowlab/$lab1/._lab1.c"
printf 'Finder' >"$work/davis/shadowlab/.DS_Store"
zip_of "$c/davisdan_104_5006_shadowlab.zip" "$work/davis"
cp "$stubs/$lab1/lab1.c" "$c/evanseve_105_5010_lab1.c"
windows "$sol/lab1.c" "$c/evanseve_105_5020_lab1-1.c"
windows "$sol/shaders/depth.vert" "$c/evanseve_105_5021_depth.vert"
windows "$sol/shaders/depth.frag" "$c/evanseve_105_5022_depth.frag"
printf 'thumbnails' >"$c/evanseve_105_5023_Thumbs.db"
printf '[.ShellClassInfo]\r\n' >"$c/evanseve_105_5024_desktop.ini"
mkdir -p "$work/foster/labs"
cp -R "$sol" "$work/foster/labs/"
(cd "$work/foster" && cmake -E tar czf "$c/fosterfay_106_5030_labs.tar.gz" -- labs)
printf '<p>I will send my code by email.</p>\n' >"$c/garciagus_107_text.html"
h="$work/harris/shadowlab-main"
mkdir -p "$h/labs" "$h/build/CMakeFiles"
cp -R "$sol" "$h/labs/"
for i in $(seq 1 1500); do printf 'object %d\n' "$i" >"$h/build/CMakeFiles/unit$i.o"; done
zip_of "$c/harrishal_108_5040_project.zip" "$work/harris"
sed '0,/return SL_OK;/s//return SL_OK/' "$sol/lab1.c" >"$c/ivanovivy_109_5050_lab1.c"
cp "$sol/shaders/depth.vert" "$c/ivanovivy_109_5051_depth.vert"
cp "$stubs/$lab1/lab1.c" "$c/jonesjay_110_5060_lab1.c"
printf '#error "jonesjay put this here"\n' >"$c/jonesjay_110_5061_adamsamy_101_999_lab1.c"
printf '%%PDF-1.4 my report\n' >"$c/kingkim_111_5070_report.pdf"
mkdir -p "$work/lee/__MACOSX"
printf 'resource fork' >"$work/lee/__MACOSX/._nothing"
zip_of "$c/leelou_112_5080_empty.zip" "$work/lee"
zip_of "$out/canvas-v1.zip" "$c"
# a day later: clarkcat uploaded lab 1 again, fixed (Canvas names the new files -1)
cp "$sol/lab1.c" "$c/clarkcat_LATE_103_6001_lab1-1.c"
cp "$sol/shaders/depth.vert" "$c/clarkcat_LATE_103_6002_depth-1.vert"
cp "$sol/shaders/depth.frag" "$c/clarkcat_LATE_103_6003_depth-1.frag"
zip_of "$out/canvas-v2.zip" "$c"

# ---- Moodle, not in folders ----
m="$work/moodle"
mkdir -p "$m" "$work/amy/labs" "$work/ben/labs"
cp -R "$stubs/." "$work/ben/labs/"
zip_of "$m/Ben Brown_2002_assignsubmission_file_labs.zip" "$work/ben"
cp -R "$source/solutions/." "$work/amy/labs/"
zip_of "$m/Amy Adams_2001_assignsubmission_file_shadowlab.zip" "$work/amy"
for f in lab1.c shaders/depth.vert shaders/depth.frag; do
  cp "$sol/$f" "$m/Jay Jones_2010_assignsubmission_file_$(basename "$f")"
done
cp "$stubs/$lab1/lab1.c" "$m/.._2011_assignsubmission_file_lab1.c"
printf '#error "Jay Jones put this here"\n' >"$m/Jay Jones_2010_assignsubmission_file_Amy Adams_2001_assignsubmission_file_lab1.c"
printf '<p>See my report.</p>\n' >"$m/Gus Garcia_2007_assignsubmission_onlinetext_onlinetext.html"
mkdir -p "$work/gb/__MACOSX"
printf 'resource fork' >"$work/gb/__MACOSX/._x"
zip_of "$m/gradebook.csv_2013_assignsubmission_file_nothing.zip" "$work/gb"
zip_of "$out/moodle.zip" "$m"

# ---- handed in by hand, under names that reduce to the batch's own ----
b="$out/by-hand"
mkdir -p "$b/_.." "$b/_.split" "$b/gradebook.csv" "$b/grader-options"
cp "$stubs/$lab1/lab1.c" "$b/_.split/lab1.c"
cp "$stubs/$lab1/lab1.c" "$b/gradebook.csv/lab1.c"
printf 'notes\n' >"$b/grader-options/notes.txt"

# ---- GitHub Classroom ----
g="$out/classroom"
mkdir -p "$g/shadowlab-alice/labs" "$g/shadowlab-bob-smith"
cp -R "$sol" "$g/shadowlab-alice/labs/"
cp "$sol/lab1.c" "$g/shadowlab-bob-smith/"
