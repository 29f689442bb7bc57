/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row with SSE2 intrinsics, step by
 * step, for the two port functions that search rows with it:
 * symline_i_line_cand() (x86/linefilter_sse2.c) lists the entries that
 * pass, symline_i_cand_down() (x86/linepoints_sse2.c) decides them down the
 * columns at once. One to five entries in a hundred pass, so the row is
 * tested 64 entries a step: the gray value and the ridge first (three loads
 * and four instructions per 16: max, saturating add, max, saturating
 * subtract; zero where they pass), one test for the step on the minimum of
 * the four, and only in steps where some pass the brighter side's limit and
 * the masks (it rarely decides whether a step has a candidate, so the
 * common step goes without it). The last 33 to 63 entries of a row of 64
 * and more are one such step too, over the row's last 64 (the bits before
 * them cleared).
 */
#ifndef SYMLINE_PORT_X86_BYTETEST_SSE2_H
#define SYMLINE_PORT_X86_BYTETEST_SSE2_H

#include <emmintrin.h>

#include "linefilter.h"

static inline __m128i sl_load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* A row's byte test: gray values c[], sides lo[], hi[] (linefilter.h), the
 * entries at .. end-1 not yet tested (at 64 bits wide: the block offsets
 * fold into the loads). */
typedef struct sl_bytetest {
    __m128i mg, rm, sm;
    const uint8_t *c, *lo, *hi;
    size_t at, end;
} sl_bytetest;

static inline void sl_bytetest_init(sl_bytetest *t, const symline_i_prefilter *pf,
                                    const uint8_t *c, const uint8_t *lo, const uint8_t *hi,
                                    uint32_t x, uint32_t n)
{
    t->mg = _mm_set1_epi8((char)pf->min_gray);
    t->rm = _mm_set1_epi8((char)pf->ridge_min);
    t->sm = _mm_set1_epi8((char)pf->side_max);
    t->c = c;
    t->lo = lo;
    t->hi = hi;
    t->at = x;
    t->end = n;
}

/* Lanes 0 where entries x .. x+15 pass the byte test: how far each gray
 * value stays below what it needs, or its brighter side above side_max. */
static inline __m128i sl_gray_short(const sl_bytetest *t, size_t x)
{
    const __m128i side = _mm_max_epu8(sl_load16(t->lo + x), sl_load16(t->hi + x));
    const __m128i need = _mm_max_epu8(_mm_adds_epu8(side, t->rm), t->mg);
    return _mm_or_si128(_mm_subs_epu8(need, sl_load16(t->c + x)), _mm_subs_epu8(side, t->sm));
}

/* sl_gray_short() without the brighter side's limit: lanes 0 where entries
 * x .. x+15 are bright enough and stand out enough; their brighter sides to
 * *side. */
static inline __m128i sl_ridge_short(const sl_bytetest *t, size_t x, __m128i *side)
{
    *side = _mm_max_epu8(sl_load16(t->lo + x), sl_load16(t->hi + x));
    return _mm_subs_epu8(_mm_max_epu8(_mm_adds_epu8(*side, t->rm), t->mg), sl_load16(t->c + x));
}

/* Bit i set where entry i of the 16 passes (shortfall 0). */
static inline uint64_t sl_passed(__m128i shortfall)
{
    return (uint64_t)(uint32_t)_mm_movemask_epi8(_mm_cmpeq_epi8(shortfall, _mm_setzero_si128()));
}

/*
 * The next step with entries that pass, at least 16 entries (end - at >= 16
 * at the start): bit i of the result set where entry *base + i passes, the
 * step's entries after them left for the next call; 0 when no entry is
 * left.
 */
static inline __attribute__((always_inline)) uint64_t sl_bytetest_next(sl_bytetest *t,
                                                                         size_t *base)
{
    const size_t end = t->end;
    size_t at = t->at;
    while (at < end) {
        uint64_t bits = 0u;
        /* 64 entries a step, one test for all; most steps have no candidate. */
        for (; at + 64u <= end; at += 64u) {
            __m128i sa, sb, sd, se;
            const __m128i a = sl_ridge_short(t, at, &sa);
            const __m128i b = sl_ridge_short(t, at + 16u, &sb);
            const __m128i d = sl_ridge_short(t, at + 32u, &sd);
            const __m128i e = sl_ridge_short(t, at + 48u, &se);
            /* A lane of the minimum is 0 where one of the four passes. */
            if (sl_passed(_mm_min_epu8(_mm_min_epu8(a, b), _mm_min_epu8(d, e))) != 0u) {
                bits = sl_passed(_mm_or_si128(a, _mm_subs_epu8(sa, t->sm))) |
                       sl_passed(_mm_or_si128(b, _mm_subs_epu8(sb, t->sm))) << 16 |
                       sl_passed(_mm_or_si128(d, _mm_subs_epu8(sd, t->sm))) << 32 |
                       sl_passed(_mm_or_si128(e, _mm_subs_epu8(se, t->sm))) << 48;
                if (bits != 0u) {
                    break;
                }
            }
        }
        *base = at;
        if (bits != 0u) {
            at += 64u;
        } else if (at + 32u < end && end >= 64u) {
            /* The last 33 to 63 entries: the row's last 64 in one step,
             * without those before at (0 < at - base < 32). */
            const __m128i a = sl_gray_short(t, end - 64u);
            const __m128i b = sl_gray_short(t, end - 48u);
            const __m128i d = sl_gray_short(t, end - 32u);
            const __m128i e = sl_gray_short(t, end - 16u);
            *base = end - 64u;
            if (sl_passed(_mm_min_epu8(_mm_min_epu8(a, b), _mm_min_epu8(d, e))) != 0u) {
                bits = (sl_passed(a) | sl_passed(b) << 16 | sl_passed(d) << 32 |
                        sl_passed(e) << 48) &
                       (~(uint64_t)0 << (at - *base));
            }
            at = end;
        } else if (at + 16u <= end) {
            bits = sl_passed(sl_gray_short(t, at));
            at += 16u;
        } else if (at < end) {
            /* The last 16 entries, without those before at. */
            *base = end - 16u;
            bits = sl_passed(sl_gray_short(t, *base)) & (0xffffu << (at - *base));
            at = end;
        }
        if (bits != 0u) {
            t->at = at;
            return bits;
        }
    }
    t->at = at;
    return 0u;
}

#endif
