#include "sl_case_result.h"

#include <string.h>

const char *sl_result_gl_error(const sl_case_result *r, const char *function) {
    for (int i = 0; r && function && i < r->gl_error_count; i++)
        if (strcmp(r->gl_error_function[i], function) == 0) return r->gl_error[i];
    return NULL;
}

const sl_capture *sl_result_capture(const sl_case_result *r, const char *name) {
    for (int i = 0; i < r->capture_count; i++)
        if (strcmp(r->captures[i].name, name) == 0) return &r->captures[i];
    return NULL;
}

void sl_case_result_free(sl_case_result *r) {
    for (int i = 0; i < r->capture_count; i++) sl_image_free(&r->captures[i].image);
    r->capture_count = 0;
}
