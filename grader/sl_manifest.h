/* sl_manifest: grader/references/MANIFEST.json, written by
 * --update-references: the SHA-256 of every reference file and the CPU time
 * one of the solutions' frames took per case. A reference that no longer matches its hash
 * was changed by hand (or by someone else) after it was rendered: the grader
 * then refuses to grade with it (exit 2) instead of grading against it. */
#ifndef SL_MANIFEST_H
#define SL_MANIFEST_H

#include <stdbool.h>
#include <stddef.h>

typedef struct sl_manifest sl_manifest;

#define SL_MANIFEST_FILE "MANIFEST.json"

/* The manifest of a references folder; NULL with the reason in err when it is
 * missing or unreadable. With `create`, a missing one comes back empty. */
sl_manifest *sl_manifest_load(const char *references_dir, bool create, char *err, size_t err_size);
void sl_manifest_free(sl_manifest *m);
/* True when `path` (the case's reference `file`) has the hash recorded for
 * it; otherwise false with the reason. */
bool sl_manifest_verify(const sl_manifest *m, const char *case_name, const char *file, const char *path, char *why,
                        size_t why_size);
/* The SHA-256 recorded for a case's reference `file` (64 hex digits), NULL if none. */
const char *sl_manifest_hash(const sl_manifest *m, const char *case_name, const char *file);
/* The CPU seconds the solutions' runner took for the whole case, as the grader measured it (its
 * rusage), 0 when not recorded. */
double sl_manifest_cpu_seconds(const sl_manifest *m, const char *case_name);
/* Forgets what a case had: its references are about to be written anew. */
void sl_manifest_forget_case(sl_manifest *m, const char *case_name);
/* Records a freshly written reference (and the CPU time of the case's run). */
bool sl_manifest_record(sl_manifest *m, const char *case_name, const char *file, const char *path,
                        double cpu_seconds, char *err, size_t err_size);
/* The renderer the references were made with ("llvmpipe (LLVM 15.0.6, 256 bits)"), "" if unknown. */
const char *sl_manifest_renderer(const sl_manifest *m);
void sl_manifest_set_renderer(sl_manifest *m, const char *renderer);
bool sl_manifest_save(const sl_manifest *m, const char *references_dir, char *err, size_t err_size);

#endif
