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

/* With the LMS's roster (sl_roster.h): each row's name from the roster,
 * matched by the LMS id of the bulk download (student.json), a "no
 * submission" row after the submissions for each roster student without one,
 * and a submission whose id is not on the roster kept with a note saying so.
 * With a due date (Moodle), late is the worksheet's Last modified
 * (submission) after it. */
typedef struct sl_gradebook_roster {
    const struct sl_roster *roster;
    bool have_due;
    long long due; /* sl_roster_parse_due */
} sl_gradebook_roster;
bool sl_gradebook_write_roster(const char *batch_dir, const char *csv_path, const sl_gradebook_roster *roster,
                               char *err, size_t err_size);

#endif
