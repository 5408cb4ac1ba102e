#!/usr/bin/env bash
# Files come out of an archive whole: every byte, at every size around the
# 64 KiB reads, in every format students and course platforms upload, through
# --extract and through staging, compared byte for byte with their sources
# (text that never repeats: a byte lost shifts all that follows). And a file
# extracted or staged wrong is caught, as the tool's fault, not the archive's.
#   stage_sizes.sh CASE STAGE_TOOL FAULTY_STAGE_TOOL FIXTURES_TOOL SOURCE WORK
# CASE: zip | zip-stored | tar | tgz | tbz2 | txz | tzst (one format), lms (a
# platform's zip of students' zips), wrong (a test-only build that damages
# what it reads: exit 4 and both records said), damaged (a zip whose data or
# records are wrong: exit 1, the archive's problem).
set -euo pipefail
case_name=$1 stager=$2 faulty=$3 fixtures=$4 source=$5 work=$6
rm -rf "$work"
mkdir -p "$work"
chmod 755 "$work"
fail=0
problem() { echo "stage_sizes.$case_name: $*" >&2; fail=1; }
stubs="${SHADOWLAB_STUBS:-$source/labs}"

sizes=(0 1 65535 65536 65537 131071 131072 131073 1048583)
# one lab file per size, so that staging takes them all
targets=(lab1_depth_fbo/lab1.c lab2_projective/lab2.c lab3_bias/lab3.c lab4_pcf/lab4.c lab5_vsm/lab5.c
         lab6_cascades/lab6.c lab7_cube/lab7.c lab1_depth_fbo/shaders/depth.frag lab7_cube/shaders/cube_depth.geom)
mkdir -p "$work/src"
specs=()
for i in "${!sizes[@]}"; do
  "$fixtures" text "$work/src/$i" "${sizes[$i]}" "$((i + 1))"
  specs+=("copy:labs/${targets[$i]}=$work/src/$i")
done

# run NAME TOOL ARGS...: $status and $out (what it said) set
run() {
  local name=$1
  shift
  set +e
  out=$("$@" 2>&1)
  status=$?
  set -e
  printf '%s\n' "--- $name (exit $status)" "$out"
}
expect_status() { [ "$status" = "$1" ] || problem "$2: exit $status, not $1"; }
said() { grep -qF -- "$1" <<<"$out" || problem "$2: it did not say \"$1\""; }
# same_files DIR WHAT: DIR/labs/TARGET is the source of each size, byte for byte
same_files() {
  local i
  for i in "${!sizes[@]}"; do
    cmp "$work/src/$i" "$1/${targets[$i]}" >/dev/null 2>&1 ||
      problem "$2: the file of ${sizes[$i]} bytes differs ($(cmp "$work/src/$i" "$1/${targets[$i]}" 2>&1 | head -1))"
  done
}
# extract ARCHIVE NAME [TOOL]: --extract into $work/NAME.out, exit 0 and every file whole
extract() {
  rm -rf "$work/$2.out"
  run "extract $2" "${3:-$stager}" --extract "$1" "$work/$2.out"
  expect_status 0 "--extract of $2"
  same_files "$work/$2.out/labs" "--extract of $2"
}
# stage_it ARCHIVE NAME: staged over a copy of the stubs, exit 0 and every lab file whole
stage_it() {
  local stage="$work/$2.stage"
  rm -rf "$stage"
  cp -R "$stubs" "$stage"
  run "stage $2" "$stager" --max-file-bytes 2000000 "$1" "$stage"
  expect_status 0 "staging $2"
  same_files "$stage" "staging $2"
}
ending() {
  case $1 in
  zip | zip-stored) echo zip ;; tar) echo tar ;; tgz) echo tar.gz ;; tbz2) echo tar.bz2 ;;
  txz) echo tar.xz ;; tzst) echo tar.zst ;;
  esac
}

case $case_name in
zip | zip-stored | tar | tgz | tbz2 | txz | tzst)
  archive="$work/sizes.$(ending "$case_name")"
  "$fixtures" archive "$archive" "$case_name" "${specs[@]}"
  extract "$archive" sizes
  stage_it "$archive" sizes
  ;;
lms)
  # a course platform's download: one zip holding each student's upload as it was sent
  mkdir -p "$work/uploads"
  "$fixtures" archive "$work/uploads/alice.zip" zip "${specs[@]}"
  "$fixtures" archive "$work/uploads/bob.zip" zip-stored "${specs[@]}"
  "$fixtures" archive "$work/uploads/carol.tar.gz" tgz "${specs[@]}"
  names=("Alice Liddell_1001_assignsubmission_file_shadowlab.zip" "Bob Ross_1002_assignsubmission_file_shadowlab.zip"
         "Carol Danvers_1003_assignsubmission_file_shadowlab.tar.gz")
  uploads=(alice.zip bob.zip carol.tar.gz)
  outer=()
  for i in 0 1 2; do outer+=("copy:${names[$i]}=$work/uploads/${uploads[$i]}"); done
  "$fixtures" archive "$work/download.zip" zip "${outer[@]}"
  rm -rf "$work/download"
  run "extract the download" "$stager" --extract "$work/download.zip" "$work/download"
  expect_status 0 "--extract of the platform's zip"
  for i in 0 1 2; do
    inner="$work/download/${names[$i]}"
    cmp "$work/uploads/${uploads[$i]}" "$inner" || { problem "${uploads[$i]} came out of the download changed"; continue; }
    extract "$inner" "student$i"
    stage_it "$inner" "student$i"
  done
  ;;
wrong)
  # The test-only build damages what it reads when SL_ARCHIVE_FAULT says so;
  # without it, it is the shipped program.
  "$fixtures" archive "$work/sizes.zip" zip "${specs[@]}"
  "$fixtures" archive "$work/sizes.tar.gz" tgz "${specs[@]}"
  extract "$work/sizes.zip" plain "$faulty"
  for name in sizes.zip sizes.tar.gz; do
    rm -rf "$work/drop.out"
    run "drop a byte: $name" env SL_ARCHIVE_FAULT=drop "$faulty" --extract "$work/$name" "$work/drop.out"
    expect_status 4 "a byte lost extracting $name"
    said "PROBLEM (not the submission's fault)" "a byte lost extracting $name"
    said "a fault of this extraction, not of the archive" "a byte lost extracting $name"
    for i in 4 5 6 7 8; do # the files past 64 KiB
      if [ "$name" = sizes.zip ]; then
        crc=$(python3 -c 'import sys, zlib; print("%08x" % zlib.crc32(open(sys.argv[1], "rb").read()))' "$work/src/$i")
        said "labs/${targets[$i]} extracted as $((sizes[i] - 1)) bytes, CRC-32 " "a byte lost extracting $name"
        said "where the zip's central directory records ${sizes[$i]} bytes, CRC-32 ${crc}" "a byte lost extracting $name"
      else
        said "labs/${targets[$i]} extracted as $((sizes[i] - 1)) bytes" "a byte lost extracting $name"
        said "where the archive's header records ${sizes[$i]} bytes" "a byte lost extracting $name"
      fi
    done
    grep -qF "labs/${targets[3]} extracted" <<<"$out" && problem "the file of 65536 bytes, whole, was said to differ"
  done
  # a bit changed, the size kept: only a CRC can tell (a zip's; tar records none)
  rm -rf "$work/flip.out"
  run "change a bit: zip" env SL_ARCHIVE_FAULT=flip "$faulty" --extract "$work/sizes.zip" "$work/flip.out"
  expect_status 4 "a bit changed extracting a zip"
  said "labs/${targets[2]} extracted as 65535 bytes, CRC-32 " "a bit changed extracting a zip"
  said "where the zip's central directory records 65535 bytes, CRC-32 " "a bit changed extracting a zip"
  # staging: the file read wrong is not staged (the stub stays), exit 4
  rm -rf "$work/drop.stage"
  cp -R "$stubs" "$work/drop.stage"
  run "stage, a byte lost" env SL_ARCHIVE_FAULT=drop "$faulty" --max-file-bytes 2000000 --summary "$work/drop.json" \
    "$work/sizes.zip" "$work/drop.stage"
  expect_status 4 "a byte lost staging a zip"
  said "PROBLEM (not the submission's fault) sizes.zip: labs/lab5_vsm/lab5.c was read as 65536 bytes" \
    "a byte lost staging a zip"
  cmp -s "$work/drop.stage/lab5_vsm/lab5.c" "$stubs/lab5_vsm/lab5.c" || problem "a file read wrong was staged"
  cmp -s "$work/drop.stage/lab4_pcf/lab4.c" "$work/src/3" || problem "the file of 65536 bytes, read whole, was not staged"
  grep -qF "was read as 65536 bytes" "$work/drop.json" || problem "the summary's staff problems do not name the file"
  # the shipped program has no such hook
  rm -rf "$work/shipped.out"
  run "shipped, asked to drop" env SL_ARCHIVE_FAULT=drop "$stager" --extract "$work/sizes.zip" "$work/shipped.out"
  expect_status 0 "the shipped program asked for a fault"
  same_files "$work/shipped.out/labs" "the shipped program asked for a fault"
  if grep -qa SL_ARCHIVE_FAULT "$stager"; then problem "the shipped program holds the test-only fault hook"; fi
  ;;
damaged)
  # the archive's own fault: exit 1, not 4
  "$fixtures" archive "$work/sizes.zip" zip-stored "${specs[@]:2:2}"
  "$fixtures" zip-flip "$work/sizes.zip" "$work/data.zip" data
  "$fixtures" zip-flip "$work/sizes.zip" "$work/records.zip" cd-crc
  run "data changed" "$stager" --extract "$work/data.zip" "$work/data.out"
  expect_status 1 "a zip whose data fails its CRC"
  said "data.zip: the data of labs/${targets[2]} cannot be read" "a zip whose data fails its CRC"
  run "records disagree" "$stager" --extract "$work/records.zip" "$work/records.out"
  expect_status 1 "a zip whose central directory and local header disagree"
  said "records.zip: a damaged zip: the central directory records labs/${targets[2]} with CRC-32 " \
    "a zip whose central directory and local header disagree"
  [ -z "$(ls -A "$work/records.out" 2>/dev/null)" ] || problem "a zip contradicting itself had files extracted"
  run "list, records disagree" "$stager" --list "$work/records.zip"
  expect_status 1 "--list of a zip whose records disagree"
  said "records.zip: a damaged zip: the central directory records" "--list of a zip whose records disagree"
  # the same in a zip with no data descriptor (as Python writes them): the local header disagrees
  "$fixtures" zip-flip "$source/tests/fuzz/archive_seeds/python.zip" "$work/local.zip" cd-crc
  run "local header disagrees" "$stager" --extract "$work/local.zip" "$work/local.out"
  expect_status 1 "a zip whose central directory and local header disagree"
  said "a damaged zip: the central directory records Shadowlab/lab1.c as 24 bytes, CRC-32 " \
    "a zip whose central directory and local header disagree"
  said "its local header as 24 bytes, CRC-32 " "a zip whose central directory and local header disagree"
  run "list, sound" "$stager" --list "$work/sizes.zip"
  expect_status 0 "--list of the sound zip"
  cp -R "$stubs" "$work/records.stage"
  run "stage, records disagree" "$stager" "$work/records.zip" "$work/records.stage"
  expect_status 3 "staging a zip whose records disagree"
  said "a damaged zip: the central directory records" "staging a zip whose records disagree"
  ;;
*)
  echo "stage_sizes.sh: no case $case_name" >&2
  exit 2
  ;;
esac
exit $fail
