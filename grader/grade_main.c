/* shadowlab-grade: the headless grader. All of it lives in grader/sl_grader.c. */
#include "sl_grader.h"

int main(int argc, char **argv) { return sl_grader_main(argc, argv); }
