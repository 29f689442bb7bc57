/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — vertical symmetry histogram (docs/format.md).
 *
 * counts[x] = the number of S points (symmetry maxima, docs/algorithm.md) of the
 * vertical-axis extrema map in image column x. Symmetry about vertical axes
 * is computed along each row, so every row contributes on its own: a frame
 * (or a camera streaming rows) is accumulated row by row with one row of
 * energies and one row of extrema as working memory. On panoramic images its
 * peaks mark upright symmetric structures (doors, posts, corridor axes).
 * Exact integer arithmetic; no allocation, no floating point, no I/O.
 * Optional module: firmware that does not call it does not link it.
 */
#ifndef SYMLINE_HISTOGRAM_H
#define SYMLINE_HISTOGRAM_H

#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Bytes of workspace for rows of `width` pixels (1..65535) at radius m
 * (1..255): 5 bytes per pixel plus alignment, or 0 when invalid.
 */
size_t symline_histogram_workspace_size(uint32_t width, uint32_t m);

/*
 * Adds the S points of one row (width pixels at `row`) to counts[0..width-1]
 * (caller-owned; a count of 65535 stays there rather than wrapping, which a
 * frame of at most 65535 rows never reaches). Start with all counts 0.
 * Returns SYMLINE_OK, ERR_NULL, ERR_SIZE, ERR_RADIUS or ERR_BUFFER (workspace).
 */
symline_status symline_histogram_row(const uint8_t *row, uint32_t width, uint32_t m,
                                     uint16_t *counts, void *ws, size_t ws_size);

/*
 * The histogram of a whole frame: counts[0..width-1] (counts_len >= width
 * entries) are set, not added to. Returns SYMLINE_OK, ERR_NULL, ERR_SIZE,
 * ERR_STRIDE, ERR_RADIUS or ERR_BUFFER (counts_len or workspace too small;
 * nothing written).
 */
symline_status symline_histogram(const symline_image *img, uint32_t m, uint16_t *counts,
                                 uint32_t counts_len, void *ws, size_t ws_size);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_HISTOGRAM_H */
