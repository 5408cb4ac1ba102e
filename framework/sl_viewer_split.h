/* sl_viewer_split: --split A,B, two settings of one scene side by side (private to the viewer's
 * modules). Same camera, same light, same options; each half differs from the other only in what its
 * side names: a lab ("2"), lab 4's filter ("4:pcss") or the lab code ("solutions", in builds that carry
 * both). Each half is the single view's picture of its setting over that half of the frame: the left
 * half draws with the viewer's renderer, the right half with one of its own, both over the whole frame,
 * the right first: its right half waits aside while the left draws, then goes back. A divider and a label on each half go over the seam. */
#ifndef SL_VIEWER_SPLIT_H
#define SL_VIEWER_SPLIT_H

#include <stdio.h>

#include "sl_viewer_state.h"

/* The settings a key may change that --split may hold apart. */
typedef enum _sl_split_setting { _SL_SPLIT_LAB, _SL_SPLIT_FILTER, _SL_SPLIT_CODE } _sl_split_setting;

/* Reads --split's value ("A,B") into v->split; false, said on stderr, when it is not one. */
bool _sl_viewer_split_parse(_sl_viewer *v, const char *text);
/* --help's lines about --split. */
void _sl_viewer_split_usage(FILE *f);
/* Turns the halves on or off (key Y). On: the viewer's settings become the left half's, so keys, the
 * overlay and the title speak of what the left half shows. */
void _sl_viewer_split_show(_sl_viewer *v, bool on);
/* Whether the halves show now and hold `setting` apart: a key that changes it would change one half's
 * setting into the other's, so it does not apply (and this says so on stdout). */
bool _sl_viewer_split_holds(_sl_viewer *v, _sl_split_setting setting);
/* Before the left half's renderer draws the whole frame into `target`: the right half's setting drawn
 * there, its right half kept aside. Turns the halves off, said on stderr, if the right half's renderer
 * cannot be made. */
void _sl_viewer_split_draw_right(_sl_viewer *v, GLuint target, int width, int height);
/* After the left half's renderer drew: the right half put back over it, and the divider. */
void _sl_viewer_split_compose(_sl_viewer *v, GLuint target, int width, int height);
/* The halves' labels into the overlay: what each draws (`left` the left renderer's last frame). */
void _sl_viewer_split_labels(_sl_viewer *v, const sl_frame_info *left, int width, int height);
/* Shaders saved since: the right half's renderer reloads them too. */
void _sl_viewer_split_reload(_sl_viewer *v);
void _sl_viewer_split_destroy(_sl_viewer *v);

#endif
