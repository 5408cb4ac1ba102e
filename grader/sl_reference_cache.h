/* sl_reference_cache: the decoded pixels of reference images, kept in a
 * folder of the build so a grade whose references are all there never loads
 * the image module (OpenImageIO and its ~250 libraries: most of a short
 * grade's CPU time).
 *
 * An entry is named by the SHA-256 of the reference file's bytes, which the
 * grader takes itself and compares with the manifest's before it looks: the
 * same file anywhere (--references DIR) finds the same entry, a changed one
 * none. Its pixels are the decode of those very bytes (copied into the cache
 * folder and decoded there, so a file that changes meanwhile cannot put
 * other pixels under its hash). The format is the project's own: a header
 * (magic, width, height, channels, byte order, the file's hash, the pixels'
 * hash) and the floats, written to a temporary file and renamed into place,
 * so graders running at once never see half an entry.
 *
 * Trust: the folder and every entry must be owned by the grader's effective
 * uid and writable by nobody else (the folder: no access at all for group or
 * others, as it holds references); anything else, a header that does not
 * parse, a size or a pixels' hash that does not fit, is ignored and written
 * anew. The pixels' hash catches damage, not forgery: what keeps forgers out
 * is that only the grader's uid can write there, and the grader uses the
 * cache only at a sandbox level whose runners are another uid or see no
 * build (sl_grader.c decides; grader/README.md says so). Nothing here is
 * ever an error: a failure means "decode the file the usual way". */
#ifndef SL_REFERENCE_CACHE_H
#define SL_REFERENCE_CACHE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_image.h"

typedef struct sl_reference_cache sl_reference_cache;

typedef struct sl_reference_cache_counts {
    int hits;    /* images read from an entry */
    int stored;  /* images decoded and stored */
    int ignored; /* entries there that were not trusted or did not parse */
    int removed; /* files removed when the folder was opened: a dead grader's temporary ones, and
                    entries no grade had read for months */
} sl_reference_cache_counts;

/* This build's cache folder: ../cache/references beside the running program. */
bool sl_reference_cache_default_dir(char *out, size_t out_size);
/* Opens the folder `dir`, making it (and its parent) with mode 0700 where
 * missing, and sweeps it (counts.removed). NULL, with the reason in `why`, where it cannot be made or is not
 * the grader's own (another owner, access for group or others, a link). */
sl_reference_cache *sl_reference_cache_open(const char *dir, char *why, size_t why_size);
void sl_reference_cache_close(sl_reference_cache *cache);

/* The pixels of the image file at `path`, whose bytes must have the SHA-256
 * `sha256` (64 hex digits: the manifest's). True with `out` filled: from an
 * entry, or decoded from exactly those bytes and stored. False with `out`
 * empty: the bytes have another hash, or could not be read or decoded; the
 * caller then reads the file the usual way, which names the problem. */
bool sl_reference_cache_read(sl_reference_cache *cache, const char *path, const char *sha256, sl_image *out);

sl_reference_cache_counts sl_reference_cache_counts_of(const sl_reference_cache *cache);
const char *sl_reference_cache_dir(const sl_reference_cache *cache);

#endif
