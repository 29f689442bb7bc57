/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The first kept row per grid column (symline_i_field_rows(),
 * lib/fieldboundary.h) against symline_field_y() at every column's centre:
 * where the build optimises for speed the rows are stepped along each chord
 * by a running quotient and remainder, which must give the same rows.
 * Random boundaries (1 to SYMLINE_FIELD_MAX_VERTICES vertices, steep and
 * flat chords, vertices at and inside the image edges), frames from 1 px,
 * levels 0 to 5, margins from 0.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fieldboundary.h"
#include "testutil.h"

/* A boundary as symline_i_field_run() leaves it: x strictly growing within
 * the frame, y within 0..height. */
static void random_boundary(symline_field_boundary *b, uint32_t width, uint32_t height, uint32_t *s)
{
    const uint32_t want = 1u + tu_rand(s) % SYMLINE_FIELD_MAX_VERTICES;
    uint32_t n = 0u;
    int32_t x = (int32_t)(tu_rand(s) % 2u == 0u ? 0u : tu_rand(s) % width);
    while (n < want && x < (int32_t)width) {
        b->v[n].x = x;
        b->v[n].y = (int32_t)(tu_rand(s) % (height + 1u));
        n++;
        x += 1 + (int32_t)(tu_rand(s) % (1u + width / 4u));
    }
    b->count = n;
}

static void test_rows_match_field_y(void **state)
{
    uint32_t seed = 12345u, run;
    uint16_t rows[800];
    (void)state;
    for (run = 0; run < 3000u; run++) {
        const uint32_t width = 1u + tu_rand(&seed) % 700u;
        const uint32_t height = 1u + tu_rand(&seed) % 600u;
        const uint32_t level = tu_rand(&seed) % 6u, s = 1u << level;
        const uint32_t margin = tu_rand(&seed) % 3u == 0u ? 0u : tu_rand(&seed) % 40u;
        /* The pass grid's columns, and one more whose centre is clamped. */
        const uint32_t w = (width >> level) + (tu_rand(&seed) % 2u);
        symline_field_boundary b;
        uint32_t x;
        memset(&b, 0, sizeof b);
        random_boundary(&b, width, height, &seed);
        if (w == 0u) {
            continue;
        }
        symline_i_field_rows(&b, level, w, width, margin, rows);
        for (x = 0; x < w; x++) {
            const uint32_t c = x * s + s / 2u;
            const int32_t y = symline_field_y(&b, (int32_t)(c < width ? c : width - 1u)) -
                              (int32_t)(margin + s / 2u);
            const uint32_t want = y <= 0 ? 0u : (uint32_t)(y + (int32_t)s - 1) >> level;
            if (rows[x] != want) {
                print_error("run %u: width %u level %u margin %u column %u: %u, want %u\n", run,
                            width, level, margin, x, rows[x], want);
                fail();
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows_match_field_y),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
