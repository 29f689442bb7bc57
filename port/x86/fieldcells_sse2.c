/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary's cells of 8 px (lib/fieldboundary.h) with SSE2
 * intrinsics (x86-64 baseline), selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable reference,
 * with the same output (tests/core/test_fieldcells_simd.c compares them):
 *
 * symline_i_field_cells8() for symline_i_field_cells8_c(): two cells a
 * step, one in each 64-bit lane. psadbw against zero sums a cell's 8 gray
 * values; the smaller value of each neighbour pair is the low byte of
 * min(v, v >> 8) in 16-bit lanes (the high byte is 0 there), whose psadbw
 * is the sum of the pairs' smaller values. Only the division of the texture
 * stays per cell.
 */
#include <emmintrin.h>

#include "fieldboundary.h"

static inline __m128i load8(const uint8_t *p)
{
    return _mm_loadl_epi64((const __m128i *)(const void *)p);
}

void symline_i_field_cells8(const uint8_t *row, size_t sx, uint32_t n, uint8_t *out)
{
    const __m128i z = _mm_setzero_si128();
    uint32_t c;
    for (c = 0; c + 2u <= n; c += 2u, row += 2u * sx, out += 4) {
        const __m128i v = _mm_unpacklo_epi64(load8(row), load8(row + sx));
        const __m128i sums = _mm_sad_epu8(v, z);
        const __m128i lows = _mm_sad_epu8(_mm_min_epu8(v, _mm_srli_epi16(v, 8)), z);
        /* sums (<= 2040) and lows in the 16-bit lanes 0, 2 and 4, 6 */
        const __m128i both = _mm_packs_epi32(sums, lows);
        symline_i_field_put8(out, (uint32_t)_mm_extract_epi16(both, 0),
                             (uint32_t)_mm_extract_epi16(both, 4));
        symline_i_field_put8(out + 2, (uint32_t)_mm_extract_epi16(both, 2),
                             (uint32_t)_mm_extract_epi16(both, 6));
    }
    if (c < n) {
        symline_i_field_cells8_c(row, sx, 1u, out);
    }
}
