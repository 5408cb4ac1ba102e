/* sl_json: reading JSON files (scenes, cases, references) with messages that
 * name the file and, for a syntax error, the line. */
#ifndef SL_JSON_H
#define SL_JSON_H

#include <stdbool.h>
#include <stddef.h>

#include <cjson/cJSON.h>

/* The parsed file, or NULL with "PATH: cannot read WHAT file" or
 * "PATH:LINE: invalid JSON" in err. Free with cJSON_Delete. */
cJSON *sl_json_load_file(const char *path, const char *what, char *err, size_t err_size);
/* obj's number `key` into *out where it is there (absent: true, *out untouched); false with
 * "PATH: "KEY" must be a number in [LO, HI]" in err where it is no number or out of range. */
bool sl_json_number(const cJSON *obj, const char *key, double *out, double lo, double hi, const char *path, char *err,
                    size_t n);

/* Makes every string of the tree (values and keys, of item and every item
 * below it) valid UTF-8 of printable characters, newlines and tabs, as
 * sl_utf8_clean does, before it is written: a JSON reader refuses a whole file
 * for one string that is not UTF-8. False where memory ran out (a string then stays as it was). */
bool sl_json_clean_strings(cJSON *item);

#endif
