/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The operator's row bodies as the build has them (a SIMD version from port/
 * where SYMLINE_SIMD built one, else lib/symmetry.c's portable C) against the
 * definition of the energy (SPEC section 1: E = sum_j (m+1-j) d_j^2, 255^2 for
 * a pair leaving the image), and where built, the SIMD version against the
 * portable reference entry by entry: random images, every radius 1..32 the
 * detector allows and larger ones up to 255, odd and short widths, unaligned
 * starts, strides, both axes, gray-value extremes, and no write past the row.
 * Also the line filter's search for S points (lib/linefilter.h), SIMD against
 * the portable reference where built.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "linefilter.h"
#include "symline/symmetry.h"
#include "symmetry.h"
#include "testutil.h"

#define MAXW 300u
#define MAXM 255u
#define GUARD 0xa5a5a5a5u

/* Radii: the detector's 1..32, then larger ones around the SIMD limit. */
static const uint32_t big_radii[] = {33u, 47u, 64u, 100u, 127u, 128u, 129u, 200u, 255u};

static uint32_t pair_term(uint32_t m, uint32_t j, int in, uint8_t a, uint8_t b)
{
    const int32_t d = (int32_t)a - (int32_t)b;
    return (m + 1u - j) * (in ? (uint32_t)(d * d) : 65025u);
}

/* E[x] of a row q[0..n-1] by the definition. */
static uint32_t def_row(const uint8_t *q, uint32_t n, uint32_t m, uint32_t x)
{
    uint32_t j, e = 0u;
    for (j = 1u; j <= m; j++) {
        const int in = x >= j && x + j < n;
        e += pair_term(m, j, in, in ? q[x - j] : 0u, in ? q[x + j] : 0u);
    }
    return e;
}

/* Fills n gray values: uniform, two-valued extremes (0/255), or a smooth ramp with noise. */
static void fill_gray(uint8_t *g, uint32_t n, uint32_t *s)
{
    const uint32_t kind = tu_rand(s) % 3u;
    uint32_t i;
    for (i = 0; i < n; i++) {
        const uint32_t r = tu_rand(s);
        g[i] = (uint8_t)(kind == 0u   ? r
                         : kind == 1u ? ((r & 1u) ? 255u : 0u)
                                      : (i * 3u + r % 9u) & 255u);
    }
}

static uint32_t pick_radius(uint32_t t, uint32_t *s)
{
    if (t % 4u == 3u) {
        return big_radii[tu_rand(s) % (sizeof big_radii / sizeof big_radii[0])];
    }
    return 1u + t % 32u;
}

/* symline_energy_row() (the build's row body) by the definition, every entry,
 * the entries after the row untouched. */
static void row_is_definition(void **state)
{
    uint8_t q[MAXW + 16u];
    uint32_t E[MAXW + 8u], s = 11u, t, x;
    (void)state;
    for (t = 0; t < 3000u; t++) {
        const uint32_t m = pick_radius(t, &s);
        const uint32_t n = 1u + tu_rand(&s) % MAXW, off = tu_rand(&s) % 16u;
        fill_gray(q, sizeof q, &s);
        for (x = 0; x < MAXW + 8u; x++) {
            E[x] = GUARD;
        }
        assert_int_equal(symline_energy_row(q + off, n, m, E + 1), SYMLINE_OK);
        assert_int_equal(E[0], GUARD);
        for (x = 0; x < n; x++) {
            if (E[1u + x] != def_row(q + off, n, m, x)) {
                print_error("m %u n %u off %u x %u: %u, want %u\n", m, n, off, x, E[1u + x],
                            def_row(q + off, n, m, x));
            }
            assert_int_equal(E[1u + x], def_row(q + off, n, m, x));
        }
        for (x = n + 1u; x < MAXW + 8u; x++) {
            assert_int_equal(E[x], GUARD);
        }
    }
}

/* Random rows of an image (stride > width, unaligned starts) as the window
 * rows[0..2m]: the detector's (the frame's edge leaves a run of NULLs at one
 * end) or any NULL pattern the public call accepts. */
static void make_window(const uint8_t *img, uint32_t stride, uint32_t h, uint32_t m, uint32_t t,
                        uint32_t *s, const uint8_t **rows)
{
    uint32_t j;
    const uint32_t y = tu_rand(s) % (h + 2u * m); /* centre row, offset by m */
    for (j = 0; j <= 2u * m; j++) {
        const uint32_t yy = y + j; /* row y - m + j, offset by 2m */
        int in = yy >= 2u * m && yy - 2u * m < h;
        if (t % 5u == 4u && j != m) {
            in = (tu_rand(s) % 3u) != 0u;
        }
        rows[j] = in ? img + (size_t)((yy - 2u * m) % h) * stride + (yy % 7u) : NULL;
    }
    rows[m] = img + (size_t)(y % h) * stride;
}

/* symline_energy_across() by the definition. */
static void across_is_definition(void **state)
{
    static uint8_t img[64u * (MAXW + 16u)];
    const uint8_t *rows[2u * MAXM + 1u];
    uint32_t E[MAXW + 8u], s = 23u, t, x, j;
    const uint32_t stride = MAXW + 16u, h = 64u;
    (void)state;
    fill_gray(img, sizeof img, &s);
    for (t = 0; t < 3000u; t++) {
        const uint32_t m = pick_radius(t, &s), w = 1u + tu_rand(&s) % MAXW;
        if (t % 50u == 0u) {
            fill_gray(img, sizeof img, &s);
        }
        make_window(img, stride, h, m, t, &s, rows);
        for (x = 0; x < MAXW + 8u; x++) {
            E[x] = GUARD;
        }
        assert_int_equal(symline_energy_across(rows, m, w, E + 1), SYMLINE_OK);
        assert_int_equal(E[0], GUARD);
        for (x = 0; x < w; x++) {
            uint32_t e = 0u;
            for (j = 1u; j <= m; j++) {
                const int in = rows[m - j] != NULL && rows[m + j] != NULL;
                e += pair_term(m, j, in, in ? rows[m - j][x] : 0u, in ? rows[m + j][x] : 0u);
            }
            assert_int_equal(E[1u + x], e);
        }
        for (x = w + 1u; x < MAXW + 8u; x++) {
            assert_int_equal(E[x], GUARD);
        }
    }
}

/* The whole-frame operator on both axes, with a stride, by the definition. */
static void frames_are_definition(void **state)
{
    static uint8_t px[70u * 81u];
    static uint32_t E[70u * 77u];
    uint32_t s = 5u, t, x, y, j;
    (void)state;
    for (t = 0; t < 40u; t++) {
        const uint32_t w = 17u + tu_rand(&s) % 60u, h = 1u + tu_rand(&s) % 70u;
        const uint32_t m = t < 32u ? t + 1u : big_radii[t - 32u];
        const symline_image img = {w, h, 81u, px};
        const symline_axis axis = (t % 2u) ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL;
        fill_gray(px, sizeof px, &s);
        assert_int_equal(symline_energy_frame(&img, axis, m, E, 77u, sizeof E / sizeof E[0]),
                         SYMLINE_OK);
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                uint32_t e = 0u;
                if (axis == SYMLINE_AXIS_VERTICAL) {
                    e = def_row(px + (size_t)y * 81u, w, m, x);
                } else {
                    for (j = 1u; j <= m; j++) {
                        const int in = y >= j && y + j < h;
                        e += pair_term(m, j, in, in ? px[(size_t)(y - j) * 81u + x] : 0u,
                                       in ? px[(size_t)(y + j) * 81u + x] : 0u);
                    }
                }
                assert_int_equal(E[(size_t)y * 77u + x], e);
            }
        }
    }
}

#ifdef SYMLINE_PORT_ENERGY
/* The SIMD bodies against lib/symmetry.c's portable references, output and
 * untouched entries alike. */
static void simd_is_reference(void **state)
{
    static uint8_t img[64u * (MAXW + 16u)];
    const uint8_t *rows[2u * MAXM + 1u];
    uint32_t a[MAXW + 8u], b[MAXW + 8u], s = 77u, t;
    const uint32_t stride = MAXW + 16u, h = 64u;
    (void)state;
    for (t = 0; t < 6000u; t++) {
        const uint32_t m = pick_radius(t, &s), n = 1u + tu_rand(&s) % MAXW;
        const uint32_t off = tu_rand(&s) % 16u;
        if (t % 50u == 0u) {
            fill_gray(img, sizeof img, &s);
        }
        memset(a, 0x5a, sizeof a);
        memset(b, 0x5a, sizeof b);
        symline_i_energy_row(img + (size_t)(t % h) * stride + off, n, m, a + 1);
        symline_i_energy_row_c(img + (size_t)(t % h) * stride + off, n, m, b + 1);
        assert_memory_equal(a, b, sizeof a);
        make_window(img, stride, h, m, t, &s, rows);
        memset(a, 0x5a, sizeof a);
        memset(b, 0x5a, sizeof b);
        symline_i_energy_across(rows, m, n, a + 1);
        symline_i_energy_across_c(rows, m, n, b + 1);
        assert_memory_equal(a, b, sizeof a);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(row_is_definition),
        cmocka_unit_test(across_is_definition),
        cmocka_unit_test(frames_are_definition),
#ifdef SYMLINE_PORT_ENERGY
        cmocka_unit_test(simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
