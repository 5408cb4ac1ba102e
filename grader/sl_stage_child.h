/* The process that reads a submission (sl_stage.c): behind its fence it
 * chooses the lab files by the submission's layout and sends them, and what
 * it left out, over the channel. */
#ifndef SL_STAGE_CHILD_H
#define SL_STAGE_CHILD_H

#include "sl_stage_desc.h"
#include "sl_stage_handout.h"

/* The child's whole life: opens the submission, enters the fence, sends what it chose; never returns. */
void _sl_child_main(const sl_stage_desc *d, const _sl_labs *labs, int channel);

#endif
