/* sl_class_report: what a class got wrong, from the reports of a batch
 * (shadowlab-grade --gradebook DIR, written by scripts/grade-batch beside the
 * gradebook), for the instructor before the next lecture:
 *
 * - one row per mistake, with the students who made it ("2 of 5: amy, ben"),
 *   each counted once whatever the number of checks it failed. A mistake is
 *   the lab function a failed check's evidence names plus the kind of cause
 *   (results.json's "cause": wrong, stub, crash, timeout), so a probe's
 *   verdict, a lead from it, a stub, a crash or a time cut in the function
 *   are one row each, whatever their wording; a check that names no function
 *   counts by its diagnosis id (not by the message's text, whose numbers
 *   differ per student); a lab that did not compile counts as one. Failures
 *   that follow from an earlier lab's and name no function come apart, below;
 * - per check, how many students failed it, and the mistake most of them made;
 * - a histogram of each lab's scores, and of the totals.
 *
 * Counted are the submissions that were graded: those that did not build, held
 * no lab file, are incomplete or could not be graded (staff problems, with
 * their cause) are named in the header, not counted. Students are named as
 * the gradebook names them (DIR/gradebook.json: a bulk download's or the
 * roster's name), else by their submission. Written to
 * DIR/class-report.html (a page with no script, no fetched file),
 * DIR/class-report.csv: kind,lab,name,text,who,students,of — kind "mistake"
 * (name: "function: kind" or the diagnosis id; who: the students, "; "
 * between them), "follows" (the same, following from an earlier lab),
 * "check" (name: case / check; text: the most common mistake), a status for
 * each submission not counted ("did not build", "no lab file", "incomplete",
 * "staff problem" with its cause as text, "not finished"; name: the
 * submission), "score" (name: a range of the lab's score, "40-49%"; lab
 * "total" for the totals); and DIR/class-mistakes.csv:
 * submission,student,status, then a column per mistake named as in
 * class-report.csv: 1 or 0, empty for a submission not counted. */
#ifndef SL_CLASS_REPORT_H
#define SL_CLASS_REPORT_H

#include <stdbool.h>
#include <stddef.h>

/* Writes both files (each whole or not at all); false with the reason. */
bool sl_class_report_write(const char *batch_dir, char *err, size_t err_size);

#endif
