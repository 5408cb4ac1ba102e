#include "sl_json.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_utf8.h"

static char *_sl_read_text(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *text = NULL;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size >= 0 && fseek(f, 0, SEEK_SET) == 0) text = malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text) text[size] = '\0';
    fclose(f);
    return text;
}

cJSON *sl_json_load_file(const char *path, const char *what, char *err, size_t err_size) {
    char *text = _sl_read_text(path);
    if (!text) {
        snprintf(err, err_size, "%s: cannot read %s file", path, what);
        return NULL;
    }
    cJSON *json = cJSON_Parse(text);
    if (!json) {
        const char *at = cJSON_GetErrorPtr();
        int line = 1;
        for (const char *p = text; at && p < at && *p; p++) line += *p == '\n';
        snprintf(err, err_size, "%s:%d: invalid JSON", path, line);
    }
    free(text);
    return json;
}

bool sl_json_number(const cJSON *obj, const char *key, double *out, double lo, double hi, const char *path, char *err,
                    size_t n) {
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v) return true;
    if (!cJSON_IsNumber(v) || v->valuedouble < lo || v->valuedouble > hi) {
        snprintf(err, n, "%s: \"%s\" must be a number in [%g, %g]", path, key, lo, hi);
        return false;
    }
    *out = v->valuedouble;
    return true;
}

/* A string of the tree made clean, replaced where it is not. */
static bool _sl_clean_string(char **text) {
    size_t len = strlen(*text);
    if (sl_utf8_is_clean(*text, len, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB)) return true;
    size_t size = 3 * len + 1; /* at most U+FFFD for every byte */
    char *clean = cJSON_malloc(size);
    if (!clean) return false;
    sl_utf8_clean(clean, size, *text, len, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB);
    cJSON_free(*text);
    *text = clean;
    return true;
}

bool sl_json_clean_strings(cJSON *item) {
    if (!item) return true;
    bool ok = true;
    if (item->string && !(item->type & cJSON_StringIsConst)) ok = _sl_clean_string(&item->string);
    if (cJSON_IsString(item) && item->valuestring) ok = _sl_clean_string(&item->valuestring) && ok;
    for (cJSON *child = item->child; child; child = child->next) ok = sl_json_clean_strings(child) && ok;
    return ok;
}
