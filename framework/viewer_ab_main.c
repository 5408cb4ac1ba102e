/* shadowlab, the viewer of a student build that also carries the solutions'
 * lab code (key U, --solutions): that code is compiled a second time with
 * every lab function renamed (see "Viewer: student vs solutions" in the top
 * CMakeLists.txt), so both sets live in this one program. */
#include "sl_viewer.h"

extern const sl_lab_functions sl_second_lab_functions;

int main(int argc, char **argv) {
    sl_viewer_set_second_labs(&sl_second_lab_functions, SL_SECOND_LABS_DIR, "solutions");
    return sl_viewer_main(argc, argv);
}
