/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The field boundary's column scan in lanes (lib/fieldboundary.c, builds
 * that optimise for speed on 64-bit targets) against the scan cell by cell
 * that the other builds run: the same boundary, vertex for vertex. Random
 * scenes (carpets of any brightness and grain, shadows, lines, robots, walls
 * smooth and textured, a lens's black rim, a black band over the bottom with
 * carpet below it in some columns, frames from 1 px) under the
 * default settings and under random ones within their ranges, so that
 * barriers, the rim's second scan and every branch of a cell's score occur.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fieldboundary.h"
#include "testutil.h"

#if SL_FOR_SPEED_DEEP

/* A value in lo .. hi. */
static uint32_t pick(uint32_t *s, uint32_t lo, uint32_t hi)
{
    return lo + tu_rand(s) % (hi - lo + 1u);
}

static uint8_t clip(int32_t v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
}

/* A scene of w x h px: carpet below a slanted, bent boundary, a wall above
 * it, shadow stripes, bright lines and dark robots on the carpet, now and
 * then a lens's black rim. */
static void make_scene(uint8_t *px, uint32_t w, uint32_t h, uint32_t *s)
{
    const int32_t base = (int32_t)pick(s, 8u, 160u), grain = (int32_t)pick(s, 0u, 48u);
    const int32_t wall = (int32_t)pick(s, 0u, 255u), wall_grain = (int32_t)pick(s, 0u, 40u);
    const int32_t y0 = (int32_t)pick(s, 0u, h), y1 = (int32_t)pick(s, 0u, h);
    const int32_t bend = (int32_t)pick(s, 0u, w), lift = (int32_t)pick(s, 0u, h / 2u + 1u);
    const int32_t shade_x = (int32_t)pick(s, 0u, w), shade_w = (int32_t)pick(s, 0u, w);
    const int32_t shade = (int32_t)pick(s, 40u, 160u); /* % of the carpet's gray */
    const int32_t line_y = (int32_t)pick(s, 0u, h), line_w = (int32_t)pick(s, 1u, 8u);
    const int32_t line_x = (int32_t)pick(s, 0u, w), line_g = (int32_t)pick(s, 120u, 255u);
    const int32_t bot_x = (int32_t)pick(s, 0u, w), bot_w = (int32_t)pick(s, 0u, w / 4u + 1u);
    const int32_t bot_h = (int32_t)pick(s, 0u, h / 2u + 1u);
    const bool rim = pick(s, 0u, 3u) == 0u;
    const int32_t r2 = (int32_t)((w * w + h * h) / pick(s, 4u, 6u));
    /* a black band over the bottom (a tall rim: most columns find no carpet
     * at first), carpet below it in some columns */
    const bool band = pick(s, 0u, 3u) == 0u;
    const int32_t band_h = (int32_t)pick(s, 1u, h / 3u + 1u), foot = (int32_t)pick(s, 0u, 12u);
    const int32_t foot_x = (int32_t)pick(s, 0u, w), foot_w = (int32_t)pick(s, 0u, w);
    uint32_t x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int32_t xi = (int32_t)x, yi = (int32_t)y;
            const int32_t top = y0 + (y1 - y0) * xi / (int32_t)w -
                                (xi < bend ? lift * xi / (bend + 1)
                                           : lift * ((int32_t)w - xi) / ((int32_t)w - bend + 1));
            const int32_t dx = 2 * xi - (int32_t)w, dy = 2 * yi - (int32_t)h;
            int32_t v;
            if (yi < top) {
                v = wall + (int32_t)pick(s, 0u, (uint32_t)(2 * wall_grain)) - wall_grain;
            } else {
                v = base + (int32_t)pick(s, 0u, (uint32_t)(2 * grain)) - grain;
                if (xi >= shade_x && xi < shade_x + shade_w) {
                    v = v * shade / 100;
                }
                if ((yi >= line_y && yi < line_y + line_w) ||
                    (xi >= line_x && xi < line_x + line_w)) {
                    v = line_g - (int32_t)pick(s, 0u, 10u);
                }
                if (xi >= bot_x && xi < bot_x + bot_w && yi > (int32_t)h - bot_h) {
                    v = (int32_t)pick(s, 10u, 40u);
                }
            }
            if (rim && dx * dx + dy * dy > 4 * r2) {
                v = (int32_t)pick(s, 0u, 8u);
            }
            if (band && yi >= (int32_t)h - band_h - foot &&
                (yi < (int32_t)h - foot || xi < foot_x || xi >= foot_x + foot_w)) {
                v = (int32_t)pick(s, 0u, 8u);
            }
            px[(size_t)y * w + x] = clip(v);
        }
    }
}

/* Random settings within their ranges, or the defaults. */
static void make_config(symline_field_config *fc, uint32_t *s)
{
    static const uint32_t cells[7] = {0u, 2u, 4u, 8u, 16u, 32u, 64u};
    symline_field_config_default(fc);
    if (pick(s, 0u, 2u) == 0u) {
        return;
    }
    fc->cell = cells[pick(s, 0u, 6u)];
    fc->band_pct = pick(s, 1u, 100u);
    fc->mean_tol = pick(s, 0u, 64u);
    fc->local_tol = pick(s, 0u, 3u) == 0u ? 255u : pick(s, 0u, 64u);
    fc->tex_lo_pct = pick(s, 0u, 100u);
    fc->tex_hi_pct = pick(s, 0u, 3u) == 0u ? 10000u : pick(s, 100u, 400u);
    fc->miss_cost = pick(s, 1u, 16u);
    fc->gap_pct = pick(s, 0u, 3u) == 0u ? 0u : pick(s, 1u, 100u);
    fc->support = pick(s, 1u, 8u);
    fc->col_cells = pick(s, 1u, 4u);
    fc->restore_cells = pick(s, 0u, 8u);
    fc->edge_slope_pct = pick(s, 0u, 200u);
}

/* The boundaries of the lanes and of the scalar scan of px under fc. */
static void compare(const uint8_t *px, uint32_t w, uint32_t h, const symline_field_config *fc,
                    uint32_t scene)
{
    const size_t n = symline_field_workspace_size(w, h, fc);
    uint8_t *const ws = (uint8_t *)malloc(n);
    symline_field_boundary a, b;
    symline_image img;
    assert_true(n > 0u);
    assert_non_null(ws);
    img.data = px;
    img.width = w;
    img.height = h;
    img.stride = w;
    memset(&a, 0x5A, sizeof a);
    memset(&b, 0x5A, sizeof b);
    symline_i_field_run(&img, fc, ws, n, &a);
    symline_i_field_run_scalar(&img, fc, ws, n, &b);
    if (memcmp(&a, &b, sizeof a) != 0) {
        fail_msg("scene %u (%ux%u, cell %u, gap %u %%): lanes %u vertices, scalar %u", scene, w, h,
                 fc->cell, fc->gap_pct, a.count, b.count);
    }
    free(ws);
}

static void test_lanes_match_scalar(void **state)
{
    uint32_t s = 20261202u, i;
    (void)state;
    for (i = 0; i < 600u; i++) {
        const uint32_t w = i % 10u == 0u ? pick(&s, 1u, 40u) : pick(&s, 16u, 720u);
        const uint32_t h = i % 10u == 1u ? pick(&s, 1u, 40u) : pick(&s, 16u, 560u);
        uint8_t *px = (uint8_t *)malloc((size_t)w * h);
        symline_field_config fc;
        assert_non_null(px);
        make_scene(px, w, h, &s);
        make_config(&fc, &s);
        assert_true(symline_i_field_config_ok(&fc));
        compare(px, w, h, &fc, i);
        free(px);
    }
}

/* A tall black band over the bottom of a dim carpet, rows of every height
 * in grid rows: carpet through it in the middle columns, below it (a foot)
 * in those at the left edge, none in the rest, so that most columns find no
 * carpet at first and the second scan runs with the rim's rows free; the
 * left columns found carpet before the band, so in the rim's rows their
 * black cells are not free, and the band is their barrier or not. */
static void test_rim(void **state)
{
    static const uint32_t gaps[3] = {30u, 20u, 12u};
    const uint32_t w = 320u, h = 240u, foot = 6u;
    uint8_t *px = (uint8_t *)malloc((size_t)w * h);
    uint32_t s = 7u, band, g, x, y;
    (void)state;
    assert_non_null(px);
    for (g = 0; g < 3u; g++) {
        for (band = 40u; band <= 120u; band += 8u) {
            symline_field_config fc;
            symline_field_config_default(&fc);
            fc.gap_pct = gaps[g];
            fc.band_pct = 100u; /* the model from the carpet, not the band */
            for (y = 0; y < h; y++) {
                const bool in_band = y >= h - band - foot;
                for (x = 0; x < w; x++) {
                    const bool black = x >= 120u && x < 200u ? false
                                       : x < 80u             ? in_band && y < h - foot
                                                             : in_band;
                    px[(size_t)y * w + x] =
                        (uint8_t)(black ? tu_rand(&s) % 6u : 30u + tu_rand(&s) % 12u);
                }
            }
            compare(px, w, h, &fc, band);
        }
    }
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lanes_match_scalar),
        cmocka_unit_test(test_rim),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

#else

#include <stdio.h>

int main(void)
{
    puts("SKIPPED: this build has no column scan in lanes (64-bit speed builds only)");
    return 77;
}

#endif
