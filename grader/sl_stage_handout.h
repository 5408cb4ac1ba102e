/* The handout's lab files, read from a stage's stubs (trusted): the lab
 * folders in order, and every stub file a submission may replace
 * (sl_stage.c). */
#ifndef SL_STAGE_HANDOUT_H
#define SL_STAGE_HANDOUT_H

#include <stdbool.h>
#include <stddef.h>

#define _SL_SHADERS_DEPTH 3    /* folders under a lab's shaders/ */
#define _SL_MAX_LABS 16

typedef struct _sl_labs {
    char folder[_SL_MAX_LABS][64]; /* lab1_depth_fbo, ... in order */
    int number[_SL_MAX_LABS];
    int count;
    char (*files)[256]; /* every stub file: "lab1_depth_fbo/lab1.c", "lab1_depth_fbo/shaders/depth.vert" */
    int file_count;
} _sl_labs;

/* Reads the lab folders and their stub files from the stage; false with the reason. */
bool _sl_read_labs(int stage_fd, _sl_labs *labs, char *err, size_t n);

/* The index of lab folder `name` in `labs`, or -1. */
int _sl_lab_index(const _sl_labs *labs, const char *name);

/* A name a staged file may have under shaders/: valid UTF-8 without control
 * characters or separators (spaces and letters of any language are fine). */
bool _sl_stageable_name(const char *name);

#endif
