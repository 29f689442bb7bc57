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
 * The run rule where runs are single entries, over whole rows in 32-bit
 * lanes: map[x] = S where mid[x] is below both up[x] and dn[x], A where it
 * is above both, NONE otherwise (n entries). Returns nonzero when some mid[x]
 * equals up[x] or dn[x]: a plateau, which the caller decides on its slow path
 * (map[x] is NONE there). Rows of a frame (extrema down the columns) or one
 * row shifted by one entry (along it). Energies below 2^31.
 * symline_i_extrema_kinds_c() is the portable reference; symline_i_extrema_kinds()
 * is the build's choice: a SIMD version from port/ (SYMLINE_PORT_EXTREMA_KINDS,
 * CMake option SYMLINE_SIMD) with the same output, or the reference.
 */
uint32_t symline_i_extrema_kinds_c(const uint32_t *restrict up, const uint32_t *restrict mid,
                                   const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map);
uint32_t symline_i_extrema_kinds(const uint32_t *restrict up, const uint32_t *restrict mid,
                                 const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map);

/*
 * Extrema of a row of n >= 1 energies into map (n entries: NONE, A or S) by
 * the run rule: a run of equal energies with larger neighbours on both sides
 * is an S point at its middle (lower middle for even lengths), with smaller
 * neighbours an A point; runs touching either end are never marked. A run
 * whose middle lies more than `lag` entries before its end is not marked
 * either (the detector's plateau limit; SL_RUN_ANY_LENGTH for none).
 */
void symline_i_extrema_runs(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map);

/* Entries decided together by symline_i_extrema_runs() and columns by
 * symline_i_extrema_down(); a plateau sends only its block down the slow
 * path. SL_PLATEAU_SPAN(left): the next block of the `left` still to do;
 * the blocks only save time (SL_FOR_SPEED; else all of them). */
#ifndef SL_PLATEAU_BLOCK /* a port may take smaller blocks (port/CMakeLists.txt) */
#define SL_PLATEAU_BLOCK 64u
#endif
#define SL_PLATEAU_SPAN(left)                                                                      \
    (SL_FOR_SPEED && (left) > SL_PLATEAU_BLOCK ? SL_PLATEAU_BLOCK : (left))

/*
 * Extrema down the columns, one row at a time: the state of a frame's or a
 * ring's map. Energies of row y live in E3 + (y % 3) * width; map row y at
 * map + (y % ring) * stride (ring: rows held, at least lag + 2); run_start
 * and left (width entries each) follow the plateaus.
 */
typedef struct symline_i_coldown {
    uint32_t *E3;
    uint16_t *run_start;
    int8_t *left;
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
