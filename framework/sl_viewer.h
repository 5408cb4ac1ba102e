/* sl_viewer: the interactive viewer (and its unattended mode for screenshots).
 * The framework owns main(): shadowlab's main() only calls sl_viewer_main(). */
#ifndef SL_VIEWER_H
#define SL_VIEWER_H

int sl_viewer_main(int argc, char **argv);

#endif
