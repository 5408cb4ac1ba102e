/* sl_case_probe: a case's probe check read from its JSON (sl_case_load calls it): the function
 * it calls, its rows of inputs by the function's parameters, and how --hidden varies them. */
#ifndef SL_CASE_PROBE_H
#define SL_CASE_PROBE_H

#include <stdbool.h>
#include <stddef.h>

#include <cjson/cJSON.h>

#include "sl_case_types.h"

/* Fills probe check `k` of case `c` from its JSON; false with a message naming the case's file. */
bool sl_case_probe_check(const sl_case *c, sl_check *k, const cJSON *json, char *err, size_t n);

#endif
