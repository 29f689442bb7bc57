/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The run rule (lib/extrema.c, docs/algorithm.md): the one routine behind
 * symline_extrema_row() and the detector's rows, with and without the
 * detector's plateau limit.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "extrema.h"
#include "testutil.h"

static void runs_by_hand(void **state)
{
    /* A valley of one, a plateau valley of five, a peak of two, a descent to the end. */
    static const uint32_t E[] = {9, 4, 9, 3, 3, 3, 3, 3, 9, 12, 12, 8, 7, 7};
    const uint32_t n = (uint32_t)(sizeof E / sizeof E[0]);
    uint8_t map[sizeof E / sizeof E[0]];
    uint32_t i;
    (void)state;
    symline_i_extrema_runs(E, n, SL_RUN_ANY_LENGTH, map);
    for (i = 0; i < n; i++) {
        const uint8_t want = (i == 1u || i == 5u)   ? SYMLINE_MAP_S
                             : (i == 2u || i == 9u) ? SYMLINE_MAP_A
                                                    : SYMLINE_MAP_NONE;
        assert_int_equal(map[i], want);
    }
    /* The plateau [3, 7] is marked at 5, 2 before its end: a lag of 2 keeps it, 1 drops it. */
    symline_i_extrema_runs(E, n, 2, map);
    assert_int_equal(map[5], SYMLINE_MAP_S);
    symline_i_extrema_runs(E, n, 1, map);
    assert_int_equal(map[5], SYMLINE_MAP_NONE);
    assert_int_equal(map[1], SYMLINE_MAP_S); /* runs of one always count */
    assert_int_equal(map[9], SYMLINE_MAP_A); /* [9, 10]: middle 9, 1 before the end */
    symline_i_extrema_runs(E, n, 0, map);
    assert_int_equal(map[9], SYMLINE_MAP_NONE);
    assert_int_equal(map[2], SYMLINE_MAP_A);
}

/* On random rows with many plateaus the public row call and the routine agree. */
static void public_row_is_the_routine(void **state)
{
    uint32_t E[300], s = 99u, t, i;
    uint8_t a[300], b[300];
    (void)state;
    for (t = 0; t < 200u; t++) {
        const uint32_t n = 1u + tu_rand(&s) % 300u;
        for (i = 0; i < n; i++) {
            E[i] = tu_rand(&s) % 4u; /* few values: long runs */
        }
        memset(a, 0x77, sizeof a);
        memset(b, 0x77, sizeof b);
        assert_int_equal(symline_extrema_row(E, n, a), SYMLINE_OK);
        symline_i_extrema_runs(E, n, SL_RUN_ANY_LENGTH, b);
        assert_memory_equal(a, b, sizeof a); /* equal, and nothing beyond n written */
        assert_int_equal(a[n - 1u], SYMLINE_MAP_NONE);
    }
}

/* The run rule written plainly: every run [a, b] with a > 0 and b < n-1 whose
 * middle lies no more than lag before b, marked by its neighbours. */
static void runs_reference(const uint32_t *E, uint32_t n, uint32_t lag, uint8_t *map)
{
    uint32_t a = 0u, b;
    memset(map, SYMLINE_MAP_NONE, n);
    while (a < n) {
        b = a;
        while (b + 1u < n && E[b + 1u] == E[a]) {
            b++;
        }
        if (a > 0u && b + 1u < n && b - (a + b) / 2u <= lag) {
            if (E[a - 1u] > E[a] && E[b + 1u] > E[a]) {
                map[(a + b) / 2u] = SYMLINE_MAP_S;
            } else if (E[a - 1u] < E[a] && E[b + 1u] < E[a]) {
                map[(a + b) / 2u] = SYMLINE_MAP_A;
            }
        }
        a = b + 1u;
    }
}

/* Rows longer than the blocks (SL_KINDS_MAX), runs across block borders, all lags. */
static void routine_is_the_rule(void **state)
{
    uint32_t E[400], s = 7u, t, i;
    uint8_t a[400], b[400];
    (void)state;
    for (t = 0; t < 3000u; t++) {
        const uint32_t n = 1u + tu_rand(&s) % 400u;
        const uint32_t lag = (t % 5u == 0u) ? SL_RUN_ANY_LENGTH : tu_rand(&s) % 40u;
        const uint32_t values = 2u + tu_rand(&s) % 6u, runmax = 1u + tu_rand(&s) % 90u;
        for (i = 0; i < n;) {
            const uint32_t v = tu_rand(&s) % values;
            uint32_t len = 1u + tu_rand(&s) % runmax;
            if (tu_rand(&s) % 2u == 0u) {
                len = 1u; /* many single entries between the plateaus */
            }
            for (; len > 0u && i < n; len--) {
                E[i++] = v;
            }
        }
        runs_reference(E, n, lag, a);
        symline_i_extrema_runs(E, n, lag, b);
        assert_memory_equal(a, b, n);
    }
}

/* The kinds and plateau mask by their definition: entry x with energy b
 * between a (left or upper neighbour) and c. */
static void kinds_rule(const uint32_t *up, const uint32_t *mid, const uint32_t *dn, uint32_t n,
                       uint8_t *map, uint32_t *ev)
{
    uint32_t x;
    memset(ev, 0, SL_KINDS_WORDS * sizeof *ev);
    for (x = 0; x < n; x++) {
        const uint32_t a = up[x], b = mid[x], c = dn[x];
        map[x] = (b < a && b < c)   ? SYMLINE_MAP_S
                 : (b > a && b > c) ? SYMLINE_MAP_A
                                    : SYMLINE_MAP_NONE;
        if ((a == b) != (b == c)) {
            ev[x / 32u] |= 1u << (x % 32u);
        }
    }
}

#define KN (SL_KINDS_MAX + 8u)

/* Random energies below 2^31: few values (plateaus), values near 2^31 - 1,
 * or any. */
static void random_row(uint32_t *v, uint32_t t, uint32_t *s)
{
    const uint32_t big = (t % 3u == 0u) ? 0x7fffffffu - 8u : 0u;
    const uint32_t range = (t % 2u == 0u) ? 3u : (t % 5u == 1u) ? 2u : 0x7fffffffu;
    uint32_t i;
    for (i = 0; i < KN; i++) {
        v[i] = big + tu_rand(s) % range % (0x7fffffffu - big + 1u);
    }
}

/* The build's decisions along a row and down the columns (SIMD versions
 * from port/ where built) and the portable references give the rule's
 * output, plateau mask and next signs included, at every length up to
 * SL_KINDS_MAX and alignment, for energies up to 2^31 - 1. */
static void kinds_build_is_reference(void **state)
{
    uint32_t up[KN], mid[KN], dn[KN], s = 5u, t, i, k;
    uint32_t ea[SL_KINDS_WORDS], eb[SL_KINDS_WORDS], ec[SL_KINDS_WORDS], any;
    uint8_t a[KN], b[KN], c[KN];
    int8_t sa[KN], sb[KN], sc[KN];
    (void)state;
    for (t = 0; t < 6000u; t++) {
        const uint32_t n =
            1u + tu_rand(&s) % ((t % 2u == 0u && SL_KINDS_MAX > 70u) ? 70u : SL_KINDS_MAX);
        const uint32_t off = 1u + tu_rand(&s) % 6u, words = (n + 31u) / 32u;
        random_row(up, t, &s);
        random_row(mid, t, &s);
        random_row(dn, t, &s);
        for (k = 0; k < 2u; k++) {
            uint32_t ra, rb;
            memset(a, 0x77, sizeof a);
            memset(b, 0x77, sizeof b);
            memset(c, 0x77, sizeof c);
            memset(ea, 0x55, sizeof ea);
            memset(eb, 0x55, sizeof eb);
            if (k == 0u) { /* along the row mid */
                kinds_rule(mid + off - 1u, mid + off, mid + off + 1u, n, c + off, ec);
                ra = symline_i_extrema_along(mid + off, n, a + off, ea);
                rb = symline_i_extrema_along_c(mid + off, n, b + off, eb);
            } else { /* down the columns: up, mid, dn */
                kinds_rule(up + off, mid + off, dn + off, n, c + off, ec);
                for (i = 0; i < KN; i++) {
                    sa[i] = sb[i] = (int8_t)((mid[i] > up[i]) - (mid[i] < up[i]));
                    sc[i] = (int8_t)((dn[i] > mid[i]) - (dn[i] < mid[i]));
                }
                ra = symline_i_extrema_across(mid + off, dn + off, sa + off, n, a + off, ea);
                rb = symline_i_extrema_across_c(mid + off, dn + off, sb + off, n, b + off, eb);
                assert_memory_equal(sa + off, sc + off, n);
                assert_memory_equal(sb + off, sc + off, n);
                assert_memory_equal(sa, sb, sizeof sa); /* nothing outside the n entries */
            }
            for (any = 0u, i = 0; i < words; i++) {
                any |= ec[i];
            }
            assert_memory_equal(a + off, c + off, n);
            assert_memory_equal(b + off, c + off, n);
            assert_memory_equal(a, b, sizeof a);
            assert_memory_equal(ea, ec, words * sizeof *ea);
            assert_memory_equal(eb, ec, words * sizeof *eb);
            assert_int_equal(ra, any);
            assert_int_equal(rb, any);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(runs_by_hand),
        cmocka_unit_test(public_row_is_the_routine),
        cmocka_unit_test(routine_is_the_rule),
        cmocka_unit_test(kinds_build_is_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
