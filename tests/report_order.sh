#!/usr/bin/env bash
# report_order.sh GRADER OUT -- GRADER ARGS
# Grades a lab with a mistake and checks that every report lists its cases in
# the order a student works the lab: its probes first, the pictures by the
# last step they need, the cases only a bonus has last; so the first failure a
# student reads is a regular one, never the bonus's. The text report,
# results.json, the JUnit file and Gradescope's results give the same order.
set -u
grader=$1 out=$2
shift 3
rm -rf "$out"
mkdir -p "$out"
"$grader" "$@" --report "$out/report" --junit "$out/junit.xml" --gradescope "$out/gradescope.json" \
  >"$out/grade.txt" 2>&1
status=$?
cat "$out/grade.txt"
[ "$status" = 1 ] || { echo "report_order: exit status $status, expected 1 (points lost)" >&2; exit 1; }
python3 - "$out" <<'EOF'
import json, re, sys, xml.dom.minidom
out = sys.argv[1]
problems = []
text = [m.groups() for m in (re.match(r"^  (PASS|FAIL)  \S+  (\S+) / (\S+)( \(bonus\))?$", l)
                             for l in open(f"{out}/grade.txt", encoding="utf-8")) if m]
order = [(case, check) for _, case, check, _ in text]
cases = list(dict.fromkeys(case for case, _ in order))
if not cases:
    problems.append("no check in the text report")
else:
    lab = re.match(r"lab(\d+)_", cases[0]).group(1)
    if cases[0] != f"lab{lab}_probes":
        problems.append(f"the first case is {cases[0]}, not the lab's probes")
    bonus_only = [c for c in cases if all(bonus for _, cc, _, bonus in text if cc == c)]
    if not bonus_only or cases[-len(bonus_only):] != bonus_only:
        problems.append(f"the cases only a bonus has ({bonus_only}) are not last: {cases}")
    first_fail = next(((c, k) for v, c, k, _ in text if v == "FAIL"), None)
    if first_fail and first_fail[0] in bonus_only:
        problems.append(f"the first failure a student reads is a bonus case's: {first_fail}")
    # each case's checks together
    seen = []
    for case, _ in order:
        if seen and seen[-1] == case:
            continue
        if case in seen:
            problems.append(f"{case}'s checks are apart")
        seen.append(case)
results = json.load(open(f"{out}/report/results.json", encoding="utf-8"))
in_json = [(c["name"], k["name"]) for c in results["cases"] for k in c["checks"]]
if in_json != order:
    problems.append(f"results.json's order differs from the text's:\n  {in_json}\n  {order}")
junit = xml.dom.minidom.parse(f"{out}/junit.xml")
in_junit = [(t.getAttribute("classname"), t.getAttribute("name")) for t in junit.getElementsByTagName("testcase")]
if in_junit != order:
    problems.append(f"the JUnit file's order differs from the text's:\n  {in_junit}\n  {order}")
gradescope = json.load(open(f"{out}/gradescope.json", encoding="utf-8"))
in_gradescope = [tuple(re.match(r".*: (\S+) / (\S+)", t["name"]).groups()) for t in gradescope["tests"]]
if in_gradescope != order:
    problems.append(f"Gradescope's order differs from the text's:\n  {in_gradescope}\n  {order}")
for p in problems:
    print("report_order:", p, file=sys.stderr)
print("report_order: cases in order:", " ".join(dict.fromkeys(c for c, _ in order)))
sys.exit(1 if problems else 0)
EOF
