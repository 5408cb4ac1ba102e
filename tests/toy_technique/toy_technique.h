/* The test technique, "lab 0": a plane drawn with one constant visibility.
 * It is not a lab of the course: it shows, and its test keeps true, that a
 * technique is added through the technique table alone, without a line in
 * the renderer, the viewer or the grader (docs/adding-a-technique.md). */
#ifndef TOY_TECHNIQUE_H
#define TOY_TECHNIQUE_H

#include "sl_technique.h"

/* The toy's one function, the one its probe calls: the visibility of every
 * point of the plane (0: in shadow, 1: lit). */
sl_status toy_visibility(float *visibility);

/* Its descriptor: the build puts it in slot 0 of the table (sl_labs_program's TECHNIQUE). */
extern const sl_technique toy_technique;

#endif
