#!/usr/bin/env bash
# roster_round_trip.sh GRADER WORK_DIR
# The LMS gradebook round trip, on batch folders of graded submissions made by
# hand (no grade is run): a Canvas gradebook export and a Moodle grading
# worksheet as the LMSs write them (byte-order mark, CRLF or LF, quoted commas,
# doubled quotes, a line break inside a cell, accents, Canvas's test student, a
# student without a submission, a submission not on the roster, a student
# named =HYPERLINK(...)) go in with --roster; the gradebook takes its names
# from them, matched by id, with a "no submission" row per missing student.
# --export writes the grades back; a mock of each LMS's import (python3's csv)
# reads them with that LMS's column rules. Rosters that cannot be read are
# named by file and line.
set -u
grader=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
fail=0
problem() { echo "roster_round_trip: $*" >&2; fail=1; }
command -v python3 >/dev/null || { echo "roster_round_trip: python3 is needed for the mock importers" >&2; exit 77; }

# submission FOLDER STUDENT ID LATE FROM STATUS SCORE MAX BONUS: one graded submission as grade-batch leaves it
# (graded with --bonus add: the bonus can take a total past the assignment's points)
submission() {
  local dir=$1
  mkdir -p "$dir/report"
  printf '{"name": "%s", "id": "%s", "late": %s, "from": "%s"}\n' "$2" "$3" "$4" "$5" >"$dir/student.json"
  echo "$6" >"$dir/status"
  [ "$7" = none ] && return
  cat >"$dir/report/results.json" <<JSON
{"score": $7, "max_score": $8, "bonus": $9, "bonus_policy": "add", "total": $(awk -v s="$7" -v b="$9" 'BEGIN { print s + b }'),
 "complete": true, "built": true, "options": "--isolate --bonus add", "seed": "",
 "lab_scores": [{"lab": 1, "score": $7, "max_score": $8}], "problems": []}
JSON
}
run() { # run LOG ARGS...: the grader's exit status, its output in LOG
  local log=$1
  shift
  "$grader" "$@" >"$log" 2>&1
  local status=$?
  cat "$log"
  return $status
}

# ---- Canvas ----
canvas=$work/canvas
from="Canvas (submissions.zip)"
submission "$canvas/garciamaria_12345" garciamaria 12345 false "$from" 1 9 14 0
submission "$canvas/lopezjose_12346" lopezjose 12346 true "$from" 0 14 14 1
submission "$canvas/hyperlink_12347" hyperlink 12347 false "$from" 1 7 14 0
submission "$canvas/kimlee_12348" kimlee 12348 false "$from" 2 none
submission "$canvas/strangerbob_99999" strangerbob 99999 false "$from" 1 5 14 0
# Canvas's Gradebook export: BOM, CRLF, every cell as its CSV writer quotes it
{ printf '\xef\xbb\xbf'; printf '%s\r\n' \
  'Student,ID,SIS User ID,SIS Login ID,Section,Lab 1: Depth (678901),Lab 2 (678902),Assignments Current Score,Current Score,Final Score' \
  '    Points Possible,,,,,14.00,10.00,(read only),(read only),(read only)' \
  '"Student, Test",12350,,a1b2c3d4,CS 480,,,,,' \
  '"Garcia, Maria",12345,S001,mgarcia,CS 480,,,0.00,0.00,0.00' \
  '"López, José",12346,S002,jlopez,CS 480,,,0.00,0.00,0.00' \
  '"=HYPERLINK(""http://evil.example"",""click"")",12347,S003,hlink,CS 480,,,0.00,0.00,0.00' \
  '"Kim, Lee",12348,S004,lkim,"CS 480, Section 2",,,0.00,0.00,0.00' \
  '"Nguyen, An",12349,S005,anguyen,CS 480,,,0.00,0.00,0.00'; } >"$work/canvas-roster.csv"

run "$work/canvas-gradebook.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" ||
  problem "--gradebook --roster (Canvas) failed"
grep -q 'strangerbob_99999 is not on the roster' "$work/canvas-gradebook.log" ||
  problem "the submission not on the Canvas roster is not named"
python3 - "$canvas/gradebook.csv" <<'PY' || problem "the Canvas gradebook's rows (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8", newline="")))
by_id = {r["student_id"]: r for r in rows}
bad = []
def want(cond, what):
    if not cond: bad.append(what)
want(by_id["12345"]["student"] == "Garcia, Maria" and by_id["12345"]["total"] == "9", "Garcia, Maria's row")
want(by_id["12346"]["student"] == "López, José" and by_id["12346"]["late"] == "late" and by_id["12346"]["total"] == "15",
     "López, José's row (late, 14 + 1 bonus)")
want(by_id["12347"]["student"] == "'=HYPERLINK(\"http://evil.example\",\"click\")", "the formula name, defused")
want(by_id["12348"]["status"] == "staff problem" and by_id["12348"]["student"] == "Kim, Lee", "Kim, Lee's row")
want(by_id["12349"]["status"] == "no submission" and by_id["12349"]["student"] == "Nguyen, An"
     and by_id["12349"]["submission"] == "" and by_id["12349"]["total"] == "", "a 'no submission' row for Nguyen, An")
want("12350" not in by_id, "no row for Canvas's test student")
want(by_id["99999"]["note"].startswith("not on the roster") and by_id["99999"]["total"] == "5",
     "the submission not on the roster keeps its row, with a note")
want(len(rows) == 6, "6 rows, not %d" % len(rows))
for b in bad: print("canvas gradebook:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY

# two assignments: --export must be told which, and names them
if run "$work/canvas-which.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --export canvas "$work/canvas-import.csv"; then
  problem "--export canvas with two assignments and no --assignment succeeded"
fi
grep -q '"Lab 1: Depth (678901)" "Lab 2 (678902)"' "$work/canvas-which.log" || problem "the refusal does not list the assignments"
# an assignment whose points are not the gradebook's max is refused, not scaled
if run "$work/canvas-max.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --export canvas "$work/canvas-lab2.csv" \
  --assignment "Lab 2 (678902)"; then
  problem "--export into a 10-point assignment of 14-point grades succeeded"
fi
grep -q "max is 14, the Canvas assignment's is 10" "$work/canvas-max.log" || problem "the refusal does not name both maxima"
[ ! -e "$work/canvas-lab2.csv" ] || problem "a refused export left a file"

canvas_import() { # the mock of Canvas's gradebook import: canvas_import EXPORT ROSTER NOSUBMISSION_GRADE
  python3 - "$@" <<'PY'
import csv, sys
export, roster, missing = sys.argv[1], sys.argv[2], sys.argv[3]
raw = open(export, "rb").read()
bad = []
def want(cond, what):
    if not cond: bad.append(what)
want(raw.startswith(b"\xef\xbb\xbf"), "the byte-order mark is kept")
want(raw.count(b"\r\n") == raw.count(b"\n"), "every line ends in CRLF, as the roster's")
rows = list(csv.reader(open(export, encoding="utf-8-sig", newline="")))
src = list(csv.reader(open(roster, encoding="utf-8-sig", newline="")))
identity = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
want(rows[0] == identity + ["Lab 1: Depth (678901)"], "the header: %s" % rows[0])
want(rows[0][-1].endswith(")") and rows[0][-1].rsplit(" (", 1)[1][:-1].isdigit(), "the assignment header is 'Name (id)'")
want(len(rows) == len(src), "%d rows, the roster has %d" % (len(rows), len(src)))
points = None
for row, orig in zip(rows, src):
    want(len(row) == 6, "row %s has %d cells" % (row[:2], len(row)))
    for k in range(5):
        same = row[k] == orig[k] or (k == 0 and row[k] == "'" + orig[k] and orig[k][:1] in "=+-@")
        want(same, "identity cell %s of %s changed: %r" % (identity[k], orig[1], row[k]))
    want(row[0][:1] not in "=+-@", "a name a spreadsheet takes for a formula: %r" % row[0])
    if row[0].strip() == "Points Possible":
        points = float(row[5])
        continue
    if row is rows[0]: continue
    g = row[5]
    if g:
        try: v = float(g)
        except ValueError: bad.append("grade %r of %s is not a number" % (g, row[1])); continue
        # above the points only with the bonus (extra credit), which the gradebook shows
        want(v <= points or row[1] == "12346", "grade %s of %s above the points possible" % (g, row[1]))
want(points == 14.0, "the Points Possible row is kept (14.00)")
grades = {r[1]: r[5] for r in rows[2:]}
expect = {"12350": "", "12345": "9", "12346": "15", "12347": "7", "12348": "", "12349": missing}
want(grades == expect, "grades %s, expected %s" % (grades, expect))
want("99999" not in grades, "the submission not on the roster is not exported")
for b in bad: print("canvas import:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
}
if run "$work/canvas-export.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --export canvas "$work/canvas-import.csv" \
  --assignment "Lab 1: Depth (678901)"; then
  canvas_import "$work/canvas-import.csv" "$work/canvas-roster.csv" "" || problem "Canvas's mock import refused the export (above)"
  grep -q 'Kim, Lee (kimlee_12348): no grade exported: staff problem' "$work/canvas-export.log" ||
    problem "the staff fault left out of the export is not said"
  grep -q 'López, José (lopezjose_12346): 15 points, above' "$work/canvas-export.log" || problem "the extra credit is not said"
else
  problem "--export canvas --assignment failed"
fi
if run "$work/canvas-zero.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --export canvas "$work/canvas-zero.csv" \
  --assignment "Lab 1: Depth (678901)" --missing-as-zero; then
  canvas_import "$work/canvas-zero.csv" "$work/canvas-roster.csv" 0 || problem "--missing-as-zero: Canvas's mock import (above)"
else
  problem "--export canvas --missing-as-zero failed"
fi
# the roster's own LMS only
if run "$work/canvas-as-moodle.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --export moodle "$work/x.csv"; then
  problem "a Canvas roster exported as Moodle's"
fi
if run "$work/canvas-due.log" --gradebook "$canvas" --roster "$work/canvas-roster.csv" --due "2026-12-04 23:59"; then
  problem "--due with a Canvas roster was taken"
fi

# ---- Moodle ----
moodle=$work/moodle
from="Moodle (submissions.zip)"
submission "$moodle/Jane_Doe_123456" "Jane Doe" 123456 false "$from" 1 12 14 0
submission "$moodle/Zoe_Angstrom_123457" "Zoë Ångström" 123457 false "$from" 0 14 14 2
submission "$moodle/HYPERLINK_123458" '=HYPERLINK(x)' 123458 false "$from" 1 3 14 0
submission "$moodle/Other_Course_555555" "Other Course" 555555 false "$from" 1 6 14 0
# a Canvas submission whose id is a Moodle participant's is not that participant's
submission "$moodle/samroe_123459" samroe 123459 false "Canvas (other.zip)" 1 8 14 0
# Moodle's worksheet: BOM, LF, PHP's fputcsv quoting (spaces too), a feedback cell with a line break
{
  printf '\xef\xbb\xbf'
  printf '%s\n' \
    'Identifier,"Full name","Email address",Status,Grade,"Maximum Grade","Grade can be changed","Last modified (submission)","Last modified (grade)","Feedback comments"' \
    '"Participant 123456","Jane Doe",jane@example.edu,"Submitted for grading",,14.00,Yes,"Thursday, 3 December 2026, 11:40 PM",-,' \
    '"Participant 123457","Zoë Ångström",zoe@example.edu,"Submitted for grading",,14.00,Yes,"Friday, 4 December 2026, 9:15 AM",-,' \
    '"Participant 123458","=HYPERLINK(""http://evil.example"",""x"")",h@example.edu,"Submitted for grading",,14.00,Yes,"Saturday, 5 December 2026, 12:05 AM",-,' \
    '"Participant 123459","Sam Roe",sam@example.edu,"No submission",,14.00,Yes,-,-,"Seen in the lab,'
  printf '%s\n' 'no upload yet"'
} >"$work/moodle-worksheet.csv"

run "$work/moodle-gradebook.log" --gradebook "$moodle" --roster "$work/moodle-worksheet.csv" --due "2026-12-04 23:59" ||
  problem "--gradebook --roster --due (Moodle) failed"
python3 - "$moodle/gradebook.csv" <<'PY' || problem "the Moodle gradebook's rows (above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8", newline="")))
by_id = {}
for r in rows: by_id.setdefault(r["student_id"], []).append(r)
bad = []
def want(cond, what):
    if not cond: bad.append(what)
want(by_id["123456"][0]["late"] == "" and by_id["123456"][0]["student"] == "Jane Doe", "Jane Doe: on time")
want(by_id["123457"][0]["late"] == "" and by_id["123457"][0]["total"] == "16", "Zoë: on time, 14 + 2")
want(by_id["123458"][0]["late"] == "late", "12:05 AM on the 5th is after the due date: late")
sam = [r for r in by_id["123459"] if r["status"] == "no submission"]
want(len(sam) == 1 and sam[0]["student"] == "Sam Roe", "a 'no submission' row for Sam Roe")
other = [r for r in by_id["123459"] if r["submission"] == "samroe_123459"]
want(len(other) == 1 and other[0]["note"].startswith("not on the roster (id '123459', not from a Moodle download)"), "a Canvas submission is not a Moodle participant's")
want(by_id["555555"][0]["note"].startswith("not on the roster"), "555555 is not on the roster")
for b in bad: print("moodle gradebook:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
if run "$work/moodle-export.log" --gradebook "$moodle" --roster "$work/moodle-worksheet.csv" --export moodle "$work/moodle-import.csv"; then
  python3 - "$work/moodle-import.csv" "$work/moodle-worksheet.csv" <<'PY' || problem "Moodle's mock import refused the export (above)"
import csv, sys
export, worksheet = sys.argv[1], sys.argv[2]
raw, before = open(export, "rb").read(), open(worksheet, "rb").read()
bad = []
def want(cond, what):
    if not cond: bad.append(what)
want(raw.startswith(b"\xef\xbb\xbf") and b"\r" not in raw, "BOM and LF line ends kept")
want(raw.split(b"\n")[0] == before.split(b"\n")[0], "the header byte for byte")
sam = before[before.index(b'"Participant 123459"'):]
want(raw.endswith(sam), "Sam Roe's row (no submission) byte for byte, its two-line feedback with it")
rows = list(csv.reader(open(export, encoding="utf-8-sig", newline="")))
src = list(csv.reader(open(worksheet, encoding="utf-8-sig", newline="")))
h = rows[0]
col = {name: h.index(name) for name in ("Identifier", "Full name", "Grade", "Maximum Grade", "Last modified (grade)", "Feedback comments")}
want(len(rows) == len(src), "row count %d, the worksheet's %d" % (len(rows), len(src)))
want([r[col["Identifier"]] for r in rows] == [r[col["Identifier"]] for r in src], "Identifier column unchanged, in order")
changed = {col["Grade"], col["Feedback comments"]}
for row, orig in zip(rows[1:], src[1:]):
    for k in range(len(h)):
        if k in changed: continue
        same = row[k] == orig[k] or (k == col["Full name"] and row[k] == "'" + orig[k] and orig[k][:1] in "=+-@")
        want(same, "%s: column %s changed: %r" % (orig[0], h[k], row[k]))
    want(row[col["Full name"]][:1] not in "=+-@", "a name a spreadsheet takes for a formula: %r" % row[col["Full name"]])
    g = row[col["Grade"]]
    if g:
        # Moodle's import skips a grade above the maximum: none may be
        want(0 <= float(g) <= float(row[col["Maximum Grade"]]), "%s: grade %s above the maximum" % (row[0], g))
grade = {r[0]: r[col["Grade"]] for r in rows[1:]}
want(grade == {"Participant 123456": "12", "Participant 123457": "14", "Participant 123458": "3", "Participant 123459": ""},
     "grades %s" % grade)
fb = {r[0]: r[col["Feedback comments"]] for r in rows[1:]}
want(fb["Participant 123456"].startswith("graded: 12 of 14 points.") and "Jane_Doe_123456/report/report.html" in fb["Participant 123456"],
     "Jane's feedback: %r" % fb["Participant 123456"])
want("16 with the bonus" in fb["Participant 123457"], "Zoë's feedback says the bonus beyond the maximum: %r" % fb["Participant 123457"])
want(fb["Participant 123459"] == "Seen in the lab,\nno upload yet", "Sam's feedback kept")
for b in bad: print("moodle import:", b, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
else
  problem "--export moodle failed"
fi

run "$work/moodle-assignment.log" --gradebook "$moodle" --roster "$work/moodle-worksheet.csv" --export moodle "$work/x.csv" \
  --assignment "Lab 1 (1)" && problem "--assignment was taken with a Moodle worksheet"
# an assignment graded with a scale has no numeric maximum: refused, not guessed
sed 's/,14\.00,/,-,/' "$work/moodle-worksheet.csv" >"$work/scale.csv"
run "$work/scale.log" --gradebook "$moodle" --roster "$work/scale.csv" --export moodle "$work/scale-import.csv" &&
  problem "a worksheet of a scale was exported"
grep -q "scale.csv:2: Maximum Grade '-' is not a number" "$work/scale.log" || problem "the scale is not named"
[ ! -e "$work/scale-import.csv" ] && [ ! -e "$work/x.csv" ] || problem "a refused Moodle export left a file"

# ---- rosters that cannot be read: named by file and line ----
{ head -n 3 "$work/moodle-worksheet.csv"; printf '"Participant 9,Broken,-\n'; } >"$work/broken.csv"
run "$work/broken.log" --gradebook "$moodle" --roster "$work/broken.csv" && problem "a roster with an open quote was read"
grep -q "broken.csv:4: a quoted field is never closed" "$work/broken.log" || problem "the open quote is not named by line"
{ head -n 2 "$work/canvas-roster.csv"; printf 'Garc\xeda, Maria,12345,,,,,,,,\r\n'; } >"$work/latin1.csv"
run "$work/latin1.log" --gradebook "$canvas" --roster "$work/latin1.csv" && problem "a Latin-1 roster was read"
grep -q "latin1.csv:3: not UTF-8" "$work/latin1.log" || problem "the Latin-1 byte is not named by line"
printf 'Name,Score\nx,1\n' >"$work/other.csv"
run "$work/other.log" --gradebook "$canvas" --roster "$work/other.csv" && problem "a CSV of neither LMS was read"
grep -q "other.csv:1: neither a Canvas gradebook export" "$work/other.log" || problem "an unknown roster is not said"
sed 's/Saturday, 5 December 2026, 12:05 AM/Samstag, 5. Dezember 2026, 00:05/' "$work/moodle-worksheet.csv" >"$work/german.csv"
run "$work/german.log" --gradebook "$moodle" --roster "$work/german.csv" --due "2026-12-04 23:59" &&
  problem "a date it cannot read was taken for on time"
grep -q "german.csv:4: Last modified (submission) 'Samstag" "$work/german.log" || problem "the unreadable date is not named by line"
exit $fail
