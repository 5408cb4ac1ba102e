/* sl_probe_pass: calls a student's function on a probe table, in the runner.
 * GLSL functions run in a full-screen pass, one pixel per row, that includes
 * the lab's shader file and writes the function's result into an RGBA32F
 * target; functions that read a depth map get synthetic ones (sl_probe_map).
 * C functions are called directly, one row at a time, by the probes of the
 * technique of their lab (sl_technique.h; the labs' are in sl_probe_calls.c),
 * with the GL state they set read back. */
#ifndef SL_PROBE_PASS_H
#define SL_PROBE_PASS_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_probe.h"

/* The function a probe table names, as this build has it: sl_probe.c's table, or the description of a
 * technique's probe (sl_technique_probe.described: a technique a build adds); NULL: this build has none. */
const sl_probe_function *sl_probe_pass_function(const char *name);
/* outputs: rows x output_count numbers. not_implemented: a C function
 * returned SL_NOT_IMPLEMENTED. False, with the reason (a GLSL compile error
 * names the lab's file and line), when the function could not be called: this build has none of that
 * name, or its inputs or outputs a row are not the table's counts (the case described another). */
bool sl_probe_pass_run(const sl_probe_table *table, const char *labs_dir, const char *framework_dir, double *outputs,
                       bool *not_implemented, char *err, size_t err_size);
/* The same for function `f` as given (table->function and the counts unused). */
bool sl_probe_pass_run_function(const sl_probe_function *f, const sl_probe_table *table, const char *labs_dir,
                                const char *framework_dir, double *outputs, bool *not_implemented, char *err,
                                size_t err_size);

#endif
