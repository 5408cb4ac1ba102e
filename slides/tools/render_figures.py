#!/usr/bin/env python3
"""render_figures.py: makes every figure the decks name, from the command written in the deck.

  render_figures.py --viewer SHADOWLAB --out OUT_DIR [--from solutions|none]
                    [--prerendered DIR] [--jobs N] DECK.md...

A deck names each figure in a comment just above where it shows it; the
command runs from OUT_DIR, so figures/... lands in OUT_DIR/figures:

  <!-- figure: shadowlab ARGS --screenshot figures/x.png -->          the viewer, one
        frame, headless (--headless --frames 1 in front; ARGS may ask for more frames)
  <!-- animation: shadowlab ARGS --frames N --screenshot figures/x.gif -->
  <!-- diagram: NAME.py ARGS --out figures/x.svg -->     slides/diagrams/NAME.py
  <!-- derive: crop|inset figures/src.png X,Y WxH [--scale S] --out figures/x.png -->
        slides/tools/figtool.py on a figure made before it
  <!-- truth: shadowlab ARGS --samples N --screenshot figures/x.png -->
        an area light's soft shadow as it is: the mean of N hard-shadow renders (ARGS as
        a figure's, e.g. --filter none --visibility), each with the scene's light moved to
        one of N points spread evenly over a disk across its axis, of radius the light's
        size (--light-size in ARGS, else the scene's "size": the radius, as PCSS takes it)

The viewer's figures show the solutions' code. With --from none (a copy
without solutions/, e.g. the students' handout) they are copied from
--prerendered (staff render them once and ship them), or left out: the
manifest (OUT_DIR/figures/manifest.json) says which, and the deck builder
puts a note where a left-out figure was. A figure whose command, viewer
binary, shaders and scenes are unchanged since it was made is not made again
(OUT_DIR/figures/.stamps), so the tests and a second build share renders.
The viewer's figures are drawn by --jobs viewer processes, each drawing its
share one after another (shadowlab --batch): the image module and the GL
drivers load once a process, not once a figure.
"""
import argparse
import concurrent.futures
import hashlib
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

LINE = re.compile(r"^<!-- (figure|animation|diagram|derive|truth): *(.*?) *-->$")
BATCH_LINE = re.compile(r"^shadowlab: batch line ([0-9]+)$")            # shadowlab --batch: a line starts
BATCH_EXIT = re.compile(r"^shadowlab: batch line ([0-9]+): exit ([0-9]+)$")  # and how it ended
VIEWER_KINDS = ("figure", "animation", "truth")   # drawn by the viewer, with the solutions' code
HERE = os.path.dirname(os.path.abspath(__file__))
SLIDES = os.path.dirname(HERE)
ROOT = os.path.dirname(SLIDES)


def directives(deck):
    out = []
    with open(deck, encoding="utf-8") as f:
        for no, line in enumerate(f, 1):
            m = LINE.match(line.strip())
            if m:
                out.append((m.group(1), shlex.split(m.group(2)), no))
    return out


def target_of(kind, args):
    flag = "--screenshot" if kind in VIEWER_KINDS else "--out"
    for i, a in enumerate(args):
        if a == flag and i + 1 < len(args):
            return args[i + 1]
    return None


def tree_hash(paths):
    """A digest of the files a render depends on besides its command."""
    h = hashlib.sha256()
    for base in paths:
        if os.path.isfile(base):
            with open(base, "rb") as f:
                h.update(f.read())
            continue
        for d, dirs, files in sorted(os.walk(base)):
            dirs.sort()
            for name in sorted(files):
                p = os.path.join(d, name)
                h.update(p.encode())
                with open(p, "rb") as f:
                    h.update(f.read())
    return h.hexdigest()


def derive(args, out):
    """figtool.py ARGS run from OUT, in this process: (failed, what it said)."""
    try:
        sys.path.insert(0, HERE)
        import figtool  # beside this file; needs PIL, as the crops do
        figtool.main(args, cwd=out)
    except SystemExit as e:
        if e.code not in (None, 0):
            return True, e.code if isinstance(e.code, str) else f"figtool.py exited with {e.code}"
    except Exception as e:  # a broken picture: that figure fails, the others are made
        return True, f"figtool.py: {type(e).__name__}: {e}"
    return False, ""


def light_samples(scene, radius, n):
    """n copies of a scene (parsed JSON) with its light moved to points spread evenly over a disk of
    the given radius across the light's axis (a Vogel spiral: equal area per point, no randomness).
    The light's target moves with it, so each copy's light points the same way."""
    light = scene.get("light", {})
    if "position" not in light:
        raise ValueError("truth: the scene's light has no position (a directional light has no disk to sample)")
    pos = light["position"]
    if "target" in light:
        axis = [t - p for t, p in zip(light["target"], pos)]
    else:
        axis = list(light.get("direction", [0, -1, 0]))
    length = math.sqrt(sum(v * v for v in axis))
    axis = [v / length for v in axis]
    helper = [0.0, 1.0, 0.0] if abs(axis[1]) < 0.9 else [1.0, 0.0, 0.0]
    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    e1 = cross(axis, helper)
    l1 = math.sqrt(sum(v * v for v in e1))
    e1 = [v / l1 for v in e1]
    e2 = cross(axis, e1)
    golden = math.pi * (3.0 - math.sqrt(5.0))
    out = []
    for k in range(n):
        r, a = radius * math.sqrt((k + 0.5) / n), k * golden
        off = [r * math.cos(a) * u + r * math.sin(a) * v for u, v in zip(e1, e2)]
        copy = json.loads(json.dumps(scene))
        copy["light"]["position"] = [p + o for p, o in zip(pos, off)]
        if "target" in light:
            copy["light"]["target"] = [t + o for t, o in zip(light["target"], off)]
        out.append((copy, off))
    return out


def _image_math(function, expression, **images):
    """ImageMath on any Pillow: lambda_eval where it exists (Pillow 10.3 on; eval is gone from 12), eval before."""
    from PIL import ImageMath
    if hasattr(ImageMath, "lambda_eval"):
        return ImageMath.lambda_eval(function, **images)
    return ImageMath.eval(expression, **images)


def average_images(paths, dest):
    """The per-pixel mean of same-sized pictures, rounded (PIL: sums in 32-bit channels)."""
    from PIL import Image
    first = Image.open(paths[0]).convert("RGB")
    sums = [Image.new("I", first.size, 0) for _ in range(3)]
    for p in paths:
        im = Image.open(p).convert("RGB")
        if im.size != first.size:
            raise ValueError(f"truth: {p} is {im.size}, not {first.size}")
        sums = [_image_math(lambda a: a["s"] + a["c"], "s + c", s=s, c=im.getchannel(k).convert("I"))
                for k, s in enumerate(sums)]
    n = len(paths)
    mean = [_image_math(lambda a: (a["s"] + a["h"]) / a["n"], "(s + h) / n", s=s, h=n // 2, n=n).convert("L")
            for s in sums]
    Image.merge("RGB", mean).save(dest)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--viewer")
    ap.add_argument("--viewer-args", default="", help="options put in front of every viewer command")
    ap.add_argument("--out", required=True)
    ap.add_argument("--from", dest="source", choices=["solutions", "none"], default="solutions")
    ap.add_argument("--prerendered")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("SL_FIGURE_JOBS", "2")))
    ap.add_argument("--python", default=sys.executable)
    ap.add_argument("decks", nargs="+")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    if a.viewer:
        a.viewer = os.path.abspath(a.viewer)
    figures = os.path.join(out, "figures")
    stamps = os.path.join(figures, ".stamps")
    os.makedirs(stamps, exist_ok=True)
    viewer_args = shlex.split(a.viewer_args)
    dep_paths = [p for p in [a.viewer] if p] + [
        os.path.join(ROOT, d) for d in ("framework/shaders", "framework/scenes", "labs", "solutions") if
        os.path.isdir(os.path.join(ROOT, d))]
    deps = tree_hash(dep_paths) if a.source == "solutions" and a.viewer else "none"

    jobs = []  # (deck, line, kind, args, target)
    for deck in a.decks:
        for kind, args, no in directives(deck):
            t = target_of(kind, args)
            if not t:
                sys.exit(f"render-figures: {deck}:{no}: a {kind} line without its output (--screenshot/--out)")
            jobs.append((os.path.basename(deck), no, kind, args, t))
    manifest = {}
    failures = []
    counts = {"rendered": 0, "cached": 0, "copied": 0, "missing": 0}

    # What else a figure depends on: the viewer and its inputs; a diagram's scripts; figtool.
    tool_hash = {"diagram": tree_hash([os.path.join(SLIDES, "diagrams")]),
                 "derive": tree_hash([os.path.join(HERE, "figtool.py")]),
                 "truth": deps + tree_hash([os.path.abspath(__file__)])}

    def stamp_of(kind, args):
        extra = tool_hash.get(kind, deps)
        if kind == "derive":   # a crop is as new as the picture it is cut from
            src = os.path.join(out, args[1])
            extra += tree_hash([src]) if os.path.isfile(src) else "none"
        return hashlib.sha256(json.dumps([kind, args, viewer_args, extra]).encode()).hexdigest()

    def prepare(job):
        """What a job needs: (target, status, err) when nothing is to run, else (target, None, work)."""
        deck, no, kind, args, target = job
        path = os.path.join(out, target)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        stamp_file = os.path.join(stamps, target.replace("/", "_") + ".key")
        if kind in VIEWER_KINDS and a.source == "none":
            pre = os.path.join(a.prerendered, os.path.basename(target)) if a.prerendered else None
            if pre and os.path.isfile(pre):
                shutil.copyfile(pre, path)
                return target, "copied", None
            if os.path.exists(path):
                os.remove(path)
            return target, "missing", None
        if kind == "derive" and manifest_status.get(args[1]) == "missing":
            if os.path.exists(path):
                os.remove(path)
            return target, "missing", None
        key = stamp_of(kind, args)
        if os.path.isfile(path) and os.path.isfile(stamp_file) and open(stamp_file).read() == key:
            return target, "cached", None
        if kind in VIEWER_KINDS and args[0] != "shadowlab":
            return target, "failed", f"{deck}:{no}: a {kind} command starts with shadowlab"
        return target, None, (path, stamp_file, key)

    def finish(job, work, failed, err, seconds):
        deck, no, kind, args, target = job
        path, stamp_file, key = work
        if failed or not os.path.isfile(path):
            err = "\n".join(err.strip().splitlines()[-3:])
            return target, "failed", f"{deck}:{no}: {' '.join(shlex.quote(x) for x in args)}\n  {err}"
        with open(stamp_file, "w") as f:
            f.write(key)
        print(f"render-figures: {target} ({seconds:.1f} s)", flush=True)
        return target, "rendered", None

    def run(job, work):
        """A diagram (its script) or a derived figure (figtool, in this process: no Python and PIL to start)."""
        deck, no, kind, args, target = job
        t0 = time.time()
        if kind == "diagram":
            cmd = [a.python, os.path.join(SLIDES, "diagrams", args[0])] + args[1:]
            r = subprocess.run(cmd, cwd=out, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            failed, err = r.returncode != 0, r.stderr
        else:
            failed, err = derive(args, out)
        return finish(job, work, failed, err, time.time() - t0)

    def run_truth(job, work):
        """An area light's shadow as it is: the mean of --samples hard-shadow renders, the light moved
        over its disk (light_samples), drawn by one viewer process (shadowlab --batch)."""
        deck, no, kind, args, target = job
        t0 = time.time()
        rest, samples, size, scene_name = [], 64, None, "boxes_on_floor"
        it = iter(range(1, len(args)))
        for i in it:
            x = args[i]
            if x in ("--samples", "--light-size", "--scene", "--screenshot") and i + 1 < len(args):
                v = args[i + 1]
                next(it)
                if x == "--samples":
                    samples = int(v)
                elif x == "--light-size":
                    size = float(v)
                elif x == "--scene":
                    scene_name = v
                continue
            rest.append(x)
        scenes = os.environ.get("SHADOWLAB_SCENES", os.path.join(ROOT, "framework", "scenes"))
        scene_file = scene_name if scene_name.endswith(".json") else os.path.join(scenes, scene_name + ".json")
        try:
            scene = json.load(open(os.path.join(out, scene_file)))
            radius = size if size is not None else float(scene.get("light", {}).get("size", 0.0))
            if not radius > 0:
                raise ValueError("truth: the light has no size (--light-size or the scene's \"size\")")
            copies = light_samples(scene, radius, samples)
        except (OSError, ValueError) as e:
            return finish(job, work, True, str(e), 0.0)
        with tempfile.TemporaryDirectory(prefix="render-truth-") as tmp:
            lines, pictures = [], []
            for k, (copy, _) in enumerate(copies):
                sf, pf = os.path.join(tmp, f"scene{k}.json"), os.path.join(tmp, f"{k}.png")
                with open(sf, "w") as f:
                    json.dump(copy, f)
                lines.append(shlex.join(viewer_args + ["--headless", "--frames", "1"] + rest +
                                        ["--scene", sf, "--screenshot", pf]))
                pictures.append(pf)
            with open(os.path.join(tmp, "batch"), "w") as f:
                f.write("\n".join(lines) + "\n")
            r = subprocess.run([a.viewer, "--batch", os.path.join(tmp, "batch")], cwd=out,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            failed, err = r.returncode != 0, r.stderr
            if not failed:
                try:
                    average_images(pictures, work[0])
                except (OSError, ValueError) as e:
                    failed, err = True, str(e)
        return finish(job, work, failed, err, time.time() - t0)

    def run_viewer(batch):
        """Viewer figures and animations, [(job, work)], in one viewer process (shadowlab --batch): the
        image module and the GL drivers load once, not once a figure. Each line's stderr is its own
        (the viewer marks where each line starts)."""
        lines = []
        for job, work in batch:
            kind, args = job[2], job[3]
            first = ["--headless"] + (["--frames", "1"] if kind == "figure" else [])
            lines.append(shlex.join(viewer_args + first + args[1:]))
        with tempfile.TemporaryDirectory(prefix="render-figures-") as tmp:
            batch_file = os.path.join(tmp, "batch")
            with open(batch_file, "w") as f:
                f.write("\n".join(lines) + "\n")
            stderr_file = open(os.path.join(tmp, "stderr"), "w+")
            exits, seconds = {}, {}
            t0 = time.time()
            with stderr_file, subprocess.Popen([a.viewer, "--batch", batch_file], cwd=out, stdout=subprocess.PIPE,
                                               stderr=stderr_file, text=True) as p:
                for line in p.stdout:
                    m = BATCH_EXIT.match(line)
                    if m:
                        n = int(m.group(1))
                        exits[n], seconds[n] = int(m.group(2)), time.time() - t0
                        t0 = time.time()
                status = p.wait()
                stderr_file.seek(0)
                said, current = {}, 0
                for line in stderr_file:
                    m = BATCH_LINE.match(line)
                    if m:
                        current = int(m.group(1))
                    else:
                        said.setdefault(current, []).append(line)
        results = []
        for n, (job, work) in enumerate(batch, 1):
            err = "".join(said.get(n, []))
            if n not in exits:
                err += f"\n(the viewer stopped before this figure was done: exit {status})"
            results.append(finish(job, work, exits.get(n, 1) != 0, err, seconds.get(n, 0.0)))
        return results

    # Viewer figures and diagrams first (in parallel), then what is derived from them.
    manifest_status = {}
    first = [j for j in jobs if j[2] != "derive"]
    later = [j for j in jobs if j[2] == "derive"]
    for batch in (first, later):
        results = {}
        todo = []
        for i, job in enumerate(batch):
            target, status, work = prepare(job)
            if status:
                results[i] = (target, status, work)
            else:
                todo.append((i, job, work))
        # The viewer's figures in --jobs viewer processes, the longest (most frames) first into the least loaded.
        viewer = [t for t in todo if t[1][2] in ("figure", "animation")]
        groups = [[] for _ in range(max(1, a.jobs))]
        loads = [0] * len(groups)

        def frames_of(job):
            args = job[3]
            for k, x in enumerate(args[:-1]):
                if x == "--frames" and args[k + 1].isdigit():
                    return int(args[k + 1])
            return 1

        for t in sorted(viewer, key=lambda t: -frames_of(t[1])):
            g = loads.index(min(loads))
            groups[g].append(t)
            loads[g] += frames_of(t[1]) + 2
        for g in groups:
            g.sort()  # the decks' order within a process
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            viewer_runs = [(g, pool.submit(run_viewer, [(job, work) for _, job, work in g])) for g in groups if g]
            other_runs = [(i, pool.submit(run, job, work)) for i, job, work in todo
                          if job[2] not in ("figure", "animation", "truth")]
            other_runs += [(i, pool.submit(run_truth, job, work)) for i, job, work in todo if job[2] == "truth"]
            for g, future in viewer_runs:
                for (i, _, _), result in zip(g, future.result()):
                    results[i] = result
            for i, future in other_runs:
                results[i] = future.result()
        for i, job in enumerate(batch):
            target, status, err = results[i]
            manifest_status[target] = status
            manifest[target] = {"deck": job[0], "line": job[1], "kind": job[2], "status": status}
            if err:
                failures.append(err)
            else:
                counts[status] += 1
    with open(os.path.join(figures, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
    print("render-figures: %d made, %d unchanged since the last build, %d copied from pre-rendered figures, "
          "%d left out (no solutions and none pre-rendered), %d failed, in %s" %
          (counts["rendered"], counts["cached"], counts["copied"], counts["missing"], len(failures), figures))
    for e in failures:
        print("render-figures: FAILED " + e, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
