/* sl_data_url: an image as a "data:image/png;base64,..." URL, for results
 * files that carry their pictures inline (PrairieLearn shows a test's images
 * from such URLs; its results.json must stay under 1 MB). */
#ifndef SL_DATA_URL_H
#define SL_DATA_URL_H

#include <stddef.h>

#include "sl_image.h"

/* The image as a PNG data URL (malloc'd, free it), or NULL when it cannot be
 * written or its URL would be longer than max_length characters. */
char *sl_image_data_url(const sl_image *image, size_t max_length);

#endif
