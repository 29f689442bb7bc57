/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Fixed-point helpers (lib/fixed.c): Q8 coordinates of grid points, block
 * offsets, the integer square root and the 32-bit Q8 division.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "fixed.h"

static void q8_coordinates(void **state)
{
    (void)state;
    assert_int_equal(SL_PX_Q8(2u), 512);
    assert_int_equal(symline_i_q8(3, 0), 3 * 256);
    /* Level 1: grid point 3 is the block of pixels 6 and 7, centre 6.5. */
    assert_int_equal(symline_i_q8(3, 1), 6 * 256 + 128);
    /* Level 2: pixels 12..15, centre 13.5. */
    assert_int_equal(symline_i_q8(3, 2), 13 * 256 + 128);
    assert_int_equal(symline_i_block_half_q8(0), 0);
    assert_int_equal(symline_i_block_half_q8(2), 3 * 128);
    assert_int_equal(symline_i_block_q8(0), 0);
    assert_int_equal(symline_i_block_q8(2), 3 * 256);
}

static void integer_square_root(void **state)
{
    uint64_t v;
    (void)state;
    assert_int_equal(symline_i_isqrt64(0), 0);
    assert_int_equal(symline_i_isqrt64(1), 1);
    assert_int_equal(symline_i_isqrt64(15), 3);
    assert_int_equal(symline_i_isqrt64(16), 4);
    assert_true(symline_i_isqrt64((uint64_t)1 << 62) == (uint64_t)1 << 31);
    assert_true(symline_i_isqrt64(UINT64_MAX) == 0xFFFFFFFFu);
    /* floor: r^2 <= v < (r+1)^2 over a spread of values */
    for (v = 3; v < ((uint64_t)1 << 60); v = v * 7u + 5u) {
        const uint64_t r = symline_i_isqrt64(v);
        assert_true(r * r <= v);
        assert_true((r + 1u) * (r + 1u) > v);
    }
}

/* Every bit length: the root starts at the largest power of 4 not above v
 * (found from v's highest bit where the build optimises for speed), so
 * each power of 2, its neighbours and the squares next to it are checked. */
static void square_root_every_bit_length(void **state)
{
    uint32_t k;
    (void)state;
    for (k = 1; k < 64; k++) {
        const uint64_t p = (uint64_t)1 << k;
        const uint64_t vs[3] = {p - 1u, p, p + 1u};
        uint32_t j;
        for (j = 0; j < 3u; j++) {
            const uint64_t r = symline_i_isqrt64(vs[j]);
            assert_true(r * r <= vs[j]);
            assert_true(r >= 0xFFFFFFFFu || (r + 1u) * (r + 1u) > vs[j]);
        }
        if (k < 32) {
            const uint64_t q = p * p; /* 2^2k and its neighbours */
            assert_true(symline_i_isqrt64(q) == p);
            assert_true(symline_i_isqrt64(q - 1u) == p - 1u);
            assert_true(symline_i_isqrt64(q + 1u) == p);
        }
    }
}

static void q8_division(void **state)
{
    (void)state;
    assert_int_equal(symline_i_div_q8(10, 5), 2);
    assert_int_equal(symline_i_div_q8(9, 10), 0);
    assert_int_equal(symline_i_div_q8(0, 0), SL_Q8_NO_QUOTIENT);
    /* Above 32 bits both are shifted alike: 2^40 / 2^20. */
    assert_int_equal(symline_i_div_q8((uint64_t)1 << 40, (uint64_t)1 << 20), 1u << 20);
    /* A length that shifts to zero has no quotient. */
    assert_int_equal(symline_i_div_q8((uint64_t)1 << 40, 1), SL_Q8_NO_QUOTIENT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(q8_coordinates),
        cmocka_unit_test(integer_square_root),
        cmocka_unit_test(square_root_every_bit_length),
        cmocka_unit_test(q8_division),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
