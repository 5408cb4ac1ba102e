/* Preloaded into shadowlab-grade by tests/exit_statuses.sh: a library whose
 * exit-time clean-up crashes (as a C++ library's static destructors can). The
 * grader's status must stay the grade's, never the crash's 128 + 11. */
#include <signal.h>

__attribute__((destructor)) static void _sl_crash_at_exit(void) { raise(SIGSEGV); }
