#!/usr/bin/env bash
# A fault of the tools is never a student's: grade-batch with a stager that
# fails (exit 4: its extraction does not match the archive's records) for one
# submission, and with a damaged or unreadable download.
#   1. the submission the stager failed on is "staff problem" with the cause in its
#      note and no score (never "not implemented" or "no lab file"), gradebook.json
#      lists it, the class report names it and counts it nowhere, the batch exits 2;
#      the others are graded (an empty upload and the handout's stubs, neither built);
#   2. the stager fixed, the same command grades it again by itself, and exits 0;
#   3. a damaged Canvas download: none of its students is graded or blamed: each is a
#      staff problem saying the download is damaged; exit 2;
#   4. a download the stager cannot extract faithfully stops the batch before any grade.
#   batch_staff_problems.sh BUILD SOURCE WORK
set -euo pipefail
build=$1 source=$2 work=$3
[ -x "$build/bin/shadowlab-stage" ] || { echo "batch_staff_problems: no $build/bin/shadowlab-stage: skipped"; exit 77; }
build=$(cd "$build" && pwd)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
fail=0
problem() { echo "batch_staff_problems: $*" >&2; fail=1; }
lab1=lab1_depth_fbo

# The staff's build, but a stager that fails on what is named *victim* or *mismatch*
# while $work/broken exists (a stand-in for a fault of the tool).
fake="$work/build"
mkdir -p "$fake/bin"
for f in "$build"/bin/*; do ln -s "$f" "$fake/bin/"; done
for f in submission-kit stubs CMakeCache.txt; do [ ! -e "$build/$f" ] || ln -s "$build/$f" "$fake/$f"; done
rm "$fake/bin/shadowlab-stage"
cat >"$fake/bin/shadowlab-stage" <<EOF
#!/usr/bin/env bash
if [ -e "$work/broken" ]; then
  for a in "\$@"; do
    case \$a in *victim*|*mismatch*)
      echo "shadowlab-stage: PROBLEM (not the submission's fault) lab1.c: extracted 4096 bytes, the archive's records say 5000"
      exit 4 ;;
    esac
  done
fi
exec "$build/bin/shadowlab-stage" "\$@"
EOF
chmod 755 "$fake/bin/shadowlab-stage"
touch "$work/broken"

subs="$work/submissions" out="$work/grades"
mkdir -p "$subs/victim/labs" "$subs/stubs" "$subs/empty"
cp -R "$source/solutions/$lab1" "$subs/victim/labs/"
cp "$build/stubs/labs/$lab1/lab1.c" "$subs/stubs/"
batch=("$source/scripts/grade-batch" -j 2 --build "$fake" --out "$out" "$subs" -- --case lab1_depth_boxes --timeout 120)

# ---- 1. the stager fails on one submission ----
set +e
"${batch[@]}" >"$work/first.log" 2>&1
status=$?
set -e
cat "$work/first.log"
gradebook=$out/gradebook.csv
cat "$gradebook"
[ "$status" = 2 ] || problem "the batch exited $status, not 2"
grep -q "^grade-batch:   victim: could not stage the submission (shadowlab-stage exit 4): lab1.c: .*records say 5000" "$work/first.log" ||
  problem "the batch does not name victim's staff problem and its cause"
row=$(grep '^victim,' "$gradebook") || row=""
[[ "$row" == 'victim,,,,staff problem,,,,,,'*'could not stage the submission (shadowlab-stage exit 4)'*'records say 5000'* ]] ||
  problem "victim's row is not a staff problem with the cause and no score: $row"
! grep -Eq 'not implemented|no lab file' <<<"$row" || problem "victim's row blames the student: $row"
grep -q '^stubs,,,,graded,0,' "$gradebook" || problem "the stubs' row is not graded 0"
grep -q '^empty,,,,no lab file,0,' "$gradebook" || problem "the empty upload's row is not 'no lab file'"
for name in stubs empty; do
  grep -q "nothing to build or run" "$out/$name/grade.log" || problem "$name was built"
done
grep -q '"submission":.*"victim"' "$out/gradebook.json" && grep -q '"cause":.*records say 5000' "$out/gradebook.json" ||
  problem "gradebook.json does not list victim's staff problem: $(cat "$out/gradebook.json")"
grep -q '^staff problem,,victim,"could not stage' "$out/class-report.csv" || problem "the class report does not name victim"
grep -q '1 staff problem' "$out/class-report.html" || problem "the class report's summary does not count the staff problem"
# (counted: the stubs alone; the empty upload held no lab file)
[ "$(awk -F, '$1 == "score" && $2 == "total" { n += $(NF - 1) } END { print n + 0 }' "$out/class-report.csv")" = 1 ] ||
  problem "the class report's histogram counts another number of students than the one graded"

# ---- 2. fixed: the same command grades it again, alone ----
rm "$work/broken"
before=$(stat -c '%i %Y' "$out/stubs/report/results.json")
set +e
"${batch[@]}" >"$work/second.log" 2>&1
status=$?
set -e
cat "$work/second.log"
cat "$gradebook"
[ "$status" = 0 ] || problem "the batch after the fix exited $status"
grep -q "^grade-batch: a staff problem stopped their last grade, graded again: victim$" "$work/second.log" ||
  problem "the batch after the fix does not grade victim again by itself"
[ "$before" = "$(stat -c '%i %Y' "$out/stubs/report/results.json")" ] || problem "the stubs were graded again"
row=$(grep '^victim,' "$gradebook") || row=""
[[ "$row" == 'victim,,,,graded,6,0,6,6,'* ]] || problem "victim is not graded full marks after the fix: $row"
[ "$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["staff_problems"]))' "$out/gradebook.json")" = 0 ] ||
  problem "gradebook.json still lists a staff problem"

# ---- 3. a damaged Canvas download ----
c="$work/canvas"
mkdir -p "$c"
for s in 1 2 3 4; do
  # text that does not compress, so the archive's damage falls among its students
  { cat "$build/stubs/labs/$lab1/lab1.c"; head -c 30000 /dev/urandom | od -An -tx1; } >"$c/student${s}_10${s}_50${s}_lab1.c"
done
(cd "$c" && cmake -E tar cf "$work/canvas.zip" --format=zip -- *)
size=$(stat -c %s "$work/canvas.zip")
head -c $((size * 2 / 3)) "$work/canvas.zip" >"$work/damaged.zip"
set +e
"$source/scripts/grade-batch" --build "$build" --out "$work/damaged-grades" "$work/damaged.zip" -- --case lab1_depth_boxes \
  >"$work/damaged.log" 2>&1
status=$?
set -e
cat "$work/damaged.log"
[ "$status" = 2 ] || problem "the damaged download's batch exited $status, not 2"
grep -q "damaged.zip is damaged: a problem of the download, not of a student's" "$work/damaged.log" ||
  problem "the batch does not say the download is damaged"
# A zip cut short has no central directory: nothing in it can be checked against its
# records, so no student may be read from it (no row at all); where some are read,
# each is a staff problem.
rows=""
if [ -f "$work/damaged-grades/gradebook.csv" ]; then
  cat "$work/damaged-grades/gradebook.csv"
  rows=$(tail -n +2 "$work/damaged-grades/gradebook.csv")
fi
[ -z "$rows" ] || ! grep -v ',staff problem,.*the download damaged.zip is damaged' <<<"$rows" ||
  problem "a student of the damaged download is graded or blamed"
! compgen -G "$work/damaged-grades/*/grade.log" >/dev/null || problem "a student of the damaged download was graded"

# ---- 4. a download the stager cannot extract faithfully ----
touch "$work/broken"
cp "$work/canvas.zip" "$work/mismatch.zip"
set +e
"$source/scripts/grade-batch" --build "$fake" --out "$work/mismatch-grades" "$work/mismatch.zip" -- --case lab1_depth_boxes \
  >"$work/mismatch.log" 2>&1
status=$?
set -e
cat "$work/mismatch.log"
[ "$status" = 2 ] && grep -q "could not unpack .*mismatch.zip (exit 4): a problem on the staff's side" "$work/mismatch.log" ||
  problem "a download the stager extracts wrongly: exit $status, not a stop naming it"
! compgen -G "$work/mismatch-grades/*/status" >/dev/null || problem "a student of that download was graded"
[ $fail = 0 ] && echo "batch_staff_problems: every fault of the tools is a staff problem, named, and never a student's"
exit $fail
