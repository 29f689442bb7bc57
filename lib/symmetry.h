/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's private interface (symmetry.c): the common start
 * of the whole-frame operator calls. The row and frame calls themselves are
 * public (include/symline/symmetry.h).
 */
#ifndef SYMLINE_LIB_SYMMETRY_H
#define SYMLINE_LIB_SYMMETRY_H

#include "common.h"
#include "symline/symmetry.h"

/*
 * Start of every whole-frame operator call: checks the image, axis, radius
 * and an output plane of height rows of width elements (out, out_stride,
 * out_len), then carves one row of uint32_t energies from the workspace.
 * On success *cur points past the carved row, ready for further carving.
 */
symline_status symline_i_frame_begin(const symline_image *img, symline_axis axis, uint32_t m,
                                     const void *out, uint32_t out_stride, size_t out_len, void *ws,
                                     size_t ws_size, uint8_t **cur, uint8_t **end, uint32_t **E);

#endif /* SYMLINE_LIB_SYMMETRY_H */
