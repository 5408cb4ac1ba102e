/* The stage's channel, child -> parent (sl_stage.c): records of a kind and
 * up to three texts. The child writes them; the parent, which trusts none
 * of them, reads them. */
#ifndef SL_STAGE_CHANNEL_H
#define SL_STAGE_CHANNEL_H

#include <stddef.h>
#include <stdint.h>

#define _SL_TEXT_MAX 4096      /* a name or a reason on the channel */

typedef struct _sl_record_header {
    uint8_t kind;
    uint32_t len[3];
} __attribute__((packed)) _sl_record_header;

enum {
    _SL_R_FENCE = 'A',   /* how the submission was read */
    _SL_R_SOURCE = 'S',  /* "folder" | "archive", the folder looked into */
    _SL_R_LAYOUT = 'L',
    _SL_R_FOUND = 'T',   /* what the folder looked into holds (for "no lab file") */
    _SL_R_IGNORED = 'I', /* path, reason */
    _SL_R_REFUSED = 'R', /* path, reason */
    _SL_R_ERROR = 'E',   /* the submission's fault: a corrupt archive, a limit */
    _SL_R_STAFF = 'X',   /* not the submission's fault: unreadable files, a fence that failed */
    _SL_R_MISMATCH = 'M', /* not the submission's fault: a file read is not what the archive records */
    _SL_R_FILE = 'F',    /* target, content, source path */
    _SL_R_END = 'Z',
};

/* The child's end of the channel. */
extern int _sl_channel_fd;

/* One record: a kind and three texts of the lengths given (exits if the parent is gone). */
void _sl_send_record3(int kind, const char *a, size_t la, const char *b, size_t lb, const char *c, size_t lc);

/* One record of two texts (NULL: none), each cut at _SL_TEXT_MAX. */
void _sl_send_record(int kind, const char *a, const char *b);

#endif
