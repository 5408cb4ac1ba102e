#include "sl_diag_words.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define _SL_PI 3.14159265358979323846

const char *sl_diag_darkening_word(double mean_visibility) {
    double lost = 1.0 - mean_visibility;
    if (lost < SL_DIAG_SLIGHT_LOSS) return "slightly";
    if (lost < SL_DIAG_NOTICEABLE_LOSS) return "noticeably";
    return "strongly";
}

const char *sl_diag_shadowed_share_words(double fraction_of_lit) {
    return fraction_of_lit >= SL_DIAG_ALMOST_ALL ? "almost everything" : "most of the lit area";
}

double sl_diag_perspective_fov_deg(double m11) {
    if (!isfinite(m11) || m11 == 0) return NAN;
    double half = atan(1.0 / m11); /* (-90, 90) degrees: a negative m11 is a half-angle past 90 */
    if (half < 0) half += _SL_PI;
    return 2 * half * 180 / _SL_PI;
}

/* Does m11 come from glm_perspective(fovy_radians)? Compared as the matrix holds it: tan folds the angle,
 * so 90 radians is the same matrix as 90 - 28 pi, and only m11 itself tells the two readings apart. */
static bool _sl_m11_of(double m11, double fovy_radians) {
    double want = 1.0 / tan(fovy_radians / 2);
    return isfinite(want) && fabs(m11 - want) <= 1e-3 * fmax(1.0, fabs(want));
}

bool sl_diag_angle_slip(double m11, double expected_deg, const char *expression, char *text, size_t n) {
    if (!isfinite(m11) || !isfinite(expected_deg) || expected_deg <= 0) return false;
    double in_radians = expected_deg * _SL_PI / 180;
    /* a right answer is no slip, even where a slip's matrix happens to be close */
    if (_sl_m11_of(m11, in_radians)) return false;
    /* "90.0f" is the number itself; "2 * spot_angle_deg" is named with its value */
    char *end = NULL;
    strtod(expression, &end);
    bool literal = end != expression && (*end == '\0' || ((*end == 'f' || *end == 'F') && end[1] == '\0'));
    char value[96];
    if (literal) snprintf(value, sizeof value, "%.4g", expected_deg);
    else snprintf(value, sizeof value, "%s = %.4g", expression, expected_deg);
    if (_sl_m11_of(m11, expected_deg)) {
        snprintf(text, n, "%s was passed as radians: use glm_rad(%s)", value, expression);
        return true;
    }
    if (_sl_m11_of(m11, in_radians * _SL_PI / 180)) {
        snprintf(text, n, "glm_rad was applied twice: %s degrees became %.3g degrees; use glm_rad(%s) once", value,
                 expected_deg * _SL_PI / 180, expression);
        return true;
    }
    return false;
}
