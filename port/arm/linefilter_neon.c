/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's searches of a map row with AArch64 Advanced SIMD (NEON)
 * intrinsics, selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable references of
 * lib/linefilter.h, with the same results (tests/core/test_operator_simd.c and
 * tests/core/test_linefilter_simd.c compare them):
 *
 * symline_i_find_s() for symline_i_find_s_c(): the reference spends a compare
 * and a branch on every entry to find the next S point. Here 16 entries are
 * compared at once; NEON has no byte mask like SSE2's movemask, so a block
 * with a hit is narrowed to 4 bits per entry (vshrn), whose lowest set bit
 * gives the entry. Compilers do not vectorise a search that stops at its
 * first hit.
 *
 * symline_i_line_s() for symline_i_line_s_c(): about one entry in four is an S
 * point and few of them pass the byte test (one in 30 to 60 on the frames
 * measured), so the test and the search are one pass, 64 entries a step: the
 * gray values first (three loads and four instructions per 16: max,
 * saturating add, max, compare), one test for the step, and only in steps
 * where some pass (about a third) the map, its S compare and the nibble masks.
 */
#include <arm_neon.h>

#include "linefilter.h"

/* Bits 4i .. 4i+3 set where byte lane i of v is set (lanes all 0 or all 1). */
static inline uint64_t nibbles(uint8x16_t v)
{
    return vget_lane_u64(vreinterpret_u64_u8(vshrn_n_u16(vreinterpretq_u16_u8(v), 4)), 0);
}

/* Bits 4i .. 4i+3 set where entry i of p[0..15] is an S point. */
static inline uint64_t s_nibbles(const uint8_t *p)
{
    return nibbles(vceqq_u8(vld1q_u8(p), vdupq_n_u8(SYMLINE_MAP_S)));
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

/* Lanes all set where entry x + i (i < 16) passes the byte test (S point or not). */
static inline uint8x16_t gray_lanes(const uint8_t *c, const uint8_t *lo, const uint8_t *hi,
                                    size_t x, uint8x16_t mg, uint8x16_t rm)
{
    const uint8x16_t side = vmaxq_u8(vld1q_u8(lo + x), vld1q_u8(hi + x));
    return vcgeq_u8(vld1q_u8(c + x), vmaxq_u8(vqaddq_u8(side, rm), mg));
}

/* The S points among lanes g of entries x .. x+15. */
static inline uint8x16_t s_of(const uint8_t *map, size_t x, uint8x16_t g)
{
    return vandq_u8(g, vceqq_u8(vld1q_u8(map + x), vdupq_n_u8(SYMLINE_MAP_S)));
}

static inline uint8x16_t line_s_lanes(const uint8_t *map, const uint8_t *c, const uint8_t *lo,
                                      const uint8_t *hi, size_t x, uint8x16_t mg, uint8x16_t rm)
{
    return s_of(map, x, gray_lanes(c, lo, hi, x, mg, rm));
}

/* Appends base + i for every set nibble i of bits; false when out filled up
 * (then *next is the entry after the last one). */
static inline int report(uint64_t bits, uint32_t base, uint16_t *out, uint32_t *k, uint32_t *next)
{
    for (bits &= 0x8888888888888888u; bits != 0u; bits &= bits - 1u) {
        const uint32_t i = base + (uint32_t)__builtin_ctzll(bits) / 4u;
        out[(*k)++] = (uint16_t)i;
        if (*k == SL_LINE_S_MAX) {
            *next = i + 1u;
            return 0;
        }
    }
    return 1;
}

uint32_t symline_i_line_s(const symline_i_prefilter *pf, const uint8_t *map, const uint8_t *c,
                          const uint8_t *lo, const uint8_t *hi, uint32_t x, uint32_t n,
                          uint16_t *out, uint32_t *next)
{
    const uint8x16_t mg = vdupq_n_u8(pf->min_gray), rm = vdupq_n_u8(pf->ridge_min);
    uint32_t k = 0u;
    if (n < 16u) {
        return symline_i_line_s_c(pf, map, c, lo, hi, x, n, out, next);
    }
    /* 64 entries a step, one test for all; the map only where some gray
     * values pass. */
    for (; x + 64u <= n; x += 64u) {
        const size_t at = x; /* 64 bits wide: the block offsets fold into the loads */
        const uint8x16_t a = gray_lanes(c, lo, hi, at, mg, rm);
        const uint8x16_t b = gray_lanes(c, lo, hi, at + 16u, mg, rm);
        const uint8x16_t d = gray_lanes(c, lo, hi, at + 32u, mg, rm);
        const uint8x16_t e = gray_lanes(c, lo, hi, at + 48u, mg, rm);
        if (nibbles(vorrq_u8(vorrq_u8(a, b), vorrq_u8(d, e))) != 0u &&
            !(report(nibbles(s_of(map, at, a)), x, out, &k, next) &&
              report(nibbles(s_of(map, at + 16u, b)), x + 16u, out, &k, next) &&
              report(nibbles(s_of(map, at + 32u, d)), x + 32u, out, &k, next) &&
              report(nibbles(s_of(map, at + 48u, e)), x + 48u, out, &k, next))) {
            return k;
        }
    }
    for (; x + 16u <= n; x += 16u) {
        if (!report(nibbles(line_s_lanes(map, c, lo, hi, x, mg, rm)), x, out, &k, next)) {
            return k;
        }
    }
    if (x < n) {
        /* The last 16 entries, without those before x. */
        const uint32_t base = n - 16u;
        const uint64_t bits = nibbles(line_s_lanes(map, c, lo, hi, base, mg, rm));
        if (!report(bits & (~(uint64_t)0 << (4u * (x - base))), base, out, &k, next)) {
            return k;
        }
    }
    *next = n;
    return k;
}
