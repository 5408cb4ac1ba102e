#include "sl_diag_words.h"

const char *sl_diag_darkening_word(double mean_visibility) {
    double lost = 1.0 - mean_visibility;
    if (lost < SL_DIAG_SLIGHT_LOSS) return "slightly";
    if (lost < SL_DIAG_NOTICEABLE_LOSS) return "noticeably";
    return "strongly";
}
