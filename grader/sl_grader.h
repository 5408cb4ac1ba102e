/* sl_grader: shadowlab-grade's command line. The framework owns main():
 * shadowlab-grade's main() only calls sl_grader_main(). */
#ifndef SL_GRADER_H
#define SL_GRADER_H

int sl_grader_main(int argc, char **argv);

#endif
