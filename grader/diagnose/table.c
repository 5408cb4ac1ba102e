/* The diagnosis table: each lab's descriptor (sl_diagnose.h), registered at
 * the end of its own file. A new lab adds its line here and nowhere else. */
#include "sl_diagnose.h"

#include <stddef.h>
#include <string.h>

static const sl_lab_diagnoses *const _sl_labs[] = {
    &sl_lab1_diagnoses, &sl_lab2_diagnoses, &sl_lab3_diagnoses, &sl_lab4_diagnoses,
    &sl_lab5_diagnoses, &sl_lab6_diagnoses, &sl_lab7_diagnoses,
};
#define _SL_LAB_COUNT ((int)(sizeof _sl_labs / sizeof _sl_labs[0]))

const sl_lab_diagnoses *sl_lab_diagnoses_at(int i) { return i >= 0 && i < _SL_LAB_COUNT ? _sl_labs[i] : NULL; }

const sl_lab_diagnoses *sl_lab_diagnoses_of(int lab) {
    for (int i = 0; i < _SL_LAB_COUNT; i++)
        if (_sl_labs[i]->lab == lab) return _sl_labs[i];
    return NULL;
}

sl_check_diagnosis_fn sl_check_diagnosis_of(sl_check_kind kind) {
    for (int i = 0; i < _SL_LAB_COUNT; i++)
        for (int j = 0; j < SL_LAB_MAX_CHECK_KINDS && _sl_labs[i]->checks[j].diagnose; j++)
            if (_sl_labs[i]->checks[j].kind == kind) return _sl_labs[i]->checks[j].diagnose;
    return NULL;
}

const sl_function_verdict *sl_function_verdict_of(const sl_probe_function *f) {
    const sl_lab_diagnoses *lab = f ? sl_lab_diagnoses_of(f->lab) : NULL;
    for (int i = 0; lab && i < SL_LAB_MAX_FUNCTION_VERDICTS && lab->functions[i].function; i++)
        if (strcmp(lab->functions[i].function, f->name) == 0) return &lab->functions[i];
    return NULL;
}
