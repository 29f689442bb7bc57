/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row with SSE2 intrinsics (x86-64
 * baseline), selected at build time (CMake option SYMLINE_SIMD,
 * port/CMakeLists.txt) in place of the portable reference of
 * lib/linefilter.h, with the same result (tests/core/test_linefilter_simd.c
 * compares them):
 *
 * symline_i_line_cand() for symline_i_line_cand_c(): one to five entries in
 * a hundred pass, so the row is tested 64 entries a step: the gray value
 * and the ridge first (three loads and four instructions per 16: max,
 * saturating add, max, saturating subtract; zero where they pass), one test
 * for the step on the minimum of the four, and only in steps where some
 * pass the brighter side's limit and the masks (it rarely decides whether
 * a step has a candidate, so the common step goes without it);
 * then only the set bits of the masks are visited. The last 33 to 63
 * entries of a row of 64 and more are one such step too, over the row's
 * last 64 (the bits before them cleared).
 */
#include <emmintrin.h>

#include "linefilter.h"

static inline __m128i load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* Lanes 0 where entries x .. x+15 pass the byte test: how far each gray
 * value stays below what it needs, or its brighter side above side_max. */
static inline __m128i gray_short(const uint8_t *c, const uint8_t *lo, const uint8_t *hi, size_t x,
                                 __m128i mg, __m128i rm, __m128i sm)
{
    const __m128i side = _mm_max_epu8(load16(lo + x), load16(hi + x));
    const __m128i need = _mm_max_epu8(_mm_adds_epu8(side, rm), mg);
    return _mm_or_si128(_mm_subs_epu8(need, load16(c + x)), _mm_subs_epu8(side, sm));
}

/* gray_short() without the brighter side's limit: lanes 0 where entries
 * x .. x+15 are bright enough and stand out enough; their brighter sides to
 * *side. */
static inline __m128i ridge_short(const uint8_t *c, const uint8_t *lo, const uint8_t *hi, size_t x,
                                  __m128i mg, __m128i rm, __m128i *side)
{
    *side = _mm_max_epu8(load16(lo + x), load16(hi + x));
    return _mm_subs_epu8(_mm_max_epu8(_mm_adds_epu8(*side, rm), mg), load16(c + x));
}

/* Bit i set where entry i of the 16 passes (shortfall 0). */
static inline uint64_t passed(__m128i shortfall)
{
    return (uint64_t)(uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(shortfall, _mm_setzero_si128()));
}

uint32_t symline_i_line_cand(const symline_i_prefilter *pf, const uint8_t *c, const uint8_t *lo,
                             const uint8_t *hi, uint32_t x, uint32_t n, uint16_t *out,
                             uint32_t *next)
{
    const __m128i mg = _mm_set1_epi8((char)pf->min_gray);
    const __m128i rm = _mm_set1_epi8((char)pf->ridge_min);
    const __m128i sm = _mm_set1_epi8((char)pf->side_max);
    const size_t end = n;
    size_t at = x;     /* 64 bits wide: the block offsets fold into the loads */
    uint16_t *o = out; /* the next index goes here */
    uint16_t *const full = out + SL_LINE_CAND_MAX;
    if (n < 16u) {
        return symline_i_line_cand_c(pf, c, lo, hi, x, n, out, next);
    }
    while (at < end) {
        uint64_t bits = 0u;
        size_t base;
        /* 64 entries a step, one test for all; most steps have no candidate. */
        for (; at + 64u <= end; at += 64u) {
            __m128i sa, sb, sd, se;
            const __m128i a = ridge_short(c, lo, hi, at, mg, rm, &sa);
            const __m128i b = ridge_short(c, lo, hi, at + 16u, mg, rm, &sb);
            const __m128i d = ridge_short(c, lo, hi, at + 32u, mg, rm, &sd);
            const __m128i e = ridge_short(c, lo, hi, at + 48u, mg, rm, &se);
            /* A lane of the minimum is 0 where one of the four passes. */
            if (passed(_mm_min_epu8(_mm_min_epu8(a, b), _mm_min_epu8(d, e))) != 0u) {
                bits = passed(_mm_or_si128(a, _mm_subs_epu8(sa, sm))) |
                       passed(_mm_or_si128(b, _mm_subs_epu8(sb, sm))) << 16 |
                       passed(_mm_or_si128(d, _mm_subs_epu8(sd, sm))) << 32 |
                       passed(_mm_or_si128(e, _mm_subs_epu8(se, sm))) << 48;
                if (bits != 0u) {
                    break;
                }
            }
        }
        base = at;
        if (bits != 0u) {
            at += 64u;
        } else if (at + 32u < end && end >= 64u) {
            /* The last 33 to 63 entries: the row's last 64 in one step,
             * without those before at (0 < at - base < 32). */
            const __m128i a = gray_short(c, lo, hi, end - 64u, mg, rm, sm);
            const __m128i b = gray_short(c, lo, hi, end - 48u, mg, rm, sm);
            const __m128i d = gray_short(c, lo, hi, end - 32u, mg, rm, sm);
            const __m128i e = gray_short(c, lo, hi, end - 16u, mg, rm, sm);
            base = end - 64u;
            if (passed(_mm_min_epu8(_mm_min_epu8(a, b), _mm_min_epu8(d, e))) != 0u) {
                bits = (passed(a) | passed(b) << 16 | passed(d) << 32 | passed(e) << 48) &
                       (~(uint64_t)0 << (at - base));
            }
            at = end;
        } else if (at + 16u <= end) {
            bits = passed(gray_short(c, lo, hi, at, mg, rm, sm));
            at += 16u;
        } else if (at < end) {
            /* The last 16 entries, without those before at. */
            base = end - 16u;
            bits = passed(gray_short(c, lo, hi, base, mg, rm, sm)) & (0xffffu << (at - base));
            at = end;
        }
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
