/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Properties the operator must have whatever the picture, checked on
 * pseudo-random images of many sizes and radii, plus a differential check of
 * every output against the formulas of docs/algorithm.md evaluated directly.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "symline/extrema.h"
#include "symline/symmetry.h"
#include "testutil.h"

typedef struct frame {
    uint32_t w, h;
    uint8_t *px;
} frame;

static frame random_frame(uint32_t w, uint32_t h, uint32_t *seed, uint32_t levels)
{
    frame f;
    uint32_t i;
    f.w = w;
    f.h = h;
    f.px = (uint8_t *)malloc((size_t)w * h);
    assert_non_null(f.px);
    for (i = 0; i < w * h; i++) {
        /* few levels give many equal energies, i.e. plateaus */
        f.px[i] = (uint8_t)((tu_rand(seed) % levels) * (255u / (levels - 1u)));
    }
    return f;
}

static symline_image view(const frame *f)
{
    symline_image v;
    v.width = f->w;
    v.height = f->h;
    v.stride = f->w;
    v.data = f->px;
    return v;
}

static uint32_t *energies(const frame *f, symline_axis axis, uint32_t m)
{
    symline_image v = view(f);
    uint32_t *E = (uint32_t *)malloc(sizeof(uint32_t) * f->w * f->h);
    assert_non_null(E);
    assert_int_equal(symline_energy_frame(&v, axis, m, E, f->w, (size_t)f->w * f->h), SYMLINE_OK);
    return E;
}

static uint8_t *plane(const frame *f, symline_axis axis, uint32_t m, int extrema)
{
    symline_image v = view(f);
    size_t ws_size = extrema ? symline_extrema_workspace_size(f->w, f->h, axis, m)
                             : symline_symmetry_workspace_size(f->w, f->h, axis, m);
    void *ws = malloc(ws_size);
    uint8_t *out = (uint8_t *)malloc((size_t)f->w * f->h);
    symline_status st;
    assert_non_null(ws);
    assert_non_null(out);
    st = extrema ? symline_extrema(&v, axis, m, out, f->w, (size_t)f->w * f->h, ws, ws_size)
                 : symline_symmetry(&v, axis, m, out, f->w, (size_t)f->w * f->h, ws, ws_size);
    assert_int_equal(st, SYMLINE_OK);
    free(ws);
    return out;
}

static frame transpose(const frame *f)
{
    frame t;
    uint32_t x, y;
    t.w = f->h;
    t.h = f->w;
    t.px = (uint8_t *)malloc((size_t)f->w * f->h);
    assert_non_null(t.px);
    for (y = 0; y < f->h; y++) {
        for (x = 0; x < f->w; x++) {
            t.px[(size_t)x * t.w + y] = f->px[(size_t)y * f->w + x];
        }
    }
    return t;
}

/* A mirror-symmetric row is perfectly symmetric at its centre when the window fits. */
static void test_mirror_row_is_255_at_centre(void **state)
{
    uint32_t seed = 11, m, trial;
    (void)state;
    for (trial = 0; trial < 50; trial++) {
        uint32_t half = 1 + tu_rand(&seed) % 40, n = 2 * half + 1, i;
        uint8_t q[81], s8[81];
        uint32_t E[81];
        for (i = 0; i <= half; i++) {
            q[half - i] = q[half + i] = (uint8_t)tu_rand(&seed);
        }
        m = 1 + tu_rand(&seed) % half;
        assert_int_equal(symline_energy_row(q, n, m, E), SYMLINE_OK);
        assert_int_equal(E[half], 0);
        assert_int_equal(symline_s8_row(E, n, m, s8), SYMLINE_OK);
        assert_int_equal(s8[half], 255);
    }
}

/* Adding a constant (no clipping) leaves E unchanged wherever the window is inside. */
static void test_constant_offset_keeps_energy(void **state)
{
    uint32_t seed = 5, trial;
    (void)state;
    for (trial = 0; trial < 20; trial++) {
        const uint32_t w = 5 + tu_rand(&seed) % 30, h = 5 + tu_rand(&seed) % 30;
        const uint32_t m = 1 + tu_rand(&seed) % 6, add = 1 + tu_rand(&seed) % 55;
        frame f = random_frame(w, h, &seed, 200), g;
        uint32_t i, x, y, a;
        g = f;
        g.px = (uint8_t *)malloc((size_t)w * h);
        for (i = 0; i < w * h; i++) {
            g.px[i] = (uint8_t)(f.px[i] + add); /* values <= 200, so no clipping */
        }
        for (a = 0; a < 2; a++) {
            const symline_axis axis = a ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
            uint32_t *e1 = energies(&f, axis, m), *e2 = energies(&g, axis, m);
            for (y = 0; y < h; y++) {
                for (x = 0; x < w; x++) {
                    const uint32_t i0 = axis == SYMLINE_AXIS_VERTICAL ? x : y;
                    const uint32_t n = axis == SYMLINE_AXIS_VERTICAL ? w : h;
                    if (i0 >= m && i0 + m <= n - 1) {
                        assert_int_equal(e1[y * w + x], e2[y * w + x]);
                    }
                }
            }
            free(e1);
            free(e2);
        }
        free(f.px);
        free(g.px);
    }
}

/* Transposing the image swaps the axes exactly: energies, S8 and extrema. */
static void test_transpose_swaps_axes(void **state)
{
    uint32_t seed = 77, trial;
    (void)state;
    for (trial = 0; trial < 30; trial++) {
        const uint32_t w = 1 + tu_rand(&seed) % 33, h = 1 + tu_rand(&seed) % 33;
        const uint32_t m = 1 + tu_rand(&seed) % 12;
        frame f = random_frame(w, h, &seed, 2 + tu_rand(&seed) % 6), t = transpose(&f);
        uint32_t x, y, k;
        for (k = 0; k < 2; k++) {
            uint8_t *a = plane(&f, SYMLINE_AXIS_HORIZONTAL, m, (int)k);
            uint8_t *b = plane(&t, SYMLINE_AXIS_VERTICAL, m, (int)k);
            uint8_t *c = plane(&f, SYMLINE_AXIS_VERTICAL, m, (int)k);
            uint8_t *d = plane(&t, SYMLINE_AXIS_HORIZONTAL, m, (int)k);
            for (y = 0; y < h; y++) {
                for (x = 0; x < w; x++) {
                    assert_int_equal(a[y * w + x], b[x * h + y]);
                    assert_int_equal(c[y * w + x], d[x * h + y]);
                }
            }
            free(a);
            free(b);
            free(c);
            free(d);
        }
        free(f.px);
        free(t.px);
    }
}

/*
 * A horizontal flip mirrors the vertical-axis results. Energies and S8 mirror
 * exactly; an extremum on a run [a, b] is marked at (a+b) div 2, so on a run
 * of even length the mirrored mark lands one pixel to the right, on the same
 * plateau.
 */
static void test_flip_mirrors_vertical_axis(void **state)
{
    uint32_t seed = 123, trial;
    (void)state;
    for (trial = 0; trial < 30; trial++) {
        const uint32_t w = 1 + tu_rand(&seed) % 40, h = 1 + tu_rand(&seed) % 8;
        const uint32_t m = 1 + tu_rand(&seed) % 10;
        frame f = random_frame(w, h, &seed, 2 + tu_rand(&seed) % 4), g = f;
        uint32_t x, y;
        uint32_t *e1, *e2;
        uint8_t *s1, *s2, *x1, *x2;
        g.px = (uint8_t *)malloc((size_t)w * h);
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                g.px[y * w + x] = f.px[y * w + (w - 1 - x)];
            }
        }
        e1 = energies(&f, SYMLINE_AXIS_VERTICAL, m);
        e2 = energies(&g, SYMLINE_AXIS_VERTICAL, m);
        s1 = plane(&f, SYMLINE_AXIS_VERTICAL, m, 0);
        s2 = plane(&g, SYMLINE_AXIS_VERTICAL, m, 0);
        x1 = plane(&f, SYMLINE_AXIS_VERTICAL, m, 1);
        x2 = plane(&g, SYMLINE_AXIS_VERTICAL, m, 1);
        for (y = 0; y < h; y++) {
            const uint32_t *e = e1 + y * w;
            for (x = 0; x < w; x++) {
                const uint32_t fx = w - 1 - x;
                assert_int_equal(e1[y * w + x], e2[y * w + fx]);
                assert_int_equal(s1[y * w + x], s2[y * w + fx]);
                if (x1[y * w + x] != 0) {
                    /* mark k in the original: the flip marks k, or k+1 on an even plateau */
                    const int same = x2[y * w + fx] == x1[y * w + x];
                    const int next = x + 1 < w && e[x + 1] == e[x] && fx >= 1 &&
                                     x2[y * w + fx - 1] == x1[y * w + x];
                    assert_true(same || next);
                }
            }
        }
        free(e1);
        free(e2);
        free(s1);
        free(s2);
        free(x1);
        free(x2);
        free(f.px);
        free(g.px);
    }
}

/* Every output against the formulas evaluated directly, on many random images. */
static void test_differential_against_formulas(void **state)
{
    uint32_t seed = 2024, trial;
    (void)state;
    for (trial = 0; trial < 300; trial++) {
        const uint32_t w = 1 + tu_rand(&seed) % 40, h = 1 + tu_rand(&seed) % 40;
        const uint32_t m = (trial % 10 == 0) ? 200 + tu_rand(&seed) % 56 : 1 + tu_rand(&seed) % 60;
        frame f = random_frame(w, h, &seed, 2 + tu_rand(&seed) % 255);
        uint32_t a;
        for (a = 0; a < 2; a++) {
            const symline_axis axis = a ? SYMLINE_AXIS_VERTICAL : SYMLINE_AXIS_HORIZONTAL;
            const uint32_t n = a ? w : h, lines = a ? h : w;
            const uint64_t emax = 65025ull * (m * (m + 1) / 2);
            uint32_t *E = energies(&f, axis, m);
            uint8_t *s8 = plane(&f, axis, m, 0), *ext = plane(&f, axis, m, 1);
            uint32_t line, i;
            for (line = 0; line < lines; line++) {
                /* index i of this line lives at pixel `at(i)` */
                const size_t step = a ? 1 : w, first = a ? (size_t)line * w : line;
                uint32_t *seq = (uint32_t *)malloc(sizeof(uint32_t) * n);
                uint32_t r0 = 0;
                for (i = 0; i < n; i++) {
                    const uint32_t want = tu_energy_direct(f.px + first, step, n, i, m);
                    seq[i] = want;
                    assert_int_equal(E[first + i * step], want);
                    assert_int_equal(s8[first + i * step],
                                     (uint8_t)((510 * (emax - want) + emax) / (2 * emax)));
                }
                /* runs of equal E, straight from docs/algorithm.md */
                while (r0 < n) {
                    uint32_t r1 = r0, k;
                    uint8_t want = 0;
                    while (r1 + 1 < n && seq[r1 + 1] == seq[r0]) {
                        r1++;
                    }
                    if (r0 >= 1 && r1 + 2 <= n) {
                        if (seq[r0 - 1] > seq[r0] && seq[r1 + 1] > seq[r1]) {
                            want = 255;
                        } else if (seq[r0 - 1] < seq[r0] && seq[r1 + 1] < seq[r1]) {
                            want = 128;
                        }
                    }
                    for (k = r0; k <= r1; k++) {
                        assert_int_equal(ext[first + k * step], k == (r0 + r1) / 2 ? want : 0);
                    }
                    r0 = r1 + 1;
                }
                free(seq);
            }
            free(E);
            free(s8);
            free(ext);
        }
        free(f.px);
    }
}

/* Two S points are never adjacent along the direction they were found in. */
static void test_s_points_never_adjacent(void **state)
{
    uint32_t seed = 99, trial;
    (void)state;
    for (trial = 0; trial < 40; trial++) {
        const uint32_t w = 2 + tu_rand(&seed) % 50, h = 2 + tu_rand(&seed) % 50;
        const uint32_t m = 1 + tu_rand(&seed) % 8;
        frame f = random_frame(w, h, &seed, 2 + tu_rand(&seed) % 10);
        uint8_t *hx = plane(&f, SYMLINE_AXIS_HORIZONTAL, m, 1);
        uint8_t *vx = plane(&f, SYMLINE_AXIS_VERTICAL, m, 1);
        uint32_t x, y;
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                if (x + 1 < w) {
                    assert_false(vx[y * w + x] == 255 && vx[y * w + x + 1] == 255);
                }
                if (y + 1 < h) {
                    assert_false(hx[y * w + x] == 255 && hx[(y + 1) * w + x] == 255);
                }
            }
        }
        free(hx);
        free(vx);
        free(f.px);
    }
}

/* Row-pointer energies (a ring of camera rows) equal the whole-frame energies. */
static void test_row_window_matches_frame(void **state)
{
    uint32_t seed = 31, trial;
    (void)state;
    for (trial = 0; trial < 20; trial++) {
        const uint32_t w = 1 + tu_rand(&seed) % 30, h = 1 + tu_rand(&seed) % 30;
        const uint32_t m = 1 + tu_rand(&seed) % 15;
        frame f = random_frame(w, h, &seed, 256);
        uint32_t *E = energies(&f, SYMLINE_AXIS_HORIZONTAL, m), *row = malloc(sizeof(uint32_t) * w);
        const uint8_t *rows[31];
        uint32_t y, j, x;
        for (y = 0; y < h; y++) {
            for (j = 0; j <= 2 * m; j++) {
                const int32_t r = (int32_t)y + (int32_t)j - (int32_t)m;
                rows[j] = (r >= 0 && r < (int32_t)h) ? f.px + (size_t)r * w : NULL;
            }
            assert_int_equal(symline_energy_across(rows, m, w, row), SYMLINE_OK);
            for (x = 0; x < w; x++) {
                assert_int_equal(row[x], E[y * w + x]);
            }
        }
        free(row);
        free(E);
        free(f.px);
    }
}

/* S8 of every energy 0..Emax for every radius up to 20, against the 64-bit formula. */
static void test_s8_exhaustive(void **state)
{
    static uint32_t E[4096];
    static uint8_t out[4096];
    uint32_t m;
    (void)state;
    for (m = 1; m <= 20; m++) {
        const uint64_t emax = symline_emax(m);
        uint64_t e0;
        for (e0 = 0; e0 <= emax; e0 += 4096) {
            const uint32_t n = (uint32_t)((emax - e0 + 1 < 4096) ? emax - e0 + 1 : 4096);
            uint32_t i;
            for (i = 0; i < n; i++) {
                E[i] = (uint32_t)(e0 + i);
            }
            assert_int_equal(symline_s8_row(E, n, m, out), SYMLINE_OK);
            for (i = 0; i < n; i++) {
                const uint64_t want = (510u * (emax - E[i]) + emax) / (2u * emax);
                if (out[i] != want) {
                    fail_msg("m=%u E=%u: S8 %u, want %u", m, E[i], out[i], (unsigned)want);
                }
            }
        }
    }
}

/* S8 around every step of the quotient (E where it changes, +-3) for every
 * radius 1..255, against the 64-bit formula: the radii above 20 that the
 * exhaustive test leaves out. */
static void test_s8_steps_every_radius(void **state)
{
    uint32_t E[7 * 257];
    uint8_t out[7 * 257];
    uint32_t m;
    (void)state;
    for (m = 1; m <= 255; m++) {
        const uint64_t emax = symline_emax(m);
        uint32_t n = 0, i, q;
        int32_t d;
        for (q = 0; q <= 256; q++) {
            /* 510 D + emax = q * 2 emax at D = (2q - 1) emax / 510. */
            const int64_t d0 = ((int64_t)(2 * q) - 1) * (int64_t)emax / 510;
            for (d = -3; d <= 3; d++) {
                if (d0 + d >= 0 && d0 + d <= (int64_t)emax) {
                    E[n++] = (uint32_t)(emax - (uint64_t)(d0 + d));
                }
            }
        }
        assert_int_equal(symline_s8_row(E, n, m, out), SYMLINE_OK);
        for (i = 0; i < n; i++) {
            const uint64_t want = (510u * (emax - E[i]) + emax) / (2u * emax);
            if (out[i] != want) {
                fail_msg("m=%u E=%u: S8 %u, want %u", m, E[i], out[i], (unsigned)want);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mirror_row_is_255_at_centre),
        cmocka_unit_test(test_constant_offset_keeps_energy),
        cmocka_unit_test(test_transpose_swaps_axes),
        cmocka_unit_test(test_flip_mirrors_vertical_axis),
        cmocka_unit_test(test_differential_against_formulas),
        cmocka_unit_test(test_s_points_never_adjacent),
        cmocka_unit_test(test_row_window_matches_frame),
        cmocka_unit_test(test_s8_exhaustive),
        cmocka_unit_test(test_s8_steps_every_radius),
    };
    return cmocka_run_group_tests_name("core_properties", tests, NULL, NULL);
}
