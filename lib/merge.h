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
 * The joined piece's points are kept contiguous by rotation (piece after
 * piece); a merged segment gets merged = true.
 */
void symline_i_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8);

#endif /* SYMLINE_LIB_MERGE_H */
