/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The extrema stage's private interface (extrema.c): the run rule of
 * docs/algorithm.md over whole rows, for the public symline_extrema_row() and
 * symline_extrema(). The detector decides its extrema at the line filter's
 * candidates instead (linepoints.c, the same rule entry by entry).
 */
#ifndef SYMLINE_LIB_EXTREMA_H
#define SYMLINE_LIB_EXTREMA_H

#include "common.h"
#include "symline/extrema.h"

/* Plateau limit of symline_i_extrema_runs() that marks runs of any length. */
#define SL_RUN_ANY_LENGTH UINT32_MAX

/* Entries of one call of symline_i_extrema_along() or _across() at most,
 * and the 32-bit words of their plateau masks (on the caller's stack): 256
 * where SIMD versions decide them (fewer calls), else 32. */
#ifdef SYMLINE_PORT_EXTREMA_ROWS
#define SL_KINDS_MAX 256u
#else
#define SL_KINDS_MAX 32u
#endif
#define SL_KINDS_WORDS (SL_KINDS_MAX / 32u)

/*
 * The run rule where runs are single entries, for 1 <= n <= SL_KINDS_MAX
 * entries at once: map[x] = S where the energy of entry x is below both its
 * neighbours', A where it is above both, NONE otherwise. The plateau mask
 * ev[0 .. (n+31)/32 - 1]: bit x % 32 of ev[x / 32] is set where the energy
 * equals exactly one neighbour's, that is where a run of equal energies
 * begins or ends, which the caller decides on its slow path (map[x] is NONE
 * there); the bits of a run's inner entries stay clear. Both return the OR
 * of those words: nonzero when the block has such an entry. Energies below
 * 2^31.
 *
 * symline_i_extrema_along(): along a row, the neighbours of E[x] are E[x-1]
 * and E[x+1] (E[-1] and E[n] are read).
 * symline_i_extrema_across(): down the columns, the neighbours of mid[x] are
 * the row above, known by sg[x] = the sign of mid[x] - up[x] (-1, 0, +1;
 * 0 where there is no row above), and dn[x]; sg[x] becomes the sign of
 * dn[x] - mid[x], the next row's. So each difference is taken once.
 *
 * The _c versions are the portable references; the others are the build's
 * choice: SIMD versions from port/ (SYMLINE_PORT_EXTREMA_ROWS, CMake option
 * SYMLINE_SIMD) with the same output, or the references.
 */
uint32_t symline_i_extrema_along_c(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                   uint32_t *restrict ev);
uint32_t symline_i_extrema_along(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                 uint32_t *restrict ev);
uint32_t symline_i_extrema_across_c(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                    int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                    uint32_t *restrict ev);
uint32_t symline_i_extrema_across(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                  int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                  uint32_t *restrict ev);
#ifndef SYMLINE_PORT_EXTREMA_ROWS /* no SIMD versions: the references */
#define symline_i_extrema_along symline_i_extrema_along_c
#define symline_i_extrema_across symline_i_extrema_across_c
#endif

/*
 * Extrema of a row of n >= 1 energies into map (n entries: NONE, A or S) by
 * the run rule: a run of equal energies with larger neighbours on both sides
 * is an S point at its middle (lower middle for even lengths), with smaller
 * neighbours an A point; runs touching either end are never marked. A run
 * whose middle lies more than `lag` entries before its end is not marked
 * either (a plateau limit like the detector's; SL_RUN_ANY_LENGTH, what the
 * public calls pass, for none).
 */
void symline_i_extrema_runs(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map);

/*
 * Extrema down the columns, one row at a time: the state of a frame's or a
 * ring's map. Energies of row y live in E3 + (y % 3) * width; map row y at
 * map + (y % ring) * stride (ring: rows held, at least lag + 2). sg: 2 x
 * width entries, the signs of the last two rows' differences
 * (symline_i_extrema_across()), then how each column's plateau was entered;
 * run_start (width entries): where it began.
 */
typedef struct symline_i_coldown {
    uint32_t *E3;
    int8_t *sg;
    uint16_t *run_start;
    uint8_t *map;
    uint32_t stride, width, ring, lag;
} symline_i_coldown;

/*
 * Row t >= 1 of energies E (row t % 3 of cd->E3, rows t-1 and t-2 held there too)
 * has arrived: writes the whole map row t-1 (row 0: NONE) and marks the
 * plateaus that end at t-1 at their middle rows, if no more than lag rows
 * above t-1. Runs touching the bottom row are never marked; the caller
 * clears the last row.
 */
void symline_i_extrema_down(const symline_i_coldown *cd, const uint32_t *E, uint32_t t);

#endif /* SYMLINE_LIB_EXTREMA_H */
