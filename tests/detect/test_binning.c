/* SPDX-License-Identifier: Apache-2.0 */
/*
 * 2x2 binning (symline/binning.h): the means, exact, over odd sizes and
 * strides; the advice; a result moved back to the frame, exactly for every
 * sub-pixel offset; a detection on a binned frame lands on the frame's
 * lines; the argument errors, which leave every buffer unchanged.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "symline/binning.h"
#include "symline/detect.h"

static uint32_t rng_state = 12345u;
static uint32_t rnd(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return rng_state >> 8;
}

static void test_bin2_means(void **state)
{
    static const uint32_t sizes[][2] = {{2, 2}, {3, 3}, {17, 6}, {64, 9}, {131, 77}};
    size_t k;
    (void)state;
    for (k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        const uint32_t w = sizes[k][0], h = sizes[k][1], stride = w + 5u;
        uint8_t *px = malloc((size_t)stride * h), *buf;
        const size_t n = symline_bin2_size(w, h);
        symline_image in = {w, h, stride, px}, out;
        uint32_t x, y;
        assert_non_null(px);
        for (x = 0; x < stride * h; x++) {
            px[x] = (uint8_t)rnd();
        }
        assert_int_equal(n, (size_t)(w / 2u) * (h / 2u));
        buf = malloc(n + 1u);
        assert_non_null(buf);
        buf[n] = 0xA5; /* nothing written past the size */
        assert_int_equal(symline_bin2(&in, buf, n, &out), SYMLINE_OK);
        assert_int_equal(out.width, w / 2u);
        assert_int_equal(out.height, h / 2u);
        assert_int_equal(out.stride, w / 2u);
        assert_ptr_equal(out.data, buf);
        assert_int_equal(buf[n], 0xA5);
        for (y = 0; y < h / 2u; y++) {
            for (x = 0; x < w / 2u; x++) {
                const uint8_t *a = px + (size_t)2u * y * stride + 2u * x;
                const uint32_t s = a[0] + a[1] + a[stride] + a[stride + 1u];
                assert_int_equal(buf[y * (w / 2u) + x], (s + 2u) / 4u);
            }
        }
        free(buf);
        free(px);
    }
}

static void test_bin2_errors(void **state)
{
    uint8_t px[16] = {0}, buf[4];
    symline_image in = {4, 4, 4, px}, out = {0, 0, 0, NULL};
    (void)state;
    memset(buf, 0x5A, sizeof buf);
    assert_int_equal(symline_bin2(NULL, buf, 4, &out), SYMLINE_ERR_NULL);
    assert_int_equal(symline_bin2(&in, NULL, 4, &out), SYMLINE_ERR_NULL);
    assert_int_equal(symline_bin2(&in, buf, 4, NULL), SYMLINE_ERR_NULL);
    assert_int_equal(symline_bin2(&in, buf, 3, &out), SYMLINE_ERR_BUFFER);
    in.stride = 3;
    assert_int_equal(symline_bin2(&in, buf, 4, &out), SYMLINE_ERR_STRIDE);
    in.stride = 4;
    in.width = 1;
    assert_int_equal(symline_bin2(&in, buf, 4, &out), SYMLINE_ERR_SIZE);
    in.width = 4;
    in.height = 0;
    assert_int_equal(symline_bin2(&in, buf, 4, &out), SYMLINE_ERR_SIZE);
    assert_int_equal(buf[0], 0x5A);
    assert_null(out.data);
    assert_int_equal(symline_bin2_size(1, 100), 0);
    assert_int_equal(symline_bin2_size(100, 1), 0);
    assert_int_equal(symline_bin2_size(SYMLINE_MAX_DIM + 1u, 2), 0);
    assert_int_equal(symline_bin2_size(SYMLINE_MAX_DIM, SYMLINE_MAX_DIM),
                     (size_t)(SYMLINE_MAX_DIM / 2u) * (SYMLINE_MAX_DIM / 2u));
}

static void test_bin2_advised(void **state)
{
    (void)state;
    assert_true(symline_bin2_advised(1024, 768));
    assert_true(symline_bin2_advised(1280, 720));
    assert_true(symline_bin2_advised(912, 1200));
    assert_true(symline_bin2_advised(SYMLINE_MAX_DIM, SYMLINE_MAX_DIM)); /* no overflow */
    assert_false(symline_bin2_advised(1023, 768));
    assert_false(symline_bin2_advised(SYMLINE_MAX_DIM + 1u, 1024));
    assert_false(symline_bin2_advised(960, 720));
    assert_false(symline_bin2_advised(800, 600));
    assert_false(symline_bin2_advised(608, 800));
}

/* Every offset of a point moves exactly: 2 (p + f/128) + 1/2 = P + F/128. */
static void test_unbin2_points(void **state)
{
    symline_point pts[128];
    symline_result r;
    int f;
    (void)state;
    memset(&r, 0, sizeof r);
    r.points = pts;
    r.point_cap = 128;
    r.point_count = 128;
    for (f = -64; f < 64; f++) {
        pts[f + 64].x = (uint16_t)(f + 64);
        pts[f + 64].y = 9;
        pts[f + 64].fx = (int8_t)f;
        pts[f + 64].fy = (int8_t)(-1 - f);
    }
    assert_int_equal(symline_result_unbin2(&r, 301, 41), SYMLINE_OK);
    for (f = -64; f < 64; f++) {
        const symline_point *p = &pts[f + 64];
        /* In 1/128 px: 2 (128 p + f) + 64 = 128 P + F. */
        assert_int_equal(128 * (int32_t)p->x + p->fx, 2 * (128 * (f + 64) + f) + 64);
        assert_int_equal(128 * (int32_t)p->y + p->fy, 2 * (128 * 9 - 1 - f) + 64);
        assert_true(p->fx >= -64 && p->fx <= 63);
        assert_true(p->fy >= -64 && p->fy <= 63);
    }
}

static void test_unbin2_segments_and_field(void **state)
{
    symline_segment seg[2];
    symline_result r;
    (void)state;
    memset(&r, 0, sizeof r);
    memset(seg, 0, sizeof seg);
    r.segments = seg;
    r.segment_cap = 2;
    r.segment_count = 2;
    seg[0].x0 = 0;
    seg[0].y0 = 256 * 10 + 64;
    seg[0].x1 = 256 * 149;
    seg[0].y1 = -100;
    seg[0].max_dev = 300;
    seg[0].level = 0;
    seg[1].level = 3;
    r.field.count = 3;
    r.field.cell = 8;
    r.field.v[0].x = 0;
    r.field.v[0].y = 20;
    r.field.v[1].x = 40;
    r.field.v[1].y = 0;
    r.field.v[2].x = 149; /* the binned frame's last column (301 / 2 - 1) */
    r.field.v[2].y = 50;  /* no field: the binned frame's height (101 / 2) */
    assert_int_equal(symline_result_unbin2(&r, 301, 101), SYMLINE_OK);
    assert_int_equal(seg[0].x0, 128);
    assert_int_equal(seg[0].y0, 2 * (256 * 10 + 64) + 128);
    assert_int_equal(seg[0].x1, 2 * 256 * 149 + 128);
    assert_int_equal(seg[0].y1, -200 + 128);
    assert_int_equal(seg[0].max_dev, 600);
    assert_int_equal(seg[0].level, 1);
    assert_int_equal(seg[1].level, 4);
    assert_int_equal(r.field.v[0].x, 0);
    assert_int_equal(r.field.v[0].y, 40);
    assert_int_equal(r.field.v[1].x, 80);
    assert_int_equal(r.field.v[1].y, 0);
    assert_int_equal(r.field.v[2].x, 300);
    assert_int_equal(r.field.v[2].y, 101);
    assert_int_equal(r.field.cell, 16);
}

static void test_unbin2_errors(void **state)
{
    symline_segment seg[1];
    symline_point pts[1];
    symline_result r, before;
    (void)state;
    memset(&r, 0, sizeof r);
    memset(seg, 0, sizeof seg);
    memset(pts, 0, sizeof pts);
    r.segments = seg;
    r.segment_cap = 1;
    r.segment_count = 1;
    r.points = pts;
    r.point_cap = 1;
    r.point_count = 1;
    seg[0].x0 = 1000;
    pts[0].x = 9;
    before = r;
    assert_int_equal(symline_result_unbin2(NULL, 20, 20), SYMLINE_ERR_NULL);
    assert_int_equal(symline_result_unbin2(&r, 1, 20), SYMLINE_ERR_SIZE);
    assert_int_equal(symline_result_unbin2(&r, 20, SYMLINE_MAX_DIM + 1u), SYMLINE_ERR_SIZE);
    /* A point outside the binned frame (x 9 of 18 / 2 = 9 columns). */
    assert_int_equal(symline_result_unbin2(&r, 18, 20), SYMLINE_ERR_RANGE);
    r.point_count = 2; /* beyond the capacity */
    assert_int_equal(symline_result_unbin2(&r, 20, 20), SYMLINE_ERR_RANGE);
    r.point_count = 1;
    seg[0].level = 255;
    assert_int_equal(symline_result_unbin2(&r, 20, 20), SYMLINE_ERR_RANGE);
    seg[0].level = 0;
    seg[0].y1 = INT32_C(1) << 29; /* would overflow when doubled */
    assert_int_equal(symline_result_unbin2(&r, 20, 20), SYMLINE_ERR_RANGE);
    seg[0].y1 = 0;
    r.field.count = 1;
    r.field.v[0].y = 11; /* below the binned frame's 10 rows */
    assert_int_equal(symline_result_unbin2(&r, 20, 20), SYMLINE_ERR_RANGE);
    r.field.count = 0;
    r.points = NULL;
    assert_int_equal(symline_result_unbin2(&r, 20, 20), SYMLINE_ERR_NULL);
    r.points = pts;
    /* Nothing was changed by the failed calls. */
    assert_int_equal(seg[0].x0, 1000);
    assert_int_equal(pts[0].x, 9);
    assert_int_equal(r.segment_count, before.segment_count);
}

/* A 1280x960 frame with a bright band across (rows 400..411, centre 405.5)
 * and one down (columns 700..711, centre 705.5), detected binned: the
 * segments and their points lie on the bands' centres in frame pixels. */
static void test_detect_binned_frame(void **state)
{
    enum {
        W = 1280,
        H = 960,
        SEGS = 256
    };
    const uint32_t pcap = 2u * (W / 2u) * (H / 2u) + 1024u;
    uint8_t *px = malloc((size_t)W * H), *half = malloc(symline_bin2_size(W, H));
    symline_point *pts = malloc(pcap * sizeof *pts);
    symline_segment seg[SEGS];
    symline_image img = {W, H, W, px}, bimg;
    symline_config cfg;
    symline_result r;
    void *ws;
    size_t need;
    uint32_t i, j, x, y, across = 0, down = 0;
    (void)state;
    assert_non_null(px);
    assert_non_null(half);
    assert_non_null(pts);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            const int band = (y >= 400u && y <= 411u) || (x >= 700u && x <= 711u);
            px[(size_t)y * W + x] = (uint8_t)((band ? 200u : 80u) + rnd() % 9u);
        }
    }
    symline_config_default(&cfg);
    assert_true(symline_bin2_advised(W, H));
    assert_int_equal(symline_bin2(&img, half, symline_bin2_size(W, H), &bimg), SYMLINE_OK);
    need = symline_detect_workspace_size(bimg.width, bimg.height, &cfg);
    ws = malloc(need);
    assert_non_null(ws);
    memset(&r, 0, sizeof r);
    r.segments = seg;
    r.segment_cap = SEGS;
    r.points = pts;
    r.point_cap = pcap;
    assert_int_equal(symline_detect(&bimg, &cfg, ws, need, &r), SYMLINE_OK);
    assert_true(r.segment_count > 0u);
    assert_int_equal(symline_result_unbin2(&r, W, H), SYMLINE_OK);
    for (i = 0; i < r.segment_count; i++) {
        const symline_segment *s = &r.segments[i];
        const int horiz = s->axis == SYMLINE_AXIS_HORIZONTAL;
        /* Q8 distance of both ends from the band's centre line. */
        const int32_t c = horiz ? 405 * 256 + 128 : 705 * 256 + 128;
        const int32_t e0 = (horiz ? s->y0 : s->x0) - c, e1 = (horiz ? s->y1 : s->x1) - c;
        assert_true(s->level >= 1u);
        if (s->count < 20u) {
            continue; /* a short piece where the bands cross */
        }
        assert_true(e0 > -256 && e0 < 256);
        assert_true(e1 > -256 && e1 < 256);
        for (j = s->first; j < s->first + s->count; j++) {
            const symline_point *p = &r.points[j];
            const int32_t q = horiz ? 128 * (int32_t)p->y + p->fy : 128 * (int32_t)p->x + p->fx;
            assert_true(q - (c / 2) > -128 && q - (c / 2) < 128); /* within 1 px */
        }
        if (horiz) {
            across++;
        } else {
            down++;
        }
    }
    assert_true(across > 0u);
    assert_true(down > 0u);
    /* The field boundary spans the frame, not the binned one. */
    assert_true(r.field.count >= 1u);
    assert_int_equal(r.field.v[0].x, 0);
    assert_int_equal(r.field.v[r.field.count - 1u].x, W - 1);
    free(ws);
    free(pts);
    free(half);
    free(px);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bin2_means),
        cmocka_unit_test(test_bin2_errors),
        cmocka_unit_test(test_bin2_advised),
        cmocka_unit_test(test_unbin2_points),
        cmocka_unit_test(test_unbin2_segments_and_field),
        cmocka_unit_test(test_unbin2_errors),
        cmocka_unit_test(test_detect_binned_frame),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
