/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Sub-pixel position of line points across the line (private to the core).
 *
 * A line point is an S point: the middle pixel of a run of equal symmetry
 * energy E that is smaller than both neighbours. A line an even number of
 * pixels wide has its ridge between two pixels, and a line at any sub-pixel
 * position has its energy minimum between pixels, so the pixel alone is up to
 * half a pixel (of the pass's grid) off the line's middle. The offset is
 * taken from E around the point: the exact middle of an equal-E run, else the
 * vertex of the parabola through E at the point and its two neighbours
 * across the line (E sums squared differences, so it is close to a parabola
 * around its minimum). Offsets are stored in the points' fx / fy fields in
 * 1/128 px of the grid they are in (subpixel.c); fixed.h turns them into
 * positions.
 */
#ifndef SYMLINE_LIB_SUBPIXEL_H
#define SYMLINE_LIB_SUBPIXEL_H

#include "common.h"
#include "linepoints.h"
#include "symline/detect.h"

/*
 * Sets fx, fy of the pass's grid points q[0..n-1]: the offset across the line
 * (fx for the vertical axis, fy for the horizontal one) in 1/128 grid px,
 * -64..64, the other 0. Reads the frame (box means at coarse levels, as the
 * pass computed them), or where the pass keeps its grid rows in the grid row
 * cache (linepoints.h) those, which hold the same values; points at the
 * grid's border get offset 0.
 */
void symline_i_subpixel(const symline_image *img, const symline_i_pass *p, symline_point *q,
                        uint32_t n);

#endif /* SYMLINE_LIB_SUBPIXEL_H */
