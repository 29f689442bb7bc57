/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_find_s() with AArch64 Advanced SIMD (NEON) intrinsics, selected at
 * build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of the
 * portable reference symline_i_find_s_c() of lib/linefilter.h, with the same
 * result (tests/core/test_operator_simd.c compares the two).
 *
 * Why: after the byte-lane pre-filter few S points are left in a row, and the
 * reference spends a compare and a branch on every entry to find them. Here
 * 16 entries are compared at once; NEON has no byte mask like SSE2's movemask,
 * so a block with a hit is narrowed to 4 bits per entry (vshrn), whose lowest
 * set bit gives the entry. Compilers do not vectorise a search that stops at
 * its first hit.
 */
#include <arm_neon.h>

#include "linefilter.h"

/* Bits 4i .. 4i+3 set where entry i of p[0..15] is an S point. */
static inline uint64_t s_nibbles(const uint8_t *p)
{
    const uint8x16_t eq = vceqq_u8(vld1q_u8(p), vdupq_n_u8(SYMLINE_MAP_S));
    return vget_lane_u64(vreinterpret_u64_u8(vshrn_n_u16(vreinterpretq_u16_u8(eq), 4)), 0);
}

uint32_t symline_i_find_s(const uint8_t *map, uint32_t x, uint32_t n)
{
    uint64_t bits;
    for (; x + 16u <= n; x += 16u) {
        bits = s_nibbles(map + x);
        if (bits != 0u) {
            return x + (uint32_t)__builtin_ctzll(bits) / 4u;
        }
    }
    if (x >= n) {
        return n;
    }
    if (n < 16u) {
        return symline_i_find_s_c(map, x, n);
    }
    /* The last 16 entries, without those before x. */
    bits = s_nibbles(map + (n - 16u)) >> (4u * (x - (n - 16u)));
    return bits != 0u ? x + (uint32_t)__builtin_ctzll(bits) / 4u : n;
}
