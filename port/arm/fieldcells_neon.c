/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary's cells of 8 px (lib/fieldboundary.h) with AArch64
 * Advanced SIMD (NEON) intrinsics, selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable reference,
 * with the same output (tests/core/test_fieldcells_simd.c compares them):
 *
 * symline_i_field_cells8() for symline_i_field_cells8_c(): a cell's 8 gray
 * values summed by one widening add across the vector (uaddlv); the pairs
 * of neighbours swapped within 16 bits (rev16), so that the lane-wise
 * minimum holds each pair's smaller value twice: its sum is twice the sum
 * of the smaller values. Only the division of the texture stays scalar.
 */
#include <arm_neon.h>

#include "fieldboundary.h"

void symline_i_field_cells8(const uint8_t *row, size_t sx, uint32_t n, uint8_t *out)
{
    uint32_t c;
    for (c = 0; c < n; c++, row += sx, out += 2) {
        const uint8x8_t v = vld1_u8(row);
        symline_i_field_put8(out, vaddlv_u8(v), (uint32_t)vaddlv_u8(vmin_u8(v, vrev16_u8(v))) / 2u);
    }
}
