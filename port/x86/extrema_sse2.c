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

/* The kinds of 16 entries into map from l (the sign of each energy minus
 * its left or upper neighbour's) and r (the right or lower neighbour's
 * minus the energy's): S where l < 0 < r, A where l > 0 > r. Returns their
 * plateau mask (exactly one of l, r zero). lt_r, gt_r: r < 0, r > 0. */
static inline uint32_t decide16(__m128i l, __m128i r, __m128i lt_r, __m128i gt_r, uint8_t *map)
{
    const __m128i zero = _mm_setzero_si128();
    const __m128i s = _mm_and_si128(_mm_cmpgt_epi8(zero, l), gt_r);
    const __m128i a = _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi8(l, zero), lt_r),
                                    _mm_set1_epi8((char)SYMLINE_MAP_A));
    _mm_storeu_si128((__m128i *)(void *)map, _mm_or_si128(s, a));
    return (uint32_t)_mm_movemask_epi8(
        _mm_xor_si128(_mm_cmpeq_epi8(l, zero), _mm_cmpeq_epi8(r, zero)));
}

static inline uint32_t decide16_lr(__m128i l, __m128i r, uint8_t *map)
{
    const __m128i zero = _mm_setzero_si128();
    return decide16(l, r, _mm_cmpgt_epi8(zero, r), _mm_cmpgt_epi8(r, zero), map);
}

/* Sets the plateau mask m of the 16 entries at x in ev (cleared before). */
static inline void put16(uint32_t *ev, size_t x, uint32_t m)
{
    const uint32_t sh = (uint32_t)x % 32u;
    ev[x / 32u] |= m << sh;
    if (sh > 16u) {
        ev[x / 32u + 1u] |= m >> (32u - sh);
    }
}

/* Clears the n entries' words of ev; returns their OR after the decisions. */
static inline void clear_words(uint32_t *ev, uint32_t n)
{
    uint32_t k;
    for (k = 0; 32u * k < n; k++) {
        ev[k] = 0u;
    }
}

static inline uint32_t or_words(const uint32_t *ev, uint32_t n)
{
    uint32_t k, any = 0u;
    for (k = 0; 32u * k < n; k++) {
        any |= ev[k];
    }
    return any;
}

uint32_t symline_i_extrema_along(const uint32_t *E, uint32_t n, uint8_t *restrict map,
                                 uint32_t *restrict ev)
{
    __m128i l, r;
    size_t x = 0u;
    if (n < 16u) {
        return symline_i_extrema_along_c(E, n, map, ev);
    }
    clear_words(ev, n);
    l = diff16(E, E - 1);
    r = diff16(E + 1, E);
    for (;;) {
        put16(ev, x, decide16_lr(l, r, map + x));
        x += 16u;
        if (x + 16u > n) {
            break;
        }
        {
            /* l of the next 16: the last r of these, then the next r's first 15. */
            const __m128i rn = diff16(E + x + 1, E + x);
            l = _mm_or_si128(_mm_srli_si128(r, 15), _mm_slli_si128(rn, 1));
            r = rn;
        }
    }
    if (x < n) {
        x = n - 16u;
        put16(ev, x, decide16_lr(diff16(E + x, E + x - 1), diff16(E + x + 1, E + x), map + x));
    }
    return or_words(ev, n);
}

/* Down the columns: 16 entries at x, with sg's signs s (read before any store). */
static inline uint32_t across16(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                int8_t *restrict sg, __m128i s, size_t x, uint8_t *restrict map)
{
    const __m128i zero = _mm_setzero_si128();
    const __m128i r = diff16(dn + x, mid + x);
    const __m128i lt_r = _mm_cmpgt_epi8(zero, r), gt_r = _mm_cmpgt_epi8(r, zero);
    /* the signs -1, 0, +1 of r for the next row */
    _mm_storeu_si128((__m128i *)(void *)(sg + x), _mm_sub_epi8(lt_r, gt_r));
    return decide16(s, r, lt_r, gt_r, map + x);
}

uint32_t symline_i_extrema_across(const uint32_t *restrict mid, const uint32_t *restrict dn,
                                  int8_t *restrict sg, uint32_t n, uint8_t *restrict map,
                                  uint32_t *restrict ev)
{
    __m128i s_tail;
    size_t x;
    if (n < 16u) {
        return symline_i_extrema_across_c(mid, dn, sg, n, map, ev);
    }
    clear_words(ev, n);
    /* The last 16 signs before the loop overwrites some of them. */
    s_tail = _mm_loadu_si128((const __m128i *)(const void *)(sg + (n - 16u)));
    for (x = 0; x + 16u <= n; x += 16u) {
        put16(ev, x,
              across16(mid, dn, sg, _mm_loadu_si128((const __m128i *)(const void *)(sg + x)), x,
                       map));
    }
    if (x < n) {
        put16(ev, n - 16u, across16(mid, dn, sg, s_tail, n - 16u, map));
    }
    return or_words(ev, n);
}
