/* sl_reference: the references a check is compared with, as the solutions
 * made them, checked against the manifest (sl_grade.c grades with them). */
#ifndef SL_REFERENCE_H
#define SL_REFERENCE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_case.h"
#include "sl_diag.h"
#include "sl_manifest.h"
#include "sl_reference_cache.h"
#include "sl_run.h"

/* Loads the reference of one check, if it needs one. A missing, corrupt or
 * changed file (against the manifest: NULL means the manifest itself could
 * not be read, `manifest_error` says why), or one that does not fit the case
 * (another image size), comes back with loaded = false and an error naming
 * the file: a problem for the staff, not the student. */
void sl_reference_load(sl_reference *ref, const char *references_dir, const sl_manifest *manifest,
                       const char *manifest_error, const sl_case *c, const sl_check *k);
/* The same, with image references read through `cache` where it has them
 * (NULL: none; sl_reference_cache.h): the same reference, error or message. */
void sl_reference_load_cached(sl_reference *ref, const char *references_dir, const sl_manifest *manifest,
                              const char *manifest_error, sl_reference_cache *cache, const sl_case *c,
                              const sl_check *k);
void sl_reference_free(sl_reference *ref);
/* The file, beside a case's other references, of the surfaces facing the light (the solutions' drawing):
 * the checks that measure only on lit surfaces read it (ref->lit_mask), never the runner's capture. */
#define SL_LIT_MASK_FILE "lit_mask.exr"
bool sl_check_uses_lit_mask(const sl_case *c, const sl_check *k);
/* Writes the capture a check needs as its reference (from the solutions'
 * runner), and its case's lit surfaces where it uses them, and records them
 * in the manifest. */
bool sl_reference_write(const char *references_dir, sl_manifest *manifest, const sl_case *c, const sl_check *k,
                        const sl_case_result *r, char *err, size_t err_size);

#endif
