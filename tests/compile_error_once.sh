#!/usr/bin/env bash
# compile_error_once.sh GRADER OUT FILE MAX_LINES -- GRADER ARGS
# Grades a labs tree in which the shader FILE (as the handout names it:
# labs/lab3_bias/shaders/bias.glsl) does not compile, and checks every report:
# - the compiler's words come once, at the first check the error stopped (in
#   the report's order), with FILE's own path, never the sandbox's;
# - every other check it stopped says "not reached: FILE did not compile (see
#   above)" in one line, none "failed", "was not called" or "could not be called";
# - results.json, the JUnit file and Gradescope's results say the same, in the
#   same order;
# - the text report has at most MAX_LINES lines.
set -u
grader=$1 out=$2 file=$3 max_lines=$4
shift 5
rm -rf "$out"
mkdir -p "$out"
"$grader" "$@" --report "$out/report" --junit "$out/junit.xml" --gradescope "$out/gradescope.json" \
  >"$out/grade.txt" 2>&1
status=$?
cat "$out/grade.txt"
[ "$status" = 1 ] || { echo "compile_error_once: exit status $status, expected 1 (points lost)" >&2; exit 1; }
python3 - "$out" "$file" "$max_lines" <<'EOF'
import json, re, sys, xml.dom.minidom
out, file, max_lines = sys.argv[1], sys.argv[2], int(sys.argv[3])
problems = []
lines = open(f"{out}/grade.txt", encoding="utf-8").read().splitlines()
# the text report's failed checks and their messages
checks, current = [], None
for line in lines:
    m = re.match(r"^  (PASS|FAIL)  \S+  (\S+) / (\S+)", line)
    if m:
        current = {"passed": m.group(1) == "PASS", "where": (m.group(2), m.group(3)), "message": []}
        checks.append(current)
    elif current and line.startswith("          "):
        current["message"].append(line.strip())
    else:
        current = None
stopped = [c for c in checks if not c["passed"] and c["message"] and
           c["message"][0].startswith(f"not reached: {file} did not compile")]
if not stopped:
    problems.append(f"no check says {file} did not compile")
else:
    first = stopped[0]
    if first["message"][0] != f"not reached: {file} did not compile:":
        problems.append(f"the first check it stopped does not quote the compiler: {first['message']}")
    quoted = [l for l in first["message"][1:] if l.startswith(f"| {file}:")]
    if not quoted or not re.match(rf"\| {re.escape(file)}:\d+:\d+: error: ", quoted[0]):
        problems.append(f"the compiler's first error is not quoted with {file}'s line: {first['message']}")
    for c in stopped[1:]:
        if c["message"] != [f"not reached: {file} did not compile (see above)"]:
            problems.append(f"{c['where']} says more than that it was not reached: {c['message']}")
errors = [l for l in lines if re.search(r"\d+:\d+: error: ", l)]
first_quote = [l for l in stopped[0]["message"] if re.search(r"\d+:\d+: error: ", l)] if stopped else []
if len(errors) != len(first_quote):
    problems.append(f"the compiler's lines come more than once ({len(errors)} quoted): {errors[:2]}")
wrong = [l for l in lines
         if re.search(r"was not called|could not be called|GLSL compile error in|[ (]/labs/|[ (]/framework/|error: {2}", l)]
for l in wrong[:3]:
    problems.append(f"a line names the check failed or not called, a sandbox path, or one candidate alone: {l}")
if len(wrong) > 3:
    problems.append(f"... and {len(wrong) - 3} more such lines")
if len(lines) > max_lines:
    problems.append(f"the text report has {len(lines)} lines, at most {max_lines} expected")
print(f"compile_error_once: {len(lines)} lines, {len(stopped)} checks not reached, "
      f"{len(errors)} compiler line(s) quoted")
# the other reports: the same checks, the same messages, in the same order
text_order = [c["where"] for c in checks]
results = json.load(open(f"{out}/report/results.json", encoding="utf-8"))
json_checks = [((c["name"], k["name"]), k) for c in results["cases"] for k in c["checks"]]
if [w for w, _ in json_checks] != text_order:
    problems.append("results.json's order differs from the text's")
json_stopped = [k["message"] for _, k in json_checks if k["message"].startswith(f"not reached: {file} did not compile")]
if len(json_stopped) != len(stopped) or not json_stopped or \
        not json_stopped[0].startswith(f"not reached: {file} did not compile:\n") or \
        any(m != f"not reached: {file} did not compile (see above)" for m in json_stopped[1:]):
    problems.append(f"results.json does not quote the compiler once: {json_stopped[:3]}")
junit = xml.dom.minidom.parse(f"{out}/junit.xml")
junit_messages = [(t.getAttribute("classname"), t.getAttribute("name"),
                   "".join(n.firstChild.data if n.firstChild else "" for n in
                           t.getElementsByTagName("failure") + t.getElementsByTagName("skipped")))
                  for t in junit.getElementsByTagName("testcase")]
if [(a, b) for a, b, _ in junit_messages] != text_order:
    problems.append("the JUnit file's order differs from the text's")
if sum(1 for _, _, m in junit_messages if re.search(r"\d+:\d+: error: ", m)) != 1:
    problems.append("the JUnit file quotes the compiler more or less than once")
gradescope = json.load(open(f"{out}/gradescope.json", encoding="utf-8"))
if sum(1 for t in gradescope["tests"] if re.search(r"\d+:\d+: error: ", t.get("output", ""))) != 1:
    problems.append("Gradescope's tests quote the compiler more or less than once")
for p in problems:
    print("compile_error_once:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
EOF
