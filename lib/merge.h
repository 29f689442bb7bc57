/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The merge of collinear line pieces (merge.c).
 */
#ifndef SYMLINE_LIB_MERGE_H
#define SYMLINE_LIB_MERGE_H

#include "common.h"
#include "pass.h"
#include "symline/detect.h"

/*
 * Merges collinear line segments of d->r: ends at most the configured gap
 * apart (d->cfg->merge_gap; automatic: d->img->width / 8), each end within
 * merge_dev_q8 of the other's line, the joined piece no curve by
 * curve_dev_q8 (both thresholds plus half a block of the coarser scale).
 * The joined piece's points are kept contiguous (piece after piece); a
 * merged segment gets merged = true. ws: ws_size bytes of scratch for the
 * grid of segment ends (any alignment, may be NULL); the free end of the
 * point storage holds the points' new layout. Less of either only costs
 * time: every pair is tried then, with the same result. As symline_detect()
 * calls it: a checked configuration and frame, segment levels below
 * SYMLINE_DETECT_MAX_LEVELS, segment ends within 2^25 Q8 of the frame (the
 * grid's walk is 32-bit), and the points [0, point_count) laid out piece
 * after piece in slot order (as the passes leave them). Only cfg, img and r
 * of d are read.
 */
void symline_i_merge(const symline_i_run *d, void *ws, size_t ws_size);

#endif /* SYMLINE_LIB_MERGE_H */
