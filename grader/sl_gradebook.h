/* sl_gradebook: the CSV gradebook of a batch of graded submissions
 * (shadowlab-grade --gradebook DIR, written by scripts/grade-batch).
 *
 * DIR holds one folder per submission; a finished one has a `status` file
 * (the grade's exit status) and `report/results.json`. The gradebook has one
 * row per folder, in name order: submission, status (graded, did not build,
 * incomplete, no lab file, staff problem, not finished), one
 * column per lab, bonus, total (with the bonus), max, and a note (the
 * compiler's first error, or the grader's problem). A grade that stopped on
 * the staff's side has no scores: what its report holds is not the student's. It is made from the reports alone, so it can be
 * written again at any time. */
#ifndef SL_GRADEBOOK_H
#define SL_GRADEBOOK_H

#include <stdbool.h>
#include <stddef.h>

/* Writes `csv_path` (whole or not at all); false with the reason. */
bool sl_gradebook_write(const char *batch_dir, const char *csv_path, char *err, size_t err_size);

#endif
