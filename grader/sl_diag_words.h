/* sl_diag_words: the words a message chooses for what it measured, so that
 * every lab says them the same way: how large an effect is. */
#ifndef SL_DIAG_WORDS_H
#define SL_DIAG_WORDS_H

#include <stdbool.h>
#include <stddef.h>

/* How much light a surface lit in the reference lost, as one word. Below
 * SL_DIAG_SLIGHT_LOSS of the light (a mean visibility above 0.9) "slightly",
 * below SL_DIAG_NOTICEABLE_LOSS "noticeably", from there on "strongly". */
#define SL_DIAG_SLIGHT_LOSS 0.10
#define SL_DIAG_NOTICEABLE_LOSS 0.30
const char *sl_diag_darkening_word(double mean_visibility);

#endif
