/* sl_viewer: the interactive viewer (and its unattended mode for screenshots).
 * The framework owns main(): shadowlab's main() only calls sl_viewer_main(). */
#ifndef SL_VIEWER_H
#define SL_VIEWER_H

#include "sl_labs.h"

int sl_viewer_main(int argc, char **argv);

/* A second set of lab code the viewer can switch to (the A key, --solutions):
 * the solutions beside a student build, for course staff and lectures. Call
 * before sl_viewer_main; `labs_dir` is that code's tree (its shaders). */
void sl_viewer_set_second_labs(const sl_lab_functions *functions, const char *labs_dir, const char *kind);

#endif
