/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row with SSE2 intrinsics (x86-64
 * baseline), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable reference of
 * lib/linefilter.h, with the same result (tests/core/test_linefilter_simd.c
 * compares them):
 *
 * symline_i_line_cand() for symline_i_line_cand_c(): the byte test 64
 * entries a step (x86/bytetest_sse2.h), then only the set bits of its masks
 * are visited.
 */
#include "bytetest_sse2.h"

uint32_t symline_i_line_cand(const symline_i_prefilter *pf, const uint8_t *c, const uint8_t *lo,
                             const uint8_t *hi, uint32_t x, uint32_t n, uint16_t *out,
                             uint32_t *next)
{
    uint16_t *o = out; /* the next index goes here */
    uint16_t *const full = out + SL_LINE_CAND_MAX;
    sl_bytetest t;
    uint64_t bits;
    size_t base;
    if (n < 16u) {
        return symline_i_line_cand_c(pf, c, lo, hi, x, n, out, next);
    }
    sl_bytetest_init(&t, pf, c, lo, hi, x, n);
    while ((bits = sl_bytetest_next(&t, &base)) != 0u) {
        for (; bits != 0u; bits &= bits - 1u) {
            const uint32_t i = (uint32_t)base + (uint32_t)__builtin_ctzll(bits);
            *o++ = (uint16_t)i;
            if (o == full) {
                *next = i + 1u;
                return SL_LINE_CAND_MAX;
            }
        }
    }
    *next = n;
    return (uint32_t)(o - out);
}
