/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The scale grid's rows (lib/grid.c) as the build has them (a SIMD version
 * from port/ where SYMLINE_SIMD built one, else the portable lane loops)
 * against the definition (the rounded mean of each 2^level x 2^level block,
 * (sum + 2^(2 level - 1)) >> 2 level), and where built, the SIMD version
 * against the portable reference: random images, levels 0..5, odd and short
 * widths, unaligned starts, strides, gray-value extremes, the row written
 * once or twice (the twin), and no write past the rows or the scratch.
 * Likewise the grid pyramid's rows (grid.h) built from the sums of the
 * level below.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "linepoints.h"
#include "testutil.h"

#define MAXW 1100u
#define MAXSTRIDE (MAXW + 40u)
#define ROWS 64u /* two grid rows at level 5 */
#define GUARD 0x5a

static uint8_t img[(size_t)MAXSTRIDE * ROWS + 16u];

/* Random gray values, now and then all dark, all bright or only extremes. */
static void fill_gray(uint32_t t, uint32_t *s)
{
    size_t i;
    const uint32_t kind = t % 7u;
    for (i = 0; i < sizeof img; i++) {
        const uint32_t r = tu_rand(s);
        img[i] = (uint8_t)(kind == 0u ? 255u : kind == 1u ? 0u : kind == 2u ? (r & 1u) * 255u : r);
    }
}

/* A frame of width x (2 2^level) with the given stride, copied from img at
 * offset off into a buffer that ends with its last pixel (the sanitizer
 * builds then catch a read past it); free it with free_frame(). */
static symline_image frame(uint32_t width, uint32_t level, uint32_t stride, uint32_t off)
{
    symline_image im;
    const size_t n = (size_t)stride * ((2u << level) - 1u) + width;
    uint8_t *data = (uint8_t *)malloc(n);
    assert_non_null(data);
    memcpy(data, img + off, n);
    im.width = width;
    im.height = 2u << level;
    im.stride = stride;
    im.data = data;
    return im;
}

static void free_frame(symline_image *im)
{
    free((void *)(uintptr_t)im->data);
}

/* Grid row y by the definition. */
static void definition(const symline_image *im, uint32_t level, uint32_t y, uint8_t *out)
{
    const uint32_t s = 1u << level, shift = 2u * level;
    uint32_t x, i, j;
    for (x = 0; x < (im->width >> level); x++) {
        uint32_t sum = 0u;
        for (j = 0; j < s; j++) {
            for (i = 0; i < s; i++) {
                sum += im->data[(size_t)(y * s + j) * im->stride + x * s + i];
            }
        }
        out[x] = (uint8_t)((sum + ((1u << shift) >> 1)) >> shift);
    }
}

/* The pass fields the grid reads. */
static symline_i_pass pass_of(const symline_image *im, uint32_t level)
{
    symline_i_pass p;
    memset(&p, 0, sizeof p);
    p.level = level;
    p.w = im->width >> level;
    p.h = im->height >> level;
    return p;
}

/* Width, level, stride and start of trial t: short widths often. */
static symline_image pick(uint32_t t, uint32_t *s, uint32_t *level)
{
    const uint32_t lv = t % 6u;
    const uint32_t width = (t % 3u == 0u) ? 1u + tu_rand(s) % 80u : 1u + tu_rand(s) % MAXW;
    const uint32_t stride = width + tu_rand(s) % 40u, off = tu_rand(s) % 16u;
    *level = lv;
    return frame(width, lv, stride, off);
}

static void row_is_definition(void **state)
{
    uint8_t got[MAXW + 16u], want[MAXW + 16u], twin[MAXW + 16u];
    uint16_t acc[MAXW + 8u];
    uint32_t s = 11u, t, y, level;
    symline_i_pass p;
    (void)state;
    for (t = 0; t < 1500u; t++) {
        symline_image im;
        if (t % 10u == 0u) {
            fill_gray(t / 10u, &s);
        }
        im = pick(t, &s, &level);
        p = pass_of(&im, level);
        for (y = 0; y < 2u; y++) {
            memset(got, GUARD, sizeof got);
            memset(acc, GUARD, sizeof acc);
            memcpy(want, got, sizeof want);
            symline_i_grid_row(&im, &p, y, acc, got, NULL);
            definition(&im, level, y, want);
            assert_memory_equal(got, want, sizeof got); /* nothing past w either */
            assert_int_equal(acc[im.width], 0x5a5au);   /* scratch: width entries */
            /* Twice: the same row in both. */
            memset(got, GUARD, sizeof got);
            memset(twin, GUARD, sizeof twin);
            symline_i_grid_row(&im, &p, y, acc, got, twin);
            assert_memory_equal(got, want, sizeof got);
            assert_memory_equal(twin, want, sizeof twin);
            assert_int_equal(acc[im.width], 0x5a5au);
        }
        free_frame(&im);
    }
}

#ifdef SYMLINE_PORT_GRID
/* The SIMD rows against lib/grid.c's portable reference, nothing written
 * past the row. */
static void simd_is_reference(void **state)
{
    uint8_t a[MAXW + 16u], b[MAXW + 16u], a2[MAXW + 16u], b2[MAXW + 16u];
    uint16_t acc[MAXW + 8u];
    uint32_t s = 5u, t, y, level;
    symline_i_pass p;
    (void)state;
    for (t = 0; t < 3000u; t++) {
        symline_image im;
        if (t % 10u == 0u) {
            fill_gray(t / 10u, &s);
        }
        im = pick(t, &s, &level);
        p = pass_of(&im, level);
        for (y = 0; y < 2u; y++) {
            memset(a, GUARD, sizeof a);
            memset(b, GUARD, sizeof b);
            symline_i_grid_row(&im, &p, y, acc, a, NULL);
            symline_i_grid_row_c(&im, &p, y, acc, b, NULL);
            assert_memory_equal(a, b, sizeof a);
            /* Twice, each: both rows the reference's. */
            memset(a, GUARD, sizeof a);
            memset(a2, GUARD, sizeof a2);
            symline_i_grid_row(&im, &p, y, acc, a, a2);
            assert_memory_equal(a, b, sizeof a);
            assert_memory_equal(a2, b, sizeof a2);
            memset(a, GUARD, sizeof a);
            memset(b2, GUARD, sizeof b2);
            symline_i_grid_row_c(&im, &p, y, acc, a, b2);
            assert_memory_equal(a, b, sizeof a);
            assert_memory_equal(b2, b, sizeof b2);
        }
        free_frame(&im);
    }
}
#endif

/* The grid pyramid (grid.h) as the grid row cache builds it (linepoints.c):
 * level 1's rows, level 2's from their sums, each coarser level's from the
 * sums of the level below, a row started by an even row and finished by the
 * odd one after it, against the definition at levels 1..4 (frames of two
 * level-4 rows), nothing written past a row or the sums (width / 2 entries
 * in all). */
static void pyramid_is_definition(void **state)
{
    uint8_t got[MAXW + 16u], want[MAXW + 16u], two[MAXW + 16u];
    uint16_t acc[MAXW + 8u];
    uint32_t s = 23u, t, r, l;
    (void)state;
    for (t = 0; t < 600u; t++) {
        const uint32_t width = (t % 3u == 0u) ? 2u + tu_rand(&s) % 80u : 2u + tu_rand(&s) % MAXW;
        const uint32_t stride = width + tu_rand(&s) % 40u, off = tu_rand(&s) % 16u;
        symline_image im;
        if (t % 10u == 0u) {
            fill_gray(t / 10u, &s);
        }
        im = frame(width, 4u, stride, off);
        memset(acc, GUARD, sizeof acc);
        for (r = 0; r < (im.height >> 1); r++) {
            uint16_t *sum = acc;
            uint32_t j = r >> 1;
            memset(got, GUARD, sizeof got);
            memset(want, GUARD, sizeof want);
            memset(two, GUARD, sizeof two);
            symline_i_grid_sums1(im.data + (size_t)2u * r * stride, stride, width >> 1, got, acc,
                                 (r & 1u) != 0u ? two : NULL);
            definition(&im, 1u, r, want);
            assert_memory_equal(got, want, sizeof got);
            memset(want, GUARD, sizeof want);
            if ((r & 1u) != 0u) {
                definition(&im, 2u, j, want);
            }
            assert_memory_equal(two, want, sizeof two);
            for (l = 3u; (r & 1u) != 0u && l <= 4u && (width >> l) > 0u; l++) {
                uint16_t *const next = sum + (width >> (l - 1u));
                if ((j & 1u) == 0u) {
                    symline_i_grid_fold(sum, width >> l, l, next, NULL);
                    break;
                }
                memset(got, GUARD, sizeof got);
                memset(want, GUARD, sizeof want);
                symline_i_grid_fold(sum, width >> l, l, next, got);
                definition(&im, l, j >> 1, want);
                assert_memory_equal(got, want, sizeof got);
                sum = next;
                j >>= 1;
            }
            assert_int_equal(acc[width / 2u], 0x5a5au);
        }
        /* without the sums: the row alone, acc untouched */
        memset(got, GUARD, sizeof got);
        memset(want, GUARD, sizeof want);
        memset(acc, GUARD, sizeof acc);
        symline_i_grid_sums1(im.data, stride, width >> 1, got, NULL, NULL);
        definition(&im, 1u, 0u, want);
        assert_memory_equal(got, want, sizeof got);
        assert_int_equal(acc[0], 0x5a5au);
        free_frame(&im);
    }
}

#ifdef SYMLINE_PORT_GRID_SUMS
/* The SIMD pyramid against the portable reference: level 1's rows alone
 * and with level 2's sums, both rows of a level-2 row, on random frames;
 * the folds on random sums as large as each level's get (the second row's
 * sums added to the first's), both rows of a grid row; nothing written past
 * a row or the sums. */
static void pyramid_simd_is_reference(void **state)
{
    uint8_t a[MAXW + 16u], b[MAXW + 16u], a2[MAXW + 16u], b2[MAXW + 16u];
    uint16_t sa[MAXW + 8u], sb[MAXW + 8u], in[2u * MAXW + 16u];
    uint32_t s = 29u, t, x, l;
    (void)state;
    for (t = 0; t < 3000u; t++) {
        const uint32_t w = (t % 3u == 0u) ? 1u + tu_rand(&s) % 40u : 1u + tu_rand(&s) % (MAXW / 2u);
        const uint32_t stride = 2u * w + tu_rand(&s) % 40u, off = tu_rand(&s) % 16u;
        symline_image im;
        if (t % 10u == 0u) {
            fill_gray(t / 10u, &s);
        }
        im = frame(2u * w, 1u, stride, off); /* four rows */
        memset(a, GUARD, sizeof a);
        memset(b, GUARD, sizeof b);
        memset(a2, GUARD, sizeof a2);
        memset(b2, GUARD, sizeof b2);
        memset(sa, GUARD, sizeof sa);
        memset(sb, GUARD, sizeof sb);
        symline_i_grid_sums1(im.data, stride, w, a, NULL, NULL);
        symline_i_grid_sums1_c(im.data, stride, w, b, NULL, NULL);
        assert_memory_equal(a, b, sizeof a);
        symline_i_grid_sums1(im.data, stride, w, a, sa, NULL);
        symline_i_grid_sums1_c(im.data, stride, w, b, sb, NULL);
        assert_memory_equal(a, b, sizeof a);
        assert_memory_equal(sa, sb, sizeof sa);
        symline_i_grid_sums1(im.data + 2u * stride, stride, w, a, sa, a2);
        symline_i_grid_sums1_c(im.data + 2u * stride, stride, w, b, sb, b2);
        assert_memory_equal(a, b, sizeof a);
        assert_memory_equal(sa, sb, sizeof sa);
        assert_memory_equal(a2, b2, sizeof a2);
        free_frame(&im);
        l = 3u + t % 2u;
        for (x = 0; x < 2u * w + 16u; x++) { /* a level l - 1 sum: <= 4^(l-1) 255 */
            const uint32_t top = (1u << (2u * l - 2u)) * 255u, r = tu_rand(&s);
            in[x] = (uint16_t)((t / 3u) % 4u == 0u   ? top
                               : (t / 3u) % 4u == 1u ? 0u
                                                     : r % (top + 1u));
        }
        memset(a, GUARD, sizeof a);
        memset(b, GUARD, sizeof b);
        memset(sa, GUARD, sizeof sa);
        memset(sb, GUARD, sizeof sb);
        symline_i_grid_fold(in, w, l, sa, NULL);
        symline_i_grid_fold_c(in, w, l, sb, NULL);
        assert_memory_equal(sa, sb, sizeof sa);
        symline_i_grid_fold(in + 1, w, l, sa, a); /* the second row: other sums */
        symline_i_grid_fold_c(in + 1, w, l, sb, b);
        assert_memory_equal(sa, sb, sizeof sa);
        assert_memory_equal(a, b, sizeof a);
    }
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(row_is_definition),
        cmocka_unit_test(pyramid_is_definition),
#ifdef SYMLINE_PORT_GRID_SUMS
        cmocka_unit_test(pyramid_simd_is_reference),
#endif
#ifdef SYMLINE_PORT_GRID
        cmocka_unit_test(simd_is_reference),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
