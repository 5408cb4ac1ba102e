#!/usr/bin/env bash
# determinism.sh GRADER SOLUTIONS_RUNNERS SOLUTIONS_DIR VARIANT_DIR WORK [CASE...]
# A grade is the same every time: on each backend this build has (OSMesa, EGL, the
# hidden window), the solutions and a variant with a mistake (its shaders over the
# solutions') are each graded three times at once, with the machine also kept busy
# (two processes spinning beside them), and every grade must give the same exit
# status, scores and messages: run to run, and backend to backend (all are the
# same software renderer). Timings are the only fields left out of the comparison.
set -u
grader=$1 runners=$2 solutions=$3 variant=$4 work=$5
shift 5
cases=()
for c in "$@"; do cases+=(--case "$c"); done
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"
fail=0
problem() { echo "determinism: $*" >&2; fail=1; }

backends=$("$grader" --backend none 2>&1 | sed -n 's/.*(it has \(.*\))$/\1/p' | sed 's/,//g; s/ or / /')
[ -n "$backends" ] || { problem "could not tell this build's backends"; exit 1; }
if ! command -v Xvfb >/dev/null; then backends=${backends//window/}; fi
echo "determinism: backends: $backends"

# Load beside the grades, for as long as they run (bounded: never outlives the test).
busy=()
for _ in 1 2; do timeout 600 sh -c 'while :; do :; done' & busy+=($!); done
stop_busy() { kill "${busy[@]}" 2>/dev/null; wait "${busy[@]}" 2>/dev/null; }
trap stop_busy EXIT

# One round: three grades at once of WHO's labs on BACKEND, each with its report.
round() { # round BACKEND WHO LABS_DIR
  local backend=$1 who=$2 labs=$3 k
  local script='for k in 1 2 3; do
      "$0" -j 1 --backend "$1" --runners "$2" --labs-dir "$3" --report "$4/$k" "${@:6}" >"$4/$k.log" 2>&1 &
      pids[$k]=$!
    done
    for k in 1 2 3; do wait "${pids[$k]}"; echo $? >"$4/$k.status"; done'
  mkdir -p "$work/$backend/$who"
  if [ "$backend" = window ]; then
    bash "$here/with_display.sh" -s "-screen 0 640x480x24" \
      bash -c "$script" "$grader" "$backend" "$runners" "$labs" "$work/$backend/$who" - "${cases[@]}"
  else
    bash -c "$script" "$grader" "$backend" "$runners" "$labs" "$work/$backend/$who" - "${cases[@]}"
  fi
}
for backend in $backends; do
  round "$backend" solutions "$solutions"
  round "$backend" variant "$variant"
done
stop_busy

# What a grade says, timings aside: a line per check, and the exit status.
python3 - "$work" $backends <<'EOF' || fail=1
import json, os, sys
work, backends = sys.argv[1], sys.argv[2:]
bad = []
def said(folder, k):
    status = open(f"{folder}/{k}.status").read().strip()
    try:
        r = json.load(open(f"{folder}/{k}/results.json", encoding="utf-8"))
    except (OSError, ValueError) as e:
        return [f"exit {status}; no readable results.json ({e})"]
    lines = [f"exit {status}", f"score {r.get('score')}/{r.get('max_score')} bonus {r.get('bonus')}"]
    for c in r.get("cases", []):
        for ch in c.get("checks", []):
            lines.append(f"{c['name']} / {ch['name']}: {ch.get('points')}/{ch.get('max_points')} "
                         f"{'passed' if ch.get('passed') else 'FAILED'} {ch.get('message', '')}")
    return lines
for who in ("solutions", "variant"):
    first = None
    for b in backends:
        for k in (1, 2, 3):
            got = said(f"{work}/{b}/{who}", k)
            if first is None:
                first, where = got, f"{b} #{k}"
                print(f"determinism: {who}: {got[0]}, {got[1]}")
                if who == "solutions" and (got[0] != "exit 0" or "FAILED" in " ".join(got)):
                    bad.append(f"the solutions lose points on {where}: " + "; ".join(l for l in got if "FAILED" in l or l.startswith("exit")))
                if who == "variant" and "FAILED" not in " ".join(got):
                    bad.append(f"the variant loses no point on {where}: nothing to compare")
            elif got != first:
                diff = [f"  {where}: {a}\n  {b} #{k}: {c}" for a, c in zip(first, got) if a != c] or \
                       [f"  {len(first)} lines on {where}, {len(got)} on {b} #{k}"]
                bad.append(f"{who}: {b} #{k} differs from {where}:\n" + "\n".join(diff[:5]))
for line in bad:
    print("determinism:", line, file=sys.stderr)
sys.exit(1 if bad else 0)
EOF
[ $fail = 0 ] && echo "determinism: every grade the same, on every backend" || echo "determinism: failed"
exit $fail
