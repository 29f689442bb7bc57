/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid's rows (lib/grid.c) with AArch64 Advanced SIMD (NEON)
 * intrinsics, selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable lane loops, with the same
 * output (tests/core/test_grid_simd.c compares them). Eight, then four grid
 * pixels per step, then the last three at most one block at a time. Other
 * levels (0, above 5) take the reference.
 *
 * Why: every coarse pass reads the whole frame, so the cost is in the loads.
 * NEON adds neighbouring bytes into 16-bit lanes as it accumulates the rows
 * (vpadal: one instruction per 16 pixels and row), adds neighbouring lanes
 * (vpadd) and rounds while it narrows ((x + 2^(n-1)) >> n exactly, vrshrn).
 * Sums fit 16 bits up to blocks of 16 x 16 (256 * 255); larger blocks add
 * across the lanes in 32 bits.
 */
#include <arm_neon.h>
#include <string.h>

#include "linepoints.h"

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

/* (q + 2^(2 level - 1)) >> 2 level narrowed to bytes (block sums q). */
static inline __attribute__((always_inline)) uint8x8_t narrow(uint16x8_t q, uint32_t level)
{
    switch (level) { /* vrshrn takes a constant shift */
    case 1u: return vrshrn_n_u16(q, 2);
    case 2u: return vrshrn_n_u16(q, 4);
    case 3u: return vrshrn_n_u16(q, 6);
    default: return vrshrn_n_u16(q, 8);
    }
}

/* Pair sums P[0 .. nv-1] added pairwise into P[0] (nv a power of 2). */
static inline __attribute__((always_inline)) void reduce(uint16x8_t *P, uint32_t nv)
{
    uint32_t n, i;
    for (n = nv; n > 1u; n /= 2u) {
        for (i = 0; i < n / 2u; i++) {
            P[i] = vpaddq_u16(P[2u * i], P[2u * i + 1u]);
        }
    }
}

/* Levels 1..4: nv = 2^level / 2 vectors per 8 pixels, their pair sums
 * (<= 2 * 16 * 255) added pairwise level - 1 times (<= 256 * 255); then
 * four pixels from half as many (or half a vector at level 1). */
static inline __attribute__((always_inline)) uint32_t
lanes(const uint8_t *src, size_t stride, uint32_t level, uint32_t w, uint8_t *out, uint8_t *twin)
{
    const uint32_t s = 1u << level, nv = s / 2u;
    uint16x8_t P[8], Q;
    uint32_t x;
    for (x = 0; x + 8u <= w; x += 8u) {
        uint8x8_t v;
        pair_sums(src + (size_t)x * s, stride, s, nv, P);
        reduce(P, nv);
        v = narrow(P[0], level);
        vst1_u8(out + x, v);
        if (twin != NULL) {
            vst1_u8(twin + x, v);
        }
    }
    if (x + 4u <= w) {
        const uint8_t *b = src + (size_t)x * s;
        uint32_t t;
        if (level == 1u) {
            const uint16x4_t p = vpadal_u8(vpaddl_u8(vld1_u8(b)), vld1_u8(b + stride));
            Q = vcombine_u16(p, p);
        } else {
            pair_sums(b, stride, s, nv / 2u, P);
            reduce(P, nv / 2u);
            Q = vpaddq_u16(P[0], P[0]);
        }
        t = vget_lane_u32(vreinterpret_u32_u8(narrow(Q, level)), 0);
        memcpy(out + x, &t, 4u);
        if (twin != NULL) {
            memcpy(twin + x, &t, 4u);
        }
        x += 4u;
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

/* The row into out and, where twin is not NULL, into twin too: the lanes
 * store both, the last blocks (all of them at level 5) are copied. */
void symline_i_grid_row(const symline_image *img, const symline_i_pass *p, uint32_t y,
                        uint16_t *acc, uint8_t *out, uint8_t *twin)
{
    const uint32_t level = p->level, w = p->w;
    const size_t stride = img->stride;
    const uint8_t *src = img->data + ((size_t)y << level) * stride;
    uint32_t x;
    switch (level) {
    case 1u: x = lanes(src, stride, 1u, w, out, twin); break;
    case 2u: x = lanes(src, stride, 2u, w, out, twin); break;
    case 3u: x = lanes(src, stride, 3u, w, out, twin); break;
    case 4u: x = lanes(src, stride, 4u, w, out, twin); break;
    case 5u:
        (void)wide(src, stride, 5u, w, out);
        x = 0u;
        break; /* none in twin yet */
    default: symline_i_grid_row_c(img, p, y, acc, out, twin); return;
    }
    if (level < 5u) {
        symline_i_grid_blocks(src, stride, level, x, w, out); /* at most three blocks */
    }
    symline_i_grid_twin(out, x, w, twin);
}

/* The grid pyramid (grid.h): level 1's row, sixteen pixels a step (vpadal
 * for each row's pairs), and where asked the pairs of its sums into level
 * 2's (vpadd; fold: 0 none, 1 the first row, 2 the second, with level 2's
 * row; a constant in each inlined copy). */
static inline __attribute__((always_inline)) size_t sums1(const uint8_t *src, size_t stride,
                                                          size_t w16, uint8_t *out, uint16_t *acc,
                                                          uint8_t *out2, uint32_t fold)
{
    size_t x = 0u;
    for (; x < w16; x += 16u) {
        uint16x8_t S[2], P;
        pair_sums(src + 2u * x, stride, 2u, 2u, S);
        vst1q_u8(out + x, vcombine_u8(vrshrn_n_u16(S[0], 2), vrshrn_n_u16(S[1], 2)));
        if (fold != 0u) {
            P = vpaddq_u16(S[0], S[1]);
            if (fold == 2u) {
                P = vaddq_u16(vld1q_u16(acc + x / 2u), P);
                vst1_u8(out2 + x / 2u, vrshrn_n_u16(P, 4));
            }
            vst1q_u16(acc + x / 2u, P);
        }
    }
    return x;
}

void symline_i_grid_sums1(const uint8_t *src, size_t stride, uint32_t w, uint8_t *out,
                          uint16_t *acc, uint8_t *out2)
{
    const size_t w16 = w & ~15u;
    const size_t x = acc == NULL    ? sums1(src, stride, w16, out, NULL, NULL, 0u)
                     : out2 == NULL ? sums1(src, stride, w16, out, acc, NULL, 1u)
                                    : sums1(src, stride, w16, out, acc, out2, 2u);
    symline_i_grid_sums1_from(x, src, stride, w, out, acc, out2);
}

/* Level 3 or 4's sums from the level below's: eight pair sums a step
 * (vpadd), the second row's added and rounded as they narrow. */
void symline_i_grid_fold(const uint16_t *s, uint32_t w, uint32_t level, uint16_t *acc, uint8_t *out)
{
    const int16x8_t sh = vdupq_n_s16((int16_t) - (int32_t)(2u * level));
    const size_t w8 = w & ~7u;
    size_t x = 0u;
    for (; x < w8; x += 8u) {
        uint16x8_t P = vpaddq_u16(vld1q_u16(s + 2u * x), vld1q_u16(s + 2u * x + 8u));
        if (out != NULL) {
            P = vaddq_u16(vld1q_u16(acc + x), P);
            /* a rounding shift right: (P + 2^(2 level - 1)) >> 2 level */
            vst1_u8(out + x, vmovn_u16(vrshlq_u16(P, sh)));
        }
        vst1q_u16(acc + x, P);
    }
    symline_i_grid_fold_c(s + 2u * x, w - (uint32_t)x, level, acc + x,
                          out != NULL ? out + x : NULL);
}
