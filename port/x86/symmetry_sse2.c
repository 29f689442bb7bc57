/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The symmetry operator's row bodies symline_i_energy_row() and
 * symline_i_energy_across() with SSE2 intrinsics (x86-64 baseline), selected
 * at build time (CMake option SYMLINE_SIMD, port/CMakeLists.txt) in place of
 * the portable references symline_i_energy_*_c() of lib/symmetry.c, with the
 * same output (tests/core/test_operator_simd.c compares them).
 *
 * Why: the reference adds one pair offset j at a time over the whole row, so
 * every pair loads and stores the row of 32-bit energies again, and each
 * product is widened to 32 bits in two multiplies and two shuffles. Here all
 * pairs of a block of 16 pixels are summed in registers and stored once, and
 * two pairs j, k share one _mm_madd_epi16: with the differences interleaved
 * in 16-bit lanes (d_j, d_k) and multiplied by (w_j, w_k), it returns
 * w_j d_j^2 + w_k d_k^2 in each pixel's 32-bit lane. madd multiplies signed
 * 16-bit lanes: w d <= 128 * 255 < 2^15 holds for radii up to 128; larger
 * radii (not used by the detector, which allows 32) take the reference. The
 * detector's default radius 3 needs no weight multiply at all (block()).
 * Sums are exact: an energy is below 2^32 (255^2 * 255 * 256 / 2). The passes
 * over a row, its ends and tail: ../symmetry_rows.h.
 */
#include <emmintrin.h>

/* Largest radius whose weighted differences fit madd's signed 16 bits. */
#define SL_PORT_RADIUS_MAX 128u
#include "../symmetry_rows.h"

static inline __m128i load16(const uint8_t *p)
{
    return _mm_loadu_si128((const __m128i *)(const void *)p);
}

/* |a - b| in byte lanes. */
static inline __m128i absdiff(const uint8_t *a, const uint8_t *b)
{
    const __m128i va = load16(a), vb = load16(b);
    return _mm_or_si128(_mm_subs_epu8(va, vb), _mm_subs_epu8(vb, va));
}

/* The 16-bit lanes (a_i, b_i) of pixels x..x+15, 4 pixels per register, from
 * byte lanes a and b. */
static inline void interleave(__m128i a, __m128i b, __m128i v[4])
{
    const __m128i zero = _mm_setzero_si128();
    const __m128i il = _mm_unpacklo_epi8(a, b), ih = _mm_unpackhi_epi8(a, b);
    v[0] = _mm_unpacklo_epi8(il, zero);
    v[1] = _mm_unpackhi_epi8(il, zero);
    v[2] = _mm_unpacklo_epi8(ih, zero);
    v[3] = _mm_unpackhi_epi8(ih, zero);
}

/*
 * acc[0..3] (pixels x .. x+15, 4 per register) += the np pairs' sums, two
 * pairs per madd (an odd last pair with a zero partner). np and r3 are
 * constants where this is inlined, so the pair loop unrolls and the row
 * pointers stay in registers. r3: the pass is radius 3's whole sum,
 * 3 d1^2 + 2 d2^2 + d3^2 = 2 (d1^2 + d2^2) + (d1^2 + d3^2), two madds of the
 * differences with themselves and no weight multiplies.
 */
static inline __attribute__((always_inline)) void block(const uint8_t *const *lo,
                                                        const uint8_t *const *hi, const __m128i *wv,
                                                        uint32_t np, int r3, size_t x,
                                                        __m128i acc[4])
{
    uint32_t p;
    int i;
    if (r3) {
        const __m128i d1 = absdiff(lo[0] + x, hi[0] + x);
        __m128i v[4], u[4];
        interleave(d1, absdiff(lo[1] + x, hi[1] + x), v);
        interleave(d1, absdiff(lo[2] + x, hi[2] + x), u);
        for (i = 0; i < 4; i++) {
            const __m128i a = _mm_madd_epi16(v[i], v[i]);
            acc[i] = _mm_add_epi32(_mm_add_epi32(acc[i], _mm_madd_epi16(u[i], u[i])),
                                   _mm_add_epi32(a, a));
        }
        return;
    }
    for (p = 0; p < np; p += 2u) {
        const __m128i d1 = absdiff(lo[p] + x, hi[p] + x);
        const __m128i d2 =
            (p + 1u < np) ? absdiff(lo[p + 1u] + x, hi[p + 1u] + x) : _mm_setzero_si128();
        const __m128i w = wv[p / 2u];
        __m128i v[4];
        interleave(d1, d2, v);
        for (i = 0; i < 4; i++) {
            acc[i] = _mm_add_epi32(acc[i], _mm_madd_epi16(v[i], _mm_mullo_epi16(v[i], w)));
        }
    }
}

static inline void store_block(uint32_t *E, const __m128i acc[4])
{
    int i;
    for (i = 0; i < 4; i++) {
        _mm_storeu_si128((__m128i *)(void *)(E + 4 * i), acc[i]);
    }
}

/* One pass over a row (run_pass() below), with the radius-3 form r3 as a constant. */
static inline __attribute__((always_inline)) void
rows(const sl_pass *ps, uint32_t np, int r3, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    const uint8_t *lo[SL_PASS_PAIRS], *hi[SL_PASS_PAIRS];
    __m128i wv[SL_PASS_PAIRS / 2u];
    const __m128i vinit = _mm_set1_epi32((int)init);
    uint32_t p;
    size_t x = 0u;
    for (p = 0; p < np; p++) {
        lo[p] = ps->lo[p];
        hi[p] = ps->hi[p];
    }
    for (p = 0; p < np; p += 2u) {
        /* 16-bit lanes (w_p, w_p+1) matching (d_p, d_p+1) */
        const uint32_t w2 = (p + 1u < np) ? ps->w[p + 1u] : 0u;
        wv[p / 2u] = _mm_set1_epi32((int)(ps->w[p] | (w2 << 16)));
    }
    for (; x + 16u <= count; x += 16u) {
        __m128i acc[4];
        int i;
        for (i = 0; i < 4; i++) {
            acc[i] = add ? _mm_loadu_si128((const __m128i *)(const void *)(E + x + 4u * (size_t)i))
                         : vinit;
        }
        block(lo, hi, wv, np, r3, x, acc);
        store_block(E + x, acc);
    }
    if (x < count && !add && count >= 16u) {
        /* The last 16 entries once more: the same values, rewritten. */
        __m128i acc[4] = {vinit, vinit, vinit, vinit};
        block(lo, hi, wv, np, r3, count - 16u, acc);
        store_block(E + (count - 16u), acc);
        return;
    }
    pass_tail(ps, np, x, count, init, add, E);
}

static inline __attribute__((always_inline)) void
run_pass(const sl_pass *ps, uint32_t np, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    if (np == 3u && !add && ps->w[0] == 3u && ps->w[1] == 2u && ps->w[2] == 1u) {
        /* Rows with every pair inside the image (most) start at zero: no add. */
        if (init == 0u) {
            rows(ps, 3u, 1, count, 0u, 0, E);
        } else {
            rows(ps, 3u, 1, count, init, 0, E);
        }
    } else {
        rows(ps, np, 0, count, init, add, E);
    }
}
