/* shadowlab: the viewer. All of it lives in the framework (sl_viewer.c). */
#include "sl_viewer.h"

int main(int argc, char **argv) { return sl_viewer_main(argc, argv); }
