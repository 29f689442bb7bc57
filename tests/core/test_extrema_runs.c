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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(runs_by_hand),
        cmocka_unit_test(public_row_is_the_routine),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
