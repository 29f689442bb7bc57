/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Tests that only a painted line on the field passes (linecheck.c), applied
 * to a traced piece before it becomes a segment.
 */
#ifndef SYMLINE_LIB_LINECHECK_H
#define SYMLINE_LIB_LINECHECK_H

#include "common.h"
#include "symline/detect.h"

/*
 * A painted line's width in the image grows toward the camera: from about a
 * pixel at the field boundary to its widest at the bottom of the frame. A
 * piece found at a coarse scale (a wide ridge) close below the boundary is a
 * leg, a robot or a post, not paint. True when piece q[0..n-1] (grid
 * coordinates at `level` >= 1, grid height h) lies in the upper quarter of
 * the field below the boundary (rows[x]: the first field row of grid column
 * x; a boundary at the top of the frame tells nothing and passes).
 */
bool symline_i_linecheck_too_wide(const uint16_t *rows, uint32_t level, uint32_t h,
                                  const symline_point *q, uint32_t n);

#endif /* SYMLINE_LIB_LINECHECK_H */
