/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line points' decision of a block of entries down the columns
 * (symline_i_lanes_down_c(), lib/linepoints.h) against its definition: for
 * every entry that passes the line filter's byte test, the code says what
 * the exact gray test (symline_i_linefilter_gray()) and the energies
 * E(y-1), E(y), E(y+1) of docs/algorithm.md at m = 3 say, and one entry's
 * code (symline_i_lane_code_down()) is the block's. Where the build has a
 * SIMD version of the byte test and decision of a row in one pass
 * (SYMLINE_PORT_CAND_DOWN, CMake option SYMLINE_SIMD) it is compared with
 * the reference (symline_i_cand_down_c()) over whole rows: columns of
 * random, nearly equal (ties, plateaus), mirrored (equal energies) and
 * extreme gray values, both filters, thresholds across their ranges.
 */
#include <setjmp.h>
#include <stdbool.h>
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
            assert_int_equal(symline_i_lane_code_down(r + i, (ptrdiff_t)st, &g), want);
            codes[want]++;
            checked++;
        }
    }
    /* every outcome was met many times */
    assert_true(checked > 10000u);
    assert_true(codes[0] > 1000u && codes[1] > 1000u && codes[2] > 1000u);
}

#ifdef SYMLINE_PORT_CAND_DOWN
#define ROW_MAX 200u /* entries of a row, at most */

/* The entries symline_i_cand_down() (port) or symline_i_cand_down_c()
 * (reference) keeps of entries x .. n-1 of the row r, call after call as
 * the detector makes them, to keep[0 ..] with plateau[i] its plateau bit;
 * returns how many. Each call must keep some entries or stop at the row's
 * end, and *next must move on. */
static uint32_t down_all(bool port, const symline_i_prefilter *pf, const symline_i_lane_gray *g,
                         const uint8_t *r, const uint8_t *lo, const uint8_t *hi, ptrdiff_t st,
                         uint32_t x, uint32_t n, uint16_t *keep, uint8_t *plateau)
{
    uint32_t total = 0u;
    while (x < n) {
        uint16_t out[SL_LINE_CAND_MAX];
        uint64_t pl = 0x5a5au;
        uint32_t next = 0u, k, i;
        memset(out, 0xa5, sizeof out);
        k = port ? symline_i_cand_down(pf, g, r, lo, hi, st, x, n, out, &pl, &next)
                 : symline_i_cand_down_c(pf, g, r, lo, hi, st, x, n, out, &pl, &next);
        assert_true(k <= SL_LINE_CAND_MAX);
        assert_true(next > x && next <= n);
        assert_int_equal(k < 64u ? pl >> k : 0u, 0u);
        for (i = 0; i < k; i++) {
            assert_true(out[i] >= x && out[i] < next);
            assert_true(total < ROW_MAX);
            keep[total] = out[i];
            plateau[total] = (uint8_t)((pl >> i) & 1u);
            total++;
        }
        x = next;
    }
    return total;
}

/* The SIMD version against the reference over whole rows of 1 to ROW_MAX
 * entries, from any first entry: the same entries kept in the same order,
 * the same plateaus; rows with many candidates (a bright band, the paper
 * filter on a bright carpet) fill the output and go on from where the call
 * stopped, also in a row's last step, which starts before the first entry.
 * Rows exactly as wide as read at every alignment (the sanitizer builds
 * catch a read beyond them). */
static void down_simd_is_reference(void **state)
{
    static uint8_t buf[16u + ROWS * ROW_MAX];
    uint32_t s = 17u, t, kept = 0u, plateaus = 0u, full = 0u;
    (void)state;
    for (t = 0; t < 6000u; t++) {
        const uint32_t n = 1u + tu_rand(&s) % ROW_MAX, off = tu_rand(&s) % 16u;
        const uint32_t x = tu_rand(&s) % 3u == 0u ? 0u : tu_rand(&s) % n;
        const ptrdiff_t st = (ptrdiff_t)n;
        uint8_t *const r = buf + off + 4u * n;
        symline_i_linefilter f;
        symline_i_lane_gray g;
        symline_i_prefilter pf;
        uint16_t ka[ROW_MAX], kb[ROW_MAX];
        uint8_t pa[ROW_MAX], pb[ROW_MAX];
        const uint8_t *lo, *hi;
        uint32_t na, nb, row, i;
        /* nine rows of n entries: the generator's columns, side by side */
        for (i = 0; i < n; i += 8u) {
            uint8_t cols[ROWS * 8u];
            const uint32_t w = n - i < 8u ? n - i : 8u;
            fill(cols, 8u, &s);
            for (row = 0; row < ROWS; row++) {
                memcpy(buf + off + row * n + i, cols + row * 8u, w);
            }
        }
        if (tu_rand(&s) % 2u == 0u) { /* a bright band across: runs of candidates */
            const uint32_t a = tu_rand(&s) % n, b = a + tu_rand(&s) % (n - a);
            for (i = a; i <= b; i++) {
                r[i] = (uint8_t)(200u + tu_rand(&s) % 56u);
                r[i - 4 * st] = (uint8_t)(tu_rand(&s) % 64u);
                r[i + 4 * st] = (uint8_t)(tu_rand(&s) % 64u);
            }
        }
        pick(&f, &g, &s);
        symline_i_prefilter_setup(&f, &pf);
        lo = f.kind == SYMLINE_FILTER_PAPER ? r : r - 4 * st;
        hi = f.kind == SYMLINE_FILTER_PAPER ? r : r + 4 * st;
        na = down_all(true, &pf, &g, r, lo, hi, st, x, n, ka, pa);
        nb = down_all(false, &pf, &g, r, lo, hi, st, x, n, kb, pb);
        assert_int_equal(na, nb);
        assert_memory_equal(ka, kb, na * sizeof ka[0]);
        assert_memory_equal(pa, pb, na);
        kept += na;
        for (i = 0; i < na; i++) {
            plateaus += pa[i];
        }
        full += na > SL_LINE_CAND_MAX ? 1u : 0u;
    }
    /* every case was met many times */
    assert_true(kept > 20000u && plateaus > 500u && full > 50u);
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
#ifdef SYMLINE_PORT_CAND_DOWN
        cmocka_unit_test(down_simd_is_reference),
#endif
#ifdef SYMLINE_PORT_S_ALONG3
        cmocka_unit_test(along_simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
