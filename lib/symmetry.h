/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's private interface (symmetry.c): the common start
 * of the whole-frame operator calls, and the row bodies a SIMD version may
 * replace. The row and frame calls themselves are public
 * (include/symline/symmetry.h).
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

#ifdef SYMLINE_PORT_ENERGY
/*
 * The operator's row bodies where the build has SIMD versions of them
 * (port/, CMake option SYMLINE_SIMD): symline_i_energy_row() is the body of
 * symline_energy_row() (q: n >= 1 gray values, energies into E[0..n-1]) and
 * symline_i_energy_across() that of symline_energy_across() (rows[0..2m],
 * NULL outside the image; energies into E[0..width-1]), on arguments those
 * have checked (radius 1..255, sizes 1..65535). The *_c versions are the
 * portable references in symmetry.c, which scalar builds use directly; the
 * SIMD versions give the same output (tests/core/test_operator_simd.c).
 */
void symline_i_energy_row_c(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E);
void symline_i_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E);
void symline_i_energy_across_c(const uint8_t *const *rows, uint32_t m, uint32_t width, uint32_t *E);
void symline_i_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width, uint32_t *E);
#endif

#endif /* SYMLINE_LIB_SYMMETRY_H */
