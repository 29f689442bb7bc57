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
 * point and few of them pass the byte test (one in 30 to 60 on the frames
 * measured), so the test and the search are one pass, 64 entries a step: the gray values first (three loads
 * and four instructions per 16: max, saturating add, max, saturating
 * subtract; zero where they pass), one test for the step on the minimum of
 * the four, and only in steps where some pass (about a third) the map and
 * the masks; then only the set bits of the masks are visited.
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

/* Lanes 0 where entries x .. x+15 pass the byte test (S points or not): how
 * far each gray value stays below what it needs. */
static inline __m128i gray_short(const uint8_t *c, const uint8_t *lo, const uint8_t *hi, size_t x,
                                 __m128i mg, __m128i rm)
{
    const __m128i side = _mm_max_epu8(load16(lo + x), load16(hi + x));
    const __m128i need = _mm_max_epu8(_mm_adds_epu8(side, rm), mg);
    return _mm_subs_epu8(need, load16(c + x));
}

/* Lanes all set where entries x .. x+15 pass the byte test. */
static inline __m128i passed(__m128i shortfall)
{
    return _mm_cmpeq_epi8(shortfall, _mm_setzero_si128());
}

static inline __m128i gray_lanes(const uint8_t *c, const uint8_t *lo, const uint8_t *hi, size_t x,
                                 __m128i mg, __m128i rm)
{
    return passed(gray_short(c, lo, hi, x, mg, rm));
}

/* The S points among lanes g of entries x .. x+15: the top bit of each byte
 * lane (the other bits are not defined). S (255) doubled is 254, A (128) and
 * none (0) give 0. */
static inline __m128i s_of(const uint8_t *map, size_t x, __m128i g)
{
    const __m128i m = load16(map + x);
    return _mm_and_si128(g, _mm_add_epi8(m, m));
}

static inline __m128i line_s_lanes(const uint8_t *map, const uint8_t *c, const uint8_t *lo,
                                   const uint8_t *hi, size_t x, __m128i mg, __m128i rm)
{
    return s_of(map, x, gray_lanes(c, lo, hi, x, mg, rm));
}

static inline uint64_t mask16(__m128i v)
{
    return (uint64_t)(uint32_t)_mm_movemask_epi8(v);
}

uint32_t symline_i_line_s(const symline_i_prefilter *pf, const uint8_t *map, const uint8_t *c,
                          const uint8_t *lo, const uint8_t *hi, uint32_t x, uint32_t n,
                          uint16_t *out, uint32_t *next)
{
    const __m128i mg = _mm_set1_epi8((char)pf->min_gray);
    const __m128i rm = _mm_set1_epi8((char)pf->ridge_min);
    const size_t end = n;
    size_t at = x; /* 64 bits wide: the block offsets fold into the loads */
    uint32_t k = 0u;
    if (n < 16u) {
        return symline_i_line_s_c(pf, map, c, lo, hi, x, n, out, next);
    }
    while (at < end) {
        uint64_t bits = 0u;
        size_t base;
        /* 64 entries a step, one test for all; most steps have no candidate. */
        for (; at + 64u <= end; at += 64u) {
            const __m128i a = gray_short(c, lo, hi, at, mg, rm);
            const __m128i b = gray_short(c, lo, hi, at + 16u, mg, rm);
            const __m128i d = gray_short(c, lo, hi, at + 32u, mg, rm);
            const __m128i e = gray_short(c, lo, hi, at + 48u, mg, rm);
            /* A lane of the minimum is 0 where one of the four passes; the
             * map only where some gray values pass. */
            if (_mm_movemask_epi8(passed(_mm_min_epu8(_mm_min_epu8(a, b), _mm_min_epu8(d, e)))) !=
                0) {
                bits = mask16(s_of(map, at, passed(a))) |
                       mask16(s_of(map, at + 16u, passed(b))) << 16 |
                       mask16(s_of(map, at + 32u, passed(d))) << 32 |
                       mask16(s_of(map, at + 48u, passed(e))) << 48;
                if (bits != 0u) {
                    break;
                }
            }
        }
        base = at;
        if (bits != 0u) {
            at += 64u;
        } else if (at + 16u <= end) {
            bits = mask16(line_s_lanes(map, c, lo, hi, at, mg, rm));
            at += 16u;
        } else if (at < end) {
            /* The last 16 entries, without those before at. */
            base = end - 16u;
            bits = mask16(line_s_lanes(map, c, lo, hi, base, mg, rm)) & (0xffffu << (at - base));
            at = end;
        }
        for (; bits != 0u; bits &= bits - 1u) {
            const uint32_t i = (uint32_t)base + (uint32_t)__builtin_ctzll(bits);
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
