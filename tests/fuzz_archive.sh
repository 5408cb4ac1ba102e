#!/usr/bin/env bash
# fuzz.archive: the libFuzzer target fuzz_archive (tests/fuzz_archive.c) run a
# fixed number of times from a fixed seed (the same inputs on every machine,
# however busy), from the seed archives, then every input kept from a crash
# it found replayed. 77 (skipped) when the build has no fuzzer (no clang with
# its fuzzer runtime when it was configured).
#   fuzz_archive.sh FUZZER|"" FUZZ_DIR WORK [RUNS]
set -euo pipefail
fuzzer=$1 fuzz_dir=$2 work=$3 runs=${4:-4000}
if [ -z "$fuzzer" ]; then
  echo "fuzz.archive: skipped: this build has no libFuzzer target (it needs clang and its fuzzer runtime:" \
    "scripts/install-deps.sh --tests installs clang and libclang-rt-dev; then configure again)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/corpus"
# The fuzzer learns from the values its target compares, addresses included:
# two runs from one seed differ unless the process is laid out the same way.
# So: no random layout (setarch -R, where the system lets it), and the same
# program path, arguments and environment on every machine (a copy of the
# fuzzer and the seeds in the work folder, named relative to it).
cp "$fuzzer" "$work/fuzz_archive"
cp -R "$fuzz_dir/archive_seeds" "$work/seeds"
mkdir -p "$work/regressions"
cp "$fuzz_dir"/archive_regressions/* "$work/regressions/" 2>/dev/null || true
same=(env -i PATH=/usr/bin:/bin)
if command -v setarch >/dev/null && setarch "$(uname -m)" -R true 2>/dev/null; then
  same+=(setarch "$(uname -m)" -R)
else
  echo "fuzz.archive: no setarch -R here: this run's inputs may differ from another machine's"
fi
cd "$work"
# new inputs go to the first folder (corpus/): the committed seeds stay as they are
"${same[@]}" ./fuzz_archive -seed=1 -runs="$runs" -reload=0 -max_len=65536 -timeout=30 -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix=./ corpus seeds
shopt -s nullglob
regressions=(regressions/*)
if [ ${#regressions[@]} -gt 0 ]; then
  echo "fuzz.archive: replaying ${#regressions[@]} inputs that once crashed it"
  "${same[@]}" ./fuzz_archive -timeout=30 -rss_limit_mb=2048 "${regressions[@]}"
fi
echo "fuzz.archive: $runs runs from seed 1, ${#regressions[@]} regressions replayed: no crash, no leak"
