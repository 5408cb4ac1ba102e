#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image
# (Ubuntu-based): it installs the packages (scripts/install-deps.sh: the same
# package names as Debian), builds the grader, checks that the solutions get
# full marks on this image, and makes the answers unreadable to uid 65534 (the
# runners' uid when the container refuses namespaces, and the compiler's).
set -euo pipefail
autograder=${SHADOWLAB_AUTOGRADER:-/autograder}   # tests point this at a mock of the layout
source_dir="$autograder/source"

"$source_dir/scripts/install-deps.sh"
cmake -S "$source_dir" -B "$source_dir/build" -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$source_dir/build" -j "$(nproc)" --target shadowlab-grade

# The shipped references were rendered elsewhere: the solutions must still get
# full marks with this image's libraries and renderer, or the upload fails here
# rather than every student's grade later. (Pixels are checked, not speed: an
# image build may run on a busy machine.) An assignment of one lab
# (make-gradescope-bundle --lab N) checks the lab it grades.
labs=()
if [ -f "$source_dir/grader-options" ]; then
  previous=""
  while IFS= read -r line; do [ "$previous" != --lab ] || labs+=(--lab "$line"); previous=$line; done \
    <"$source_dir/grader-options"
fi
if ! "$source_dir/build/bin/shadowlab-grade" --runners "$source_dir/build/bin/solutions" \
       --labs-dir "$source_dir/solutions" --timeout 300 "${labs[@]+"${labs[@]}"}" \
       >"$source_dir/build/self-check.log" 2>&1; then
  cat "$source_dir/build/self-check.log"
  echo "setup.sh: the solutions do not get full marks on this image (see above)" >&2
  exit 1
fi
echo "setup.sh: self-check: $(tail -n 1 "$source_dir/build/self-check.log")"

# What submissions build from stays readable; the answers and the build (the
# solutions' runner and objects) are the grader's alone.
chmod -R a+rX "$source_dir"
chmod -R go-rwx "$source_dir/solutions" "$source_dir/grader/references" "$source_dir/grader/cases" \
  "$source_dir/build"
chmod go-w "$autograder" "$source_dir"
chmod o+x "$autograder" "$source_dir"
echo "setup.sh: ready"
