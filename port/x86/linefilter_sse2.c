/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_find_s() with SSE2 intrinsics (x86-64 baseline), selected at
 * build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of the
 * portable reference symline_i_find_s_c() of lib/linefilter.h, with the same
 * result (tests/core/test_operator_simd.c compares the two).
 *
 * Why: after the byte-lane pre-filter few S points are left in a row, and the
 * reference spends a compare and a branch on every entry to find them. Here
 * 16 entries are compared at once and the first S among them is the lowest
 * set bit of the byte mask. Compilers do not vectorise a search that stops
 * at its first hit.
 */
#include <emmintrin.h>

#include "linefilter.h"

static inline uint32_t s_bits(const uint8_t *p)
{
    const __m128i s = _mm_set1_epi8((char)SYMLINE_MAP_S);
    return (uint32_t)_mm_movemask_epi8(
        _mm_cmpeq_epi8(_mm_loadu_si128((const __m128i *)(const void *)p), s));
}

uint32_t symline_i_find_s(const uint8_t *map, uint32_t x, uint32_t n)
{
    uint32_t bits;
    for (; x + 16u <= n; x += 16u) {
        bits = s_bits(map + x);
        if (bits != 0u) {
            return x + (uint32_t)__builtin_ctz(bits);
        }
    }
    if (x >= n) {
        return n;
    }
    if (n < 16u) {
        return symline_i_find_s_c(map, x, n);
    }
    /* The last 16 entries, without those before x. */
    bits = s_bits(map + (n - 16u)) >> (x - (n - 16u));
    return bits != 0u ? x + (uint32_t)__builtin_ctz(bits) : n;
}
