/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Line points of one pass (linepoints.c): the scale grid's rows (grid.c), the
 * line filter's byte test over each row, and at its few candidates the exact
 * filter, symmetry energies and the extremum with the plateau limit, streamed
 * over a ring of rows into a raster-ordered point list.
 */
#ifndef SYMLINE_LIB_LINEPOINTS_H
#define SYMLINE_LIB_LINEPOINTS_H

#include "common.h"
#include "grid.h"
#include "linefilter.h"
#include "symline/detect.h"

/* One pass: an axis at one scale. Coordinates of a pass are on its grid.
 * Filled by symline_i_pass_setup() (pass.c). */
typedef struct symline_i_pass {
    symline_axis axis;
    uint32_t level; /* grid = frame box-downsampled by 2^level */
    uint32_t w, h;  /* grid size: width >> level, height >> level */
    uint32_t m;     /* radius */
    uint32_t k;     /* contrast sample offset across the line: m + 1 */
    uint32_t lag;   /* longest accepted plateau: end - marked index <= lag (= m) */
    symline_i_linefilter filter;
} symline_i_pass;

/* Workspace bytes of symline_i_collect() (row index excluded). */
size_t symline_i_collect_ws_size(const symline_i_pass *p, uint32_t img_width);

/*
 * The line points of one pass, in raster order, grid coordinates, written to
 * pts[0 .. *n-1] (at most cap); row_start[y] is the index of the first point
 * of grid row y, row_start[h] = *n (h+1 entries). Adds to *dropped the line
 * points that did not fit (cap too small). Strip processing: only a ring of
 * rows is held.
 * Returns SYMLINE_OK, SYMLINE_ERR_SIZE (empty grid) or SYMLINE_ERR_BUFFER
 * (ws_size below symline_i_collect_ws_size()).
 */
symline_status symline_i_collect(const symline_image *img, const symline_i_pass *p, void *ws,
                                 size_t ws_size, symline_point *pts, uint32_t cap, uint32_t *n,
                                 uint32_t *row_start, uint32_t *dropped);

#endif /* SYMLINE_LIB_LINEPOINTS_H */
