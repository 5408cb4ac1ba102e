/* Attack (compile time): the solution's lab 3, #included by a path relative to
 * this file's own folder, climbing out of the labs tree to the project (a
 * submission built inside the course's tree). Stubs where it cannot be seen. */
#include "shadowlab.h"

#if __has_include("@RELATIVE_SOURCE_DIR@/solutions/lab3_bias/lab3.c")
#include "@RELATIVE_SOURCE_DIR@/solutions/lab3_bias/lab3.c"
#else
sl_status lab3_depth_pass_state(const sl_bias_settings *bias) { return SL_NOT_IMPLEMENTED; }
sl_status lab3_second_depth_state(void) { return SL_NOT_IMPLEMENTED; }
#endif
