/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary's cells of 8 px (symline_i_field_cells8_c(),
 * lib/fieldboundary.h) against their definition: the mean is the sum over
 * 8, floored; the texture 256 * 2 * (the sum of |a - b| over the pairs of
 * neighbours 0-1, 2-3, 4-5, 6-7) / (sum + 8), floored and clamped to 255.
 * Where the build has a SIMD version (SYMLINE_PORT_FIELD_CELLS, CMake
 * option SYMLINE_SIMD) it is compared with the reference: every count of
 * cells from 0, column spacings 8 to 33, every alignment, rows flat,
 * random, two-valued and at the extremes 0 and 255, and no write past the
 * count's bytes.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fieldboundary.h"
#include "testutil.h"

#define ROW 400u
#define MAXCELLS (ROW / 8u)

/* A random row: uniform, two values (the largest differences), or a flat
 * gray with a little grain. */
static void fill(uint8_t *row, uint32_t *s)
{
    const uint32_t kind = tu_rand(s) % 4u, base = tu_rand(s) % 256u;
    uint32_t i;
    for (i = 0; i < ROW; i++) {
        const uint32_t q = tu_rand(s);
        const uint32_t v = kind == 0u   ? q % 256u
                           : kind == 1u ? ((q & 1u) ? 255u : 0u)
                           : kind == 2u ? base
                                        : base + q % 5u;
        row[i] = (uint8_t)(v < 255u ? v : 255u);
    }
}

/* The cell at p by its definition. */
static void cell_def(const uint8_t *p, uint32_t *mean, uint32_t *tex)
{
    uint32_t i, sum = 0u, diff = 0u, t;
    for (i = 0; i < 8u; i += 2u) {
        sum += (uint32_t)p[i] + p[i + 1u];
        diff += p[i] > p[i + 1u] ? (uint32_t)p[i] - p[i + 1u] : (uint32_t)p[i + 1u] - p[i];
    }
    t = 256u * 2u * diff / (sum + 8u);
    *mean = sum / 8u;
    *tex = t < 255u ? t : 255u;
}

static void reference_is_definition(void **state)
{
    uint8_t row[ROW], out[2u * MAXCELLS];
    uint32_t s = 11u, t;
    (void)state;
    for (t = 0; t < 3000u; t++) {
        const size_t sx = 8u + tu_rand(&s) % 26u;
        const uint32_t n = (uint32_t)((ROW - 8u) / sx + 1u), c = tu_rand(&s) % (n + 1u);
        uint32_t i;
        fill(row, &s);
        symline_i_field_cells8_c(row, sx, c, out);
        for (i = 0; i < c; i++) {
            uint32_t m, x;
            cell_def(row + i * sx, &m, &x);
            assert_int_equal(out[2u * i], m);
            assert_int_equal(out[2u * i + 1u], x);
        }
    }
}

#ifdef SYMLINE_PORT_FIELD_CELLS
static void simd_is_reference(void **state)
{
    uint8_t row[ROW + 16u];
    uint32_t s = 13u, t;
    (void)state;
    for (t = 0; t < 20000u; t++) {
        const size_t sx = 8u + tu_rand(&s) % 26u, off = tu_rand(&s) % 16u;
        const uint32_t n = (uint32_t)((ROW - 8u) / sx + 1u), c = tu_rand(&s) % (n + 1u);
        uint8_t a[2u * MAXCELLS + 8u], b[2u * MAXCELLS + 8u];
        fill(row, &s);
        memcpy(row + ROW, row, 16u);
        memset(a, 0x5a, sizeof a);
        memset(b, 0x5a, sizeof b);
        symline_i_field_cells8(row + off, sx, c, a);
        symline_i_field_cells8_c(row + off, sx, c, b);
        assert_memory_equal(a, b, sizeof a);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reference_is_definition),
#ifdef SYMLINE_PORT_FIELD_CELLS
        cmocka_unit_test(simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
