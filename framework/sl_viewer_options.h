/* sl_viewer_options: the viewer's command line (private to the viewer's modules): --help and
 * the options, into the viewer's state and what the main loop needs besides. */
#ifndef SL_VIEWER_OPTIONS_H
#define SL_VIEWER_OPTIONS_H

#include "sl_viewer_state.h"

typedef struct _sl_viewer_options {
    const char *scene_name, *screenshot, *labs_dir, *case_name, *check_name, *serve_address;
    int frames, width, height;
    int overlay_option; /* --overlay 1, --no-overlay 0, default -1 */
    int serve_port;
    bool headless, lab_given;
    bool freeze; /* lab 6 */
    bool gif;    /* --screenshot FILE.gif */
    sl_backend backend;
    float light_size;
} _sl_viewer_options;

/* Reads the options into v and o: -1 to go on, else the exit status (0 after --help or --list-keys,
 * 2 after a bad option, said on stderr). */
int _sl_viewer_options_parse(int argc, char **argv, _sl_viewer *v, _sl_viewer_options *o);

#endif
