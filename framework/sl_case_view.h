/* sl_case_view: the viewer's `--case NAME`: renders exactly what the grader
 * renders for one grading case (scene, camera, light path, parameters, image
 * size, the term it captures), with this build's labs, and shows it beside
 * the shipped reference and their difference, coloured by kind: red where a
 * shadow is missing, blue where there is one too many. Every check with a
 * picture can be shown (C cycles them): visibility, shaded image, depth map,
 * lab 5's moments, lab 6's cascade index, lab 7's cube faces. It re-renders
 * every frame, so an edited shader shows at once. */
#ifndef SL_CASE_VIEW_H
#define SL_CASE_VIEW_H

#include <stdbool.h>

typedef struct sl_case_view_desc {
    const char *case_name;      /* a case file's name (grader/cases/NAME.json) or a path */
    const char *cases_dir;      /* default: this source tree's grader/cases */
    const char *references_dir; /* default: grader/references */
    const char *labs_dir;       /* NULL: the build's */
    bool headless;
    int backend;                /* sl_backend, headless only */
    int frames;                 /* > 0: render that many frames and stop */
    const char *screenshot;     /* with frames: save the last one */
    const char *check_name;     /* the check to show first (NULL: the case's first with a picture) */
} sl_case_view_desc;

/* A process exit status: 0, 1 on failure (said on stderr), 2 on a usage error. */
int sl_case_view_main(const sl_case_view_desc *desc);

/* The keys of the case view, for the viewer's --help: the keys as written and
 * what they do; the list ends with a NULL `names`. */
typedef struct sl_case_view_key {
    const char *names, *help;
} sl_case_view_key;
const sl_case_view_key *sl_case_view_keys(void);

#endif
