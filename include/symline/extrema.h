/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — extrema of symmetry (docs/algorithm.md).
 *
 * Extrema are taken on the exact energies E (smaller = more symmetric), along
 * each row (vertical axis) or each column (horizontal axis):
 *
 *  - a maximal run [a, b] of equal E with a >= 1 and b <= n-2 is
 *      an S point (symmetry maximum) when E(a-1) > E(a) and E(b+1) > E(b),
 *      an A point (symmetry minimum) when E(a-1) < E(a) and E(b+1) < E(b);
 *  - only index (a+b) div 2 of the run is marked; runs touching 0 or n-1 never.
 *
 * Map values: SYMLINE_MAP_NONE (0), SYMLINE_MAP_A (128), SYMLINE_MAP_S (255).
 * Two S points are never adjacent along the direction they were found in.
 *
 * Strip processing (horizontal axis): the column runs are followed row by row
 * by a symline_colrun state that keeps O(width) memory (11 bytes per column)
 * whatever the height; each pushed row of energies reports the extrema that
 * the row completes, as (x, y, kind) events, y <= the pushed row - 1. Together
 * with symline_energy_across() this lets a caller run the whole operator and
 * extrema over a ring of 2m+1 source rows with about 15 bytes per column of
 * working memory.
 */
#ifndef SYMLINE_EXTREMA_H
#define SYMLINE_EXTREMA_H

#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Extrema of one sequence of n energies, written as n map bytes (every byte
 * is written: 0, 128 or 255).
 */
symline_status symline_extrema_row(const uint32_t *E, uint32_t n, uint8_t *map);

/* One extremum reported by the column-run follower. */
typedef struct symline_extremum {
    uint16_t x;
    uint16_t y;
    uint8_t kind; /* SYMLINE_MAP_A or SYMLINE_MAP_S */
} symline_extremum;

/*
 * Follower of equal-E runs down every column (horizontal axis).
 * Fields are private; the struct lives wherever the caller wants it, its
 * arrays in the buffer given to symline_colrun_init().
 */
typedef struct symline_colrun {
    uint32_t width;
    uint32_t next_y;     /* index of the next row to push */
    uint32_t *prev_e;    /* E of the row above, per column */
    uint16_t *run_start; /* first row of the current run, per column */
    int8_t *left;        /* +1: E above the run is larger; -1: smaller; 0: run starts at row 0 */
} symline_colrun;

/* Bytes of buffer symline_colrun_init() needs for `width` columns (0 if width invalid). */
size_t symline_colrun_buffer_size(uint32_t width);

/* Prepares a follower for `width` columns over buf (any alignment). */
symline_status symline_colrun_init(symline_colrun *cr, uint32_t width, void *buf, size_t buf_size);

/*
 * Pushes the energies of the next row (rows must come in order 0, 1, ...,
 * at most 65535 of them). Writes the extrema completed by this row to
 * events[0 .. *count-1] (at most one per column, so `width` entries always
 * suffice; events_cap < width is ERR_BUFFER) in increasing x. Runs still open
 * when the last row has been pushed touch the last row and are never marked.
 */
symline_status symline_colrun_push(symline_colrun *cr, const uint32_t *E, symline_extremum *events,
                                   uint32_t events_cap, uint32_t *count);

/*
 * Bytes of workspace symline_extrema() needs, or 0 when the arguments are
 * invalid: one row of energies (vertical axis), or one row of energies, the
 * column follower and its event list (horizontal axis).
 */
size_t symline_extrema_workspace_size(uint32_t width, uint32_t height, symline_axis axis,
                                      uint32_t m);

/*
 * The extrema map of a whole image. map: height rows of width bytes, row y at
 * map[y*map_stride], map_stride >= width, map_len >= (height-1)*map_stride +
 * width. Every map pixel is written. ws: workspace, any alignment.
 */
symline_status symline_extrema(const symline_image *img, symline_axis axis, uint32_t m,
                               uint8_t *map, uint32_t map_stride, size_t map_len, void *ws,
                               size_t ws_size);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_EXTREMA_H */
