/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Sub-pixel position across the line, on hand-made frames whose ridge middle is
 * known: lines an even and an odd number of pixels wide, a blurred line between
 * pixels, both axes, a coarse scale, the grid border; and the detector's lines
 * on them and on anti-aliased bands at sub-pixel centres.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fixed.h"
#include "pass.h"
#include "subpixel.h"

#define W 64
#define H 48

static uint8_t g_px[W * H];

/* Carpet 60; a bright band across x (vertical line) with the given profile
 * values starting at x0, on every row. */
static symline_image vertical_band(uint32_t x0, const uint8_t *profile, uint32_t n)
{
    symline_image img;
    uint32_t x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            g_px[y * W + x] = (x >= x0 && x < x0 + n) ? profile[x - x0] : 60u;
        }
    }
    img.data = g_px;
    img.width = W;
    img.height = H;
    img.stride = W;
    return img;
}

/* The same band across y (a horizontal line). */
static symline_image horizontal_band(uint32_t y0, const uint8_t *profile, uint32_t n)
{
    symline_image img;
    uint32_t x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            g_px[y * W + x] = (y >= y0 && y < y0 + n) ? profile[y - y0] : 60u;
        }
    }
    img.data = g_px;
    img.width = W;
    img.height = H;
    img.stride = W;
    return img;
}

static symline_i_pass pass_of(symline_axis axis, uint32_t level)
{
    symline_config cfg;
    symline_i_pass p;
    symline_config_default(&cfg);
    symline_i_pass_setup(&p, &cfg, axis, level, W, H);
    return p;
}

/* Offset (1/128 grid px) of the point at index i across the line, row/column `at`. */
static int32_t offset_of(const symline_image *img, const symline_i_pass *p, uint32_t at, uint32_t i)
{
    symline_point q;
    q.x = (uint16_t)(p->axis == SYMLINE_AXIS_VERTICAL ? i : at);
    q.y = (uint16_t)(p->axis == SYMLINE_AXIS_VERTICAL ? at : i);
    q.fx = 99; /* overwritten */
    q.fy = 99;
    symline_i_subpixel(img, p, &q, 1u);
    if (p->axis == SYMLINE_AXIS_VERTICAL) {
        assert_int_equal(q.fy, 0);
        return q.fx;
    }
    assert_int_equal(q.fx, 0);
    return q.fy;
}

static void even_and_odd_widths(void **state)
{
    static const uint8_t two[] = {200, 200}, three[] = {200, 200, 200},
                         four[] = {200, 200, 200, 200};
    symline_image img;
    symline_i_pass v = pass_of(SYMLINE_AXIS_VERTICAL, 0u), h = pass_of(SYMLINE_AXIS_HORIZONTAL, 0u);
    (void)state;
    /* 2 px at x 20, 21: the S point is the lower middle 20, the ridge's middle 20.5. */
    img = vertical_band(20u, two, 2u);
    assert_int_equal(offset_of(&img, &v, 10u, 20u), 64);
    /* 3 px at 20..22: the S point is the middle. */
    img = vertical_band(20u, three, 3u);
    assert_int_equal(offset_of(&img, &v, 10u, 21u), 0);
    /* 4 px at 20..23: S point 21, middle 21.5. */
    img = vertical_band(20u, four, 4u);
    assert_int_equal(offset_of(&img, &v, 10u, 21u), 64);
    /* The same across y. */
    img = horizontal_band(30u, two, 2u);
    assert_int_equal(offset_of(&img, &h, 7u, 30u), 64);
    img = horizontal_band(30u, three, 3u);
    assert_int_equal(offset_of(&img, &h, 7u, 31u), 0);
}

/* A blurred band with its middle between pixels: the offset's sign and size. */
static void blurred_between_pixels(void **state)
{
    /* Samples of a 4 px bright band centred at 22.25 (pixels 19..25), box-blurred. */
    static const uint8_t band[] = {90, 150, 200, 200, 180, 120, 70};
    static const uint8_t mirrored[] = {70, 120, 180, 200, 200, 150, 90};
    symline_image img;
    symline_i_pass v = pass_of(SYMLINE_AXIS_VERTICAL, 0u);
    int32_t off;
    uint32_t i, best = 0u, e, beste = 0xFFFFFFFFu;
    (void)state;
    img = vertical_band(19u, band, 7u);
    /* The S point: the smallest E along the row (docs/algorithm.md). */
    for (i = 19u; i <= 25u; i++) {
        uint32_t j;
        e = 0u;
        for (j = 1u; j <= 3u; j++) {
            const int32_t d = (int32_t)g_px[10 * W + i - j] - (int32_t)g_px[10 * W + i + j];
            e += (4u - j) * (uint32_t)(d * d);
        }
        if (e < beste) {
            beste = e;
            best = i;
        }
    }
    off = offset_of(&img, &v, 10u, best);
    /* The band's brightness centroid (above the carpet) is 12840/590 = 21.76: the
     * point lands within 0.15 px of it, the pixel alone (22) does not. */
    printf("S point %u, offset %d/128\n", best, off);
    assert_int_equal(best, 22);
    assert_true(22 * 128 + off >= 2767 && 22 * 128 + off <= 2805);
    /* The mirrored band (about x 22): the mirrored position. */
    img = vertical_band(19u, mirrored, 7u);
    assert_int_equal(offset_of(&img, &v, 10u, 44u - best), -off);
}

/* Level 1: a 4 px band at full-resolution x 40..43 (middle 41.5) is grid pixels
 * 20, 21; the grid point 20 gets +0.5 and maps to 41.5 at full resolution. */
static void coarse_scale(void **state)
{
    static const uint8_t four[] = {200, 200, 200, 200};
    symline_image img = vertical_band(40u, four, 4u);
    symline_i_pass v = pass_of(SYMLINE_AXIS_VERTICAL, 1u);
    symline_point q;
    (void)state;
    q.x = 20;
    q.y = 5;
    symline_i_subpixel(&img, &v, &q, 1u);
    assert_int_equal(q.fx, 64);
    assert_int_equal(symline_i_pt_q8x(&q, 1u), (int32_t)(41.5 * 256));
    assert_int_equal(symline_i_pt_q8y(&q, 1u), (int32_t)(10.5 * 256));
    symline_i_pt_to_full(&q, 1u);
    /* 41.5 -> pixel 42 - 0.5; 10.5 -> pixel 11 - 0.5. */
    assert_int_equal(q.x, 42);
    assert_int_equal(q.fx, -64);
    assert_int_equal(q.y, 11);
    assert_int_equal(q.fy, -64);
}

/* Points on the grid's border, or where E has no minimum, get no offset. */
static void border_and_flat(void **state)
{
    static const uint8_t two[] = {200, 200};
    symline_image img = vertical_band(20u, two, 2u);
    symline_i_pass v = pass_of(SYMLINE_AXIS_VERTICAL, 0u);
    (void)state;
    assert_int_equal(offset_of(&img, &v, 10u, 0u), 0);
    assert_int_equal(offset_of(&img, &v, 10u, W - 1u), 0);
    /* x 5 lies on flat carpet: a long equal-E run, its middle bounded to 0 or 1/2. */
    {
        const int32_t off = offset_of(&img, &v, 10u, 5u);
        assert_true(off == 0 || off == 64);
    }
}

/* The detector's line on a 2 px wide horizontal band lies on the band's middle. */
static void detector_ends_on_the_middle(void **state)
{
    static const uint8_t two[] = {200, 200};
    symline_image img = horizontal_band(24u, two, 2u);
    symline_config cfg;
    symline_segment segs[8];
    symline_point pts[4096];
    symline_result r;
    size_t need;
    void *ws;
    uint32_t i;
    (void)state;
    symline_config_default(&cfg);
    cfg.axes = SYMLINE_AXES_HORIZONTAL;
    cfg.levels = 1u;
    need = symline_detect_workspace_size(W, H, &cfg);
    ws = malloc(need);
    assert_non_null(ws);
    memset(&r, 0, sizeof(r));
    r.segments = segs;
    r.segment_cap = 8u;
    r.points = pts;
    r.point_cap = 4096u;
    assert_int_equal(symline_detect(&img, &cfg, ws, need, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, 1u);
    assert_int_equal(segs[0].y0, (int32_t)(24.5 * 256));
    assert_int_equal(segs[0].y1, (int32_t)(24.5 * 256));
    for (i = 0; i < segs[0].count; i++) {
        const symline_point *q = &pts[segs[0].first + i];
        assert_int_equal((int32_t)q->y * 128 + q->fy, (int32_t)(24.5 * 128));
        assert_int_equal(q->fx, 0);
    }
    free(ws);
}

/* Anti-aliased horizontal bands at known sub-pixel centres (brightness 80 + 120 x
 * the share of each pixel the band covers): the detector's lines lie within
 * 0.15 px of each centre, where whole pixels were up to 0.5 px off. Widths 2-5 px
 * at full resolution (one scale), 8-12 px at scale 1 (two scales). */
#define BW 200
#define BH 170
static uint8_t g_bands[BW * BH];

static void bands_frame(const double *centre, const double *width, uint32_t n)
{
    uint32_t x, y, b;
    for (y = 0; y < BH; y++) {
        double v = 80.0;
        for (b = 0; b < n; b++) {
            const double top = centre[b] - width[b] / 2.0, bot = centre[b] + width[b] / 2.0;
            const double lo = top > (double)y - 0.5 ? top : (double)y - 0.5;
            const double hi = bot < (double)y + 0.5 ? bot : (double)y + 0.5;
            if (hi > lo) {
                v += 120.0 * (hi - lo);
            }
        }
        for (x = 0; x < BW; x++) {
            g_bands[y * BW + x] = (uint8_t)(x >= 10u && x < BW - 10u ? (uint32_t)(v + 0.5) : 80u);
        }
    }
}

static void check_bands(const double *centre, uint32_t n, uint32_t levels, uint32_t level)
{
    symline_image img;
    symline_config cfg;
    symline_segment segs[16];
    static symline_point pts[20000];
    symline_result r;
    size_t need;
    void *ws;
    uint32_t i, b;
    img.data = g_bands;
    img.width = BW;
    img.height = BH;
    img.stride = BW;
    symline_config_default(&cfg);
    cfg.axes = SYMLINE_AXES_HORIZONTAL;
    cfg.levels = levels;
    need = symline_detect_workspace_size(BW, BH, &cfg);
    ws = malloc(need);
    assert_non_null(ws);
    memset(&r, 0, sizeof(r));
    r.segments = segs;
    r.segment_cap = 16u;
    r.points = pts;
    r.point_cap = 20000u;
    assert_int_equal(symline_detect(&img, &cfg, ws, need, &r), SYMLINE_OK);
    assert_int_equal(r.segment_count, n);
    for (b = 0; b < n; b++) {
        const int32_t want = (int32_t)(centre[b] * 256.0 + 0.5);
        int found = 0;
        for (i = 0; i < r.segment_count; i++) {
            const int32_t d0 = segs[i].y0 - want, d1 = segs[i].y1 - want;
            if (d0 > -128 && d0 < 128) {
                printf("band at %.2f: line at %.2f .. %.2f, scale %u\n", centre[b],
                       segs[i].y0 / 256.0, segs[i].y1 / 256.0, segs[i].level);
                assert_int_equal(segs[i].level, level);
                assert_true(d0 >= -38 && d0 <= 38 && d1 >= -38 && d1 <= 38);
                found = 1;
            }
        }
        assert_true(found);
    }
    free(ws);
}

static void bands_at_subpixel_centres(void **state)
{
    static const double fine_c[] = {30.3, 60.65, 90.5, 120.15, 150.8};
    static const double fine_w[] = {3.0, 4.0, 2.0, 5.0, 3.5};
    static const double coarse_c[] = {30.3, 70.65, 110.15};
    static const double coarse_w[] = {9.0, 10.0, 8.0};
    (void)state;
    bands_frame(fine_c, fine_w, 5u);
    check_bands(fine_c, 5u, 1u, 0u);
    bands_frame(coarse_c, coarse_w, 3u);
    check_bands(coarse_c, 3u, 2u, 1u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(even_and_odd_widths),
        cmocka_unit_test(blurred_between_pixels),
        cmocka_unit_test(coarse_scale),
        cmocka_unit_test(border_and_flat),
        cmocka_unit_test(detector_ends_on_the_middle),
        cmocka_unit_test(bands_at_subpixel_centres),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
