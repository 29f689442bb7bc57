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
 * piece); a merged segment gets merged = true. Candidates come from a grid
 * of line ends over the width x height frame, in ws (ws_size bytes, may be
 * NULL) or the free end of r's point storage; without room for it every
 * pair is tried: the result is the same either way.
 */
void sl_merge(symline_result *r, uint32_t gap_px, uint32_t dev_q8, uint32_t curve_dev_q8,
              uint32_t width, uint32_t height, void *ws, size_t ws_size);

#endif /* SYMLINE_LIB_MERGE_H */
