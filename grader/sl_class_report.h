/* sl_class_report: what a class got wrong, from the reports of a batch
 * (shadowlab-grade --gradebook DIR, written by scripts/grade-batch beside the
 * gradebook), for the instructor before the next lecture:
 *
 * - per diagnosis, how many students got it ("31 of 212: sin(theta) where
 *   tan(theta) belongs"), counted once per student whatever the number of
 *   checks it failed, by the diagnosis id each failed check carries in
 *   results.json (not by the message's text, whose numbers differ per student);
 *   failures that follow from an earlier lab's come apart, below;
 * - per check, how many students failed it, and the diagnosis most of them got;
 * - a histogram of each lab's scores, and of the totals.
 *
 * Counted are the submissions that were graded: those that did not build, held
 * no lab file or could not be graded are named in the header, not counted.
 * Written to DIR/class-report.html (a page with no script, no fetched file) and
 * DIR/class-report.csv: kind,lab,name,text,students,of — kind "diagnosis"
 * (name: its id), "check" (name: case / check; text: the most common
 * diagnosis), "score" (name: a range of the lab's score, "40-49%"; lab
 * "total" for the totals). */
#ifndef SL_CLASS_REPORT_H
#define SL_CLASS_REPORT_H

#include <stdbool.h>
#include <stddef.h>

/* Writes both files (each whole or not at all); false with the reason. */
bool sl_class_report_write(const char *batch_dir, char *err, size_t err_size);

#endif
