#include "sl_manifest.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "sl_files.h"
#include "sl_json.h"
#include "sl_sha256.h"

struct sl_manifest {
    cJSON *root;
    char path[1100];
};

sl_manifest *sl_manifest_load(const char *dir, bool create, char *err, size_t n) {
    sl_manifest *m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(err, n, "out of memory");
        return NULL;
    }
    snprintf(m->path, sizeof m->path, "%s/%s", dir, SL_MANIFEST_FILE);
    struct stat st;
    if (stat(m->path, &st) != 0 && create) {
        m->root = cJSON_CreateObject();
        cJSON_AddNumberToObject(m->root, "format", 1);
        cJSON_AddObjectToObject(m->root, "cases");
        return m;
    }
    char json_err[1200];
    m->root = sl_json_load_file(m->path, "references manifest", json_err, sizeof json_err);
    if (!m->root || !cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(m->root, "cases"))) {
        snprintf(err, n, "%s", m->root ? "references manifest has no \"cases\"" : json_err);
        if (m->root) snprintf(err, n, "%s: no \"cases\" object", m->path);
        sl_manifest_free(m);
        return NULL;
    }
    return m;
}

void sl_manifest_free(sl_manifest *m) {
    if (!m) return;
    cJSON_Delete(m->root);
    free(m);
}

static cJSON *_sl_case_entry(const sl_manifest *m, const char *case_name) {
    return cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(m->root, "cases"), case_name);
}

const char *sl_manifest_hash(const sl_manifest *m, const char *case_name, const char *file) {
    return cJSON_GetStringValue(
        cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(_sl_case_entry(m, case_name), "files"), file));
}

bool sl_manifest_verify(const sl_manifest *m, const char *case_name, const char *file, const char *path, char *why,
                        size_t n) {
    const char *recorded = sl_manifest_hash(m, case_name, file);
    if (!recorded) {
        snprintf(why, n, "reference not in the manifest: %s (%s lists no %s/%s; staff: --update-references)", path,
                 m->path, case_name, file);
        return false;
    }
    char hash[65];
    if (!sl_sha256_file(path, hash)) {
        snprintf(why, n, "reference unreadable: %s (%s)", path, strerror(errno));
        return false;
    }
    if (strcmp(hash, recorded) != 0) {
        snprintf(why, n, "reference changed since it was made: %s (its SHA-256 is not the one in %s; staff: "
                         "--update-references renders it again from the solutions)", path, m->path);
        return false;
    }
    return true;
}

double sl_manifest_cpu_seconds(const sl_manifest *m, const char *case_name) {
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(_sl_case_entry(m, case_name), "cpu_seconds");
    return cJSON_IsNumber(v) && v->valuedouble > 0 ? v->valuedouble : 0;
}

void sl_manifest_forget_case(sl_manifest *m, const char *case_name) {
    cJSON_DeleteItemFromObjectCaseSensitive(cJSON_GetObjectItemCaseSensitive(m->root, "cases"), case_name);
}

bool sl_manifest_record(sl_manifest *m, const char *case_name, const char *file, const char *path,
                        double cpu_seconds, char *err, size_t n) {
    char hash[65];
    if (!sl_sha256_file(path, hash)) {
        snprintf(err, n, "%s: cannot read it back (%s)", path, strerror(errno));
        return false;
    }
    cJSON *cases = cJSON_GetObjectItemCaseSensitive(m->root, "cases");
    cJSON *entry = cJSON_GetObjectItemCaseSensitive(cases, case_name);
    if (!entry) entry = cJSON_AddObjectToObject(cases, case_name);
    cJSON_DeleteItemFromObjectCaseSensitive(entry, "render_seconds"); /* a frame's time as the runner said it, once */
    cJSON_DeleteItemFromObjectCaseSensitive(entry, "cpu_seconds");
    /* rounded up to a millisecond: noise below it does not matter */
    cJSON_AddNumberToObject(entry, "cpu_seconds", ceil(cpu_seconds * 1000) / 1000);
    cJSON *files = cJSON_GetObjectItemCaseSensitive(entry, "files");
    if (!files) files = cJSON_AddObjectToObject(entry, "files");
    cJSON_DeleteItemFromObjectCaseSensitive(files, file);
    cJSON_AddStringToObject(files, file, hash);
    return true;
}

const char *sl_manifest_renderer(const sl_manifest *m) {
    const char *r = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(m->root, "renderer"));
    return r ? r : "";
}

void sl_manifest_set_renderer(sl_manifest *m, const char *renderer) {
    cJSON_DeleteItemFromObjectCaseSensitive(m->root, "renderer");
    cJSON_AddStringToObject(m->root, "renderer", renderer);
}

bool sl_manifest_save(const sl_manifest *m, const char *dir, char *err, size_t n) {
    (void)dir;
    char *text = cJSON_Print(m->root);
    if (!text) {
        snprintf(err, n, "%s: out of memory", m->path);
        return false;
    }
    sl_atomic_file f;
    bool ok = sl_atomic_open(&f, m->path, err, n);
    if (ok) {
        fputs(text, f.f);
        fputc('\n', f.f);
        ok = sl_atomic_commit(&f, err, n);
    }
    free(text);
    return ok;
}
