#!/usr/bin/env python3
"""degenerate.py --grader EXE --runners DIR --solutions DIR --cases DIR --out DIR --lab N

The degenerate-output battery (grader/README.md, "Degenerate output"). For lab N it
writes mutants of the solutions whose output is degenerate: the runner's visibility
(every lookup the lab's cases draw with) and each of the lab's GLSL functions made to
return a constant 0, a constant 1, NaN, or noise. It grades each mutant on the cases
that run what it changed, with the solutions' runner (the C code is the solutions', so
nothing is compiled), and wants every visibility, stability (flicker), bleeding,
penumbra, moments, cascade-index and cube-face check to fail on each: a check that
passes a picture no lab code should earn points for is a hole in the grader. A check
may say in its case file why one output is right for it:

    "passes_degenerate": [{"output": "visibility=*", "why": "..."}]

(`output` is MUTANT=VALUE as this script names them; `*` matches any value). Such an
exemption that the check no longer needs is named too, so exemptions cannot rot.
Exits 1 naming every check that passes a degenerate output, 0 when none does.
"""
import argparse
import concurrent.futures
import fnmatch
import glob
import json
import os
import re
import shutil
import subprocess
import sys

# Check kinds a degenerate picture must fail. (matrices, fbo and depth_map checks measure
# C code and lab 1's depth pass, which no mutant here changes; probes call a function alone.)
KINDS = {"visibility", "flicker", "bleeding", "penumbra", "moments", "moments_blurred", "cascade_index",
         "cube_face"}

# A hash of the pixel (of the vertex in a vertex shader): noise that changes from one pixel to the next.
NOISE_FRAG = "fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453)"
NOISE_VERT = "fract(sin(float(gl_VertexID) * 12.9898) * 43758.5453)"
NAN = "uintBitsToFloat(0x7fc00000u)"


def values(kind, noise):
    """The degenerate outputs of a function returning `kind`: {name: GLSL expression}."""
    n = noise
    if kind == "float":
        return {"0": "0.0", "1": "1.0", "nan": NAN, "noise": n}
    if kind == "bool":  # a test has no NaN and no noise: always false, always true
        return {"0": "false", "1": "true"}
    if kind == "int":   # a cascade: the first, the second, any
        return {"0": "0", "1": "1", "noise": "int(%s * 4.0) %% max(count, 1)" % n}
    width = int(kind[-1])
    noisy = ", ".join([n] + ["fract(%s * %.2f)" % (n, 3.7 * (i + 1)) for i in range(width - 1)])
    return {"0": "%s(0.0)" % kind, "1": "%s(1.0)" % kind, "nan": "%s(%s)" % (kind, NAN),
            "noise": "%s(%s)" % (kind, noisy)}


# Each lab's mutants: a name, the functions it changes (file, function, return type), and
# the cases it is graded on (globs; each runs what the mutant changes). "visibility" is
# the runner's visibility: every lookup the lab's cases draw with returns the value.
L2 = "lab2_projective/shaders/shadow_lookup.glsl"
L3 = "lab3_bias/shaders/"
L4 = "lab4_pcf/shaders/pcf.glsl"
L5 = "lab5_vsm/shaders/"
L6 = "lab6_cascades/shaders/cascades.glsl"
L7 = "lab7_cube/shaders/"
COMPARES = [(L2, "shadow_compare_manual", "float"), (L2, "shadow_compare_hardware", "float")]
MUTANTS = {
    2: [("visibility", COMPARES, ["lab2_*"]),
        ("shadow_coord", [("lab2_projective/shaders/shadow_coord.glsl", "shadow_coord", "vec4")], ["lab2_*"]),
        ("outside_light_frustum", [(L2, "outside_light_frustum", "bool")],
         ["lab2_*"])],
    3: [("visibility", COMPARES + [(L3 + "midpoint.glsl", "midpoint_compare", "float")], ["lab3_*"]),
        ("slope_scaled_bias", [(L3 + "bias.glsl", "slope_scaled_bias", "float")],
         ["lab3_contact", "lab3_slope_grazing"]),
        ("normal_offset_position", [(L3 + "bias.glsl", "normal_offset_position", "vec3")], ["lab3_normal_offset"]),
        ("midpoint_compare", [(L3 + "midpoint.glsl", "midpoint_compare", "float")], ["lab3_midpoint"])],
    4: [("visibility", [(L4, f, "float") for f in ("pcf_hardware", "pcf_grid", "pcf_poisson", "pcss")],
         ["lab4_*"])],
    5: [("visibility", [(L5 + "vsm.glsl", "chebyshev_upper_bound", "float")], ["lab5_bleeding", "lab5_visibility"]),
        ("reduce_light_bleeding", [(L5 + "vsm.glsl", "reduce_light_bleeding", "float")],
         ["lab5_bleeding", "lab5_visibility"]),
        ("compute_moments", [(L5 + "moments.glsl", "compute_moments", "vec2")], ["lab5_*"]),
        ("blur_moments", [(L5 + "blur.glsl", "blur_moments", "vec2")], ["lab5_*"])],
    6: [("visibility", [(L6, "cascade_compare", "float")], ["lab6_*"]),
        ("cascade_index", [(L6, "cascade_index", "int")], ["lab6_*"]),
        ("cascade_blend", [(L6, "cascade_blend", "float")], ["lab6_blend"])],
    7: [("visibility", [(L7 + "point_shadow.glsl", f, "float") for f in ("point_shadow", "point_shadow_soft")],
         ["lab7_*"]),
        ("cube_depth", [(L7 + "cube_depth.frag", "main", "depth")], ["lab7_*"])],
}


def mutate(path, function, kind, expr):
    """Replaces the body of `function` in the GLSL file `path` with `return EXPR;` (lab 7's depth
    pass: its main() writes EXPR as the depth)."""
    with open(path) as f:
        lines = f.read().split("\n")
    start = [i for i, line in enumerate(lines) if re.match(r"^[A-Za-z_][A-Za-z0-9_ ]*[ *]%s\(" % function, line)]
    if len(start) != 1:
        sys.exit("degenerate: %s is not defined once in %s: update the battery" % (function, path))
    end = lines.index("}", start[0])
    body = "    gl_FragDepth = %s;" % expr if kind == "depth" else "    return %s;" % expr
    lines[start[0] + 1:end] = [body]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def exempt(check, label):
    for e in check.get("passes_degenerate", []):
        if fnmatch.fnmatchcase(label, e["output"]):
            return e
    return None


def grade(args, lab, name, changes, patterns, value, cases):
    label = "%s=%s" % (name, value)
    tree = os.path.join(args.out, "lab%d" % lab, "%s_%s" % (name, value))
    shutil.rmtree(tree, ignore_errors=True)
    shutil.copytree(args.solutions, tree)
    for file, function, kind in changes:
        noise = NOISE_VERT if function == "shadow_coord" else NOISE_FRAG
        mutate(os.path.join(tree, file), function, kind, values("float" if kind == "depth" else kind, noise)[value])
    names = sorted(c for c in cases if any(fnmatch.fnmatchcase(c, p) for p in patterns) and "probes" not in c)
    command = [args.grader, "--runners", args.runners, "--labs-dir", tree, "-j", "2"]
    for c in names:
        command += ["--case", c]
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    return label, names, run


def main():
    p = argparse.ArgumentParser()
    for a in ("grader", "runners", "solutions", "cases", "out"):
        p.add_argument("--" + a, required=True)
    p.add_argument("--lab", type=int, required=True)
    args = p.parse_args()
    cases = {}
    for path in glob.glob(os.path.join(args.cases, "lab%d_*.json" % args.lab)):
        with open(path) as f:
            c = json.load(f)
        cases[c["name"]] = c
    jobs = [(name, changes, patterns, value)
            for name, changes, patterns in MUTANTS[args.lab]
            for value in values(changes[0][2] if changes[0][2] != "depth" else "float", NOISE_FRAG)]
    problems, graded, failed = [], 0, 0
    used = set()
    # two grades at a time: most of a grade's time is its start, not its CPU
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = [pool.submit(grade, args, args.lab, *job, cases) for job in jobs]
        for fut in futures:
            label, names, run = fut.result()
            verdicts = {key: verdict for verdict, key in
                        re.findall(r"^  (PASS|FAIL) +[0-9.]+/[0-9.]+ +(\S+ / \S+)", run.stdout, re.M)}
            if run.returncode not in (0, 1):
                problems.append("%s: the grader exited %d:\n%s" % (label, run.returncode, run.stdout[-2000:]))
                continue
            for case in names:
                for k in cases[case]["checks"]:
                    if k["kind"] not in KINDS:
                        continue
                    key = "%s / %s" % (case, k["name"])
                    verdict = verdicts.get(key)
                    e = exempt(k, label)
                    graded += 1
                    if verdict is None:
                        problems.append("%s: %s was not graded" % (label, key))
                    elif verdict == "PASS" and not e:
                        problems.append("%s passes a degenerate output, %s (its case file says no reason why it may)"
                                        % (key, label))
                    elif verdict == "PASS":
                        used.add((key, e["output"]))
                    else:
                        failed += 1
                    print("%-5s %-34s %s%s" % (verdict, label, key, "  (exempt: %s)" % e["why"] if e else ""))
    for case, c in sorted(cases.items()):
        for k in c["checks"]:
            for e in k.get("passes_degenerate", []):
                if ("%s / %s" % (case, k["name"]), e["output"]) not in used:
                    problems.append("%s / %s: no output %s passes it any more: remove the exemption"
                                    % (case, k["name"], e["output"]))
    print("lab %d: %d mutants, %d check verdicts, %d failed as they must" % (args.lab, len(jobs), graded, failed))
    for line in problems:
        print("PROBLEM " + line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
