/* sl_build_failure: a submission whose lab files do not compile still gets a
 * complete report (shadowlab-grade --not-built LOG): every check fails with the
 * compiler's first error, so the score, the gradebook row and the course
 * platform's results all say what went wrong and where. */
#ifndef SL_BUILD_FAILURE_H
#define SL_BUILD_FAILURE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_case.h"
#include "sl_grade.h"

#define SL_BUILD_ERROR_MAX 300 /* characters of the first error kept */

/* The first error in a build log: the compiler's ("file:line:col: error: ..."),
 * else the linker's or CMake's, else a line saying the build failed. Control
 * characters and colour codes are removed, the labs tree's folder is left out
 * of paths, and the line is cut to SL_BUILD_ERROR_MAX characters. False with a
 * reason when the log cannot be read. */
bool sl_build_failure_first_error(const char *log_path, const char *labs_dir, char *out, size_t out_size, char *err,
                                  size_t err_size);

/* A check of a submission that did not build: no points, and why. */
void sl_build_failure_grade(const sl_check *k, const char *first_error, sl_check_result *out);
/* A check of a lab that did not build, where each lab is built on its own
 * (scripts/grade-submission): the other labs are graded. */
void sl_build_failure_grade_lab(const sl_check *k, int lab, const char *first_error, sl_check_result *out);

#endif
