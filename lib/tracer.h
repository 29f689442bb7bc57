/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line tracer (tracer.c): chains of neighbouring line points, read from a
 * raster-ordered point list with its per-row index.
 */
#ifndef SYMLINE_LIB_TRACER_H
#define SYMLINE_LIB_TRACER_H

#include "common.h"
#include "symline/detect.h"

/* Marks a point of the raster list as visited by the tracer (y is never 65535). */
#define SL_VISITED 0xFFFFu

/* Iterator over the chains of a raster list. */
typedef struct symline_i_tracer {
    symline_point *pts; /* raster list; visited entries get y = SL_VISITED, and */
    uint32_t n;         /* where speed counts, fx and fy the tracer's own use */
    const uint32_t *row_start;
    uint32_t h;
    uint32_t scan;  /* next raster index to try as a start */
    uint32_t phase; /* 0: starts at B points, 1: everything left (loops) */
    uint32_t left;  /* points not visited yet (kept where speed counts) */
} symline_i_tracer;

void symline_i_tracer_init(symline_i_tracer *t, symline_point *pts, uint32_t n,
                           const uint32_t *row_start, uint32_t h);

/* Number of line points among the 8 neighbours of (x, y) (visited or not). */
uint32_t symline_i_neighbours(const symline_i_tracer *t, uint32_t x, uint32_t y);

/* Reverses n points in place (the tracer's backward half, the merge's rotations). */
void symline_i_reverse_points(symline_point *p, uint32_t n);

/*
 * Next chain, written to dst[0 .. *count-1] in tracing order (grid
 * coordinates). Returns true for a chain, false when none is left. A chain longer
 * than cap is cut at cap points and *cut is set.
 */
bool symline_i_tracer_next(symline_i_tracer *t, symline_point *dst, uint32_t cap, uint32_t *count,
                           bool *cut);

#endif /* SYMLINE_LIB_TRACER_H */
