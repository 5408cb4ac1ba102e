/* The child's view of a submission (sl_stage.c): a tree of its folders or of
 * an archive's entries, listed as it is needed, one name at a time from open
 * descriptors and never through a link; and what a chosen file holds. */
#ifndef SL_STAGE_TREE_H
#define SL_STAGE_TREE_H

#include <stdbool.h>
#include <sys/types.h>

#include "sl_stage_desc.h"
#include "sl_stage_handout.h"

typedef enum _sl_kind {
    _SL_FILE,
    _SL_DIR,
    _SL_SYMLINK,
    _SL_HARDLINK,
    _SL_DEVICE,
    _SL_FIFO,
    _SL_SOCKET,
    _SL_OTHER,
    _SL_UNREADABLE,
} _sl_kind;

typedef struct _sl_node {
    char *name, *path;      /* one part; the path shown to people (from the submission's folder) */
    char *archive_path;     /* an archive's entry: its cleaned path there */
    _sl_kind kind;
    long long size;
    long nlink;
    char *link;             /* a link's target, as written */
    dev_t dev;
    ino_t ino;
    struct _sl_node *parent, *first, *next;
    bool listed, visited, descended, selected, reported;
    const char *why_ignored; /* set when a lab file is left out (a limit) */
    char why_buffer[160];
    int fd;                 /* a folder of a folder submission, once opened */
    char *data;             /* a chosen file's content */
    long long data_len;
} _sl_node;

typedef struct _sl_wanted {
    _sl_node *node;
    char target[600];
} _sl_wanted;

typedef struct _sl_child {
    const sl_stage_desc *d;
    const _sl_labs *labs;
    bool archive;           /* the tree is an archive's */
    int archive_fd;
    char archive_name[512]; /* shown in messages */
    int entries;
    bool entries_over;
    _sl_wanted *wants;
    int want_count;
    long long want_bytes;
} _sl_child;

/* A new entry `name` of `kind` under `parent` (NULL: a root). */
_sl_node *_sl_new_node(_sl_node *parent, const char *name, _sl_kind kind);

/* The entry `name` of a folder's, or NULL. */
_sl_node *_sl_child_named(_sl_node *parent, const char *name);

/* One step down, never through a link: openat2 where the kernel has it. */
int _sl_open_beneath(int dir_fd, const char *name, int flags);

/* What macOS or Windows added, said as such ("macOS metadata (AppleDouble)"), or NULL. */
const char *_sl_clutter(const char *name, _sl_kind kind);

/* A problem of the staff's (an unreadable file), sent as such. */
void _sl_staff_problem(_sl_child *c, const char *path, const char *what);

/* A folder's descriptor, opened step by step from the root (and checked to be the folder listed), or -1. */
int _sl_dir_fd(_sl_child *c, _sl_node *n);

/* Lists a folder's entries, once (an archive's tree is whole from the start). */
void _sl_list_folder(_sl_child *c, _sl_node *n);

/* Why an entry is refused, or NULL when it is a file or a folder. */
const char *_sl_refusal(_sl_node *n);

/* Reads the archive's entries into a tree whose root is named `label`. */
_sl_node *_sl_archive_tree(_sl_child *c, const char *label);

/* Pass two: the chosen entries' data, bounded whatever the headers say. */
void _sl_archive_read_wanted(_sl_child *c);

/* A chosen file of a folder submission: its content into n->data, bounded. */
void _sl_folder_read(_sl_child *c, _sl_node *n);

#endif
