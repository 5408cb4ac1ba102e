/* sl_probe_calls: the probe rows of the labs' C functions. Each runs one row of
 * its function's probe table (sl_probe.h) on this build's lab code and reads
 * back what the function returned or the GL state it set. Each lab's list is
 * its technique's probes (sl_technique.h); the probe pass walks the table to
 * find them (sl_probe_pass.h). */
#ifndef SL_PROBE_CALLS_H
#define SL_PROBE_CALLS_H

#include "sl_technique.h"

/* Ended by an entry whose function is NULL. */
extern const sl_technique_probe sl_lab1_probes[];
extern const sl_technique_probe sl_lab2_probes[];
extern const sl_technique_probe sl_lab3_probes[];
extern const sl_technique_probe sl_lab4_probes[];
extern const sl_technique_probe sl_lab5_probes[];
extern const sl_technique_probe sl_lab6_probes[];
extern const sl_technique_probe sl_lab7_probes[];

#endif
