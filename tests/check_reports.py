#!/usr/bin/env python3
"""check_reports.py [--text FILE]... [--json FILE]... [--junit FILE]... [--html FILE]... [--forged TEXT]...

Reads a grade's reports as strict readers do, whatever a runner or a compiler
printed into them:

- JSON (results.json, Gradescope's, PrairieLearn's): UTF-8 decoded strictly,
  parsed without NaN or Infinity, no lone surrogate (a \\ud800 escape), no string
  holding a control character other than newline and tab;
- JUnit XML: UTF-8 decoded strictly, parsed by an XML parser, no character XML
  1.0 forbids (even as a reference);
- HTML: UTF-8 decoded strictly, no control character other than newline, tab
  and carriage return;
- the text report (the terminal's text, a grade.log): UTF-8 decoded strictly,
  no control character (a terminal escape, a carriage return), exactly one line
  that starts with "Score:", indented or not, the last, and no line that starts with a text given
  with --forged, indented or not (what lab code wrote after a newline, hoping to
  draw a line: a message's later lines are marked "| ").

In every report, U+FFFD beside an "é" is a cut that split a character of
honest accented text (tests/attacks/hostile_text writes long runs of "é",
never next to a bad byte).

Prints each problem and exits 1 if there is one."""
import json
import re
import sys
import xml.dom.minidom

problems = []


def problem(path, what):
    problems.append(f"{path}: {what}")


def read_text(path, what):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        problem(path, f"cannot read the {what}: {e}")
        return None
    try:
        return data.decode("utf-8", errors="strict")
    except UnicodeDecodeError as e:
        problem(path, f"the {what} is not UTF-8: {e}")
        return None


def refuse_constant(name):
    raise ValueError(f"{name} is not JSON")


def walk_strings(value):
    if isinstance(value, str):
        yield value
    elif isinstance(value, list):
        for item in value:
            yield from walk_strings(item)
    elif isinstance(value, dict):
        for key, item in value.items():
            yield key
            yield from walk_strings(item)


CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
SPLIT = re.compile("\u00e9\ufffd|\ufffd\u00e9")


def check_cuts(path, text):
    split = SPLIT.search(text)
    if split:
        problem(path, f"a cut split a character: {text[max(0, split.start() - 20):split.end() + 20]!r}")


def check_json(path):
    text = read_text(path, "JSON file")
    if text is None:
        return
    try:
        value = json.loads(text, parse_constant=refuse_constant)
    except ValueError as e:
        problem(path, f"not JSON: {e}")
        return
    for s in walk_strings(value):
        try:
            s.encode("utf-8", errors="strict")
        except UnicodeEncodeError:
            problem(path, f"a lone surrogate in {s[:60]!r}")
        if CONTROL.search(s):
            problem(path, f"a control character in {s[:60]!r}")
        check_cuts(path, s)


# XML 1.0's Char production: what may stand in a document, as itself or as a reference.
XML_FORBIDDEN = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def check_junit(path):
    text = read_text(path, "JUnit file")
    if text is None:
        return
    try:
        xml.dom.minidom.parseString(text.encode("utf-8"))
    except Exception as e:  # the parser's own error types vary
        problem(path, f"not well-formed XML: {e}")
    check_cuts(path, text)
    bad = XML_FORBIDDEN.search(text)
    if bad:
        problem(path, f"a character XML 1.0 forbids: U+{ord(bad.group()):04X}")
    for ref in re.finditer(r"&#(x[0-9a-fA-F]+|[0-9]+);", text):
        n = int(ref.group(1)[1:], 16) if ref.group(1)[0] == "x" else int(ref.group(1))
        if n > 0x10FFFF or XML_FORBIDDEN.match(chr(n)):
            problem(path, f"a reference to a character XML 1.0 forbids: {ref.group()}")

def check_html(path):
    text = read_text(path, "HTML page")
    if text is None:
        return
    bad = re.search(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\ufffe\uffff]", text)
    if bad:
        problem(path, f"a control character: U+{ord(bad.group()):04X}")


def check_text(path, forged):
    text = read_text(path, "text report")
    if text is None:
        return
    check_cuts(path, text)
    lines = text.split("\n")
    for number, line in enumerate(lines, 1):
        bad = re.search(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]", line)
        if bad:
            problem(path, f"line {number}: a control character U+{ord(bad.group()):04X}: {line[:80]!r}")
        for f in forged:
            if line.lstrip(" ").startswith(f.lstrip(" ")):
                problem(path, f"line {number} was written by lab code: {line[:80]!r}")
    scores = [n for n, line in enumerate(lines, 1) if line.lstrip(" ").startswith("Score:")]
    last = max((n for n, line in enumerate(lines, 1) if line), default=0)
    if len(scores) != 1 or scores[0] != last:
        problem(path, f"{len(scores)} lines start with 'Score:', indented or not (lines {scores}); one, the last, expected")


def main(argv):
    kinds = {"--text": [], "--json": [], "--junit": [], "--html": [], "--forged": []}
    i = 0
    while i < len(argv):
        if argv[i] not in kinds or i + 1 >= len(argv):
            print(__doc__, file=sys.stderr)
            return 2
        kinds[argv[i]].append(argv[i + 1])
        i += 2
    for path in kinds["--json"]:
        check_json(path)
    for path in kinds["--junit"]:
        check_junit(path)
    for path in kinds["--html"]:
        check_html(path)
    for path in kinds["--text"]:
        check_text(path, kinds["--forged"])
    for p in problems:
        print(f"check_reports: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
