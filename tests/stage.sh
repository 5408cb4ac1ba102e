#!/usr/bin/env bash
# shadowlab-stage on the upload shapes students' systems make and on hostile
# ones, without building or grading anything (fast). Fixtures are made here:
# folders with the shell, archives with tests/stage_fixtures.c.
#   stage.sh CASE STAGE_TOOL FIXTURES_TOOL SOURCE WORK [GRADER RUNNER ARGS...]
# A refused or left-out lab file must leave the handout's stub in the stage;
# nothing a link points at may reach it.
set -euo pipefail
case_name=$1 stager=$2 fixtures=$3 source=$4 work=$5
shift 5
rm -rf "$work"
mkdir -p "$work"
chmod 755 "$work"
fail=0
problem() { echo "stage.$case_name: $*" >&2; fail=1; }
solutions="$source/solutions" stubs="${SHADOWLAB_STUBS:-$source/labs}"

# stage NAME SUBMISSION [OPTIONS...]: a fresh stage from the stubs, staged into;
# $status, $out (what it said), $stage and $summary are set.
stage() {
  local name=$1 submission=$2
  shift 2
  stage="$work/$name.stage" summary="$work/$name.json"
  rm -rf "$stage"
  cp -R "$stubs" "$stage"
  set +e
  out=$("$stager" --summary "$summary" --hide "$solutions" "$@" "$submission" "$stage" 2>&1)
  status=$?
  set -e
  printf '%s\n' "--- $name (exit $status)" "$out"
}
expect_status() { [ "$status" = "$1" ] || problem "$2: exit $status, not $1"; }
said() { grep -qF -- "$1" <<<"$out" || problem "$2: it did not say \"$1\""; }
in_summary() { grep -qF -- "$1" "$summary" || problem "$2: the summary has no \"$1\""; }
# is_stub REL: the stage's file is still the handout's
is_stub() { cmp -s "$stage/$1" "$stubs/$1" || problem "$2: $1 is not the handout's stub"; }
is_solution() { cmp -s "$stage/$1" "$solutions/$1" || problem "$2: $1 is not the submitted solution"; }
all_solutions() { # every lab file of the solutions is in the stage as it is in the solutions
  local f
  while IFS= read -r f; do is_solution "${f#"$solutions"/}" "$1"; done \
    < <(find "$solutions" -type f \( -name 'lab[0-9].c' -o -path '*/shaders/*' \) | sort)
}
all_stubs() {
  diff -r "$stubs" "$stage" >/dev/null || problem "$1: the stage is not the stubs: $(diff -rq "$stubs" "$stage" | head -3)"
}

case $case_name in
finder_zip)
  # macOS Finder: "Compress shadowlab" gives a top folder beside __MACOSX/ with ._ files
  "$fixtures" archive "$work/finder.zip" zip dir:shadowlab tree:shadowlab/labs="$solutions" \
    file:shadowlab/.DS_Store=x file:shadowlab/labs/._lab1_depth_fbo=x dir:__MACOSX dir:__MACOSX/shadowlab \
    file:__MACOSX/shadowlab/._labs=x file:__MACOSX/shadowlab/labs/lab1_depth_fbo/._lab1.c=x
  stage finder "$work/finder.zip"
  expect_status 0 "a Finder zip of the solutions"
  said "layout: a labs/ folder (in shadowlab/)" "a Finder zip"
  all_solutions "a Finder zip"
  in_summary '"path":	"__MACOSX/"' "a Finder zip"
  in_summary "macOS archive metadata" "a Finder zip"
  # Gradescope keeps an uploaded zip as it is: a folder holding the zip (and a .DS_Store)
  mkdir "$work/upload"
  cp "$work/finder.zip" "$work/upload/My Shadowlab (final).zip"
  : >"$work/upload/.DS_Store"
  stage upload "$work/upload"
  expect_status 0 "a folder holding a zip"
  said "(in My Shadowlab (final).zip/shadowlab/)" "a folder holding a zip"
  all_solutions "a folder holding a zip"
  # two top folders deep, with clutter beside each, as a .tar.gz
  mkdir -p "$work/nested/alice/shadowlab-main" "$work/nested/__MACOSX"
  cp -R "$solutions" "$work/nested/alice/shadowlab-main/labs"
  : >"$work/nested/alice/Thumbs.db"
  : >"$work/nested/alice/desktop.ini"
  : >"$work/nested/alice/._shadowlab-main"
  "$fixtures" archive "$work/nested.tgz" tgz tree:="$work/nested"
  stage nested "$work/nested.tgz"
  expect_status 0 "a .tar.gz with two top folders"
  said "(in alice/shadowlab-main/)" "a .tar.gz with two top folders"
  all_solutions "a .tar.gz with two top folders"
  # loose files in a plain tar
  loose=()
  while IFS= read -r f; do loose+=("copy:$(basename "$f")=$f"); done \
    < <(find "$solutions" -type f \( -name 'lab[0-9].c' -o -path '*/shaders/*' \) | sort)
  "$fixtures" archive "$work/loose.tar" tar "${loose[@]}" file:notes.txt=hi
  stage loose "$work/loose.tar"
  expect_status 0 "loose files in a .tar"
  said "layout: loose files" "loose files in a .tar"
  all_solutions "loose files in a .tar"
  in_summary '"notes.txt"' "loose files in a .tar"
  ;;

editors_text)
  # Windows: CRLF and a byte-order mark in every file; old Mac: lone CR in one
  mkdir "$work/windows"
  cp -R "$solutions"/lab* "$work/windows/"
  while IFS= read -r f; do
    { printf '\xef\xbb\xbf'; sed 's/$/\r/' "$f"; } >"$f.new" && mv "$f.new" "$f"
  done < <(find "$work/windows" -type f \( -name 'lab[0-9].c' -o -path '*/shaders/*' \))
  tr '\n' '\r' <"$solutions/lab4_pcf/shaders/pcf.glsl" >"$work/windows/lab4_pcf/shaders/pcf.glsl"
  stage windows "$work/windows"
  expect_status 0 "CRLF and byte-order marks"
  said "layout: the lab folders" "CRLF and byte-order marks"
  all_solutions "CRLF and byte-order marks"
  said "normalised: lab1_depth_fbo/lab1.c (a UTF-8 byte-order mark removed, " "CRLF and byte-order marks"
  said "lab4_pcf/shaders/pcf.glsl (" "a lone CR file"
  in_summary "CR line ends made LF" "a lone CR file"
  in_summary "Line ends and byte-order marks made plain before compiling" "CRLF and byte-order marks"
  # a NUL byte and invalid UTF-8: named with the byte offset, the file still staged
  mkdir -p "$work/bytes/lab2_projective/shaders"
  printf '#version 330 core\n// ok\nfloat x;\x00\n' >"$work/bytes/lab2_projective/shaders/shadow_lookup.glsl"
  printf '// caf\xe9\nint x;\n' >"$work/bytes/lab2_projective/lab2.c"
  printf '\xff\xfe/\x00/\x00' >"$work/bytes/lab2_projective/shaders/shadow_coord.glsl"
  stage bytes "$work/bytes"
  expect_status 0 "bytes that are not text"
  said "lab2_projective/shaders/shadow_lookup.glsl: a NUL byte at byte offset 32 (line 3)" "a NUL byte"
  said "lab2_projective/lab2.c: invalid UTF-8 at byte offset 6 (line 1)" "invalid UTF-8"
  said "lab2_projective/shaders/shadow_coord.glsl: saved as UTF-16" "a UTF-16 file"
  in_summary "a NUL byte at byte offset 32" "a NUL byte"
  cmp -s "$stage/lab2_projective/lab2.c" "$work/bytes/lab2_projective/lab2.c" || problem "the invalid UTF-8 file was not staged"
  ;;

links)
  # Links at every level, pointing at the solutions, at /etc/passwd and at a
  # folder outside; a hard link to a file outside; a FIFO, a socket, a device.
  secret="$work/outside/secret-answer.c"
  mkdir -p "$work/outside"
  echo "int secret_answer_0451;" >"$secret"
  chmod 644 "$secret"
  s="$work/subs"
  mkdir -p "$s"
  # 1. the submission itself is a link
  ln -s "$solutions" "$s/itself"
  # 2. labs/ is a link (a GitHub-linked submission keeps links)
  mkdir "$s/labs-link" && ln -s "$solutions" "$s/labs-link/labs"
  # 3. a lab folder, 4. a shaders/ folder, 5. files: at the solutions, /etc/passwd, a folder outside
  mkdir -p "$s/deep/labs/lab2_projective" "$s/deep/labs/lab3_bias/shaders" "$s/deep/labs/lab4_pcf/shaders" \
           "$s/deep/labs/lab5_vsm/shaders" "$s/deep/labs/lab6_cascades" "$s/deep/labs/lab7_cube"
  ln -s "$solutions/lab1_depth_fbo" "$s/deep/labs/lab1_depth_fbo"
  cp "$solutions/lab2_projective/lab2.c" "$s/deep/labs/lab2_projective/lab2.c"       # taken: the one real file
  ln -s "$solutions/lab2_projective/shaders" "$s/deep/labs/lab2_projective/shaders"
  ln -s "$solutions/lab3_bias/lab3.c" "$s/deep/labs/lab3_bias/lab3.c"
  ln -s /etc/passwd "$s/deep/labs/lab3_bias/shaders/bias.glsl"
  ln -s "$work/outside" "$s/deep/labs/lab4_pcf/shaders/pcf.glsl"
  ln "$secret" "$s/deep/labs/lab4_pcf/lab4.c"
  mkfifo "$s/deep/labs/lab5_vsm/lab5.c"
  "$fixtures" socket "$s/deep/labs/lab6_cascades/lab6.c"
  [ "$(id -u)" != 0 ] || mknod "$s/deep/labs/lab7_cube/lab7.c" c 1 3
  # 6. a top folder that is a link
  mkdir "$s/top" && ln -s "$solutions" "$s/top/shadowlab-main"
  # 7. loose files, every one a link: nothing is taken, and the summary says so (not "found lab1.c")
  mkdir "$s/only-links" && ln -s "$solutions/lab1_depth_fbo/lab1.c" "$s/only-links/lab1.c" \
    && ln -s "$solutions/lab1_depth_fbo/shaders/depth.frag" "$s/only-links/depth.frag"
  chmod -R a+rX "$work"
  run_all() { # run_all WHO
    local who=$1
    stage "$who-itself" "$s/itself"
    expect_status 3 "$who: the submission is a link"
    said "refused (never read): itself (a symbolic link (to $solutions)" "$who: the submission is a link"
    all_stubs "$who: the submission is a link"
    stage "$who-itself-slash" "$s/itself/"
    expect_status 3 "$who: the submission is a link, named with a slash"
    all_stubs "$who: the submission is a link, named with a slash"
    stage "$who-labs" "$s/labs-link"
    expect_status 3 "$who: labs/ is a link"
    said "labs (a symbolic link (to $solutions)" "$who: labs/ is a link"
    in_summary "No lab file found" "$who: labs/ is a link"
    all_stubs "$who: labs/ is a link"
    stage "$who-deep" "$s/deep"
    expect_status 0 "$who: links inside"
    said "took lab2_projective/lab2.c"$'\n' "$who: links inside"
    is_solution lab2_projective/lab2.c "$who: links inside"
    for f in lab1_depth_fbo/lab1.c lab1_depth_fbo/shaders/depth.vert lab2_projective/shaders/shadow_lookup.glsl \
             lab3_bias/lab3.c lab3_bias/shaders/bias.glsl lab4_pcf/shaders/pcf.glsl lab4_pcf/lab4.c lab5_vsm/lab5.c \
             lab6_cascades/lab6.c lab7_cube/lab7.c; do
      is_stub "$f" "$who: links inside"
    done
    for refused in "labs/lab1_depth_fbo (a symbolic link" "labs/lab2_projective/shaders (a symbolic link" \
                   "labs/lab3_bias/lab3.c (a symbolic link (to $solutions/lab3_bias/lab3.c)" \
                   "labs/lab3_bias/shaders/bias.glsl (a symbolic link (to /etc/passwd)" \
                   "labs/lab4_pcf/shaders/pcf.glsl (a symbolic link (to $work/outside)" \
                   "labs/lab4_pcf/lab4.c (a file with 2 names (a hard link)" "labs/lab5_vsm/lab5.c (a FIFO" \
                   "labs/lab6_cascades/lab6.c (a socket"; do
      said "$refused" "$who: links inside"
    done
    [ "$(id -u)" != 0 ] || [ "$who" != root ] || said "labs/lab7_cube/lab7.c (a device" "$who: a device"
    ! grep -rq "secret_answer_0451\|root:x:0:0" "$stage" || problem "$who: linked content reached the stage"
    stage "$who-top" "$s/top"
    expect_status 3 "$who: a top folder that is a link"
    said "shadowlab-main (a symbolic link" "$who: a top folder that is a link"
    all_stubs "$who: a top folder that is a link"
    stage "$who-only-links" "$s/only-links"
    expect_status 3 "$who: every file a link"
    in_summary "No lab file found: nothing but what was refused (below)" "$who: every file a link"
    ! grep -qF "found lab1.c" "$summary" || problem "$who: every file a link: a refused link counted as found"
    said "lab1.c (a symbolic link (to $solutions/lab1_depth_fbo/lab1.c)" "$who: every file a link"
    all_stubs "$who: every file a link"
  }
  if [ "$(id -u)" = 0 ]; then
    run_all root
    said "read the submission as uid 65534" "root: the reader's uid"
    # and as a user that is not root (the reader then keeps that user's uid)
    nobody_work="$work/as-user"
    mkdir -p "$nobody_work" && chown 65534:65534 "$nobody_work"
    stager_root=$stager
    stage() {
      local name=$1 submission=$2
      shift 2
      stage="$nobody_work/$name.stage" summary="$nobody_work/$name.json"
      rm -rf "$stage"
      setpriv --reuid=65534 --regid=65534 --clear-groups -- cp -R "$stubs" "$stage"
      set +e
      out=$(setpriv --reuid=65534 --regid=65534 --clear-groups -- \
              "$stager_root" --summary "$summary" --hide "$solutions" "$@" "$submission" "$stage" 2>&1)
      status=$?
      set -e
      printf '%s\n' "--- $name as uid 65534, not root (exit $status)" "$out"
    }
    # only where that user can run programs at all (not under a root folder closed to others)
    if setpriv --reuid=65534 --regid=65534 --clear-groups -- /bin/sh -c "test -x '$stager_root'" 2>/dev/null; then
      run_all user
    else
      echo "stage: the runs as uid 65534 left out: that user cannot run $stager_root here"
    fi
  else
    run_all user
  fi
  ;;

archive_entries)
  # entries that leave the archive, links, devices, backslash separators
  "$fixtures" archive "$work/evil.zip" zip \
    "copy:labs/lab2_projective/lab2.c=$solutions/lab2_projective/lab2.c" \
    "file:../escape.c=int escaped;" "file:/tmp/absolute-escape.c=int escaped;" \
    "file:labs/../../up.c=int escaped;" "copy:labs\\lab3_bias\\lab3.c=$solutions/lab3_bias/lab3.c" \
    "file:C:\\Windows\\evil.c=int escaped;" \
    "symlink:labs/lab1_depth_fbo/lab1.c=$solutions/lab1_depth_fbo/lab1.c" \
    "symlink:labs/lab4_pcf=/etc"
  "$fixtures" archive "$work/evil.tar" tar \
    "copy:labs/lab2_projective/lab2.c=$solutions/lab2_projective/lab2.c" "chardev:labs/lab7_cube/lab7.c" \
    "hardlink:labs/lab1_depth_fbo/lab1.c=labs/lab2_projective/lab2.c" "fifo:labs/lab5_vsm/lab5.c" \
    "hardlink:labs/lab6_cascades/lab6.c=/etc/passwd"
  stage zip "$work/evil.zip"
  expect_status 0 "a zip with hostile entries"
  is_solution lab2_projective/lab2.c "a zip with hostile entries"
  is_solution lab3_bias/lab3.c "a zip with backslash separators"
  for f in lab1_depth_fbo/lab1.c lab4_pcf/lab4.c; do is_stub "$f" "a zip with hostile entries"; done
  for refused in "../escape.c (a '..' in the path" "/tmp/absolute-escape.c (an absolute path" \
                 "labs/../../up.c (a '..' in the path" "C:/Windows/evil.c (a path with a drive letter" \
                 "labs/lab1_depth_fbo/lab1.c (a symbolic link (to $solutions/lab1_depth_fbo/lab1.c)" \
                 "labs/lab4_pcf (a symbolic link (to /etc)"; do
    said "$refused" "a zip with hostile entries"
  done
  [ ! -e "$work/escape.c" ] && [ ! -e /tmp/absolute-escape.c ] && [ ! -e "$work/../up.c" ] ||
    problem "an entry was written outside the stage"
  stage tar "$work/evil.tar"
  expect_status 0 "a tar with links"
  is_stub lab1_depth_fbo/lab1.c "a tar with a hard link"
  is_stub lab6_cascades/lab6.c "a tar with a hard link"
  said "labs/lab1_depth_fbo/lab1.c (a hard link (to labs/lab2_projective/lab2.c)" "a tar with a hard link"
  said "labs/lab5_vsm/lab5.c (a FIFO" "a tar with a FIFO"
  said "labs/lab7_cube/lab7.c (a device" "a tar with a device"
  is_stub lab7_cube/lab7.c "a tar with a device"
  # the extraction the batch grading uses: files and folders only, nothing outside
  mkdir "$work/extracted"
  set +e
  "$stager" --extract "$work/evil.zip" "$work/extracted/into" 2>"$work/extract.err"
  set -e
  cat "$work/extract.err"
  [ -f "$work/extracted/into/labs/lab2_projective/lab2.c" ] && [ -f "$work/extracted/into/labs/lab3_bias/lab3.c" ] ||
    problem "--extract did not extract the plain files"
  [ -z "$(find "$work/extracted" -type l)" ] || problem "--extract made a link"
  [ ! -e "$work/extracted/escape.c" ] || problem "--extract wrote outside its folder"
  grep -q "refused ../escape.c" "$work/extract.err" || problem "--extract did not name a refused entry"
  "$stager" --list "$work/evil.tar" | grep -q "^hard link	0	labs/lab1_depth_fbo/lab1.c -> labs/lab2_projective/lab2.c" ||
    problem "--list does not show the hard link"
  ;;

corrupt)
  # cut short in the middle of a large file after the lab files: what came before is staged
  head -c 2000000 /dev/urandom >"$work/video.mov"
  "$fixtures" archive "$work/good.tgz" tgz tree:labs="$solutions" "copy:video.mov=$work/video.mov" file:after.txt=x
  size=$(stat -c %s "$work/good.tgz")
  head -c $(( size / 2 )) "$work/good.tgz" >"$work/cut.tgz"
  stage cut "$work/cut.tgz"
  expect_status 0 "a cut archive"
  said "cut.tgz: corrupt or cut short after the entry video.mov" "a cut archive"
  in_summary "corrupt or cut short" "a cut archive"
  all_solutions "a cut archive"
  # cut before anything could be read
  "$fixtures" archive "$work/small.tgz" tgz tree:labs="$solutions"
  head -c 1000 "$work/small.tgz" >"$work/small-cut.tgz"
  stage small-cut "$work/small-cut.tgz"
  expect_status 3 "an archive cut at its start"
  said "small-cut.tgz: not an archive this grader reads (.zip, .tar, .tar.gz, ...), or a corrupt one" "an archive cut at its start"
  all_stubs "an archive cut at its start"
  # the lab folders only (solutions/ also holds bench/, which would be the zip's first entry)
  mkdir -p "$work/labs-only" && cp -R "$solutions"/lab[0-9]* "$work/labs-only/"
  "$fixtures" archive "$work/good.zip" zip tree:labs="$work/labs-only"
  { head -c 200 "$work/good.zip"; head -c 4000 /dev/zero; } >"$work/broken.zip"
  stage broken "$work/broken.zip"
  expect_status 3 "a broken zip"
  said "broken.zip: " "a broken zip"
  in_summary "No lab file found: broken.zip" "a broken zip"
  all_stubs "a broken zip"
  printf 'this is not an archive\n' >"$work/notes.zip"
  stage notzip "$work/notes.zip"
  expect_status 3 "a text file named .zip"
  said "notes.zip: not an archive this grader reads" "a text file named .zip"
  ;;

empty)
  mkdir "$work/empty"
  stage empty "$work/empty"
  expect_status 3 "an empty folder"
  said "No lab file found: the submission is empty" "an empty folder"
  all_stubs "an empty folder"
  "$fixtures" archive "$work/empty.zip" zip
  stage emptyzip "$work/empty.zip"
  expect_status 3 "an empty zip"
  said "No lab file found" "an empty zip"
  mkdir -p "$work/clutter/__MACOSX"
  : >"$work/clutter/.DS_Store"
  stage clutter "$work/clutter"
  expect_status 3 "only clutter"
  said "holds only what macOS or Windows add" "only clutter"
  mkdir -p "$work/wrong/My Project/src"
  echo 'int main(void) { return 0; }' >"$work/wrong/My Project/src/main.c"
  echo report >"$work/wrong/My Project/report.pdf"
  stage wrong "$work/wrong"
  expect_status 3 "the wrong files"
  said "No lab file found: found My Project/report.pdf, My Project/src/. Accepted layouts: a labs/ folder" "the wrong files"
  in_summary '"accepted_layouts"' "the wrong files"
  ;;

names)
  # names with spaces and letters of other languages: taken when they are lab files, named when not
  "$fixtures" archive "$work/names.zip" zip "dir:Études Öffentlich" \
    "copy:Études Öffentlich/labs/lab1_depth_fbo/lab1.c=$solutions/lab1_depth_fbo/lab1.c" \
    "file:Études Öffentlich/labs/lab1_depth_fbo/shaders/mon aide é.glsl=// helper" \
    "file:Études Öffentlich/notes ü 日本.txt=notes"
  stage names "$work/names.zip"
  expect_status 0 "names in other languages"
  said "(in Études Öffentlich/)" "names in other languages"
  is_solution lab1_depth_fbo/lab1.c "names in other languages"
  [ "$(cat "$stage/lab1_depth_fbo/shaders/mon aide é.glsl" 2>/dev/null)" = "// helper" ] ||
    problem "a shader named with spaces and accents was not staged"
  said "Études Öffentlich/notes ü 日本.txt (not a lab file)" "names in other languages"
  in_summary "notes ü 日本.txt" "names in other languages"
  # a name that is not UTF-8 is shown escaped
  mkdir -p "$work/latin1/lab1_depth_fbo"
  cp "$solutions/lab1_depth_fbo/lab1.c" "$work/latin1/lab1_depth_fbo/"
  echo x >"$work/latin1/$(printf 'r\xe9sum\xe9.txt')"
  stage latin1 "$work/latin1"
  expect_status 0 "a name that is not UTF-8"
  said 'r\xE9sum\xE9.txt (not a lab file)' "a name that is not UTF-8"
  ;;

limits)
  stage files "$solutions" --max-files 3
  expect_status 0 "at most 3 files"
  said "took lab1_depth_fbo/lab1.c lab2_projective/lab2.c lab3_bias/lab3.c"$'\n' "at most 3 files"
  said "lab4_pcf/lab4.c (past the limit of 3 lab files" "at most 3 files"
  is_stub lab4_pcf/lab4.c "at most 3 files"
  in_summary "Left out: lab4_pcf/lab4.c" "at most 3 files"
  mkdir -p "$work/big/lab1_depth_fbo" "$work/big/lab2_projective"
  head -c 5000 /dev/zero | tr '\0' ' ' >"$work/big/lab1_depth_fbo/lab1.c"
  cp "$solutions/lab2_projective/lab2.c" "$work/big/lab2_projective/"
  stage big "$work/big" --max-file-bytes 4096
  expect_status 0 "a file over the size limit"
  said "lab1_depth_fbo/lab1.c (more than 4 KiB)" "a file over the size limit"
  is_stub lab1_depth_fbo/lab1.c "a file over the size limit"
  is_solution lab2_projective/lab2.c "a file over the size limit"
  # an archive whose header lies about nothing but which unpacks to far more than it weighs
  "$fixtures" archive "$work/bomb.tgz" tgz zeros:aaa-padding.bin=3000000 \
    "copy:labs/lab2_projective/lab2.c=$solutions/lab2_projective/lab2.c"
  stage bomb "$work/bomb.tgz" --max-unpacked 1048576
  said "bomb.tgz unpacks to more than 1 MiB" "an archive over the unpacked limit"
  in_summary "unpacks to more than 1 MiB" "an archive over the unpacked limit"
  # deeper than the depth limit, and more entries than the entry limit
  "$fixtures" archive "$work/deep.zip" zip "copy:a/b/c/d/e/lab1_depth_fbo/lab1.c=$solutions/lab1_depth_fbo/lab1.c"
  stage deep "$work/deep.zip" --max-depth 3
  expect_status 3 "deeper than the limit"
  said "a/b/c/d/ (deeper than 3 folders" "deeper than the limit"
  mkdir -p "$work/many/lab1_depth_fbo"
  for i in $(seq 1 30); do : >"$work/many/file$i.txt"; done
  stage many "$work/many" --max-entries 10
  said "more than 10 files and folders" "more entries than the limit"
  # a folder the reading user cannot open is the staff's problem (exit 2), not a grade
  if [ "$(id -u)" = 0 ]; then
    mkdir -p "$work/closed/labs/lab1_depth_fbo"
    cp "$solutions/lab1_depth_fbo/lab1.c" "$work/closed/labs/lab1_depth_fbo/"
    chmod 700 "$work/closed/labs"
    stage closed "$work/closed"
    expect_status 2 "a folder closed to uid 65534"
    said "labs: the folder cannot be read by uid 65534, which reads submissions: make them readable to all" \
      "a folder closed to uid 65534"
  fi
  ;;

report)
  # The grader's side, with the stubs' runners (no build): a submission with no
  # lab file exits 3, and every report says so with what was found.
  grader=$1
  shift
  mkdir -p "$work/upload"
  echo "see attached" >"$work/upload/README.txt"
  stage nothing "$work/upload"
  expect_status 3 "no lab file"
  set +e
  "$grader" "$@" --case lab1_depth_boxes --submission-summary "$summary" --report "$work/report" \
    --gradescope "$work/gradescope.json" --prairielearn "$work/prairielearn.json" >"$work/grade.log" 2>&1
  status=$?
  set -e
  cat "$work/grade.log"
  expect_status 3 "shadowlab-grade on a submission without a lab file"
  grep -q "^Submission: No lab file found: found README.txt. Accepted layouts: a labs/ folder" "$work/grade.log" ||
    problem "the terminal report does not say no lab file was found"
  grep -q '"no_lab_file":	true' "$work/report/results.json" || problem "results.json has no no_lab_file"
  grep -q '"lab_files_found":	false' "$work/report/results.json" || problem "results.json has no summary"
  grep -q 'Submission: No lab file found: found README.txt' "$work/report/report.html" || problem "report.html says nothing"
  grep -q '"output":	"No lab file found: found README.txt' "$work/gradescope.json" || problem "Gradescope's output says nothing"
  grep -q '"gradable":	false' "$work/prairielearn.json" || problem "PrairieLearn's results are gradable"
  grep -q '"format_errors":	\["No lab file found: found README.txt' "$work/prairielearn.json" ||
    problem "PrairieLearn's format errors say nothing"
  ;;

chroot)
  # Under a chroot "/" is no mount point, so it cannot be made private: the reader
  # still must not see the answers (it moves into an empty root of its own).
  # A chroot of bind mounts, in a mount namespace of the test's own.
  if [ "$(id -u)" != 0 ] || ! command -v chroot >/dev/null || ! unshare -m --propagation private true 2>/dev/null; then
    echo "stage.chroot: needs root and a mount namespace: left out"
    exit 77
  fi
  mkdir -p "$work/sub" "$work/root"
  cp -R "$solutions/lab2_projective" "$work/sub/"
  rm -rf "$work/chroot.stage"
  cp -R "$stubs" "$work/chroot.stage"
  set +e
  out=$(unshare -m --propagation private bash -c '
    set -e
    root=$1 stager=$2 solutions=$3 work=$4
    for d in usr etc dev proc sys; do mkdir -p "$root/$d"; mount --rbind "/$d" "$root/$d"; done
    for l in bin lib lib64 sbin; do
      if [ -L "/$l" ]; then ln -s "$(readlink "/$l")" "$root/$l"
      elif [ -d "/$l" ]; then mkdir -p "$root/$l"; mount --rbind "/$l" "$root/$l"; fi
    done
    for d in "$(dirname "$stager")" "$solutions" "$work"; do mkdir -p "$root$d"; mount --bind "$d" "$root$d"; done
    [ "$(awk "\$5 == \"/\"" /proc/self/mountinfo | wc -l)" -gt 0 ]
    exec chroot "$root" "$stager" --summary "$work/chroot.json" --hide "$solutions" "$work/sub" "$work/chroot.stage"
  ' chroot-test "$work/root" "$stager" "$solutions" "$work" 2>&1)
  status=$?
  set -e
  printf '%s\n' "--- chroot (exit $status)" "$out"
  stage="$work/chroot.stage"
  expect_status 0 "a folder, staged under a chroot"
  said "where the answers are hidden" "under a chroot"
  is_solution lab2_projective/lab2.c "a folder, staged under a chroot"
  ;;

*) echo "stage.sh: no case $case_name" >&2; exit 2 ;;
esac
exit $fail
