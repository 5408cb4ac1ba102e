#include "sl_case_probe.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sl_json.h"
#include "sl_probe.h"

/* One row of a probe table: a value for every parameter, by name, in the
 * parameter's order; map parameters name a synthetic map. */
static bool _sl_probe_row(const sl_case *c, sl_check *k, const sl_probe_function *f, const cJSON *row, int r, char *err,
                          size_t n) {
    if (!cJSON_IsObject(row)) {
        snprintf(err, n, "%s: checks \"%s\": rows[%d] must be an object of parameter values", c->path, k->name, r);
        return false;
    }
    const cJSON *item;
    cJSON_ArrayForEach(item, row) {
        bool known = strcmp(item->string, "about") == 0 || strcmp(item->string, "tolerance") == 0 ||
                     strcmp(item->string, "keep") == 0;
        for (int i = 0; i < f->param_count; i++) known |= strcmp(item->string, f->params[i].name) == 0;
        if (!known) {
            snprintf(err, n, "%s: checks \"%s\": rows[%d]: %s() has no parameter \"%s\"", c->path, k->name, r, f->name,
                     item->string);
            return false;
        }
    }
    const char *about = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(row, "about"));
    snprintf(k->about[r], sizeof k->about[r], "%s", about ? about : "");
    const cJSON *tolerance = cJSON_GetObjectItemCaseSensitive(row, "tolerance");
    k->row_tolerance[r] = cJSON_IsNumber(tolerance) && tolerance->valuedouble > 0 ? (float)tolerance->valuedouble : 0;
    /* "keep": true (every parameter), or the names of the parameters a hidden variant leaves as written */
    const cJSON *keep = cJSON_GetObjectItemCaseSensitive(row, "keep");
    if (cJSON_IsTrue(keep)) k->row_keep[r] = 0xffffffffu;
    else if (cJSON_IsArray(keep)) {
        cJSON_ArrayForEach(item, keep) {
            int found = -1;
            for (int i = 0; cJSON_IsString(item) && i < f->param_count; i++)
                if (strcmp(item->valuestring, f->params[i].name) == 0) found = i;
            if (found < 0) {
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"keep\" names parameters of %s()", c->path, k->name, r,
                         f->name);
                return false;
            }
            k->row_keep[r] |= 1u << found;
        }
    } else if (keep && !cJSON_IsFalse(keep)) {
        snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"keep\" is true or a list of parameters", c->path, k->name, r);
        return false;
    }
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        const sl_probe_param *p = &f->params[i];
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(row, p->name);
        int size = sl_probe_type_size(p->type);
        bool ok;
        if (SL_PROBE_IS_MAP(p->type)) {
            int map = cJSON_IsString(v) ? sl_probe_map_parse(v->valuestring) : -1;
            /* a samplerCube takes the cube maps, a sampler2DArray the texture array, a 2D sampler the others */
            sl_probe_type takes = p->type == SL_PROBE_SHADOW_MAP ? SL_PROBE_MAP : p->type;
            ok = map >= 0 && sl_probe_map_type((sl_probe_map)map) == takes;
            k->inputs[r][offset] = (float)map;
        } else if (size == 1) {
            ok = cJSON_IsNumber(v);
            if (ok) k->inputs[r][offset] = (float)v->valuedouble;
        } else {
            ok = cJSON_IsArray(v) && cJSON_GetArraySize(v) == size;
            for (int j = 0; ok && j < size; j++) {
                const cJSON *e = cJSON_GetArrayItem(v, j);
                ok = cJSON_IsNumber(e);
                if (ok) k->inputs[r][offset + j] = (float)e->valuedouble;
            }
        }
        if (!ok) {
            if (p->type == SL_PROBE_CUBE_MAP)
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"%s\" must name a cube map: cube_lit, cube_occluded, "
                         "cube_room or cube_positive", c->path, k->name, r, p->name);
            else if (p->type == SL_PROBE_MOMENTS_MAP)
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"%s\" must name a moments map: moments_flat, "
                         "moments_step_x or moments_step_y", c->path, k->name, r, p->name);
            else if (p->type == SL_PROBE_ARRAY_MAP)
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"%s\" must name a texture array: cascades", c->path,
                         k->name, r, p->name);
            else if (SL_PROBE_IS_MAP(p->type))
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"%s\" must name a map: lit, occluded, step or ramp",
                         c->path, k->name, r, p->name);
            else
                snprintf(err, n, "%s: checks \"%s\": rows[%d]: \"%s\" must be %s", c->path, k->name, r, p->name,
                         size == 1 ? "a number" : size == 16 ? "16 numbers (a column-major matrix)" : "an array of numbers");
            return false;
        }
        offset += size;
    }
    return true;
}

/* "vary": {"param": {"scale": [lo, hi]} | {"add": a or [a0, a1, ...], "homogeneous": true} |
 * {"pick": [v, ...]} | {"turn": degrees}, optionally with "group": "name"}. */
static bool _sl_probe_vary(const sl_case *c, sl_check *k, const sl_probe_function *f, const cJSON *json, char *err,
                           size_t n) {
    const cJSON *vary = cJSON_GetObjectItemCaseSensitive(json, "vary"), *item;
    if (!vary) return true;
    if (!cJSON_IsObject(vary)) {
        snprintf(err, n, "%s: checks \"%s\": \"vary\" must be an object of parameters", c->path, k->name);
        return false;
    }
    cJSON_ArrayForEach(item, vary) {
        int param = -1;
        for (int i = 0; i < f->param_count; i++)
            if (strcmp(item->string, f->params[i].name) == 0) param = i;
        const sl_probe_param *p = param >= 0 ? &f->params[param] : NULL;
        int size = p ? sl_probe_type_size(p->type) : 0;
        sl_probe_vary *v = param >= 0 ? &k->vary[param] : NULL;
        bool ok = v && cJSON_IsObject(item) && !SL_PROBE_IS_MAP(p->type) && size <= 4;
        const cJSON *scale = ok ? cJSON_GetObjectItemCaseSensitive(item, "scale") : NULL;
        const cJSON *add = ok ? cJSON_GetObjectItemCaseSensitive(item, "add") : NULL;
        const cJSON *pick = ok ? cJSON_GetObjectItemCaseSensitive(item, "pick") : NULL;
        const cJSON *turn = ok ? cJSON_GetObjectItemCaseSensitive(item, "turn") : NULL;
        const cJSON *group = ok ? cJSON_GetObjectItemCaseSensitive(item, "group") : NULL;
        if (ok) snprintf(v->group, sizeof v->group, "%s", cJSON_IsString(group) ? group->valuestring : p->name);
        if (ok && scale) {
            v->kind = SL_VARY_SCALE;
            ok = cJSON_IsArray(scale) && cJSON_GetArraySize(scale) == 2 && cJSON_IsNumber(cJSON_GetArrayItem(scale, 0)) &&
                 cJSON_IsNumber(cJSON_GetArrayItem(scale, 1));
            if (ok) {
                v->range[0] = (float)cJSON_GetArrayItem(scale, 0)->valuedouble;
                v->range[1] = (float)cJSON_GetArrayItem(scale, 1)->valuedouble;
                ok = v->range[0] > 0 && v->range[1] >= v->range[0];
            }
        } else if (ok && add) {
            v->kind = SL_VARY_ADD;
            v->homogeneous = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(item, "homogeneous"));
            if (cJSON_IsNumber(add)) {
                for (int j = 0; j < size; j++) v->range[j] = (float)add->valuedouble;
            } else {
                ok = cJSON_IsArray(add) && cJSON_GetArraySize(add) == size;
                for (int j = 0; ok && j < size; j++) {
                    ok = cJSON_IsNumber(cJSON_GetArrayItem(add, j));
                    if (ok) v->range[j] = (float)cJSON_GetArrayItem(add, j)->valuedouble;
                }
            }
            ok &= !v->homogeneous || size == 4;
        } else if (ok && pick) {
            v->kind = SL_VARY_PICK;
            ok = cJSON_IsArray(pick) && cJSON_GetArraySize(pick) >= 1 && cJSON_GetArraySize(pick) <= SL_VARY_MAX_PICKS;
            const cJSON *e, *picks = ok ? pick : NULL;
            cJSON_ArrayForEach(e, picks) {
                float *to = v->picks[v->pick_count++];
                if (size == 1 && cJSON_IsNumber(e)) to[0] = (float)e->valuedouble;
                else if (size > 1 && cJSON_IsArray(e) && cJSON_GetArraySize(e) == size)
                    for (int j = 0; j < size; j++) to[j] = (float)cJSON_GetArrayItem(e, j)->valuedouble;
                else ok = false;
            }
        } else if (ok && turn) {
            v->kind = SL_VARY_TURN;
            ok = cJSON_IsNumber(turn) && size == 3;
            if (ok) v->range[0] = (float)turn->valuedouble;
        } else {
            ok = false;
        }
        if (!ok) {
            snprintf(err, n, "%s: checks \"%s\": \"vary\": \"%s\" must be a number or vector parameter of %s() with "
                             "\"scale\": [lo, hi], \"add\": amplitudes (\"homogeneous\" for a vec4), \"pick\": values, or "
                             "\"turn\": degrees (a vec3)", c->path, k->name, item->string, f->name);
            return false;
        }
    }
    return true;
}

/* A function outside the course's table, described by the case (a technique a build adds, slot 0):
 * "describe": {"lab": 0, "outputs": ["visibility"], "params": [{"name": "x", "type": "vec3"}, ...],
 * "stub": 1, "bonus": false, "file": "...", "todo": "lab0.1"}. Its strings live here, for the
 * grader's whole run. The runner finds the function by name in its own build and refuses a table
 * whose counts are not its function's (sl_probe_pass_run), so a description cannot lie to it. */
typedef struct _sl_described_store {
    sl_probe_function f;
    char name[SL_PROBE_NAME_MAX], outputs[256], file[160], todo[24];
    char params[SL_PROBE_MAX_PARAMS][32];
} _sl_described_store;

static const sl_probe_function *_sl_probe_described(const sl_case *c, sl_check *k, const char *name,
                                                    const cJSON *json, char *err, size_t n) {
    static _sl_described_store stores[SL_PROBE_MAX_DESCRIBED];
    static int store_count;
    static const char *const types[] = {"float", "int", "vec2", "vec3", "vec4", "mat4", "map", "shadow_map",
                                        "cube_map", "array_map", "moments_map"};
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(json, "describe");
    if (!d) return NULL;
    if (store_count == SL_PROBE_MAX_DESCRIBED) {
        snprintf(err, n, "%s: checks \"%s\": more than %d functions described", c->path, k->name,
                 SL_PROBE_MAX_DESCRIBED);
        return NULL;
    }
    _sl_described_store *st = &stores[store_count];
    memset(st, 0, sizeof *st);
    sl_probe_function *f = &st->f;
    const cJSON *lab = cJSON_GetObjectItemCaseSensitive(d, "lab");
    const cJSON *outputs = cJSON_GetObjectItemCaseSensitive(d, "outputs");
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(d, "params"), *item;
    const cJSON *stub = cJSON_GetObjectItemCaseSensitive(d, "stub");
    const char *file = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(d, "file"));
    const char *todo = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(d, "todo"));
    bool ok = cJSON_IsObject(d) && strlen(name) < sizeof st->name && cJSON_IsNumber(lab) && lab->valueint == c->lab &&
              cJSON_IsArray(outputs) && cJSON_GetArraySize(outputs) >= 1 &&
              cJSON_GetArraySize(outputs) <= SL_PROBE_MAX_OUTPUTS && (!params || cJSON_IsArray(params)) &&
              (!params || cJSON_GetArraySize(params) <= SL_PROBE_MAX_PARAMS) && (!stub || cJSON_IsNumber(stub));
    const cJSON *output_list = ok ? outputs : NULL, *param_list = ok ? params : NULL;
    cJSON_ArrayForEach(item, output_list) {
        ok &= cJSON_IsString(item) && strlen(st->outputs) + strlen(item->valuestring) + 2 < sizeof st->outputs;
        if (ok) snprintf(st->outputs + strlen(st->outputs), sizeof st->outputs - strlen(st->outputs), "%s%s",
                         f->output_count ? "," : "", item->valuestring);
        f->output_count++;
    }
    if (!ok) param_list = NULL;
    cJSON_ArrayForEach(item, param_list) {
        const char *pname = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(item, "name"));
        const char *type = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(item, "type"));
        int found = -1;
        for (int i = 0; type && i < (int)(sizeof types / sizeof types[0]); i++)
            if (strcmp(type, types[i]) == 0) found = i;
        ok &= pname && found >= 0 && strlen(pname) < sizeof st->params[0];
        if (!ok) break;
        snprintf(st->params[f->param_count], sizeof st->params[0], "%s", pname);
        f->params[f->param_count] = (sl_probe_param){st->params[f->param_count], (sl_probe_type)found};
        f->param_count++;
    }
    if (ok && sl_probe_input_count(f) > SL_PROBE_MAX_INPUTS) ok = false;
    if (!ok) {
        snprintf(err, n, "%s: checks \"%s\": \"describe\" must give %s()'s \"lab\" (the case's), \"outputs\" "
                         "(1..%d names), \"params\" ([{\"name\", \"type\": float, int, vec2, vec3, vec4, mat4 or a "
                         "map}], at most %d floats a row) and optionally \"stub\", \"bonus\", \"file\", \"todo\"",
                 c->path, k->name, name, SL_PROBE_MAX_OUTPUTS, SL_PROBE_MAX_INPUTS);
        return NULL;
    }
    snprintf(st->name, sizeof st->name, "%s", name);
    snprintf(st->file, sizeof st->file, "%s", file ? file : "");
    snprintf(st->todo, sizeof st->todo, "%s", todo ? todo : "");
    f->name = st->name;
    f->lab = c->lab;
    f->outputs = st->outputs;
    f->file = st->file;
    f->todo = st->todo;
    f->stub_value = stub ? stub->valuedouble : NAN;
    f->stub_param = -1;
    f->bonus = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(d, "bonus"));
    const sl_probe_function *described = sl_probe_describe(f);
    if (described) store_count++; /* its copy points at this store's strings */
    return described;
}

/* "above": {"output": amount}: the output may also be up to amount above the expected value (an output
 * the README lets students round up; below it, the usual tolerance alone). */
static bool _sl_probe_above(const sl_case *c, sl_check *k, const sl_probe_function *f, const cJSON *json, char *err,
                            size_t n) {
    const cJSON *above = cJSON_GetObjectItemCaseSensitive(json, "above"), *item;
    if (!above) return true;
    if (!cJSON_IsObject(above)) {
        snprintf(err, n, "%s: checks \"%s\": \"above\" must be an object: {\"output\": amount}", c->path, k->name);
        return false;
    }
    cJSON_ArrayForEach(item, above) {
        int found = -1;
        const char *name = f->outputs;
        for (int o = 0; o < f->output_count && name; o++) {
            size_t len = strcspn(name, ",");
            if (strlen(item->string) == len && strncmp(name, item->string, len) == 0) found = o;
            name = strchr(name, ',');
            if (name) name++;
        }
        if (found < 0 || !cJSON_IsNumber(item) || !(item->valuedouble >= 0) || item->valuedouble > 1e6) {
            snprintf(err, n, "%s: checks \"%s\": \"above\": \"%s\" must be an output of %s() (%s) with an amount "
                             "from 0 to 1e6", c->path, k->name, item->string, f->name, f->outputs);
            return false;
        }
        k->above[found] = (float)item->valuedouble;
    }
    return true;
}

bool sl_case_probe_check(const sl_case *c, sl_check *k, const cJSON *json, char *err, size_t n) {
    const char *name = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(json, "function"));
    const sl_probe_function *f = name ? sl_probe_find(name) : NULL;
    err[0] = '\0';
    if (!f && name) f = _sl_probe_described(c, k, name, json, err, n);
    if (!f) {
        if (!err[0])
            snprintf(err, n, "%s: checks \"%s\": \"function\" must name a lab function, or describe one of a "
                             "technique outside the course (%s is none)", c->path, k->name, name ? name : "nothing");
        return false;
    }
    k->function = sl_probe_index(f);
    k->tolerance = 1e-4;
    k->relative = 1e-3;
    if (!sl_json_number(json, "tolerance", &k->tolerance, 0, 1e9, c->path, err, n) ||
        !sl_json_number(json, "relative", &k->relative, 0, 1, c->path, err, n))
        return false;
    if (!_sl_probe_above(c, k, f, json, err, n)) return false;
    const cJSON *rows = cJSON_GetObjectItemCaseSensitive(json, "rows"), *row;
    if (!cJSON_IsArray(rows) || cJSON_GetArraySize(rows) < 1 || cJSON_GetArraySize(rows) > SL_PROBE_MAX_ROWS) {
        snprintf(err, n, "%s: checks \"%s\": \"rows\" must be 1..%d rows of inputs", c->path, k->name, SL_PROBE_MAX_ROWS);
        return false;
    }
    cJSON_ArrayForEach(row, rows) {
        if (!_sl_probe_row(c, k, f, row, k->rows, err, n)) return false;
        k->rows++;
    }
    return _sl_probe_vary(c, k, f, json, err, n);
}
