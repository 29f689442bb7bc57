/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The merge of collinear line pieces (merge.c).
 */
#ifndef SYMLINE_LIB_MERGE_H
#define SYMLINE_LIB_MERGE_H

#include "common.h"
#include "symline/detect.h"

/*
 * Merges collinear line segments of r: ends at most gap_px apart, each end
 * within dev_q8 of the other's line, the joined piece no curve by
 * curve_dev_q8 (both thresholds plus half a block of the coarser scale).
 * The joined piece's points are kept contiguous (piece after piece); a
 * merged segment gets merged = true. width x height: the frame (the grid of
 * segment ends); ws: ws_size bytes of scratch for that grid (any alignment,
 * may be NULL), and the free end of r's point storage for the points' new
 * layout. Less of either only costs time: every pair is tried then, with
 * the same result. As symline_detect() calls it: width, height 1 ..
 * SYMLINE_MAX_DIM, gap_px <= SYMLINE_MAX_DIM, dev_q8 <= SYMLINE_MAX_DIM px,
 * segment levels below SYMLINE_DETECT_MAX_LEVELS, segment ends within 2^25
 * Q8 of the frame (the grid's walk is 32-bit), and the points [0,
 * point_count) laid out piece after piece in slot order (as the passes
 * leave them).
 */
void symline_i_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8,
                     uint32_t width, uint32_t height, void *ws, size_t ws_size);

#endif /* SYMLINE_LIB_MERGE_H */
