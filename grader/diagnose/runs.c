/* Evidence for blame: what a case runs, and whether a failed probe explains
 * what a check's capture shows (grader/diagnose/README.md, "Blame needs
 * evidence"). The per-lab knowledge of which functions a case's frames call
 * sits with each lab's diagnoses (sl_labN_case_runs in grader/diagnose/labN.c);
 * this file holds the rules every lab shares. */
#define _POSIX_C_SOURCE 200809L
#include "sl_diagnose.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_probe.h"
#include "sl_verdict.h"

/* Lab code without a probe of its own (files and C functions a case may run), as each lab lists it in
 * its descriptor (`unprobed`), so that a message can name them as candidates: the i-th over the table. */
static const sl_lab_function *_sl_unprobed_at(int i) {
    const sl_lab_diagnoses *lab;
    for (int l = 0; (lab = sl_lab_diagnoses_at(l)) != NULL; l++)
        for (int j = 0; j < SL_LAB_MAX_UNPROBED && lab->unprobed[j].name; j++)
            if (i-- == 0) return &lab->unprobed[j];
    return NULL;
}

static const sl_lab_function *_sl_unprobed_named(const char *function) {
    const sl_lab_function *u;
    for (int i = 0; (u = _sl_unprobed_at(i)) != NULL; i++)
        if (strcmp(u->name, function) == 0) return u;
    return NULL;
}

int sl_lab_function_count(void) {
    int probed = 0, unprobed = 0;
    while (sl_probe_at(probed)) probed++;
    while (_sl_unprobed_at(unprobed)) unprobed++;
    return probed + unprobed;
}

sl_lab_function sl_lab_function_at(int i) {
    int probed = 0;
    while (sl_probe_at(probed)) probed++;
    if (i < probed) {
        const sl_probe_function *f = sl_probe_at(i);
        return (sl_lab_function){f->name, f->lab, f->todo, f->bonus};
    }
    const sl_lab_function *u = _sl_unprobed_at(i - probed);
    return u ? *u : (sl_lab_function){NULL, 0, NULL, false};
}

/* The step a TODO tag names ("lab3.2", "TODO(lab1.4)": 2 and 4), 0 for none. */
static int _sl_todo_step(const char *todo) {
    const char *lab = todo ? strstr(todo, "lab") : NULL;
    if (!lab) return 0;
    const char *p = lab + 3;
    while (*p >= '0' && *p <= '9') p++;
    return *p == '.' ? atoi(p + 1) : 0;
}

int sl_case_step(const sl_case *c) {
    bool probes_only = true;
    for (int k = 0; k < c->check_count; k++) probes_only &= c->checks[k].kind == SL_CHECK_PROBE;
    int step = 0;
    for (int k = 0; k < c->check_count; k++) {
        if (c->checks[k].bonus) continue;
        for (int i = 0; i < sl_lab_function_count(); i++) {
            sl_lab_function fn = sl_lab_function_at(i);
            if (fn.lab != c->lab || fn.bonus || !sl_case_runs(c, &c->checks[k], fn.name)) continue;
            int s = _sl_todo_step(fn.todo);
            if (s > 0 && (step == 0 || (probes_only ? s < step : s > step))) step = s;
        }
    }
    return step;
}

static bool _sl_is_bonus(const char *function) {
    const sl_probe_function *f = sl_probe_find(function);
    if (f) return f->bonus;
    const sl_lab_function *u = _sl_unprobed_named(function);
    return u && u->bonus;
}

/* ---- what a case runs ---- */

bool sl_case_runs(const sl_case *c, const sl_check *k, const char *function) {
    if (!function || !function[0]) return false;
    /* a probe check calls its own function alone */
    if (k->kind == SL_CHECK_PROBE) {
        const sl_probe_function *f = sl_probe_at(k->function);
        return f && strcmp(f->name, function) == 0;
    }
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
    return lab && lab->case_runs && lab->case_runs(c, k, function);
}

void sl_case_path(const sl_case *c, const sl_case_result *r, char *out, size_t n) {
    out[0] = '\0';
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
    if (lab && lab->case_path) lab->case_path(c, r, out, n);
}

void sl_case_lookup_function(const sl_case *c, const char **function, const char **todo) {
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
    *function = "the shadow lookup";
    *todo = "";
    if (lab && lab->lookup_function) lab->lookup_function(c, function, todo);
}

/* ---- whether a case meets a probe row ---- */

static bool _sl_perspective(const sl_case *c) { return c->scene.light.type != SL_LIGHT_DIRECTIONAL; }

/* The settings a lab's rows test (a radius): where a row's mistake is known not to depend on them, a
 * case meets the row whatever its settings. */
static bool _sl_meets_settings(const sl_case *c, const sl_check *probe, int r) {
    const sl_probe_function *f = sl_probe_at(probe->function);
    const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(f->lab);
    return !lab || !lab->meets_row || lab->meets_row(c, probe, r);
}

static bool _sl_meets_row(const sl_case *c, const sl_check *probe, int r, bool every_setting);

bool sl_case_meets_row(const sl_case *c, const sl_check *probe, int r) { return _sl_meets_row(c, probe, r, false); }

static bool _sl_meets_row(const sl_case *c, const sl_check *probe, int r, bool every_setting) {
    const sl_probe_function *f = sl_probe_at(probe->function);
    if (!f || r < 0 || r >= probe->rows) return false;
    const float *row = probe->inputs[r];
    /* A shadow coordinate with w other than 1 comes only from a perspective
     * light: under a sun's orthographic projection w is 1 everywhere. */
    const float *coord = sl_probe_row_param(f, row, "shadow_coord");
    if (coord && coord[3] != 1.0f && !_sl_perspective(c)) return false;
    /* A call right after another mode's: a case draws in one mode from its start, only the viewer switches. */
    const float *previous = sl_probe_row_param(f, row, "previous_mode");
    if (previous && *previous >= 0) return false;
    /* A mode: the case's own (a lab N function with a mode of lab N's settings, as its lab says). */
    const float *mode = sl_probe_row_param(f, row, "mode");
    const sl_function_verdict *own = sl_function_verdict_of(f);
    if (mode && own && own->case_mode && (int)*mode != own->case_mode(c)) return false;
    return every_setting || _sl_meets_settings(c, probe, r);
}

/* ---- what a failed probe predicts, and whether it explains a check ---- */

/* Whether a row's mistake, in the outputs that differ, can show in case c at all. */
static bool _sl_outputs_reach(const sl_case *c, const sl_probe_function *f, uint16_t outputs) {
    /* outputs that matter only to a filter reading past the map's edge (lab 1's wrap mode and border) */
    const sl_function_verdict *own = sl_function_verdict_of(f);
    if (own && own->edge_outputs && outputs && !(outputs & ~own->edge_outputs)) {
        const sl_lab_diagnoses *lab = sl_lab_diagnoses_of(c->lab);
        return lab && lab->filters_past_edge && lab->filters_past_edge(c);
    }
    return true;
}

uint32_t sl_probe_failure_predicts(const sl_case *c, const sl_probe_failure *failure) {
    const sl_probe_function *f = sl_probe_at(failure->function);
    if (!f) return 0;
    if (!failure->failing_rows || !failure->check) return SL_SYMPTOMS_ANY; /* failed as a whole: not called, a stub */
    uint32_t predicts = 0;
    for (int row = 0; row < failure->check->rows; row++)
        if ((failure->failing_rows >> row) & 1u &&
            _sl_meets_row(c, failure->check, row, (failure->row_predicts[row] & SL_PREDICTS_EVERY_SETTING) != 0) &&
            _sl_outputs_reach(c, f, failure->row_outputs[row]))
            predicts |= failure->row_predicts[row] ? failure->row_predicts[row] & ~SL_PREDICTS_EVERY_SETTING : SL_SYMPTOMS_ANY;
    return predicts;
}

/* What a check's symptoms need a mistake to predict: its direction, and a
 * gross symptom a gross mistake. Symptoms of the old kind say their direction. */
static uint32_t _sl_with_directions(uint32_t s) {
    if (s & (1u << SL_SYMPTOM_ACNE | 1u << SL_SYMPTOM_EXTRA_SHADOW | 1u << SL_SYMPTOM_STALE_DEPTH))
        s |= 1u << SL_SYMPTOM_TOO_DARK;
    if (s & (1u << SL_SYMPTOM_MISSING_SHADOW | 1u << SL_SYMPTOM_DETACHED | 1u << SL_SYMPTOM_NO_SHADOWS))
        s |= 1u << SL_SYMPTOM_TOO_LIGHT;
    if (s & (1u << SL_SYMPTOM_SWAPPED)) s |= 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT;
    if (s & (1u << SL_SYMPTOM_HARD_EDGES)) s |= 1u << SL_SYMPTOM_NARROW_PENUMBRA;
    return s;
}

bool sl_prediction_meets(uint32_t predicts, uint32_t symptoms) {
    symptoms = _sl_with_directions(symptoms);
    predicts = _sl_with_directions(predicts);
    const uint32_t directions = 1u << SL_SYMPTOM_TOO_DARK | 1u << SL_SYMPTOM_TOO_LIGHT |
                                1u << SL_SYMPTOM_NARROW_PENUMBRA | 1u << SL_SYMPTOM_WIDE_PENUMBRA;
    const uint32_t gross = 1u << SL_SYMPTOM_GROSS;
    if ((symptoms & gross) && !(predicts & gross)) return false; /* a small mistake cannot explain a gross symptom */
    if (!(symptoms & directions)) return predicts != 0;          /* the capture says no direction: any mistake */
    return (predicts & symptoms & directions) != 0;
}

bool sl_probe_failure_explains(const sl_case *c, const sl_check *k, const sl_probe_failure *failure, uint32_t symptoms,
                               bool isolated) {
    const sl_probe_function *f = sl_probe_at(failure->function);
    if (!f || f->lab > c->lab) return false;
    if (f->bonus && !k->bonus) return false;       /* an extension never answers for a regular check */
    if (isolated && f->lab != c->lab) return false; /* the solutions stand in for the other labs */
    if (f->lab < c->lab && !sl_lab_shows(c->lab, f->lab)) return false;
    if (!sl_case_runs(c, k, f->name)) return false;
    return sl_prediction_meets(sl_probe_failure_predicts(c, failure), symptoms);
}

bool sl_function_may_be_blamed(const sl_case *c, const sl_check *k, const char *function, bool isolated) {
    if (_sl_is_bonus(function) && !k->bonus) return false;
    const sl_probe_function *f = sl_probe_find(function);
    const sl_lab_function *u = f ? NULL : _sl_unprobed_named(function);
    int lab = f ? f->lab : u ? u->lab : 0;
    if (isolated && lab && lab != c->lab) return false;
    return sl_case_runs(c, k, function);
}
