/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_extrema_along() and symline_i_extrema_across() with SSE2
 * intrinsics (x86-64 baseline), selected at build time (CMake option
 * SYMLINE_SIMD, port/CMakeLists.txt) in place of the portable references
 * of lib/extrema.c, with the same output (tests/core/test_extrema_runs.c
 * compares them).
 *
 * Why: the decision needs only the signs of the differences to the two
 * neighbours, and a saturating pack keeps sign and zero: from 32 to 16 and
 * from 16 to 8 bits. So 16 entries are decided at once in byte lanes, and
 * each difference is taken once: along a row the difference to the right
 * neighbour, shifted by one byte lane, is the next entry's to the left; down
 * the columns the signs to the row below are kept (sg) for the next row.
 * Compilers cannot do that from the C (SSE2 has no truncating pack). The
 * plateau mask comes from the same byte lanes, one movemask per 16 entries.
 * A block whose length is not a multiple of 16 ends with its last 16 entries
 * decided once more (the same values again).
 */
#include <emmintrin.h>

#include "extrema.h"

static inline __m128i load4(const uint32_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* a[i] - b[i] for 16 entries, saturated to signed bytes (sign and zero kept;
 * E < 2^31, so the 32-bit differences are exact). */
static inline __m128i diff16(const uint32_t *a, const uint32_t *b)
{
    const __m128i lo = _mm_packs_epi32(_mm_sub_epi32(load4(a), load4(b)),
                                       _mm_sub_epi32(load4(a + 4), load4(b + 4)));
    const __m128i hi = _mm_packs_epi32(_mm_sub_epi32(load4(a + 8), load4(b + 8)),
                                       _mm_sub_epi32(load4(a + 12), load4(b + 12)));
    return _mm_packs_epi16(lo, hi);
}

/* The signs -1, 0, +1 of 16 signed bytes. */
static inline __m128i sign16(__m128i v)
{
    const __m128i zero = _mm_setzero_si128();
    return _mm_sub_epi8(_mm_cmpgt_epi8(zero, v), _mm_cmpgt_epi8(v, zero));
}

/* The kinds of 16 entries into map from the signs l (of each energy minus
 * its left or upper neighbour's) and r (of the right or lower neighbour's
 * minus the energy's), -1, 0 or +1 each. With v = r - l: an S point where
 * v = 2 (l = -1, r = +1), an A point where v = -2; exactly one of l, r is
 * zero where v is odd. Returns the plateau mask. */
static inline uint32_t decide16(__m128i l, __m128i r, uint8_t *map)
{
    const __m128i v = _mm_sub_epi8(r, l);
    const __m128i s = _mm_cmpeq_epi8(v, _mm_set1_epi8(2));
    const __m128i a =
        _mm_and_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8(-2)), _mm_set1_epi8((char)SYMLINE_MAP_A));
    _mm_storeu_si128((__m128i *)(void *)map, _mm_or_si128(s, a));
    /* bit 0 of each byte to its bit 7 (a 16-bit shift moves no other bit there) */
    return (uint32_t)_mm_movemask_epi8(_mm_slli_epi16(v, 7));
}

/* The mask m of the last 16 entries of a block, at o = n - 16, into the word
 * of entries x .. n-1 (x a multiple of 32, n - x < 32): entries below x are
 * in the word before, already set. */
static inline uint32_t tail_bits(uint32_t m, size_t o, size_t x)
{
    return (o >= x) ? m << (o - x) : m >> (x - o);
}

/* Along a row: the signs r of chunk x (the next entries' minus these) and l
 * (these minus the previous ones'), l from the last r of the chunk before
 * and the first 15 of r, shifted by one byte lane. */
static inline void along_next(const uint32_t *E, size_t x, __m128i *l, __m128i *r)
{
    const __m128i rn = sign16(diff16(E + x + 1, E + x));
    *l = _mm_or_si128(_mm_srli_si128(*r, 15), _mm_slli_si128(rn, 1));
    *r = rn;
}

uint32_t symline_i_extrema_along(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                 uint32_t *restrict ev)
{
    __m128i l, r;
    uint32_t any = 0u, w, m;
    size_t x;
    if (n < 16u) {
        return symline_i_extrema_along_c(E, n, map, ev);
    }
    l = sign16(diff16(E, E - 1));
    r = sign16(diff16(E + 1, E));
    for (x = 0; x + 32u <= n; x += 32u) {
        m = decide16(l, r, map + x);
        along_next(E, x + 16u, &l, &r);
        w = m | (decide16(l, r, map + x + 16u) << 16);
        if (x + 48u <= n) {
            along_next(E, x + 32u, &l, &r);
        }
        ev[x / 32u] = w;
        any |= w;
    }
    if (x < n) {
        /* l, r are chunk x's where it is whole; the last 16 once more */
        const size_t o = n - 16u;
        w = (x + 16u <= n) ? decide16(l, r, map + x) : 0u;
        if (x + 16u != n) {
            m = decide16(sign16(diff16(E + o, E + o - 1)), sign16(diff16(E + o + 1, E + o)),
                         map + o);
            w |= tail_bits(m, o, x);
        }
        ev[x / 32u] = w;
        any |= w;
    }
    return any;
}

/* Down the columns: 16 entries at x, with sg's signs s (read before any store). */
static inline uint32_t across16(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                int8_t *restrict sg, __m128i s, size_t x, uint8_t *restrict map)
{
    const __m128i r = sign16(diff16(dn + x, mid + x));
    _mm_storeu_si128((__m128i *)(void *)(sg + x), r); /* the next row's */
    return decide16(s, r, map + x);
}

static inline __m128i load_sg(const int8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

uint32_t symline_i_extrema_across(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                  int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                  uint32_t *restrict ev)
{
    __m128i s_tail;
    uint32_t any = 0u, w;
    size_t x;
    if (n < 16u) {
        return symline_i_extrema_across_c(mid, dn, sg, n, map, ev);
    }
    /* The last 16 signs before the loop overwrites some of them. */
    s_tail = load_sg(sg + (n - 16u));
    for (x = 0; x + 32u <= n; x += 32u) {
        w = across16(mid, dn, sg, load_sg(sg + x), x, map) |
            (across16(mid, dn, sg, load_sg(sg + x + 16u), x + 16u, map) << 16);
        ev[x / 32u] = w;
        any |= w;
    }
    if (x < n) {
        w = (x + 16u <= n) ? across16(mid, dn, sg, load_sg(sg + x), x, map) : 0u;
        if (x + 16u != n) {
            w |= tail_bits(across16(mid, dn, sg, s_tail, n - 16u, map), n - 16u, x);
        }
        ev[x / 32u] = w;
        any |= w;
    }
    return any;
}
