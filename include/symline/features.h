/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — symmetry feature points (docs/format.md): crossings of symmetry axes.
 *
 * A feature point is a pixel that is an S point (symmetry maximum, docs/algorithm.md)
 * of both the horizontal-axis and the vertical-axis extrema maps at the same
 * radius. The result is exact: it equals the two maps of symline_extrema()
 * intersected pixel by pixel.
 *
 * Memory: the frame is processed row by row (energies down the columns with
 * the column-run follower of extrema.h, and the vertical-axis extrema of the
 * rows the follower reports); the workspace grows with the width only
 * (symline_features_workspace_size()), never with the frame's area. The
 * points go to caller storage; no allocation, no floating point, no I/O.
 * Optional module: firmware that does not call it does not link it.
 */
#ifndef SYMLINE_FEATURES_H
#define SYMLINE_FEATURES_H

#include "symline/detect.h" /* symline_point */
#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Bytes of workspace symline_features() needs for a width x height frame at
 * radius m (1..255), or 0 when an argument is invalid. About 25 bytes per
 * image column; independent of the height.
 */
size_t symline_features_workspace_size(uint32_t width, uint32_t height, uint32_t m);

/*
 * Largest possible number of feature points of a width x height frame:
 * S points are never at a row's or column's ends and never adjacent along
 * either direction, so at most half of the (width-2) x (height-2) inner
 * pixels, rounded up. 0 for frames narrower or lower than 3 pixels (they
 * have none). A point buffer of this many entries never overflows.
 */
uint32_t symline_features_max_points(uint32_t width, uint32_t height);

/*
 * The feature points of img at radius m, written to pts[0 .. *count-1] in
 * raster order (y ascending, then x), each once, full-resolution pixel
 * coordinates.
 * ws: ws_size >= symline_features_workspace_size() bytes of scratch, any
 * alignment; pts: cap entries, caller-owned.
 * Returns SYMLINE_OK; ERR_NULL, ERR_SIZE, ERR_STRIDE (bad image view),
 * ERR_RADIUS, ERR_BUFFER (workspace too small: nothing written). When the
 * points do not fit, returns ERR_BUFFER with *count = the number the frame
 * has (give that many entries and call again); pts[0 .. cap-1] is then
 * scratch.
 */
symline_status symline_features(const symline_image *img, uint32_t m, void *ws, size_t ws_size,
                                symline_point *pts, uint32_t cap, uint32_t *count);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_FEATURES_H */
