/* sl_json: reading JSON files (scenes, cases, references) with messages that
 * name the file and, for a syntax error, the line. */
#ifndef SL_JSON_H
#define SL_JSON_H

#include <stddef.h>

#include <cjson/cJSON.h>

/* The parsed file, or NULL with "PATH: cannot read WHAT file" or
 * "PATH:LINE: invalid JSON" in err. Free with cJSON_Delete. */
cJSON *sl_json_load_file(const char *path, const char *what, char *err, size_t err_size);

#endif
