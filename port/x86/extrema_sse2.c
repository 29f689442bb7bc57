/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_extrema_kinds() with SSE2 intrinsics (x86-64 baseline), selected
 * at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of
 * the portable reference symline_i_extrema_kinds_c() of lib/extrema.c, with
 * the same output (tests/core/test_extrema_runs.c compares the two).
 *
 * Why: the decision needs only the signs of mid - up and mid - dn, and a
 * saturating pack keeps sign and zero: from 32 to 16 and from 16 to 8 bits.
 * So 16 entries are decided at once in byte lanes. Compilers cannot do that
 * from the C (SSE2 has no truncating pack), which costs them more than half
 * of the loop in shuffles. A row whose length is not a multiple of 16 ends
 * with its last 16 entries decided once more (the same values again). The
 * plateau mask comes from the same byte lanes: zero where mid equals a
 * neighbour, one movemask per 16 entries.
 */
#include <emmintrin.h>

#include "extrema.h"

/* The kinds of 16 entries at x into map + x; returns their plateau mask
 * (bit i: mid[x + i] equals exactly one neighbour). */
static inline uint32_t kinds16(const uint32_t *restrict up, const uint32_t *restrict mid,
                               const uint32_t *restrict dn, size_t x, uint8_t *restrict map)
{
    const __m128i zero = _mm_setzero_si128();
    __m128i d1[2], d2[2], b1, b2;
    int h;
    for (h = 0; h < 2; h++) {
        const size_t o = x + 8u * (size_t)h;
        const __m128i m0 = _mm_loadu_si128((const __m128i *)(const void *)(mid + o));
        const __m128i m1 = _mm_loadu_si128((const __m128i *)(const void *)(mid + o + 4u));
        /* E < 2^31: the differences are exact 32-bit signed values. */
        d1[h] = _mm_packs_epi32(
            _mm_sub_epi32(m0, _mm_loadu_si128((const __m128i *)(const void *)(up + o))),
            _mm_sub_epi32(m1, _mm_loadu_si128((const __m128i *)(const void *)(up + o + 4u))));
        d2[h] = _mm_packs_epi32(
            _mm_sub_epi32(m0, _mm_loadu_si128((const __m128i *)(const void *)(dn + o))),
            _mm_sub_epi32(m1, _mm_loadu_si128((const __m128i *)(const void *)(dn + o + 4u))));
    }
    b1 = _mm_packs_epi16(d1[0], d1[1]);
    b2 = _mm_packs_epi16(d2[0], d2[1]);
    _mm_storeu_si128((__m128i *)(void *)(map + x),
                     _mm_or_si128(_mm_cmpgt_epi8(zero, _mm_and_si128(b1, b2)), /* both below: S */
                                  _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi8(b1, zero),
                                                              _mm_cmpgt_epi8(b2, zero)),
                                                _mm_set1_epi8((char)SYMLINE_MAP_A))));
    return (uint32_t)_mm_movemask_epi8(
        _mm_xor_si128(_mm_cmpeq_epi8(b1, zero), _mm_cmpeq_epi8(b2, zero)));
}

uint32_t symline_i_extrema_kinds(const uint32_t *restrict up, const uint32_t *restrict mid,
                                 const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map,
                                 uint32_t *restrict ev)
{
    uint32_t any = 0u, w;
    size_t x = 0u;
    if (n < 16u) {
        return symline_i_extrema_kinds_c(up, mid, dn, n, map, ev);
    }
    for (; x + 32u <= n; x += 32u) {
        w = kinds16(up, mid, dn, x, map) | (kinds16(up, mid, dn, x + 16u, map) << 16);
        ev[x / 32u] = w;
        any |= w;
    }
    if (x < n) {
        /* Entries x .. n-1 (fewer than 32): 16 at x if there are, then the
         * last 16 once more, their mask shifted to its place in word x / 32
         * (entries below x are in the word before, already set). */
        const size_t o = n - 16u;
        w = 0u;
        if (x + 16u <= n) {
            w = kinds16(up, mid, dn, x, map);
        }
        if (x + 16u != n) {
            const uint32_t m = kinds16(up, mid, dn, o, map);
            w |= (o >= x) ? m << (o - x) : m >> (x - o);
        }
        ev[x / 32u] = w;
        any |= w;
    }
    return any;
}
