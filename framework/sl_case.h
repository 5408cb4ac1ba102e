/* sl_case: a grading case is data: a JSON file under grader/cases/ naming the
 * scene, light, camera, lab parameters, frames, and the checks with points and
 * tolerances. See grader/cases/README.md for the format. */
#ifndef SL_CASE_H
#define SL_CASE_H

#include "sl_case_types.h"

const char *sl_symptom_name(sl_symptom symptom);

const char *sl_check_kind_name(sl_check_kind kind);
/* The tolerances a check of this kind applies where its case gives none (sl_case.c's table). */
void sl_check_kind_defaults(sl_check_kind kind, double *threshold, double *fail_fraction, double *epsilon,
                            double *mean_tolerance);
/* The capture a check compares ("visibility", "depth_map", "probe_2", ...). */
const char *sl_check_capture_name(const sl_case *c, const sl_check *k);
/* Every capture a check needs of the runner, as bits (1 << sl_capture_kind). */
uint32_t sl_check_captures(const sl_case *c, const sl_check *k);
/* Case and check names become folder and file names: letters, digits, '_' and '-' only. */
bool sl_case_name_valid(const char *name);
/* The file a check's reference lives in, in its case's references folder
 * ("visibility.png", "slope.probe.json"); false when it needs none. */
bool sl_check_reference_file(const sl_check *k, char *out, size_t out_size);

/* A criterion's fraction as the percentage its case states ("0.25", "0.1", "1"), not rounded
 * to a format's digits: a message says the number the check applies. Returns `out`. */
const char *sl_criterion_percent(double fraction, char *out, size_t out_size);

/* Reads and validates one case file; false with a message naming the file. */
bool sl_case_load(sl_case *c, const char *path, char *err, size_t err_size);

#endif
