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
 * radii (not used by the detector, which allows 32) take the reference.
 * Sums are exact: an energy is below 2^32 (255^2 * 255 * 256 / 2).
 */
#include <emmintrin.h>
#include <stddef.h>

#include "symmetry.h"

/* 255^2: the squared difference counted for a pair that leaves the image. */
#define SL_DMAX2 65025u
/* Largest radius whose weighted differences fit madd's signed 16 bits. */
#define SL_MADD_RADIUS_MAX 128u
/* Pairs summed in registers per pass over a row (the detector's radius 3
 * needs one pass; larger radii add further passes onto the stored sums). Four
 * keep the eight row pointers in registers. */
#define SL_PASS_PAIRS 4u

/* The pairs of one pass: pair p compares lo[p][x] with hi[p][x] at weight w[p]. */
typedef struct pass {
    const uint8_t *lo[SL_PASS_PAIRS];
    const uint8_t *hi[SL_PASS_PAIRS];
    uint32_t w[SL_PASS_PAIRS];
    uint32_t n; /* pairs, 1..SL_PASS_PAIRS */
} pass;

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

/* acc[0..3] (pixels x .. x+15, 4 per register) += the np pairs' sums, two
 * pairs per madd (an odd last pair with a zero partner). np is a constant
 * where this is inlined, so the pair loop unrolls and the row pointers stay
 * in registers. */
static inline __attribute__((always_inline)) void block(const uint8_t *const *lo,
                                                        const uint8_t *const *hi,
                                                        const __m128i *wv, uint32_t np, size_t x,
                                                        __m128i acc[4])
{
    const __m128i zero = _mm_setzero_si128();
    uint32_t p;
    for (p = 0; p < np; p += 2u) {
        const __m128i d1 = absdiff(lo[p] + x, hi[p] + x);
        const __m128i d2 = (p + 1u < np) ? absdiff(lo[p + 1u] + x, hi[p + 1u] + x) : zero;
        const __m128i il = _mm_unpacklo_epi8(d1, d2), ih = _mm_unpackhi_epi8(d1, d2);
        const __m128i w = wv[p / 2u];
        __m128i v[4];
        int i;
        v[0] = _mm_unpacklo_epi8(il, zero);
        v[1] = _mm_unpackhi_epi8(il, zero);
        v[2] = _mm_unpacklo_epi8(ih, zero);
        v[3] = _mm_unpackhi_epi8(ih, zero);
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

/*
 * E[x] = base[x] + sum over the pass's pairs for x < count, base[x] = init on
 * the first pass over a row (add 0), E[x] itself on later ones (add 1).
 */
static inline __attribute__((always_inline)) void run_pass(const pass *ps, uint32_t np,
                                                           uint32_t count, uint32_t init, int add,
                                                           uint32_t *E)
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
        block(lo, hi, wv, np, x, acc);
        store_block(E + x, acc);
    }
    if (x == count) {
        return;
    }
    if (!add && count >= 16u) {
        /* The last 16 entries once more: the same values, rewritten. */
        __m128i acc[4] = {vinit, vinit, vinit, vinit};
        x = count - 16u;
        block(lo, hi, wv, np, x, acc);
        store_block(E + x, acc);
        return;
    }
    for (; x < count; x++) {
        uint32_t e = add ? E[x] : init;
        for (p = 0; p < np; p++) {
            const int32_t d = (int32_t)lo[p][x] - (int32_t)hi[p][x];
            e += ps->w[p] * (uint32_t)(d * d);
        }
        E[x] = e;
    }
}

/* One pass with its pair count and mode as constants. */
static void do_pass(const pass *ps, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    switch (ps->n * 2u + (add ? 1u : 0u)) {
    case 2: run_pass(ps, 1u, count, init, 0, E); break;
    case 3: run_pass(ps, 1u, count, init, 1, E); break;
    case 4: run_pass(ps, 2u, count, init, 0, E); break;
    case 5: run_pass(ps, 2u, count, init, 1, E); break;
    case 6: run_pass(ps, 3u, count, init, 0, E); break;
    case 7: run_pass(ps, 3u, count, init, 1, E); break;
    case 8: run_pass(ps, 4u, count, init, 0, E); break;
    default: run_pass(ps, 4u, count, init, 1, E); break;
    }
}

/* Adds pair (a, b) at weight w to the pass; runs it over E when full. */
static void push_pair(pass *ps, const uint8_t *a, const uint8_t *b, uint32_t w, uint32_t count,
                      uint32_t init, int *add, uint32_t *E)
{
    ps->lo[ps->n] = a;
    ps->hi[ps->n] = b;
    ps->w[ps->n] = w;
    if (++ps->n == SL_PASS_PAIRS) {
        do_pass(ps, count, init, *add, E);
        ps->n = 0u;
        *add = 1;
    }
}

/* Runs what is left of the pass; a row without any pair is init throughout. */
static void finish(pass *ps, uint32_t count, uint32_t init, int add, uint32_t *E)
{
    uint32_t x;
    if (ps->n > 0u) {
        do_pass(ps, count, init, add, E);
    } else if (!add) {
        for (x = 0; x < count; x++) {
            E[x] = init;
        }
    }
}

/* The energy at k < m entries from the nearer end of a row, q + k its centre:
 * the pairs beyond the end count 255^2 each (lib/symmetry.c). */
static uint32_t row_end(const uint8_t *q, uint32_t m, uint32_t k)
{
    const uint32_t t = m - k;
    uint32_t e = SL_DMAX2 * (t * (t + 1u) / 2u), j;
    for (j = 1u; j <= k; j++) {
        const int32_t d = (int32_t)q[k - j] - (int32_t)q[k + j];
        e += (m + 1u - j) * (uint32_t)(d * d);
    }
    return e;
}

void symline_i_energy_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t *E)
{
    pass ps;
    int add = 0;
    uint32_t j;
    const uint8_t *c;
    if (m > SL_MADD_RADIUS_MAX || n < 2u * m + 16u) {
        symline_i_energy_row_c(q, n, m, E);
        return;
    }
    /* The m entries at either end, where pairs leave the row. */
    for (j = 0; j < m; j++) {
        E[j] = row_end(q, m, j);
        E[n - 1u - j] = row_end(q + (n - 1u - 2u * j), m, j);
    }
    /* The interior m .. n-1-m, where every pair lies in the row. */
    c = q + m;
    ps.n = 0u;
    for (j = 1u; j <= m; j++) {
        push_pair(&ps, c - j, c + j, m + 1u - j, n - 2u * m, 0u, &add, E + m);
    }
    finish(&ps, n - 2u * m, 0u, add, E + m);
}

void symline_i_energy_across(const uint8_t *const *rows, uint32_t m, uint32_t width, uint32_t *E)
{
    pass ps;
    int add = 0;
    uint32_t j, border = 0u;
    if (m > SL_MADD_RADIUS_MAX) {
        symline_i_energy_across_c(rows, m, width, E);
        return;
    }
    /* A pair with a partner outside the image adds the same 255^2 to every column. */
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] == NULL || rows[m + j] == NULL) {
            border += (m + 1u - j) * SL_DMAX2;
        }
    }
    ps.n = 0u;
    for (j = 1u; j <= m; j++) {
        if (rows[m - j] != NULL && rows[m + j] != NULL) {
            push_pair(&ps, rows[m - j], rows[m + j], m + 1u - j, width, border, &add, E);
        }
    }
    finish(&ps, width, border, add, E);
}
