/* What a stage is asked and what it answers (sl_stage.h): the desc and the
 * exit statuses, below the stage's modules (sl_stage.c, the reading child's
 * sl_stage_child.c and sl_stage_tree.c), which all read them. */
#ifndef SL_STAGE_DESC_H
#define SL_STAGE_DESC_H

#include <stdio.h>

/* Exit statuses of shadowlab-stage (and sl_stage_run's results). */
enum {
    SL_STAGE_TAKEN = 0,       /* lab files were staged (--list, --extract: done) */
    SL_STAGE_DAMAGED = 1,     /* --list, --extract: the archive is corrupt, cut short, past a limit or contradicts itself */
    SL_STAGE_PROBLEM = 2,     /* could not stage: a staff-side problem (arguments, the stage, unreadable files) */
    SL_STAGE_NO_LAB_FILE = 3, /* no lab file in the submission: the stage holds the stubs only */
    SL_STAGE_MISMATCH = 4,    /* a file extracted or staged is not what the archive records, though the archive
                                 passed its own checks: a fault of shadowlab-stage (staff-side), never the student's */
};

/* Zero means the default for every number. */
typedef struct sl_stage_desc {
    const char *submission;       /* a folder or an archive */
    const char *stage;            /* a labs tree holding the handout's stubs: the lab files go over them */
    const char *summary;          /* where the JSON summary goes (NULL: none) */
    const char *const *hidden;    /* folders the reading process must not see */
    int hidden_count;
    unsigned user;                /* when root: the uid and gid that read the submission (default 65534) */
    int max_files;                /* lab files taken, default 256 */
    long long max_file_bytes;     /* per file, default 1 MiB */
    long long max_total_bytes;    /* all lab files, default 16 MiB */
    int max_entries;              /* folder and archive entries looked at, default 20000 */
    int max_depth;                /* folders deep, default 16 */
    unsigned long long max_unpacked_bytes; /* what an archive may unpack to, default 512 MiB */
    double timeout;               /* seconds, default 120 */
    FILE *log;                    /* lines for people (default stdout) */
    const char *log_prefix;       /* before each line (default "shadowlab-stage: ") */
} sl_stage_desc;

#endif
