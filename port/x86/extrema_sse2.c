/* SPDX-License-Identifier: Apache-2.0 */
/*
 * symline_i_extrema_kinds() with SSE2 intrinsics (x86-64 baseline), selected
 * at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of
 * the portable reference symline_i_extrema_kinds_c() of lib/extrema.c, with
 * the same output (tests/core/test_extrema_runs.c compares the two).
 *
 * Why: the decision needs only the signs of mid - up and mid - dn, and a
 * saturating pack from 32 to 16 bits keeps sign and zero. So the lanes are
 * packed once and compared 8 at a time; compilers cannot do that from the
 * C (SSE2 has no 32-to-16 truncating pack), which costs them more than half
 * of the loop in shuffles.
 */
#include <emmintrin.h>

#include "extrema.h"

uint32_t symline_i_extrema_kinds(const uint32_t *restrict up, const uint32_t *restrict mid,
                                 const uint32_t *restrict dn, uint32_t n, uint8_t *restrict map)
{
    const __m128i zero = _mm_setzero_si128();
    const __m128i a_bit = _mm_set1_epi8((char)SYMLINE_MAP_A);
    __m128i flat = zero;
    uint32_t x = 0u, tail;
    for (; x + 16u <= n; x += 16u) {
        __m128i d1[2], d2[2], s[2], l[2];
        int h;
        for (h = 0; h < 2; h++) {
            const size_t o = x + 8u * (uint32_t)h;
            const __m128i b0 = _mm_loadu_si128((const __m128i *)(const void *)(mid + o));
            const __m128i b1 = _mm_loadu_si128((const __m128i *)(const void *)(mid + o + 4u));
            /* E < 2^31: the differences are exact 32-bit signed values. */
            d1[h] = _mm_packs_epi32(
                _mm_sub_epi32(b0, _mm_loadu_si128((const __m128i *)(const void *)(up + o))),
                _mm_sub_epi32(b1, _mm_loadu_si128((const __m128i *)(const void *)(up + o + 4u))));
            d2[h] = _mm_packs_epi32(
                _mm_sub_epi32(b0, _mm_loadu_si128((const __m128i *)(const void *)(dn + o))),
                _mm_sub_epi32(b1, _mm_loadu_si128((const __m128i *)(const void *)(dn + o + 4u))));
            s[h] = _mm_srai_epi16(_mm_and_si128(d1[h], d2[h]), 15); /* both below: S */
            l[h] = _mm_and_si128(_mm_cmpgt_epi16(d1[h], zero), _mm_cmpgt_epi16(d2[h], zero));
            flat = _mm_or_si128(
                flat, _mm_or_si128(_mm_cmpeq_epi16(d1[h], zero), _mm_cmpeq_epi16(d2[h], zero)));
        }
        _mm_storeu_si128((__m128i *)(void *)(map + x),
                         _mm_or_si128(_mm_packs_epi16(s[0], s[1]),
                                      _mm_and_si128(_mm_packs_epi16(l[0], l[1]), a_bit)));
    }
    tail = symline_i_extrema_kinds_c(up + x, mid + x, dn + x, n - x, map + x);
    return tail | (uint32_t)_mm_movemask_epi8(flat);
}
