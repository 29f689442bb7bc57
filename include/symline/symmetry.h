/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline — the one-dimensional reflective symmetry operator (docs/algorithm.md).
 *
 * For every index i of a sequence q[0..n-1] (a row or a column) and radius m:
 *
 *     d_j  = |q[i-j] - q[i+j]|, or 255 when the pair leaves the sequence
 *     E(i) = sum_{j=1..m} (m+1-j) * d_j^2          (uint32_t, exact)
 *     Emax = 255^2 * m*(m+1)/2                     (largest possible E)
 *     S8   = (510*(Emax - E) + Emax) div (2*Emax)  (255*(1-E/Emax), rounded half up)
 *
 * Small E means symmetric. E fits 32 bits for every m <= 255.
 *
 * Two levels of API:
 *  - row primitives, for streaming and strip processing: symline_energy_row()
 *    (along a row: vertical axis) and symline_energy_across() (along the
 *    columns, one output row at a time: horizontal axis), plus
 *    symline_s8_row() to turn energies into the 8-bit symmetry image;
 *  - whole-frame calls over caller buffers: symline_energy_frame() and
 *    symline_symmetry().
 *
 * Strip processing: the horizontal-axis output row y needs only the source
 * rows y-m .. y+m. symline_energy_across() takes them as an array of 2m+1 row
 * pointers, so a driver that keeps a ring of 2m+1 camera rows (or any strip of
 * the frame) can compute the energies row by row with one row of uint32_t
 * working memory: O(width) RAM, independent of the frame height.
 */
#ifndef SYMLINE_SYMMETRY_H
#define SYMLINE_SYMMETRY_H

#include "symline/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Emax = 255^2 * m*(m+1)/2 for 1 <= m <= 255; 0 for an invalid radius. */
uint32_t symline_emax(uint32_t m);

/*
 * Energies along one row (vertical axis).
 * q: n >= 1 pixels; m: radius 1..255; E: n uint32_t written (caller-owned).
 * Returns SYMLINE_OK, ERR_NULL, ERR_SIZE (n = 0 or > 65535) or ERR_RADIUS.
 */
symline_status symline_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E);

/*
 * Energies of one image row along the columns (horizontal axis).
 * rows: 2m+1 pointers; rows[m] is the row being computed, rows[m-j] the row j
 *       above it and rows[m+j] the row j below it, or NULL where that row lies
 *       outside the image (its pairs then count as d = 255). rows[m] must not
 *       be NULL. Each non-NULL row holds at least `width` pixels.
 * E:    width uint32_t written.
 */
symline_status symline_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width,
                                     uint32_t *E);

/*
 * Convenience wrapper of symline_energy_across() for row y of a whole image.
 * Returns ERR_RANGE when y >= height.
 */
symline_status symline_energy_across_image(const symline_image *img, uint32_t y, uint32_t m,
                                           uint32_t *E);

/*
 * 8-bit symmetry values of n energies computed with radius m:
 * out[i] = (510*(Emax-E[i]) + Emax) div (2*Emax). E[i] > Emax is ERR_RANGE
 * (such a value cannot come from the operator).
 */
symline_status symline_s8_row(const uint32_t *E, uint32_t n, uint32_t m, uint8_t *out);

/*
 * Whole-frame energies. E receives height rows of width uint32_t, row y at
 * E[y * e_stride]; e_stride >= width (elements); e_len = number of uint32_t
 * elements the caller provides (>= (height-1)*e_stride + width).
 * No workspace is needed.
 */
symline_status symline_energy_frame(const symline_image *img, symline_axis axis, uint32_t m,
                                    uint32_t *E, uint32_t e_stride, size_t e_len);

/*
 * Bytes of workspace symline_symmetry() needs (one row of uint32_t plus
 * alignment slack), or 0 when the arguments are invalid.
 */
size_t symline_symmetry_workspace_size(uint32_t width, uint32_t height, symline_axis axis,
                                       uint32_t m);

/*
 * The 8-bit symmetry image S8 (255 = perfect mirror, 0 = hard transitions
 * at every pair). out: height rows of width bytes, row y at out[y*out_stride],
 * out_stride >= width, out_len >= (height-1)*out_stride + width bytes.
 * ws: workspace of ws_size >= symline_symmetry_workspace_size() bytes, any
 * alignment. `out` may alias the image only if it is the same buffer with the
 * same stride and axis is SYMLINE_AXIS_VERTICAL.
 */
symline_status symline_symmetry(const symline_image *img, symline_axis axis, uint32_t m,
                                uint8_t *out, uint32_t out_stride, size_t out_len, void *ws,
                                size_t ws_size);

#ifdef __cplusplus
}
#endif

#endif /* SYMLINE_SYMMETRY_H */
