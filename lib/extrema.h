/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The extrema stage's private interface (extrema.c): the one routine for the
 * run rule of docs/algorithm.md along a row, used by the public
 * symline_extrema_row() and by the detector's line point collection
 * (linepoints.c).
 */
#ifndef SYMLINE_LIB_EXTREMA_H
#define SYMLINE_LIB_EXTREMA_H

#include "common.h"
#include "symline/extrema.h"

/* Plateau limit of symline_i_extrema_runs() that marks runs of any length. */
#define SL_RUN_ANY_LENGTH UINT32_MAX

/*
 * Extrema of a row of n >= 1 energies into map (n entries: NONE, A or S) by
 * the run rule: a run of equal energies with larger neighbours on both sides
 * is an S point at its middle (lower middle for even lengths), with smaller
 * neighbours an A point; runs touching either end are never marked. A run
 * whose middle lies more than `lag` entries before its end is not marked
 * either (the detector's plateau limit; SL_RUN_ANY_LENGTH for none).
 */
void symline_i_extrema_runs(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map);

#endif /* SYMLINE_LIB_EXTREMA_H */
