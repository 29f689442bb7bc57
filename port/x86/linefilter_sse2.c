/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's searches of a map row with SSE2 intrinsics (x86-64
 * baseline), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable references of
 * lib/linefilter.h, with the same results (tests/core/test_operator_simd.c and
 * tests/core/test_linefilter_simd.c compare them):
 *
 * symline_i_find_s() for symline_i_find_s_c(): the reference spends a compare
 * and a branch on every entry to find the next S point. Here 16 entries are
 * compared at once and the first S among them is the lowest set bit of the
 * byte mask. Compilers do not vectorise a search that stops at its first hit.
 *
 * symline_i_line_s() for symline_i_line_s_c(): about one entry in four is an S
 * point and one S point in thirty passes the byte test, so the test and the
 * search are one pass, 32 entries per step, nine vector instructions per 16
 * (max, saturating add, max, saturating subtract, compare, the S test as the
 * top bit of the doubled map entry, and, mask), and only the set bits of the
 * mask are visited.
 */
#include <emmintrin.h>

#include "linefilter.h"

static inline __m128i load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

static inline uint32_t s_bits(const uint8_t *p)
{
    const __m128i s = _mm_set1_epi8((char)SYMLINE_MAP_S);
    return (uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(load16(p), s));
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

/* Bit i set where entry x + i (i < 16) is an S point that passes the byte test. */
static inline uint32_t line_s_bits(const uint8_t *map, const uint8_t *c, const uint8_t *lo,
                                   const uint8_t *hi, uint32_t x, __m128i mg, __m128i rm)
{
    const __m128i side = _mm_max_epu8(load16(lo + x), load16(hi + x));
    const __m128i need = _mm_max_epu8(_mm_adds_epu8(side, rm), mg);
    const __m128i pass = _mm_cmpeq_epi8(_mm_subs_epu8(need, load16(c + x)), _mm_setzero_si128());
    const __m128i m = load16(map + x);
    /* S (255) doubled is 254, A (128) and none (0) give 0: the top bit is S. */
    return (uint32_t)_mm_movemask_epi8(_mm_and_si128(pass, _mm_add_epi8(m, m)));
}

uint32_t symline_i_line_s(const symline_i_prefilter *pf, const uint8_t *map, const uint8_t *c,
                          const uint8_t *lo, const uint8_t *hi, uint32_t x, uint32_t n,
                          uint16_t *out, uint32_t *next)
{
    const __m128i mg = _mm_set1_epi8((char)pf->min_gray);
    const __m128i rm = _mm_set1_epi8((char)pf->ridge_min);
    uint32_t k = 0u;
    if (n < 16u) {
        return symline_i_line_s_c(pf, map, c, lo, hi, x, n, out, next);
    }
    while (x < n) {
        uint32_t base, bits = 0u;
        for (; x + 32u <= n; x += 32u) {
            bits = line_s_bits(map, c, lo, hi, x, mg, rm) |
                   line_s_bits(map, c, lo, hi, x + 16u, mg, rm) << 16;
            if (bits != 0u) {
                break;
            }
        }
        base = x;
        if (bits != 0u) {
            x += 32u;
        } else if (x + 16u <= n) {
            bits = line_s_bits(map, c, lo, hi, x, mg, rm);
            x += 16u;
        } else if (x < n) {
            /* The last 16 entries, without those before x. */
            base = n - 16u;
            bits = line_s_bits(map, c, lo, hi, base, mg, rm) & (0xffffu << (x - base));
            x = n;
        }
        for (; bits != 0u; bits &= bits - 1u) {
            const uint32_t i = base + (uint32_t)__builtin_ctz(bits);
            out[k++] = (uint16_t)i;
            if (k == SL_LINE_S_MAX) {
                *next = i + 1u;
                return k;
            }
        }
    }
    *next = n;
    return k;
}
