#!/usr/bin/env bash
# bonus_policy.sh GRADER WORK VARIANT_LABS -- RUNNER ARGS...
# One student, one number: a lab 3 submission with a real mistake (points lost on
# regular checks) that earns a bonus is graded under each --bonus policy, and the
# text report's Score line, results.json, report.html's title, the JUnit XML's
# properties, Gradescope's and PrairieLearn's scores and the gradebook all give the
# total the policy defines: apart (the default) never lets the bonus fill a lost
# point, fill fills up to the maximum, add adds past it. A bonus not earned is a
# skipped test in JUnit, never a failure. Every file is read with strict parsers.
set -u
grader=$1 work=$2 labs=$3
shift 4 # the "--"
rm -rf "$work"
mkdir -p "$work/book"
fail=0
problem() { echo "bonus_policy: $*" >&2; fail=1; }
for policy in default fill add; do
  args=()
  [ "$policy" = default ] || args=(--bonus "$policy")
  out="$work/$policy"
  mkdir -p "$out" "$work/book/$policy/report"
  "$grader" "$@" --labs-dir "$labs" --case lab3_probes --case lab3_slope_grazing --case lab3_midpoint \
    "${args[@]+"${args[@]}"}" --report "$work/book/$policy/report" --junit "$out/junit.xml" \
    --gradescope "$out/gradescope.json" --prairielearn "$out/prairielearn.json" >"$out/text" 2>&1
  status=$?
  echo "$status" >"$work/book/$policy/status"
  printf '{"name": "%s", "id": "", "late": false, "from": "test"}\n' "$policy" >"$work/book/$policy/student.json"
  tail -n 3 "$out/text"
  [ "$status" = 1 ] || problem "$policy: exit status $status, not 1 (checks failed)"
done
"$grader" --gradebook "$work/book" >/dev/null 2>&1 || problem "--gradebook failed"
python3 - "$work" <<'PY' || fail=1
import csv, json, re, sys
import xml.etree.ElementTree as ET
work = sys.argv[1]
bad = []
def want(cond, what):
    if not cond: bad.append(what)
def strict(path):
    def no_constant(c): raise ValueError("not JSON: " + c)
    return json.load(open(path, encoding="utf-8"), parse_constant=no_constant)
book = {r["submission"]: r for r in csv.DictReader(open(work + "/book/gradebook.csv", encoding="utf-8", newline=""))}
for policy in ["default", "fill", "add"]:
    r = strict(f"{work}/book/{policy}/report/results.json")
    score, top, bonus = r["score"], r["max_score"], r["bonus"]
    want(bonus > 0 and score < top, f"{policy}: the submission must lose regular points and earn a bonus "
         f"(score {score}/{top}, bonus {bonus})")
    total = {"default": score, "fill": min(top, score + bonus), "add": score + bonus}[policy]
    want(r.get("bonus_policy") == ("apart" if policy == "default" else policy), f"{policy}: results.json's bonus_policy {r.get('bonus_policy')}")
    want(r.get("total") == total, f"{policy}: results.json's total {r.get('total')}, expected {total}")
    want(policy == "default" or f"--bonus {policy}" in r["options"], f"{policy}: the options do not say the policy: {r['options']!r}")
    text = open(f"{work}/{policy}/text", encoding="utf-8").read().splitlines()
    m = re.match(r"^Score: ([0-9.]+)/([0-9.]+)", text[-1])
    want(m and float(m.group(1)) == total and float(m.group(2)) == top, f"{policy}: the text's last line {text[-1]!r}")
    html = open(f"{work}/book/{policy}/report/report.html", encoding="utf-8").read()
    want(f"<title>shadowlab grade: {total:g}/{top:g}</title>" in html, f"{policy}: report.html's title")
    gs = strict(f"{work}/{policy}/gradescope.json")
    want(gs["score"] == total, f"{policy}: Gradescope's score {gs['score']}, expected {total}")
    want("Bonus: " in gs.get("output", ""), f"{policy}: Gradescope's output does not say the bonus")
    want(policy != "default" or "kept apart" in gs.get("output", ""), f"{policy}: Gradescope's output does not say the bonus is kept apart")
    pl = strict(f"{work}/{policy}/prairielearn.json")
    want(abs(pl["score"] - min(1, total / top)) < 1e-9, f"{policy}: PrairieLearn's score {pl['score']}, expected {min(1, total / top)}")
    suites = ET.parse(f"{work}/{policy}/junit.xml").getroot()
    checks = [(c["name"], k) for c in r["cases"] for k in c["checks"]]
    for s in suites:
        props = {p.get("name"): p.get("value") for p in s.iter("property")}
        want(props.get("bonus_policy") == r["bonus_policy"], f"{policy}: JUnit suite {s.get('name')}'s properties {props}")
    # a failed regular check is a JUnit failure; a bonus not earned is skipped
    junit = {(c.get("classname"), c.get("name")): c for c in suites.iter("testcase")}
    for case, k in checks:
        c = junit.get((case, k["name"]))
        want(c is not None, f"{policy}: no JUnit test for {case} / {k['name']}")
        if c is None: continue
        kind = "skipped" if k["bonus"] and not k["passed"] else "failure" if not k["passed"] else None
        for element in ("failure", "skipped"):
            want((c.find(element) is not None) == (element == kind),
                 f"{policy}: JUnit's {case} / {k['name']} (passed {k['passed']}, bonus {k['bonus']}): {element} is wrong")
    row = book.get(policy)
    want(row is not None and float(row["total"]) == total and float(row["bonus"]) == bonus,
         f"{policy}: the gradebook's row {row and {k: row[k] for k in ('total', 'bonus', 'max')}}, expected total {total}")
for b in bad: print("bonus_policy:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
# the grader refuses a policy it does not know, by name
"$grader" --bonus sometimes --list >"$work/refused" 2>&1 && problem "--bonus sometimes was accepted"
grep -q "apart, fill or add" "$work/refused" || problem "an unknown --bonus does not name the policies: $(cat "$work/refused")"
exit $fail
