/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row with AArch64 Advanced SIMD (NEON)
 * intrinsics, selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable reference of
 * lib/linefilter.h, with the same result (tests/core/test_linefilter_simd.c
 * compares them):
 *
 * symline_i_line_cand() for symline_i_line_cand_c(): one to five entries in
 * a hundred pass, so the row is tested 64 entries a step: the gray value
 * and the ridge first (three loads and four instructions per 16: max,
 * saturating add, max, compare), one test for the step, and only in steps
 * where some pass the brighter side's limit (side_max rejects few of them)
 * and the nibble masks (NEON has no byte mask like SSE2's movemask: a block
 * is narrowed to 4 bits per entry by vshrn).
 */
#include <arm_neon.h>

#include "linefilter.h"

/* Bits 4i .. 4i+3 set where byte lane i of v is set (lanes all 0 or all 1). */
static inline uint64_t nibbles(uint8x16_t v)
{
    return vget_lane_u64(vreinterpret_u64_u8(vshrn_n_u16(vreinterpretq_u16_u8(v), 4)), 0);
}

/* Lanes all set where entry x + i (i < 16) passes the byte test. */
static inline uint8x16_t gray_lanes(const uint8_t *c, const uint8_t *lo, const uint8_t *hi,
                                    size_t x, uint8x16_t mg, uint8x16_t rm, uint8x16_t sm)
{
    const uint8x16_t side = vmaxq_u8(vld1q_u8(lo + x), vld1q_u8(hi + x));
    return vandq_u8(vcgeq_u8(vld1q_u8(c + x), vmaxq_u8(vqaddq_u8(side, rm), mg)),
                    vcleq_u8(side, sm));
}

/* gray_lanes() without the brighter side's limit; the brighter sides to *side. */
static inline uint8x16_t ridge_lanes(const uint8_t *c, const uint8_t *lo, const uint8_t *hi,
                                     size_t x, uint8x16_t mg, uint8x16_t rm, uint8x16_t *side)
{
    *side = vmaxq_u8(vld1q_u8(lo + x), vld1q_u8(hi + x));
    return vcgeq_u8(vld1q_u8(c + x), vmaxq_u8(vqaddq_u8(*side, rm), mg));
}

/* Appends base + i for every set nibble i of bits; false when out filled up
 * (then *next is the entry after the last one). */
static inline int report(uint64_t bits, uint32_t base, uint16_t *out, uint32_t *k, uint32_t *next)
{
    for (bits &= 0x8888888888888888u; bits != 0u; bits &= bits - 1u) {
        const uint32_t i = base + (uint32_t)__builtin_ctzll(bits) / 4u;
        out[(*k)++] = (uint16_t)i;
        if (*k == SL_LINE_CAND_MAX) {
            *next = i + 1u;
            return 0;
        }
    }
    return 1;
}

uint32_t symline_i_line_cand(const symline_i_prefilter *pf, const uint8_t *c, const uint8_t *lo,
                             const uint8_t *hi, uint32_t x, uint32_t n, uint16_t *out,
                             uint32_t *next)
{
    const uint8x16_t mg = vdupq_n_u8(pf->min_gray), rm = vdupq_n_u8(pf->ridge_min);
    const uint8x16_t sm = vdupq_n_u8(pf->side_max);
    uint32_t k = 0u;
    if (n < 16u) {
        return symline_i_line_cand_c(pf, c, lo, hi, x, n, out, next);
    }
    /* 64 entries a step, one test for all. */
    for (; x + 64u <= n; x += 64u) {
        const size_t at = x; /* 64 bits wide: the block offsets fold into the loads */
        uint8x16_t sa, sb, sd, se;
        const uint8x16_t a = ridge_lanes(c, lo, hi, at, mg, rm, &sa);
        const uint8x16_t b = ridge_lanes(c, lo, hi, at + 16u, mg, rm, &sb);
        const uint8x16_t d = ridge_lanes(c, lo, hi, at + 32u, mg, rm, &sd);
        const uint8x16_t e = ridge_lanes(c, lo, hi, at + 48u, mg, rm, &se);
        if (nibbles(vorrq_u8(vorrq_u8(a, b), vorrq_u8(d, e))) != 0u &&
            !(report(nibbles(vandq_u8(a, vcleq_u8(sa, sm))), x, out, &k, next) &&
              report(nibbles(vandq_u8(b, vcleq_u8(sb, sm))), x + 16u, out, &k, next) &&
              report(nibbles(vandq_u8(d, vcleq_u8(sd, sm))), x + 32u, out, &k, next) &&
              report(nibbles(vandq_u8(e, vcleq_u8(se, sm))), x + 48u, out, &k, next))) {
            return k;
        }
    }
    for (; x + 16u <= n; x += 16u) {
        if (!report(nibbles(gray_lanes(c, lo, hi, x, mg, rm, sm)), x, out, &k, next)) {
            return k;
        }
    }
    if (x < n) {
        /* The last 16 entries, without those before x. */
        const uint32_t base = n - 16u;
        const uint64_t bits = nibbles(gray_lanes(c, lo, hi, base, mg, rm, sm));
        if (!report(bits & (~(uint64_t)0 << (4u * (x - base))), base, out, &k, next)) {
            return k;
        }
    }
    *next = n;
    return k;
}
