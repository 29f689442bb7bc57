/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line points' decision of a block of entries down the columns
 * (symline_i_lanes_down_c(), lib/linepoints.h) against its definition: for
 * every entry that passes the line filter's byte test, the code says what
 * the exact gray test (symline_i_linefilter_gray()) and the energies
 * E(y-1), E(y), E(y+1) of docs/algorithm.md at m = 3 say. Where the build
 * has a SIMD version (SYMLINE_PORT_LANES_DOWN, CMake option SYMLINE_SIMD)
 * it is compared with the reference on every entry: columns of random,
 * nearly equal (ties, plateaus), mirrored (equal energies) and extreme gray
 * values, both filters, thresholds across their ranges.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "linefilter.h"
#include "linepoints.h"
#include "testutil.h"

#define LANES SL_LANES_DOWN
#define ROWS 9u /* rows y - 4 .. y + 4 */
#define STRIDE_MAX (LANES + 24u)

/* Rows y - 4 .. y + 4 of LANES + 8 columns at stride st from buf. */
static void fill(uint8_t *buf, uint32_t st, uint32_t *s)
{
    const uint32_t kind = tu_rand(s) % 5u, base = tu_rand(s) % 256u;
    const uint32_t spread = 1u + tu_rand(s) % 8u;
    uint32_t r, x;
    for (r = 0; r < ROWS; r++) {
        for (x = 0; x < st; x++) {
            const uint32_t q = tu_rand(s);
            const uint32_t v = kind == 0u   ? q % 256u
                               : kind == 1u ? ((q & 1u) ? 255u : 0u)
                                            : base + q % spread;
            buf[r * st + x] = (uint8_t)(v < 255u ? v : 255u);
        }
    }
    if (kind == 3u || kind == 4u) { /* mirrored about row y - 1, y or y + 1 */
        const uint32_t mid = 3u + tu_rand(s) % 3u;
        for (r = 1u; r <= 3u && mid + r < ROWS; r++) {
            memcpy(buf + (mid + r) * st, buf + (mid - r) * st, st);
        }
    }
}

/* Thresholds within the ranges the detector gives the lanes. */
static void pick(symline_i_linefilter *f, symline_i_lane_gray *g, uint32_t *s)
{
    memset(f, 0, sizeof *f);
    f->kind = tu_rand(s) % 4u == 0u ? SYMLINE_FILTER_PAPER : SYMLINE_FILTER_CONTRAST;
    f->min_gray = tu_rand(s) % 256u;
    f->ridge_min = tu_rand(s) % 8u == 0u ? 200u + tu_rand(s) % 100u : tu_rand(s) % 40u;
    f->ridge_pct = tu_rand(s) % 3u == 0u ? tu_rand(s) % 101u : 0u;
    f->asym_pct = tu_rand(s) % 2u == 0u ? 150u : tu_rand(s) % 258u;
    f->side_max = tu_rand(s) % 2u == 0u ? 255u : tu_rand(s) % 256u;
    g->ridge_min = (int16_t)(f->ridge_min < 1u ? 1u : (f->ridge_min < 256u ? f->ridge_min : 256u));
    g->ridge_pct = (uint16_t)f->ridge_pct;
    g->asym_pct = (uint16_t)f->asym_pct;
    g->paper = (uint16_t)(f->kind == SYMLINE_FILTER_PAPER);
}

/* E at row c of column p (rows at stride st), m = 3: sum of (4 - j) d_j^2. */
static uint32_t energy(const uint8_t *p, ptrdiff_t st, int32_t c)
{
    uint32_t j, e = 0u;
    for (j = 1u; j <= 3u; j++) {
        const int32_t d = (int32_t)p[(c - (int32_t)j) * st] - (int32_t)p[(c + (int32_t)j) * st];
        e += (4u - j) * (uint32_t)(d * d);
    }
    return e;
}

static void reference_is_definition(void **state)
{
    uint8_t buf[ROWS * STRIDE_MAX];
    uint32_t s = 3u, t, checked = 0u, codes[3] = {0u, 0u, 0u};
    (void)state;
    for (t = 0; t < 20000u; t++) {
        const uint32_t st = LANES + tu_rand(&s) % (STRIDE_MAX - LANES + 1u);
        const uint8_t *r = buf + 4u * st, *rlo = buf, *rhi = buf + 8u * st;
        symline_i_linefilter f;
        symline_i_lane_gray g;
        symline_i_prefilter pf;
        uint8_t code[LANES];
        uint32_t i;
        fill(buf, st, &s);
        pick(&f, &g, &s);
        symline_i_prefilter_setup(&f, &pf);
        symline_i_lanes_down_c(r, (ptrdiff_t)st, &g, code);
        for (i = 0; i < LANES; i++) {
            const uint8_t c = r[i], lo = rlo[i], hi = rhi[i];
            const uint8_t blo = f.kind == SYMLINE_FILTER_PAPER ? c : lo;
            const uint8_t bhi = f.kind == SYMLINE_FILTER_PAPER ? c : hi;
            const uint32_t up = energy(r + i, (ptrdiff_t)st, -1),
                           e = energy(r + i, (ptrdiff_t)st, 0);
            const uint32_t dn = energy(r + i, (ptrdiff_t)st, 1);
            uint16_t out[SL_LINE_CAND_MAX];
            uint32_t next;
            uint32_t want;
            if (symline_i_line_cand_c(&pf, &c, &blo, &bhi, 0u, 1u, out, &next) == 0u) {
                continue; /* no candidate: the code is not read */
            }
            want = !symline_i_linefilter_gray(&f, c, lo, hi) || up < e || dn < e ? 0u
                   : up > e && dn > e                                            ? 1u
                                                                                 : 2u;
            assert_int_equal(code[i], want);
            codes[want]++;
            checked++;
        }
    }
    /* every outcome was met many times */
    assert_true(checked > 10000u);
    assert_true(codes[0] > 1000u && codes[1] > 1000u && codes[2] > 1000u);
}

#ifdef SYMLINE_PORT_LANES_DOWN
/* The SIMD version against the reference: the same code for every entry
 * (also those no byte test would pass), at every stride and alignment. */
static void simd_is_reference(void **state)
{
    uint8_t buf[ROWS * STRIDE_MAX + 16u];
    uint32_t s = 9u, t;
    (void)state;
    for (t = 0; t < 20000u; t++) {
        const uint32_t st = LANES + tu_rand(&s) % (STRIDE_MAX - LANES + 1u);
        const uint32_t off = tu_rand(&s) % 16u;
        const uint8_t *r = buf + off + 4u * st;
        symline_i_linefilter f;
        symline_i_lane_gray g;
        uint8_t a[LANES + 1u], b[LANES + 1u];
        fill(buf + off, st, &s);
        pick(&f, &g, &s);
        memset(a, 0x5a, sizeof a);
        memset(b, 0x5a, sizeof b);
        symline_i_lanes_down(r, (ptrdiff_t)st, &g, a);
        symline_i_lanes_down_c(r, (ptrdiff_t)st, &g, b);
        assert_memory_equal(a, b, sizeof a);
    }
}
#endif

/* A row of n gray values for the decision along it: random, nearly equal,
 * extreme, or with windows mirrored about a few entries (equal energies). */
static void fill_row(uint8_t *row, uint32_t n, uint32_t *s)
{
    const uint32_t kind = tu_rand(s) % 5u, base = tu_rand(s) % 256u;
    const uint32_t spread = 1u + tu_rand(s) % 8u;
    uint32_t x, j;
    for (x = 0; x < n; x++) {
        const uint32_t q = tu_rand(s);
        const uint32_t v = kind == 0u   ? q % 256u
                           : kind == 1u ? ((q & 1u) ? 255u : 0u)
                                        : base + q % spread;
        row[x] = (uint8_t)(v < 255u ? v : 255u);
    }
    for (j = 0; kind >= 3u && j < n / 8u; j++) {
        const uint32_t mid = 4u + tu_rand(s) % (n - 8u);
        uint32_t r;
        for (r = 1u; r <= 4u; r++) {
            row[mid + r] = row[mid - r];
        }
    }
}

/* Candidates along a row of n entries, each with 4 entries to either side:
 * k of them in increasing order, or repeated, or in no order (the call
 * asks for none). Returns k. */
static uint32_t pick_along(uint16_t *cand, uint32_t n, uint32_t *s)
{
    const uint32_t k = tu_rand(s) % (SL_LINE_CAND_MAX + 1u);
    uint32_t i;
    for (i = 0; i < k; i++) {
        cand[i] = (uint16_t)(4u + tu_rand(s) % (n - 8u));
    }
    return k;
}

/* The reference along a row against the energies' definition: every
 * candidate whose E(i-1) and E(i+1) both exceed E(i) is kept, one where
 * they are at least E(i) and one equals it is kept with its plateau bit,
 * the others are dropped, the order stays; rows read only within x -+ 4. */
static void along_reference_is_definition(void **state)
{
    uint32_t s = 11u, t, codes[3] = {0u, 0u, 0u};
    (void)state;
    for (t = 0; t < 5000u; t++) {
        uint8_t row[96];
        const uint32_t n = 9u + tu_rand(&s) % (sizeof row - 8u);
        uint16_t cand[SL_LINE_CAND_MAX], orig[SL_LINE_CAND_MAX];
        uint64_t plateau = 0x5a5au;
        uint32_t i, ks = 0u, k;
        fill_row(row, n, &s);
        k = pick_along(cand, n, &s);
        memcpy(orig, cand, sizeof cand);
        const uint32_t got = symline_i_s_along3_keep_c(row, cand, k, &plateau);
        for (i = 0; i < k; i++) {
            const uint8_t *p = row + orig[i];
            const uint32_t up = energy(p, 1, -1), e = energy(p, 1, 0), dn = energy(p, 1, 1);
            const uint32_t want = up < e || dn < e ? 0u : up > e && dn > e ? 1u : 2u;
            assert_int_equal(symline_i_s_along3_c(p), want);
            codes[want]++;
            if (want != 0u) {
                assert_true(ks < got);
                assert_int_equal(cand[ks], orig[i]);
                assert_int_equal((plateau >> ks) & 1u, want == 2u ? 1u : 0u);
                ks++;
            }
        }
        assert_int_equal(got, ks);
        assert_int_equal(ks < 64u ? plateau >> ks : 0u, 0u);
    }
    assert_true(codes[0] > 1000u && codes[1] > 1000u && codes[2] > 1000u);
}

#ifdef SYMLINE_PORT_S_ALONG3
/* The SIMD version along a row against the reference: the same entries
 * kept, the same plateau bits, rows exactly as long as read (the sanitizer
 * builds catch a read beyond them) at every alignment. */
static void along_simd_is_reference(void **state)
{
    uint32_t s = 13u, t;
    (void)state;
    for (t = 0; t < 20000u; t++) {
        uint8_t buf[16u + 96u];
        const uint32_t off = tu_rand(&s) % 16u, n = 9u + tu_rand(&s) % 88u;
        uint8_t *const row = buf + off;
        uint16_t a[SL_LINE_CAND_MAX], b[SL_LINE_CAND_MAX];
        uint64_t pa = 1u, pb = 2u;
        uint32_t k;
        fill_row(row, n, &s);
        k = pick_along(a, n, &s);
        memcpy(b, a, sizeof a);
        assert_int_equal(symline_i_s_along3_keep(row, a, k, &pa),
                         symline_i_s_along3_keep_c(row, b, k, &pb));
        assert_memory_equal(a, b, sizeof a);
        assert_true(pa == pb);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reference_is_definition),
        cmocka_unit_test(along_reference_is_definition),
#ifdef SYMLINE_PORT_LANES_DOWN
        cmocka_unit_test(simd_is_reference),
#endif
#ifdef SYMLINE_PORT_S_ALONG3
        cmocka_unit_test(along_simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
