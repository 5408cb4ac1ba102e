#!/usr/bin/env python3
"""Every sentence a lab README says about a mistake is backed by a variant that makes it.

    readme_mistakes.py LABS_DIR VARIANTS_DIR PENDING

Each bullet of a lab README's "Common mistakes" section is a claim about what a mistake does.
A variant of that lab (VARIANTS_DIR/*.variant) backs it with "mistake: TEXT", TEXT copied from
the bullet; the variant's own test (variant.NAME) grades the mistake and checks what the bullet
says against the grader's output (its "expect:" lines), or, where the bullet says the grader
cannot see the mistake, that it keeps every mark ("full_marks: yes"). "claim: TEXT" does the
same for a sentence elsewhere in the README (an explanation in its Background).

A bullet no variant backs yet must be listed in PENDING as "N: TEXT -- why", TEXT copied from
the bullet. Fails when a bullet is neither backed nor pending, when a "mistake:", "claim:" or
PENDING line names no text of its lab's README (so none outlives a change of the text), when a
pending bullet is backed after all, or when a backing variant checks nothing.
"""
import glob
import os
import re
import sys


def normalise(text):
    return re.sub(r"\s+", " ", text).strip()


def lab_of_dir(path):
    m = re.match(r"lab(\d+)_", os.path.basename(os.path.dirname(path)))
    return int(m.group(1)) if m else None


def readme_bullets(path):
    """The Common mistakes bullets of one README, each as one line of text."""
    bullets, inside, current = [], False, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                inside = line.strip() == "## Common mistakes"
                if current is not None:
                    bullets.append(normalise(current))
                    current = None
                continue
            if not inside:
                continue
            if line.startswith("- "):
                if current is not None:
                    bullets.append(normalise(current))
                current = line[2:]
            elif current is not None and line.startswith("  "):
                current += " " + line
            elif current is not None and line.strip() == "":
                bullets.append(normalise(current))
                current = None
    if current is not None:
        bullets.append(normalise(current))
    return bullets


def main():
    labs_dir, variants_dir, pending_path = sys.argv[1:4]
    problems = []
    bullets, texts = {}, {}
    for readme in sorted(glob.glob(os.path.join(labs_dir, "lab[0-9]*_*", "README.md"))):
        lab = lab_of_dir(readme)
        bullets[lab] = readme_bullets(readme)
        with open(readme, encoding="utf-8") as f:
            texts[lab] = normalise(f.read())
        if not bullets[lab]:
            problems.append(f"lab {lab}'s README has no Common mistakes bullets (the section moved?)")

    def bullet_index(lab, text, who):
        hits = [i for i, b in enumerate(bullets.get(lab, [])) if normalise(text) in b]
        if len(hits) != 1:
            problems.append(f"{who}: '{text}' is in {len(hits)} Common mistakes bullets of lab {lab}'s README, "
                            "not exactly one")
            return None
        return hits[0]

    backed = {}
    for spec in sorted(glob.glob(os.path.join(variants_dir, "*.variant"))):
        name = os.path.basename(spec)[:-len(".variant")]
        lab, mistakes, claims, checks = None, [], [], 0
        with open(spec, encoding="utf-8") as f:
            for line in f:
                line = line.rstrip("\n")
                if line.startswith("lab: "):
                    lab = int(line[5:].split()[0])
                elif line.startswith("mistake: "):
                    mistakes.append(line[9:])
                elif line.startswith("claim: "):
                    claims.append(line[7:])
                elif line.startswith("expect: ") or line == "full_marks: yes":
                    checks += 1
        if not mistakes and not claims:
            continue
        if checks == 0:
            problems.append(f"{name}: backs a README sentence but checks nothing (no expect:, no full_marks: yes)")
        for text in mistakes:
            i = bullet_index(lab, text, name)
            if i is not None:
                backed.setdefault((lab, i), []).append(name)
        for text in claims:
            if normalise(text) not in texts.get(lab, ""):
                problems.append(f"{name}: lab {lab}'s README does not say: {text}")

    pending = {}
    with open(pending_path, encoding="utf-8") as f:
        for raw in f:
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            m = re.match(r"(\d+): (.*?) -- (.+)$", line)
            if not m:
                problems.append(f"pending: '{line}' is not 'N: TEXT -- why'")
                continue
            lab, text = int(m.group(1)), m.group(2)
            i = bullet_index(lab, text, "pending")
            if i is None:
                continue
            if (lab, i) in backed:
                problems.append(f"pending: lab {lab}'s '{text}' is backed by {', '.join(backed[(lab, i)])}: "
                                "take it off the list")
            pending[(lab, i)] = True

    total = 0
    for lab in sorted(bullets):
        for i, b in enumerate(bullets[lab]):
            total += 1
            if (lab, i) not in backed and (lab, i) not in pending:
                problems.append(f"lab {lab}: no variant backs this Common mistakes bullet "
                                f"(add 'mistake: ...' to the variant that makes it): {b[:100]}")
    for p in problems:
        print(f"readme_mistakes: {p}", file=sys.stderr)
    print(f"readme_mistakes: {total} bullets, {len(backed)} backed by variants, {len(pending)} pending")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
