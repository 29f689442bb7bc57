/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The line filter (lib/linefilter.c): thresholds from the configuration,
 * frame statistics and the adaptive thresholds, the gray-value and A-point
 * tests per point, and the whole-piece side test.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "linefilter.h"

static void setup_from_config(void **state)
{
    symline_config cfg;
    symline_i_linefilter f;
    (void)state;
    symline_config_default(&cfg);
    symline_i_linefilter_setup(&f, &cfg);
    assert_int_equal(f.kind, SYMLINE_FILTER_CONTRAST);
    assert_int_equal(f.a_distance, 0);
    assert_int_equal(f.min_gray, cfg.illumination);
    assert_int_equal(f.ridge_pct, cfg.contrast_pct);
    assert_int_equal(f.ridge_min, cfg.contrast_min);
    assert_int_equal(f.asym_pct, cfg.contrast_asym_pct);
    assert_int_equal(f.side_max, 255);
    /* The paper filter searches its A point within a_distance, or the radius. */
    cfg.filter = SYMLINE_FILTER_PAPER;
    cfg.radius = 4;
    symline_i_linefilter_setup(&f, &cfg);
    assert_int_equal(f.a_distance, 4);
    cfg.a_distance = 7;
    symline_i_linefilter_setup(&f, &cfg);
    assert_int_equal(f.a_distance, 7);
}

static void gray_test(void **state)
{
    symline_config cfg;
    symline_i_linefilter f;
    (void)state;
    symline_config_default(&cfg);
    symline_i_linefilter_setup(&f, &cfg);
    assert_true(symline_i_linefilter_gray(&f, 100, 60, 60));  /* a ridge 40 high */
    assert_false(symline_i_linefilter_gray(&f, 62, 60, 60));  /* 2 < contrast_min 3 */
    assert_true(symline_i_linefilter_gray(&f, 63, 60, 60));   /* exactly 3 */
    assert_false(symline_i_linefilter_gray(&f, 60, 60, 60));  /* no ridge */
    assert_false(symline_i_linefilter_gray(&f, 100, 60, 90)); /* sides differ: needs 45 > 10 */
    assert_true(symline_i_linefilter_gray(&f, 140, 60, 90));  /* 50 >= 45 */
    f.side_max = 80u;
    assert_false(symline_i_linefilter_gray(&f, 140, 60, 90)); /* a side above side_max */
    f.side_max = 255u;
    f.ridge_pct = 50u;
    assert_false(symline_i_linefilter_gray(&f, 100, 60, 60)); /* needs 50 % of 100 */
    f.ridge_pct = 0u;
    f.min_gray = 120u;
    assert_false(symline_i_linefilter_gray(&f, 100, 60, 60)); /* darker than min_gray */
    /* The paper filter asks only for the gray value. */
    cfg.filter = SYMLINE_FILTER_PAPER;
    cfg.illumination = 100u;
    symline_i_linefilter_setup(&f, &cfg);
    assert_true(symline_i_linefilter_gray(&f, 100, 200, 10));
    assert_false(symline_i_linefilter_gray(&f, 99, 0, 0));
}

static void statistics_and_adaptive_thresholds(void **state)
{
    static uint8_t px[20 * 20];
    symline_image img;
    symline_i_frame_stats st;
    symline_config cfg;
    symline_i_linefilter f;
    uint16_t top[20];
    uint32_t hist[256];
    uint32_t i;
    (void)state;
    /* Rows 0-7: a bright wall (250); rows 8-19: carpet whose sampled columns
     * (every 4th) read 90 (2), 100 (1) and 110 (2). */
    for (i = 0; i < 20u * 20u; i++) {
        const uint32_t x = i % 20u;
        px[i] = (uint8_t)(i < 8u * 20u ? 250u : (x < 8u ? 90u : (x < 12u ? 100u : 110u)));
    }
    img.width = 20;
    img.height = 20;
    img.stride = 20;
    img.data = px;
    /* The whole frame: the wall's 10 of 25 samples pull the median to 110. */
    symline_i_frame_stats_measure(&img, NULL, hist, &st);
    assert_int_equal(st.mean, 110);
    /* The field from row 8: median 100, MAD 10, sigma 1.4826 * 10 = 14.8 (Q4 237). */
    for (i = 0; i < 20u; i++) {
        top[i] = 8u;
    }
    st.grain_q8 = 99u;
    symline_i_frame_stats_measure(&img, top, hist, &st);
    assert_int_equal(st.mean, 100);
    assert_int_equal(st.sigma_q4, 237);
    assert_int_equal(st.ridge_q4, 237); /* the ridge's sigma: sigma until the carpet lowers it */
    assert_int_equal(st.grain_q8, 0);   /* no carpet model here: the detector's to set */
    /* No field in the frame: nothing measured. */
    for (i = 0; i < 20u; i++) {
        top[i] = 20u;
    }
    symline_i_frame_stats_measure(&img, top, hist, &st);
    assert_int_equal(st.mean, 0);
    assert_int_equal(st.sigma_q4, 0);
    /* Thresholds from a spread of 40 about a level of 100. */
    st.mean = 100u;
    st.sigma_q4 = 640u;
    st.ridge_q4 = 640u;
    symline_config_default(&cfg);
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 1u);
    assert_int_equal(f.min_gray, 100); /* mean + 0 sigma */
    assert_int_equal(f.ridge_min, 36); /* 0.9 sigma */
    assert_int_equal(f.side_max, 220); /* mean + 3.0 sigma */
    /* Full resolution: the sides one sigma higher (they lie in a bright
     * line's blur); the other thresholds as at coarser scales. */
    st.sigma_q4 = 320u;
    st.ridge_q4 = 320u;
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 1u);
    assert_int_equal(f.side_max, 160); /* mean + 3.0 sigma */
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 0u);
    assert_int_equal(f.side_max, 180); /* mean + 4.0 sigma */
    assert_int_equal(f.ridge_min, 18); /* 0.9 sigma */
    /* The ridge scales its own sigma; the sides and the brightness keep sigma. */
    st.ridge_q4 = 256u;
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 0u);
    assert_int_equal(f.ridge_min, 14); /* 0.9 x 16 = 14.4 */
    assert_int_equal(f.side_max, 180);
    assert_int_equal(f.min_gray, 100);
    st.sigma_q4 = 640u;
    st.ridge_q4 = 640u;
    /* Configured thresholds above the adaptive ones stay; side_sigma10 100 is off. */
    cfg.illumination = 150u;
    cfg.contrast_min = 120u;
    cfg.side_sigma10 = 100;
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 0u);
    assert_int_equal(f.min_gray, 150);
    assert_int_equal(f.ridge_min, 120);
    assert_int_equal(f.side_max, 255);
    /* The carpet's noise: a ridge of at least 2.5 grains, halved per level
     * (8 gray levels of grain: 20, 10, 5), above 0.9 sigma (9) or below it. */
    cfg.illumination = 0u;
    cfg.contrast_min = 3u;
    cfg.side_sigma10 = 30;
    st.sigma_q4 = 160u;
    st.ridge_q4 = 160u;
    st.grain_q8 = 2048u;
    for (i = 0; i < 3u; i++) {
        static const uint8_t want[3] = {20u, 10u, 9u};
        symline_i_linefilter_setup(&f, &cfg);
        symline_i_linefilter_adapt(&f, &cfg, &st, i);
        assert_int_equal(f.ridge_min, want[i]);
        assert_int_equal(f.side_max, i == 0u ? 140 : 130); /* the sides keep sigma */
    }
    cfg.contrast_min = 30u; /* a configured ridge above the floor stays */
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 0u);
    assert_int_equal(f.ridge_min, 30);
    st.sigma_q4 = 640u;
    st.ridge_q4 = 640u;
    st.grain_q8 = 0u;
    /* Clipped to gray levels. */
    cfg.bright_sigma10 = -100;
    cfg.illumination = 0u;
    cfg.side_sigma10 = 99;
    symline_i_linefilter_setup(&f, &cfg);
    symline_i_linefilter_adapt(&f, &cfg, &st, 0u);
    assert_int_equal(f.min_gray, 0);
    assert_int_equal(f.side_max, 255);
}

/* The ridge's sigma on a carpet: five grains (texture x gray value) between
 * 0.8 sigma and sigma. */
static void ridge_sigma_from_grain(void **state)
{
    uint32_t s, t, m;
    (void)state;
    /* Grain 32 / 256 x 128 = 16 gray levels (Q4 256), five grains Q4 1280. */
    assert_int_equal(symline_i_ridge_q4(1400u, 32u * 128u), 1280u); /* between the bounds */
    assert_int_equal(symline_i_ridge_q4(1000u, 32u * 128u), 1000u); /* never above sigma */
    assert_int_equal(symline_i_ridge_q4(4000u, 32u * 128u), 3200u); /* never below 0.8 sigma */
    assert_int_equal(symline_i_ridge_q4(0u, 255u * 255u), 0u);
    assert_int_equal(symline_i_ridge_q4(6048u, 0u), 4838u); /* the largest sigma, no grain */
    /* Over every sigma a frame can have and a grid of carpets: within the bounds,
     * and falling towards 0.8 sigma as the grain shrinks. */
    for (s = 0u; s <= 6048u; s += 7u) {
        for (m = 0u; m < 256u; m += 15u) {
            uint32_t prev = s;
            for (t = 255u; t < 256u; t -= 5u) {
                const uint32_t r = symline_i_ridge_q4(s, t * m);
                assert_true(r <= s && r >= s * 4u / 5u && r <= prev);
                prev = r;
            }
        }
    }
}

/* A horizontal band of gray `line` on row 20 of a 40x40 frame, `above` and
 * `below` it; the piece: its points x = 5..30; the whole-piece test with
 * this ridge_min. */
static bool band_fails(uint8_t line, uint8_t above, uint8_t below, uint32_t ridge_min)
{
    static uint8_t px[40 * 40];
    symline_point q[26];
    symline_image img;
    symline_config cfg;
    symline_i_linefilter f;
    uint32_t i;
    memset(px, above, 20 * 40);
    memset(px + 20 * 40, line, 40);
    memset(px + 21 * 40, below, 19 * 40);
    for (i = 0; i < 26u; i++) {
        q[i].x = (uint16_t)(5u + i);
        q[i].y = 20;
    }
    img.width = 40;
    img.height = 40;
    img.stride = 40;
    img.data = px;
    symline_config_default(&cfg);
    symline_i_linefilter_setup(&f, &cfg);
    f.ridge_min = ridge_min;
    return symline_i_linefilter_piece_fails(&f, &img, SYMLINE_AXIS_HORIZONTAL, 0, 4, q, 26);
}

static void whole_piece_side_test(void **state)
{
    (void)state;
    assert_false(band_fails(200, 60, 60, 3u));  /* a line on the carpet */
    assert_false(band_fails(200, 60, 75, 3u));  /* 15 apart: 4500 <= 12500 */
    assert_true(band_fails(200, 60, 140, 3u));  /* a wall's foot: 24000 > 6000 */
    assert_true(band_fails(100, 100, 100, 3u)); /* no ridge at all */
    /* A 26 px piece's mean ridge must reach ridge_min * (26 + 16) / 26. */
    assert_false(band_fails(200, 60, 60, 86u)); /* 140 >= 138.9 */
    assert_true(band_fails(200, 60, 60, 87u));  /* 140 < 140.5 */
}

/* The whole-piece test the plain way: every side clamped to the frame. */
static bool piece_fails_ref(const symline_i_linefilter *f, const symline_image *img, bool horiz,
                            uint32_t level, uint32_t k, const symline_point *q, uint32_t n)
{
    const uint32_t half = (1u << level) >> 1, off = k << level, len = n << level;
    const uint32_t lim = horiz ? img->height : img->width;
    uint32_t lo = 0u, hi = 0u, centre = 0u, i, side, ridge;
    for (i = 0; i < n; i++) {
        const uint32_t x = ((uint32_t)q[i].x << level) + half;
        const uint32_t y = ((uint32_t)q[i].y << level) + half;
        const uint32_t pos = horiz ? y : x, a = pos >= off ? pos - off : 0u;
        const uint32_t b = pos + off < lim ? pos + off : lim - 1u;
        centre += img->data[y * img->stride + x];
        lo += horiz ? img->data[a * img->stride + x] : img->data[y * img->stride + a];
        hi += horiz ? img->data[b * img->stride + x] : img->data[y * img->stride + b];
    }
    side = lo > hi ? lo : hi;
    if (centre <= side) {
        return true;
    }
    ridge = centre - side;
    if ((2u * side - lo - hi) * (2u * f->asym_pct) > ridge * 100u) {
        return true;
    }
    return (uint64_t)ridge * len < (uint64_t)f->ridge_min * n * (len + 16u);
}

/* Pieces along and across both borders of a noisy frame, both axes, the
 * first scales and reaches up to past half the frame: the same answer as
 * the plain clamped sums (the speed builds read most sides unclamped). */
static void whole_piece_side_test_at_borders(void **state)
{
    enum {
        W = 48,
        H = 36
    };
    static uint8_t px[W * H];
    symline_point q[40];
    symline_image img;
    symline_config cfg;
    symline_i_linefilter f;
    uint32_t seed = 3u, i, t, fails = 0u;
    (void)state;
    for (i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        px[i] = (uint8_t)(((i / W) % 5u == 2u ? 150u : 40u) + (seed >> 26));
    }
    img.width = W;
    img.height = H;
    img.stride = W;
    img.data = px;
    symline_config_default(&cfg);
    symline_i_linefilter_setup(&f, &cfg);
    for (t = 0; t < 400u; t++) {
        const uint32_t level = t % 3u, k = 1u + (t / 3u) % 12u, n = 4u + t % 30u;
        const bool horiz = (t / 7u) % 2u == 0u;
        const uint32_t gw = W >> level, gh = H >> level;
        uint32_t x = (t * 7u) % gw, y = (t * 5u) % gh;
        for (i = 0; i < n; i++) {
            q[i].x = (uint16_t)x;
            q[i].y = (uint16_t)y;
            x = (x + 1u) % gw;
            y = (y + (i % 3u == 0u ? 1u : 0u)) % gh;
        }
        f.ridge_min = t % 4u;
        f.asym_pct = t % 5u == 0u ? 0u : 40u;
        assert_int_equal(
            symline_i_linefilter_piece_fails(
                &f, &img, horiz ? SYMLINE_AXIS_HORIZONTAL : SYMLINE_AXIS_VERTICAL, level, k, q, n),
            piece_fails_ref(&f, &img, horiz, level, k, q, n));
        fails += piece_fails_ref(&f, &img, horiz, level, k, q, n) ? 1u : 0u;
    }
    /* Both answers occur. */
    assert_true(fails > 0u && fails < 400u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(setup_from_config),
        cmocka_unit_test(gray_test),
        cmocka_unit_test(statistics_and_adaptive_thresholds),
        cmocka_unit_test(ridge_sigma_from_grain),
        cmocka_unit_test(whole_piece_side_test),
        cmocka_unit_test(whole_piece_side_test_at_borders),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
