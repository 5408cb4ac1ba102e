#!/usr/bin/env bash
# any_tree.sh SOURCE_DIR WORK_DIR
# The test suite works in a student's tree whose labs are done: a copy of the
# project (its tracked files, the stubs committed in a git of its own) gets the
# solutions copied into labs/, is configured (not built), and every test that
# needs untouched stubs is checked to take them from the build's committed
# copy (build/stubs/labs, from git), never from the working labs/:
# grade.*student_scores_zero and the stage tests (the stubs' runners), the
# attacks (their trees), the case view and shimmer demo (the stubs' viewer),
# the scripts (SHADOWLAB_STUBS), and make-handout.sh (the committed stubs, or a
# refusal naming what differs). Lean on purpose: nothing is built or graded.
set -uo pipefail
src=$1 work=$2
fail=0
problem() { echo "any_tree: $*" >&2; fail=1; }
rm -rf "$work"; mkdir -p "$work/tree"
tree="$work/tree"

# The copy: the tracked files as they are here, with labs/ as committed (HEAD)
git -C "$src" ls-files -z | grep -zvE '^labs/' | (cd "$src" && tar --null -T - -cf -) | tar -xf - -C "$tree" || exit 1
git -C "$src" archive --format=tar HEAD labs | tar -xf - -C "$tree" || exit 1
(cd "$tree" && git init -q && git add -A && git -c user.name=test -c user.email=test@example.invalid \
   commit -qm "stubs" && [ -z "$(git status --porcelain)" ]) ||
  { echo "any_tree: could not make the scratch git" >&2; exit 1; }
# ... and a student who finished every lab
for lab in "$tree"/solutions/lab*; do cp -R "$lab"/. "$tree/labs/$(basename "$lab")/"; done
cmp -s "$tree/labs/lab1_depth_fbo/lab1.c" "$tree/solutions/lab1_depth_fbo/lab1.c" || { echo "any_tree: the copy failed" >&2; exit 1; }

gen=(); ! command -v ninja >/dev/null || gen=(-G Ninja) # as bootstrap.sh makes a new build folder
cmake "${gen[@]}" -S "$tree" -B "$tree/build" -DSL_LABS=student >"$work/configure.log" 2>&1 || { tail -n 20 "$work/configure.log"; exit 1; }
stubs="$tree/build/stubs/labs"

# 1. the build's stubs are the committed ones, not the finished labs
for f in $(cd "$tree" && git ls-files labs | grep -E '(\.c|\.glsl|\.vert|\.frag|\.geom)$'); do
  rel=${f#labs/}
  cmp -s "$stubs/$rel" <(git -C "$tree" show "HEAD:$f") || problem "build/stubs/labs/$rel is not the committed stub"
done

# 2. what each test runs, as ctest would (command and environment)
ctest --test-dir "$tree/build" --show-only=json-v1 >"$work/tests.json" 2>/dev/null || { problem "ctest --show-only failed"; exit 1; }
python3 - "$work/tests.json" "$tree" "$stubs" <<'EOF' || fail=1
import json, sys
tests = json.load(open(sys.argv[1]))["tests"]
tree, stubs = sys.argv[2], sys.argv[3]
labs = tree + "/labs"
bad = []
def args_of(t): return t.get("command", [])
def env_of(t):
    for p in t.get("properties", []):
        if p["name"] == "ENVIRONMENT": return p["value"]
    return []
named = {t["name"]: t for t in tests}
must_use_stubs = ["grade.student_scores_zero", "grade.isolate_student_scores_zero", "stage.no_lab_file_said_in_every_report"]
for name in must_use_stubs:
    t = named.get(name)
    if not t: bad.append(f"{name}: no such test"); continue
    a = args_of(t)
    if "--labs-dir" not in a or a[a.index("--labs-dir") + 1] != stubs:
        bad.append(f"{name}: --labs-dir is not the committed stubs ({stubs})")
for name in ["viewer.case_shows_what_the_grader_renders", "viewer.shimmer_demo_and_animation"]:
    t = named.get(name)
    if not t: bad.append(f"{name}: no such test"); continue
    if not any(x.endswith("/shadowlab-stubs") for x in args_of(t)):
        bad.append(f"{name}: does not run the stubs' viewer (shadowlab-stubs)")
for t in tests:
    a = args_of(t)
    if f"SHADOWLAB_STUBS={stubs}" not in env_of(t):
        bad.append(f"{t['name']}: no SHADOWLAB_STUBS={stubs} in its environment")
    if "--labs-dir" in a and a[a.index("--labs-dir") + 1] == labs:
        bad.append(f"{t['name']}: grades the working labs/ as a fixed tree")
attacks = [t for t in tests if t["name"].startswith("attack.") and t["name"].endswith(".plain")]
if not attacks: bad.append("no attack tests")
for b in bad: print("any_tree:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
EOF

# 3. the attacks' trees are made from the committed stubs (each command that makes one, in
# either generator's rules)
if [ -f "$tree/build/build.ninja" ]; then
  grep -E "bash .*make_attack\.sh" "$tree/build/build.ninja" >"$work/attack-rules"
else
  grep -rhE "bash .*make_attack\.sh" "$tree/build/tests" --include=build.make >"$work/attack-rules" 2>/dev/null
fi
[ -s "$work/attack-rules" ] || problem "no rule makes the attacks' trees"
while IFS= read -r rule; do
  grep -qF "$stubs" <<<"$rule" || problem "an attack's tree is not made from $stubs: $rule"
done <"$work/attack-rules"
# the stubs' viewer shows the committed stubs
grep -qF "\"$stubs\"" "$tree/build/generated/shadowlab-stubs_build_info.c" 2>/dev/null ||
  problem "the stubs' viewer does not take its shaders from $stubs"

# 4. the test scripts that copy the stubs take SHADOWLAB_STUBS first
while IFS= read -r line; do
  problem "a test script takes the working labs/ as the stubs: $line"
done < <(grep -nE '\$\{?(src|source|root)\}?/labs\b' "$tree"/tests/*.sh | grep -v 'SHADOWLAB_STUBS' |
         grep -vE 'any_tree\.sh|handout\.sh:|attack\.sh:.*find|make_attack\.sh:.*stubs=')
# ... and every script that lays an attack over the stubs names them (make_attack.sh's
# fourth argument; without it, it takes the working labs/)
while IFS= read -r line; do
  problem "a test script makes an attack's tree from the working labs/: $line"
done < <(grep -nE 'make_attack\.sh"? +"[^"]+" +"[^"]+" +"[^"]+" *(\||$|;|&)' "$tree"/tests/*.sh)
# ... and a stubs' grade in a tree a test builds itself runs the committed stubs' runner
grep -q -- '--labs-dir "$tree/stubs/labs" --runners "$tree/bin/stubs"' "$tree/tests/no_headless.sh" ||
  problem "no_headless.sh grades its tree's labs/ as the stubs"

# 5. make-handout.sh packs the committed stubs, and refuses a changed labs/ unless told
if out=$("$tree/scripts/make-handout.sh" "$work/dist-refused" 2>&1); then
  problem "make-handout.sh packed a tree whose labs/ differs from HEAD"
else
  grep -q "labs/ differs from the committed stubs" <<<"$out" || problem "make-handout.sh's refusal does not say why: $out"
  grep -q "lab1_depth_fbo/lab1.c" <<<"$out" || problem "make-handout.sh's refusal does not name what differs: $out"
fi
"$tree/scripts/make-handout.sh" --committed "$work/dist" >/dev/null 2>&1 || problem "make-handout.sh --committed failed"
mkdir -p "$work/unpacked"
tar -xzf "$work"/dist/shadowlab-*.tar.gz -C "$work/unpacked" 2>/dev/null || problem "no handout archive"
packed=$(find "$work/unpacked" -path '*/labs/lab1_depth_fbo/lab1.c' | head -n 1)
cmp -s "$packed" <(git -C "$tree" show HEAD:labs/lab1_depth_fbo/lab1.c) ||
  problem "make-handout.sh --committed did not pack the committed stub of lab 1"
# told to, it packs labs/ as it is (here the finished labs)
if "$tree/scripts/make-handout.sh" --from-working-tree "$work/dist-working" >/dev/null 2>&1; then
  mkdir -p "$work/unpacked-working"
  tar -xzf "$work"/dist-working/shadowlab-*.tar.gz -C "$work/unpacked-working"
  packed=$(find "$work/unpacked-working" -path '*/labs/lab1_depth_fbo/lab1.c' | head -n 1)
  cmp -s "$packed" "$tree/labs/lab1_depth_fbo/lab1.c" || problem "make-handout.sh --from-working-tree did not pack labs/"
fi
[ $fail = 0 ] && echo "any_tree: with the solutions in labs/, every stubs test takes the committed stubs"
exit $fail
