#!/usr/bin/env bash
# A class of generated submissions (tests/make_submissions.sh): two with the
# same lab 3 mistake (lab3_depth_pass_state() still a stub: its probe and a
# picture fail, each in its own words), one with a lab 2 mistake that lab 3
# builds on, and the solutions; and two not counted: one that holds no lab
# file, one whose lab does not compile.
# grade-batch writes the class report: one row per mistake (the function the
# evidence names plus the kind of cause) naming the students who made it
# ("2 of 4: amy, ben", counted once however many checks it failed), the
# submissions not counted named, per check how many failed, each lab's score
# histogram; class-mistakes.csv, a row per submission and a column per
# mistake; the gradebook row says which options made it. Then the same folder again:
#   - with other grader options: refused, naming both, nothing graded again;
#   - --regrade one student: that one alone graded again.
#   class_report.sh BUILD SOURCE WORK
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
subs="$work/submissions" out="$work/grades"
fail=0
problem() { echo "class_report: $*" >&2; fail=1; }

bash "$source/tests/make_submissions.sh" "$source" "$subs" amy=lab3_c_stub ben=lab3_c_stub \
  dan=lab2_inverted_compare eve=solutions
mkdir -p "$subs/fay" "$subs/gus"
echo "my lab report" >"$subs/fay/notes.txt"  # no lab file
# lab 3 does not compile, and lab 2 is left as the handout's: no lab graded compiled
{ echo "this is not C;"; cat "$source/solutions/lab3_bias/lab3.c"; } >"$subs/gus/lab3.c"
# a case or two per lab: each mistake shows, and the batch stays quick
options=(--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset --timeout 120)
batch=("$source/scripts/grade-batch" -j 2 --build "$build" --out "$out" "$subs" --)

# ---- 1. the class report ----
set +e
"${batch[@]}" "${options[@]}" >"$work/first.log" 2>&1
status=$?
set -e
cat "$work/first.log"
[ "$status" = 0 ] || problem "the batch exited with $status"
report=$out/class-report.csv html=$out/class-report.html
[ -s "$report" ] && [ -s "$html" ] || { problem "no class report"; exit 1; }
cat "$report"
matrix=$out/class-mistakes.csv
[ -s "$matrix" ] || problem "no class-mistakes.csv"
cat "$matrix"
# read with python's csv module, as a spreadsheet would: every claim about the rows
python3 - "$out" <<'PY' || problem "the class report's rows (above)"
import csv, json, os, sys
out = sys.argv[1]
bad = []
def check(ok, what):
    if not ok: bad.append(what)
with open(os.path.join(out, "class-report.csv"), newline="", encoding="utf-8") as f:
    rows = list(csv.reader(f))
check(rows[0] == ["kind", "lab", "name", "text", "who", "students", "of"], "the columns: %s" % rows[0])
check(all(len(r) == 7 for r in rows), "a row without 7 fields")
mistakes = [r for r in rows[1:] if r[0] in ("mistake", "follows")]
by_name = {r[2]: r for r in mistakes}
who = lambda r: r[4].split("; ") if r[4] else []
# the same mistake made by two students, through different checks (the probe's verdict, a
# picture's "not implemented"), each in its own words: one row, both named, 2 of the 4 counted
stub = by_name.get("lab3_depth_pass_state: stub")
check(stub and stub[1] == "3" and "not implemented" in stub[3], "no row 'lab3_depth_pass_state: stub'")
check(stub and (stub[5], stub[6]) == ("2", "4") and who(stub) == ["amy", "ben"], "the stub's row: %s" % (stub,))
for name in ("amy", "ben"):
    with open(os.path.join(out, name, "report", "results.json"), encoding="utf-8") as f:
        report = json.load(f)
    failed = [(c["name"], k) for c in report["cases"] for k in c["checks"] if not k["passed"]]
    ids = {k["diagnosis"] for _, k in failed}
    check(len({case for case, _ in failed}) >= 2 and len(ids) >= 2,
          "%s's stub fails fewer than two cases under two diagnosis ids: %s" % (name, ids))
    check(all(k.get("cause") == {"function": "lab3_depth_pass_state", "kind": "stub"} for _, k in failed),
          "%s's failed checks do not all carry the cause lab3_depth_pass_state, stub" % name)
    check([r[2] for r in mistakes if name in who(r)] == ["lab3_depth_pass_state: stub"],
          "%s is in more than one row: %s" % (name, [r[2] for r in mistakes if name in who(r)]))
# dan's lab 2 mistake costs lab 2 only: never charged to lab 3 as a failure that follows from it
check(not any(r[0] == "follows" for r in mistakes), "a failure that follows from an earlier lab's: %s" % mistakes)
check(any(who(r) == ["dan"] and r[1] == "2" for r in mistakes), "no lab 2 row naming dan")
# the submissions not counted: named by status, in no mistake's row
check(["no lab file", "", "fay"] == next((r[:3] for r in rows if r[2] == "fay"), None), "fay is not named 'no lab file'")
check(["did not build", "", "gus"] == next((r[:3] for r in rows if r[2] == "gus"), None), "gus is not named 'did not build'")
check(not any(n in who(r) for r in mistakes for n in ("fay", "gus")), "fay or gus counted among the mistakes")
check(all(r[6] == "4" for r in mistakes), "a mistake not counted of 4")
checks = {r[2]: r for r in rows if r[0] == "check"}
for name in ("lab3_probes / depth_pass_state", "lab3_polygon_offset / visibility"):
    check((checks[name][5], checks[name][6]) == ("2", "4"), "%s: %s" % (name, checks[name]))
check((checks["lab2_directional_manual / visibility"][5],) == ("1",), "lab2 visibility: %s" % checks["lab2_directional_manual / visibility"])
for lab in ("2", "3", "total"):
    n = sum(int(r[5]) for r in rows if r[0] == "score" and r[1] == lab)
    check(n == 4, "lab %s's histogram holds %d students, not 4" % (lab, n))
full = [r[5] for r in rows if r[0] == "score" and r[1] == "total" and r[2] == "100%"]
check(full == ["1"], "students with full marks in all: %s, expected 1 (the solutions)" % full)
# class-mistakes.csv: a row per submission, a column per mistake, as the rows above say
with open(os.path.join(out, "class-mistakes.csv"), newline="", encoding="utf-8") as f:
    grid = list(csv.reader(f))
check(grid[0] == ["submission", "student", "status"] + [r[2] for r in mistakes],
      "class-mistakes.csv's columns are not the mistakes': %s" % grid[0])
check([g[0] for g in grid[1:]] == ["amy", "ben", "dan", "eve", "fay", "gus"], "its rows: %s" % [g[0] for g in grid[1:]])
for g in grid[1:]:
    if g[0] in ("fay", "gus"):
        check(g[2] in ("no lab file", "did not build") and all(c == "" for c in g[3:]), "%s's row: %s" % (g[0], g))
        continue
    check(g[2] == "graded", "%s's status: %s" % (g[0], g[2]))
    for r, cell in zip(mistakes, g[3:]):
        check(cell == ("1" if g[1] in who(r) else "0"), "%s, %s: %s" % (g[0], r[2], cell))
if bad:
    print("\n".join("class_report: " + b for b in bad), file=sys.stderr)
    sys.exit(1)
PY
grep -qE '<td class="num">.*2 of 4</td><td>3</td><td>lab3_depth_pass_state\(\): not implemented' "$html" ||
  problem "class-report.html does not say '2 of 4: lab3_depth_pass_state(): not implemented'"
grep -q '<td class="who"><span title="amy">amy</span>, <span title="ben">ben</span></td>' "$html" ||
  problem "class-report.html does not name amy and ben beside the stub"
grep -q '<b>1 held no lab file</b>: <span title="fay">fay</span>' "$html" || problem "the html header does not name fay (no lab file)"
grep -q '<b>1 did not build</b>: <span title="gus">gus</span>' "$html" || problem "the html header does not name gus (did not build)"
grep -q '<svg' "$html" || problem "class-report.html has no histogram"

# ---- 2. each gradebook row says what made it ----
gradebook=$out/gradebook.csv
header=$(head -n 1 "$gradebook")
column() { tr ',' '\n' <<<"$header" | grep -nx "$1" | cut -d: -f1; }
options_column=$(column options)
[ -n "$options_column" ] || problem "the gradebook has no options column: $header"
amy=$(grep '^amy,' "$gradebook")
# (grade-submission adds --isolate: each lab graded on its own)
grep -q -- "--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset .*--timeout 120" <<<"$amy" ||
  problem "amy's row does not say its options: $amy"

# ---- 3. another pass with other options into the same folder: refused, naming both ----
declare -A before=()
for d in "$out"/*/; do before[$(basename "$d")]=$(stat -c '%i %Y' "$d/report/results.json"); done
set +e
"${batch[@]}" --case lab3_probes >"$work/second.log" 2>&1
status=$?
set -e
cat "$work/second.log"
[ "$status" = 2 ] || problem "a pass with other options exited $status, not 2"
grep -q "graded with other grader options" "$work/second.log" || problem "the refusal does not say why"
grep -q -- "this run: --case lab3_probes$" "$work/second.log" || problem "the refusal does not name this run's options"
grep -q -- "--case lab2_directional_manual --case lab3_probes --case lab3_polygon_offset --timeout 120$" "$work/second.log" ||
  problem "the refusal does not name the folder's options"
for name in "${!before[@]}"; do
  [ "${before[$name]}" = "$(stat -c '%i %Y' "$out/$name/report/results.json")" ] || problem "$name was graded again"
done

# ---- 4. one student graded again ----
set +e
"$source/scripts/grade-batch" -j 2 --build "$build" --out "$out" --regrade ben "$subs" -- "${options[@]}" >"$work/third.log" 2>&1
status=$?
set -e
cat "$work/third.log"
[ "$status" = 0 ] || problem "--regrade ben exited $status"
grep -q "^grade-batch: 5 of 6 already graded" "$work/third.log" || problem "--regrade did not keep the other five"
for name in "${!before[@]}"; do
  now=$(stat -c '%i %Y' "$out/$name/report/results.json")
  if [ "$name" = ben ]; then [ "${before[$name]}" != "$now" ] || problem "ben was not graded again"
  else [ "${before[$name]}" = "$now" ] || problem "$name was graded again with ben"; fi
done
set +e
"$source/scripts/grade-batch" --build "$build" --out "$out" --regrade nobody "$subs" -- "${options[@]}" >"$work/fourth.log" 2>&1
status=$?
set -e
[ "$status" = 2 ] && grep -q -- "--regrade nobody: no such submission" "$work/fourth.log" ||
  problem "--regrade of an unknown name: exit $status, $(cat "$work/fourth.log")"
# ---- 5. students named as the gradebook names them (a bulk download's names), formula-safe ----
printf '{"name": "Amy Example", "id": "101"}\n' >"$out/amy/student.json"
printf '{"name": "=HYPERLINK(\\"x\\"), Ben", "id": "102"}\n' >"$out/ben/student.json"
"$build/bin/shadowlab-grade" --gradebook "$out" >/dev/null || problem "--gradebook with names failed"
python3 - "$out" <<'PY' || problem "the class report does not name students as the gradebook does"
import csv, os, sys
out = sys.argv[1]
read = lambda name: list(csv.reader(open(os.path.join(out, name), newline="", encoding="utf-8")))
gradebook = {r[0]: r[1] for r in read("gradebook.csv")[1:]}
ben = gradebook["ben"]
assert ben == "'=HYPERLINK(\"x\"), Ben", ben
stub = [r for r in read("class-report.csv") if r[2] == "lab3_depth_pass_state: stub"][0]
assert stub[4].split("; ") == ["Amy Example", ben[1:]], stub
grid = read("class-mistakes.csv")
rows = {g[0]: g for g in grid[1:]}
assert rows["amy"][1] == "Amy Example" and rows["ben"][1] == ben and rows["dan"][1] == "dan", grid
raw = open(os.path.join(out, "class-mistakes.csv"), encoding="utf-8").read() + open(os.path.join(out, "class-report.csv"), encoding="utf-8").read()
assert '"=' not in raw and ",=" not in raw, "a cell a spreadsheet would take for a formula"
PY
grep -q '<span title="ben">=HYPERLINK(&quot;x&quot;), Ben</span>' "$html" || problem "class-report.html does not name ben as the gradebook does"
[ $fail = 0 ] && echo "class_report: the class report (a row per mistake, naming its students; those not counted named), class-mistakes.csv, the options of each row, a refused second pass and one regrade as expected"
exit $fail
