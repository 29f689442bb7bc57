/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid's rows (lib/grid.c) with AArch64 Advanced SIMD (NEON)
 * intrinsics, selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable lane loops, with the same
 * output (tests/core/test_grid_simd.c compares them). Eight grid pixels per
 * step; lib/grid.c sums the last few block by block.
 *
 * Why: every coarse pass reads the whole frame, so the cost is in the loads.
 * NEON adds neighbouring bytes into 16-bit lanes as it accumulates the rows
 * (vpadal: one instruction per 16 pixels and row), adds neighbouring lanes
 * (vpadd) and rounds while it narrows ((x + 2^(n-1)) >> n exactly, vrshrn).
 * Sums fit 16 bits up to blocks of 16 x 16 (256 * 255); larger blocks add
 * across the lanes in 32 bits.
 */
#include <arm_neon.h>

#include "grid.h"

/* Pair sums of nv vectors (16 nv columns from b) over s rows. */
static inline __attribute__((always_inline)) void pair_sums(const uint8_t *b, size_t stride,
                                                            uint32_t s, uint32_t nv, uint16x8_t *P)
{
    uint32_t d, i;
    for (i = 0; i < nv; i++) {
        P[i] = vpaddlq_u8(vld1q_u8(b + 16u * i));
    }
    for (d = 1u; d < s; d++) {
        b += stride;
        for (i = 0; i < nv; i++) {
            P[i] = vpadalq_u8(P[i], vld1q_u8(b + 16u * i));
        }
    }
}

/* Levels 1..4: nv = 2^level / 2 vectors per 8 pixels, their pair sums
 * (<= 2 * 16 * 255) added pairwise level - 1 times (<= 256 * 255). */
static inline __attribute__((always_inline)) uint32_t
lanes(const uint8_t *src, size_t stride, uint32_t level, uint32_t w, uint8_t *out)
{
    const uint32_t s = 1u << level, nv = s / 2u;
    uint16x8_t P[8];
    uint32_t x, n, i;
    for (x = 0; x + 8u <= w; x += 8u) {
        pair_sums(src + (size_t)x * s, stride, s, nv, P);
        for (n = nv; n > 1u; n /= 2u) {
            for (i = 0; i < n / 2u; i++) {
                P[i] = vpaddq_u16(P[2u * i], P[2u * i + 1u]);
            }
        }
        switch (level) { /* vrshrn takes a constant shift */
        case 1u: vst1_u8(out + x, vrshrn_n_u16(P[0], 2)); break;
        case 2u: vst1_u8(out + x, vrshrn_n_u16(P[0], 4)); break;
        case 3u: vst1_u8(out + x, vrshrn_n_u16(P[0], 6)); break;
        default: vst1_u8(out + x, vrshrn_n_u16(P[0], 8)); break;
        }
    }
    return x;
}

/* Level 5 and more: one pixel at a time, its block's pair sums (<= 2 * 32 *
 * 255 per lane and row of vectors) added across the lanes in 32 bits. */
static uint32_t wide(const uint8_t *src, size_t stride, uint32_t level, uint32_t w, uint8_t *out)
{
    const uint32_t s = 1u << level, shift = 2u * level;
    uint32_t x, d, i;
    for (x = 0; x < w; x++) {
        const uint8_t *b = src + (size_t)x * s;
        uint32_t sum = (1u << shift) >> 1;
        for (i = 0; i < s; i += 16u) {
            uint16x8_t P = vdupq_n_u16(0);
            for (d = 0; d < s; d++) {
                P = vpadalq_u8(P, vld1q_u8(b + (size_t)d * stride + i));
            }
            sum += vaddlvq_u16(P);
        }
        out[x] = (uint8_t)(sum >> shift);
    }
    return w;
}

uint32_t symline_i_grid_lanes(const uint8_t *src, size_t stride, uint32_t level, uint32_t w,
                              uint8_t *out)
{
    switch (level) {
    case 1u: return lanes(src, stride, 1u, w, out);
    case 2u: return lanes(src, stride, 2u, w, out);
    case 3u: return lanes(src, stride, 3u, w, out);
    case 4u: return lanes(src, stride, 4u, w, out);
    case 5u: return wide(src, stride, 5u, w, out);
    default: return 0u;
    }
}
