/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line points' decision of a row's candidates down the columns and
 * along a row (lib/linepoints.h) with SSE2 intrinsics (x86-64 baseline),
 * selected at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt)
 * in place of the portable references, with the same result
 * (tests/core/test_linepoints_simd.c compares them):
 *
 * symline_i_cand_down() for symline_i_cand_down_c(): the byte test 64
 * entries a step (x86/bytetest_sse2.h), then the step's candidates in
 * groups of the eight entries from a candidate on, straight from its mask,
 * with no list of candidates in between: a line across the columns gives
 * runs of them. In a group, the rest of the gray test first (it fails
 * often, and needs three rows of nine), in 16-bit lanes; then the S
 * decision of those left, in lanes where two or more are, else in scalar
 * registers. The energy 3 d1^2 + 2 d2^2 + d3^2 is two pmaddwd per four
 * entries, squares of (d1, d2) and (d1, d3) summed in pairs: the
 * compiler's version of the portable lane loop widens every product to 32
 * bits on its own (pmullw, pmulhuw, two unpacks) and, with sixteen entries
 * in 32-bit lanes, spills registers.
 *
 * symline_i_s_along3_keep() for symline_i_s_along3_keep_c(): the nine
 * differences of E(i-1), E(i), E(i+1) of a candidate along a row from five
 * 4-byte loads within p[-4 .. 4] (the pair j of each of the three energies
 * lies 2j entries apart, so one subtraction of two loads gives d_j of all
 * three), d1 and d2 side by side for one pmaddwd with weights 3 and 2, d3
 * squared by another; the two differences to E(i) and their signs in one
 * movemask. In one call per batch: a call per candidate cost the batch's
 * loop its registers (callgrind: 0.06 instructions per pixel more on ex01).
 */
#include <emmintrin.h>
#include <string.h>

#include "bytetest_sse2.h"
#include "linepoints.h"

/* Eight gray values from p, in 16-bit lanes. */
static inline __m128i load8(const uint8_t *p)
{
    return _mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(const void *)p),
                             _mm_setzero_si128());
}

/* 3 d1^2 + 2 d2^2 + d3^2 of eight entries (|d| <= 255 in 16-bit lanes) as
 * 2 (d1^2 + d2^2) + (d1^2 + d3^2), each sum one pmaddwd per four entries:
 * entries 0-3 to *lo, 4-7 to *hi. */
static inline void energy8(__m128i d1, __m128i d2, __m128i d3, __m128i *lo, __m128i *hi)
{
    const __m128i a0 = _mm_unpacklo_epi16(d1, d2), a1 = _mm_unpackhi_epi16(d1, d2);
    const __m128i b0 = _mm_unpacklo_epi16(d1, d3), b1 = _mm_unpackhi_epi16(d1, d3);
    *lo = _mm_add_epi32(_mm_slli_epi32(_mm_madd_epi16(a0, a0), 1), _mm_madd_epi16(b0, b0));
    *hi = _mm_add_epi32(_mm_slli_epi32(_mm_madd_epi16(a1, a1), 1), _mm_madd_epi16(b1, b1));
}

/* The rest of the gray test of eight entries r[0 .. 7], sides r[-4 st],
 * r[4 st] (symline_i_lane_gray_ok()), in 16-bit lanes: all ones where they
 * pass. */
static inline __m128i gray8(const uint8_t *r, ptrdiff_t st, __m128i rmin1, __m128i rp, __m128i ap,
                            __m128i paper)
{
    const __m128i m4 = load8(r - 4 * st), p0 = load8(r), p4 = load8(r + 4 * st);
    const __m128i z = _mm_setzero_si128();
    const __m128i side = _mm_max_epi16(m4, p4), t = _mm_sub_epi16(p0, side);
    /* t100 >= x (unsigned) as x -sat t100 == 0 */
    const __m128i t100 = _mm_mullo_epi16(t, _mm_set1_epi16(100));
    const __m128i ok = _mm_and_si128(
        _mm_cmpgt_epi16(t, rmin1),
        _mm_and_si128(
            _mm_cmpeq_epi16(_mm_subs_epu16(_mm_mullo_epi16(p0, rp), t100), z),
            _mm_cmpeq_epi16(
                _mm_subs_epu16(_mm_mullo_epi16(_mm_sub_epi16(side, _mm_min_epi16(m4, p4)), ap),
                               t100),
                z)));
    return _mm_or_si128(paper, ok);
}

/* The S decision of eight entries r[0 .. 7] in 16-bit lanes: *maybe all
 * ones where neither E(y-1) nor E(y+1) is below E(y), *s where both are
 * above. */
static inline void s8(const uint8_t *r, ptrdiff_t st, __m128i *maybe, __m128i *s)
{
    const __m128i m4 = load8(r - 4 * st), m3 = load8(r - 3 * st), m2 = load8(r - 2 * st);
    const __m128i m1 = load8(r - st), p0 = load8(r), p1 = load8(r + st);
    const __m128i p2 = load8(r + 2 * st), p3 = load8(r + 3 * st), p4 = load8(r + 4 * st);
    __m128i up0, up1, e0, e1, dn0, dn1, low;
    energy8(_mm_sub_epi16(m2, p0), _mm_sub_epi16(m3, p1), _mm_sub_epi16(m4, p2), &up0, &up1);
    energy8(_mm_sub_epi16(m1, p1), _mm_sub_epi16(m2, p2), _mm_sub_epi16(m3, p3), &e0, &e1);
    energy8(_mm_sub_epi16(p0, p2), _mm_sub_epi16(m1, p3), _mm_sub_epi16(m2, p4), &dn0, &dn1);
    /* the smaller of E(y-1) - E(y), E(y+1) - E(y) in 16-bit lanes (saturated:
     * the sign and 0 stay); maybe S: it is >= 0; S: > 0 */
    low = _mm_min_epi16(_mm_packs_epi32(_mm_sub_epi32(up0, e0), _mm_sub_epi32(up1, e1)),
                        _mm_packs_epi32(_mm_sub_epi32(dn0, e0), _mm_sub_epi32(dn1, e1)));
    *maybe = _mm_cmpgt_epi16(low, _mm_set1_epi16(-1));
    *s = _mm_cmpgt_epi16(low, _mm_setzero_si128());
}

/* symline_i_s3_down() (linepoints.h) of a lone candidate, in scalar
 * registers: apart, so that the row's loop keeps its registers. */
__attribute__((noinline)) static uint32_t s1(const uint8_t *p, ptrdiff_t st)
{
    return symline_i_s3_down(p, st);
}

uint32_t symline_i_cand_down(const symline_i_prefilter *pf, const symline_i_lane_gray *g,
                             const uint8_t *c, const uint8_t *lo, const uint8_t *hi, ptrdiff_t st,
                             uint32_t x, uint32_t n, uint16_t *out, uint64_t *plateau,
                             uint32_t *next)
{
    const __m128i rmin1 = _mm_set1_epi16((short)(g->ridge_min - 1));
    const __m128i rp = _mm_set1_epi16((short)g->ridge_pct), ap = _mm_set1_epi16((short)g->asym_pct);
    const __m128i paper = _mm_set1_epi16((short)(g->paper != 0u ? -1 : 0));
    uint16_t *o = out; /* the next kept entry goes here */
    const uint32_t end = n;
    uint64_t pl = 0u, bits;
    sl_bytetest t;
    size_t base;
    if (n < 16u) {
        return symline_i_cand_down_c(pf, g, c, lo, hi, st, x, n, out, plateau, next);
    }
    sl_bytetest_init(&t, pf, c, lo, hi, x, n);
    while ((bits = sl_bytetest_next(&t, &base)) != 0u) {
        do {
            /* the eight entries from the first candidate on, or the row's
             * last eight (every step starts 16 or more entries before the
             * row's end; entries before the candidate are done or before x,
             * their bits clear) */
            const uint32_t first = (uint32_t)base + (uint32_t)__builtin_ctzll(bits);
            const uint32_t at = first + 8u <= end ? first : end - 8u, j = at - (uint32_t)base;
            uint32_t want = (uint32_t)(bits >> j) & 0xffu;
            __m128i mb, sm;
            uint32_t both, keep;
            if (o + 8 > out + SL_LINE_CAND_MAX) {
                /* no room for eight more: on from the candidate */
                *next = first;
                *plateau = pl;
                return (uint32_t)(o - out);
            }
            bits &= ~((uint64_t)0xffu << j);
            if ((want & (want - 1u)) != 0u) {
                /* the rest of the gray test in lanes first: it fails often */
                want &= (uint32_t)_mm_movemask_epi8(
                    _mm_packs_epi16(gray8(c + at, st, rmin1, rp, ap, paper), _mm_setzero_si128()));
                if ((want & (want - 1u)) != 0u) {
                    s8(c + at, st, &mb, &sm);
                    /* bits 0-7: S, 8-15: maybe S */
                    both = (uint32_t)_mm_movemask_epi8(_mm_packs_epi16(sm, mb));
                    keep = (both >> 8) & want;
                    if ((keep & ~both) != 0u) { /* rare: plateaus among them */
                        for (; keep != 0u; keep &= keep - 1u) {
                            const uint32_t i = (uint32_t)__builtin_ctz(keep);
                            pl |= (uint64_t)(((both >> i) & 1u) ^ 1u) << (o - out);
                            *o++ = (uint16_t)(at + i);
                        }
                        continue;
                    }
                    for (; keep != 0u; keep &= keep - 1u) {
                        *o++ = (uint16_t)(at + (uint32_t)__builtin_ctz(keep));
                    }
                    continue;
                }
                if (want == 0u) {
                    continue;
                }
            } else {
                /* one candidate: the rest of its gray test alone */
                const uint8_t *const q = c + at + __builtin_ctz(want);
                if (symline_i_lane_gray_ok(g, q[0], q[-4 * st], q[4 * st]) == 0u) {
                    continue;
                }
            }
            {
                /* one candidate past the gray test: its energies alone */
                const uint32_t e = at + (uint32_t)__builtin_ctz(want), code = s1(c + e, st);
                pl |= (uint64_t)(code >> 1) << (o - out);
                *o = (uint16_t)e;
                o += code != 0u ? 1 : 0;
            }
        } while (bits != 0u);
    }
    *next = n;
    *plateau = pl;
    return (uint32_t)(o - out);
}

/* The four bytes from p in the low lane. */
static inline __m128i load4(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v);
    return _mm_cvtsi32_si128((int)v);
}

/* The signs that give the code of symline_i_s_along3_c() at p (below). */
static inline uint32_t s_along3(const uint8_t *p)
{
    const __m128i z = _mm_setzero_si128();
    /* entries -2 .. 0 less 0 .. 2 (d1), -3 .. -1 less 1 .. 3 (d2), -4 .. -2
     * less 2 .. 4 (d3) of E(i-1), E(i), E(i+1) in lanes 0 .. 2 */
    const __m128i l1 = load4(p - 2), r1 = load4(p), l2 = load4(p - 3), r2 = load4(p + 1);
    const __m128i l3 = load4(p - 4), r3 = _mm_srli_epi32(r2, 8);
    /* d1, d2 interleaved: (d1, d2) of E(i-1), of E(i), of E(i+1) */
    const __m128i d12 = _mm_sub_epi16(_mm_unpacklo_epi8(_mm_unpacklo_epi8(l1, l2), z),
                                      _mm_unpacklo_epi8(_mm_unpacklo_epi8(r1, r2), z));
    const __m128i d3 =
        _mm_unpacklo_epi16(_mm_sub_epi16(_mm_unpacklo_epi8(l3, z), _mm_unpacklo_epi8(r3, z)), z);
    /* 3 d1^2 + 2 d2^2 + d3^2 in 32-bit lanes: E(i-1), E(i), E(i+1) */
    const __m128i e = _mm_add_epi32(
        _mm_madd_epi16(d12, _mm_mullo_epi16(d12, _mm_set_epi16(2, 3, 2, 3, 2, 3, 2, 3))),
        _mm_madd_epi16(d3, d3));
    /* E(i-1) - E(i), E(i+1) - E(i) (as a, b: |E| < 2^20), each also less
     * 1: their signs say a < 0, a <= 0, b < 0, b <= 0 in bits 0 .. 3 */
    const __m128i d = _mm_sub_epi32(e, _mm_shuffle_epi32(e, 0x55));
    return (uint32_t)_mm_movemask_ps(
        _mm_castsi128_ps(_mm_sub_epi32(_mm_shuffle_epi32(d, 0xA0), _mm_set_epi32(1, 0, 1, 0))));
}

/* The code of symline_i_s_along3_c() for each value of s_along3(): 1 for 0
 * (a > 0 and b > 0), 2 for 2, 8, 10 (a >= 0 and b >= 0, one of them 0),
 * else 0. */
static const uint8_t along3_code[16] = {1u, 0u, 2u, 0u, 0u, 0u, 0u, 0u,
                                        2u, 0u, 2u, 0u, 0u, 0u, 0u, 0u};

uint32_t symline_i_s_along3_keep(const uint8_t *row, uint16_t *cand, uint32_t k, uint64_t *plateau)
{
    const uint16_t *const end = cand + k;
    uint16_t *in = cand, *o = cand; /* the next kept entry goes to o */
    uint64_t pl = 0u;
    for (; in != end; in++) {
        const uint32_t x = *in, code = along3_code[s_along3(row + x)];
        *o = (uint16_t)x;
        if (code > 1u) { /* rare */
            pl |= (uint64_t)1 << (o - cand);
        }
        o += code != 0u ? 1 : 0;
    }
    *plateau = pl;
    return (uint32_t)(o - cand);
}
