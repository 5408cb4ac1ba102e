/* sl_roster: the LMS's own roster, read as the LMS exports it, and the grades
 * written back in the same format, ready to import (shadowlab-grade
 * --gradebook DIR --roster FILE [--export canvas|moodle OUT]).
 *
 * Two formats, told apart by their header row:
 * - Canvas's Gradebook export (Grades > Export > CSV): Student, ID, SIS User
 *   ID, SIS Login ID, Section, then one column per assignment named
 *   "Name (assignment id)", then read-only totals; a "Points Possible" row
 *   (and possibly a "Manual Posting" row) before the students. A student is
 *   known by ID, the user id a Canvas download's file names carry.
 * - Moodle's grading worksheet (Download grading worksheet): Identifier
 *   ("Participant 123456": the number a Moodle download's folder names
 *   carry), Full name, Email address, Status, Grade, Maximum Grade, Grade can
 *   be changed, Last modified (submission), Last modified (grade), Feedback
 *   comments.
 * A student is matched by that id, never by a name. The file is read as RFC
 * 4180 CSV in UTF-8 (a byte-order mark, CRLF, quoted commas, doubled quotes
 * and line breaks inside quotes are fine); what cannot be read is named by
 * file and line. */
#ifndef SL_ROSTER_H
#define SL_ROSTER_H

#include <stdbool.h>
#include <stddef.h>

typedef enum sl_roster_kind { SL_ROSTER_CANVAS = 1, SL_ROSTER_MOODLE = 2 } sl_roster_kind;

typedef struct sl_roster sl_roster;

/* The note a gradebook row of a submission whose id is not on the roster starts with. */
#define SL_ROSTER_NOT_ON_ROSTER "not on the roster"

/* NULL with "FILE:LINE: reason" in err. */
sl_roster *sl_roster_read(const char *path, char *err, size_t err_size);
void sl_roster_free(sl_roster *roster);

sl_roster_kind sl_roster_kind_of(const sl_roster *roster);
const char *sl_roster_kind_name(sl_roster_kind kind); /* "Canvas", "Moodle" */

/* The students, in the roster's order (Canvas's test student left out). */
int sl_roster_count(const sl_roster *roster);
const char *sl_roster_name(const sl_roster *roster, int student);
const char *sl_roster_id(const sl_roster *roster, int student);
/* The student with this LMS id, or -1. */
int sl_roster_find(const sl_roster *roster, const char *id);

/* "YYYY-MM-DD HH:MM" as minutes since 1970-01-01 00:00 of the same wall clock
 * (no time zone: see sl_roster_late); false when it is not that. */
bool sl_roster_parse_due(const char *text, long long *minutes);
/* Moodle: 1 when the student's "Last modified (submission)" is after `due`
 * (both read as wall-clock times of the worksheet's time zone, to the minute),
 * 0 when not or when there is no submission ("-"); -1 with "FILE:LINE: ..."
 * in err when the date cannot be read. Canvas: 0 (its downloads mark LATE). */
int sl_roster_late(const sl_roster *roster, int student, long long due, char *err, size_t err_size);

typedef struct sl_roster_export_desc {
    const char *format;     /* "canvas" or "moodle": the roster's own */
    const char *path;       /* the file to write */
    const char *assignment; /* Canvas: the "Name (id)" column; NULL: the only one */
    bool missing_as_zero;   /* a roster student without a submission gets 0, not an empty grade */
} sl_roster_export_desc;

/* Writes the grades of `gradebook_csv` (shadowlab-grade's gradebook.csv: the
 * total of each row, bonus included) in the roster's format, whole or not at
 * all, then reads the file back and checks every cell. False with the reason.
 * What an instructor should look at (grades left empty, a bonus beyond the
 * maximum) is said on stderr. */
bool sl_roster_export(const sl_roster *roster, const char *gradebook_csv, const sl_roster_export_desc *desc,
                      char *err, size_t err_size);

#endif
