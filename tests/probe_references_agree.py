#!/usr/bin/env python3
"""probe_references_agree.py CASES_DIR FRESH SHIPPED: a probe's regenerated reference agrees with the shipped one.

Each output must lie within a quarter of the tolerance the grader grades that probe with (the case's
"tolerance" + "relative" x |value|, the defaults of framework/sl_case_probe.c otherwise): another compiler
or cglm version rounds float work differently (a frustum slice 300 m long moves its centre by 2e-4 m),
but a solution changed without its references moves an output by more than a student is forgiven.
The inputs must be the same rows, in the same order."""
import json
import os
import sys

DEFAULT_TOLERANCE, DEFAULT_RELATIVE = 1e-4, 1e-3


def probe_tolerance(cases_dir, suite, name):
    path = os.path.join(cases_dir, suite + ".json")
    with open(path) as f:
        cases = json.load(f)
    for check in cases.get("checks", []):
        if check.get("name") == name:
            return check.get("tolerance", DEFAULT_TOLERANCE), check.get("relative", DEFAULT_RELATIVE)
    sys.exit(f"{path}: no probe \"{name}\" for the reference {suite}/{name}.probe.json")


def numbers(values):
    return [v for v in values if isinstance(v, (int, float)) and not isinstance(v, bool)] if values else []


def main():
    cases_dir, fresh_path, shipped_path = sys.argv[1:4]
    suite = os.path.basename(os.path.dirname(shipped_path))
    name = os.path.basename(shipped_path)[: -len(".probe.json")]
    tolerance, relative = probe_tolerance(cases_dir, suite, name)
    with open(fresh_path) as f:
        fresh = json.load(f)
    with open(shipped_path) as f:
        shipped = json.load(f)
    label = f"{suite}/{name}.probe.json"
    if len(fresh["rows"]) != len(shipped["rows"]):
        sys.exit(f"{label}: {len(fresh['rows'])} rows regenerated, {len(shipped['rows'])} shipped")
    bad = False
    for i, (a, b) in enumerate(zip(fresh["rows"], shipped["rows"])):
        if a["inputs"] != b["inputs"]:
            print(f"{label}: row {i + 1} has other inputs than the shipped one", file=sys.stderr)
            bad = True
            continue
        got, want = a.get("outputs"), b.get("outputs")
        if (got is None) != (want is None) or len(numbers(got)) != len(numbers(want)):
            print(f"{label}: row {i + 1}: outputs {got} vs shipped {want}", file=sys.stderr)
            bad = True
            continue
        for j, (x, y) in enumerate(zip(numbers(got), numbers(want))):
            if abs(x - y) > (tolerance + relative * abs(y)) / 4:
                print(f"{label}: row {i + 1} output {j + 1}: {x} vs shipped {y} "
                      f"(a quarter of the grading tolerance is {(tolerance + relative * abs(y)) / 4:.3g})",
                      file=sys.stderr)
                bad = True
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
