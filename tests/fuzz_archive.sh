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
    "scripts/install-deps.sh installs clang and libclang-rt-dev; then configure again)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/corpus"
# new inputs go to the first folder (the work's): the committed seeds stay as they are
"$fuzzer" -seed=1 -runs="$runs" -max_len=65536 -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/" "$work/corpus" "$fuzz_dir/archive_seeds"
shopt -s nullglob
regressions=("$fuzz_dir"/archive_regressions/*)
if [ ${#regressions[@]} -gt 0 ]; then
  echo "fuzz.archive: replaying ${#regressions[@]} inputs that once crashed it"
  "$fuzzer" -timeout=30 -rss_limit_mb=2048 "${regressions[@]}"
fi
echo "fuzz.archive: $runs runs from seed 1, ${#regressions[@]} regressions replayed: no crash, no leak"
