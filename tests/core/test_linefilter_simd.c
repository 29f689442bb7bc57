/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter's byte test over a row (symline_i_line_cand_c(),
 * lib/linefilter.h) against the exact filter: it reports every entry the
 * gray-value test symline_i_linefilter_gray() keeps, in order, and only
 * entries that pass the byte test as stated; a saturated area passes none.
 * Where the build has a SIMD version (SYMLINE_PORT_LINE_CAND, CMake option
 * SYMLINE_SIMD) it is compared with the reference call by call: every start,
 * rows of every length up to 100 at every alignment, both filters,
 * thresholds from 0 to beyond 255, candidates dense to absent, full outputs.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "linefilter.h"
#include "testutil.h"

#define ROW 128u

/* A random row: gray values c, lo, hi mostly near each other (so all tests
 * are close calls), or anywhere, or at the extremes 0 and 255. */
static void fill(uint8_t *c, uint8_t *lo, uint8_t *hi, uint32_t *s)
{
    const uint32_t spread = 1u + tu_rand(s) % 64u;
    const uint32_t base = tu_rand(s) % 256u, kind = tu_rand(s) % 4u;
    uint32_t i;
    for (i = 0; i < ROW; i++) {
        uint8_t *g[3] = {c, lo, hi};
        uint32_t j;
        for (j = 0; j < 3u; j++) {
            const uint32_t q = tu_rand(s);
            const uint32_t v = kind == 0u   ? q
                               : kind == 1u ? ((q & 1u) ? 255u : 0u)
                                            : base + q % spread;
            g[j][i] = (uint8_t)(v < 255u ? v : 255u);
        }
    }
}

/* Thresholds of either filter, some beyond a byte's range. */
static void pick_filter(symline_i_linefilter *f, uint32_t *s)
{
    static const uint32_t big[] = {0u, 1u, 254u, 255u, 256u, 1000u};
    memset(f, 0, sizeof *f);
    f->kind = (tu_rand(s) % 4u == 0u) ? SYMLINE_FILTER_PAPER : SYMLINE_FILTER_CONTRAST;
    f->min_gray = tu_rand(s) % 8u == 0u ? big[tu_rand(s) % 6u] : tu_rand(s) % 200u;
    f->ridge_min = tu_rand(s) % 8u == 0u ? big[tu_rand(s) % 6u] : tu_rand(s) % 40u;
    f->ridge_pct = tu_rand(s) % 3u == 0u ? tu_rand(s) % 30u : 0u;
    f->asym_pct = tu_rand(s) % 2u == 0u ? 150u : 0u;
    f->side_max = tu_rand(s) % 2u == 0u ? 255u : tu_rand(s) % 256u;
}

/* The byte test as lib/linefilter.h states it. */
static int byte_test(const symline_i_prefilter *pf, uint32_t c, uint32_t lo, uint32_t hi)
{
    const uint32_t side = lo > hi ? lo : hi;
    const uint32_t need = side + pf->ridge_min < 255u ? side + pf->ridge_min : 255u;
    return c >= pf->min_gray && c >= need && side <= pf->side_max;
}

/* The reference over the whole of [x, n), call after call as the detector
 * makes them: every entry the exact test keeps is reported, everything
 * reported passes the byte test, in increasing order, at most
 * SL_LINE_CAND_MAX a call. */
static void reference_keeps_line_points(void **state)
{
    uint8_t c[ROW], lo[ROW], hi[ROW];
    uint32_t s = 5u, t;
    (void)state;
    for (t = 0; t < 20000u; t++) {
        symline_i_linefilter f;
        symline_i_prefilter pf;
        uint8_t seen[ROW];
        const uint32_t n = tu_rand(&s) % (ROW + 1u);
        uint32_t x = 0u, i, last = 0u, any = 0u;
        pick_filter(&f, &s);
        symline_i_prefilter_setup(&f, &pf);
        fill(c, lo, hi, &s);
        if (f.kind == SYMLINE_FILTER_PAPER) { /* as the detector calls it */
            memcpy(lo, c, sizeof lo);
            memcpy(hi, c, sizeof hi);
        }
        memset(seen, 0, sizeof seen);
        while (x < n) {
            uint16_t out[SL_LINE_CAND_MAX];
            uint32_t next = 0xffffffffu;
            const uint32_t k = symline_i_line_cand_c(&pf, c, lo, hi, x, n, out, &next);
            assert_true(k <= SL_LINE_CAND_MAX);
            assert_true(next > x && next <= n);
            assert_true(k == SL_LINE_CAND_MAX || next == n);
            for (i = 0; i < k; i++) {
                assert_true(out[i] >= x && out[i] < next);
                assert_true(any == 0u || out[i] > last);
                assert_true(byte_test(&pf, c[out[i]], lo[out[i]], hi[out[i]]));
                seen[out[i]] = 1u;
                last = out[i];
                any = 1u;
            }
            x = next;
        }
        for (i = 0; i < n; i++) {
            if (symline_i_linefilter_gray(&f, c[i], lo[i], hi[i])) {
                assert_int_equal(seen[i], 1u);
            }
        }
    }
}

/* Every gray value against every brighter side, for ridges from 0 to
 * beyond a byte: the byte test keeps what the exact test keeps, and for the
 * contrast filter it keeps c = 255 exactly where the side lies ridge_min
 * (1 to 255) or more below it, so that a saturated area, where c
 * and both sides are 255, gives no candidate at all. */
static void saturated_sides_fail(void **state)
{
    static const uint32_t ridges[] = {0u, 1u, 2u, 7u, 40u, 200u, 254u, 255u, 256u, 1000u};
    static const uint32_t sides[] = {255u, 254u, 250u, 128u, 0u};
    uint32_t r, m, c, side;
    (void)state;
    for (r = 0; r < sizeof ridges / sizeof ridges[0]; r++) {
        for (m = 0; m < sizeof sides / sizeof sides[0]; m++) {
            symline_i_linefilter f;
            symline_i_prefilter pf;
            /* the ridge as a byte holds it */
            const uint32_t rm = ridges[r] < 1u ? 1u : ridges[r] > 255u ? 255u : ridges[r];
            memset(&f, 0, sizeof f);
            f.kind = SYMLINE_FILTER_CONTRAST;
            f.ridge_min = ridges[r];
            f.side_max = sides[m];
            symline_i_prefilter_setup(&f, &pf);
            for (side = 0; side < 256u; side++) {
                const int at_255 = side + rm <= 255u && side <= f.side_max;
                assert_int_equal(byte_test(&pf, 255u, side, side / 2u), at_255);
                for (c = 0; c < 256u; c++) {
                    if (symline_i_linefilter_gray(&f, c, side, side / 2u)) {
                        assert_true(byte_test(&pf, c, side, side / 2u));
                    }
                }
            }
        }
    }
}

#ifdef SYMLINE_PORT_LINE_CAND
/* The SIMD version against the reference: the same count, indices and
 * resumption point for every start x of rows of every length and alignment,
 * and no write past the count it returns. */
static void simd_is_reference(void **state)
{
    uint8_t c[ROW + 16u], lo[ROW + 16u], hi[ROW + 16u];
    uint32_t s = 7u, t;
    (void)state;
    for (t = 0; t < 6000u; t++) {
        symline_i_linefilter f;
        symline_i_prefilter pf;
        const uint32_t n = tu_rand(&s) % 101u, off = tu_rand(&s) % 16u;
        uint32_t x;
        pick_filter(&f, &s);
        symline_i_prefilter_setup(&f, &pf);
        fill(c, lo, hi, &s);
        fill(c + 16u, lo + 16u, hi + 16u, &s);
        for (x = 0; x <= n; x++) {
            uint16_t a[SL_LINE_CAND_MAX + 1u], b[SL_LINE_CAND_MAX + 1u];
            uint32_t na = 0xfffu, nb = 0xeeeu, ka, kb;
            memset(a, 0x5a, sizeof a);
            memset(b, 0x5a, sizeof b);
            ka = symline_i_line_cand(&pf, c + off, lo + off, hi + off, x, n, a, &na);
            kb = symline_i_line_cand_c(&pf, c + off, lo + off, hi + off, x, n, b, &nb);
            assert_int_equal(ka, kb);
            assert_int_equal(na, nb);
            assert_memory_equal(a, b, sizeof a);
        }
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reference_keeps_line_points),
        cmocka_unit_test(saturated_sides_fail),
#ifdef SYMLINE_PORT_LINE_CAND
        cmocka_unit_test(simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
