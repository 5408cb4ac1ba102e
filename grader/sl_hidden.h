/* sl_hidden: hidden cases for course staff (shadowlab-grade --hidden --seed S).
 *
 * Every public case is turned into a variant drawn from the seed: the light
 * turns about the vertical and tilts a little, the camera orbits its target,
 * the objects standing on the ground move and turn together, and the shadow
 * map takes another size. Each change stays within bounds that keep what the
 * case tests (a grazing light stays grazing, a contact stays a contact). The
 * same seed gives the same cases, whatever else is selected: each case draws
 * from its own stream (splitmix64 seeded from the seed and the case's name).
 *
 * Cases with a penumbra check keep their light and objects, so the shadow stays
 * where its probe lines cross it; their camera still moves, and the lines, which
 * lie on the ground, are carried into the new image. Function probes keep their
 * tables: each row is an edge case someone chose.
 *
 * The references are rendered on the spot from the solutions, into a private
 * folder (mode 0700, removed afterwards) with its manifest, then read and
 * verified like the public ones. */
#ifndef SL_HIDDEN_H
#define SL_HIDDEN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "sl_case.h"
#include "sl_run.h"

typedef struct sl_hidden {
    uint64_t seed;
    char references_dir[64]; /* "" until sl_hidden_open */
} sl_hidden;

/* Reads a seed: decimal digits, at most 2^64 - 1. */
bool sl_hidden_parse_seed(const char *text, uint64_t *seed);

/* Derives one case from the seed, in place; `note` says what changed. */
void sl_hidden_derive(sl_case *c, uint64_t seed, char *note, size_t note_size);

/* The private folder the references go to: nobody but the grader's user may
 * read it (a runner in the uid sandbox cannot; in namespaces it sees no /tmp
 * but its own). */
bool sl_hidden_open(sl_hidden *hidden, uint64_t seed, char *err, size_t err_size);

/* Renders the references of `cases` with the solutions' runner (`solutions`
 * has it as setups[0]) and writes them with their manifest. False, with the
 * reason, when a case did not finish or a file could not be written. */
bool sl_hidden_render_references(const sl_hidden *hidden, const sl_case *cases, int count,
                                 const sl_run_options *solutions, volatile int *stop, char *err, size_t err_size);

/* Removes the folder and everything in it. */
void sl_hidden_close(sl_hidden *hidden);

#endif
