/* SPDX-License-Identifier: Apache-2.0 */
/*
 * One pass of the detector (lib/pass.c): set-up from the configuration, and
 * a whole pass over a frame: its segments, their points compacted behind
 * the earlier ones, and nothing reported twice.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "pass.h"
#include "testutil.h"

#define W 96u
#define H 64u

static void setup_from_config(void **state)
{
    symline_config cfg;
    symline_i_pass p;
    (void)state;
    symline_config_default(&cfg);
    cfg.radius = 4;
    symline_i_pass_setup(&p, &cfg, SYMLINE_AXIS_VERTICAL, 2, 101, 67);
    assert_int_equal(p.axis, SYMLINE_AXIS_VERTICAL);
    assert_int_equal(p.level, 2);
    assert_int_equal(p.w, 25); /* 101 >> 2 */
    assert_int_equal(p.h, 16);
    assert_int_equal(p.m, 4);
    assert_int_equal(p.k, 5);
    assert_int_equal(p.lag, 4);
    assert_int_equal(p.filter.kind, SYMLINE_FILTER_CONTRAST);
    assert_true(symline_i_pass_ws_size(&p, 101, 67) > symline_i_collect_ws_size(&p, 101));
}

/* Noise on a gray carpet and a 3 px bright bar across the frame at rows 30..32. */
static void bar_frame(uint8_t *px)
{
    uint32_t x, y, s = 777u;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            px[y * W + x] = (uint8_t)((y >= 30u && y <= 32u) ? 200u : 70u + tu_rand(&s) % 8u);
        }
    }
}

static void one_pass(void **state)
{
    static uint8_t px[W * H];
    static symline_point pts[4 * W * H];
    static symline_segment segs[64];
    symline_image img;
    symline_config cfg;
    symline_result r;
    symline_i_run d;
    symline_i_pass p;
    uint8_t *ws;
    uint32_t i, total = 0u;
    uint32_t hist[256];
    (void)state;
    bar_frame(px);
    img.width = W;
    img.height = H;
    img.stride = W;
    img.data = px;
    symline_config_default(&cfg);
    memset(&r, 0, sizeof r);
    r.segments = segs;
    r.segment_cap = 64;
    r.points = pts;
    r.point_cap = 4 * W * H;
    memset(&d, 0, sizeof d);
    d.cfg = &cfg;
    d.img = &img;
    d.r = &r;
    symline_i_frame_stats_measure(&img, NULL, hist, &d.stats);
    symline_i_pass_setup(&p, &cfg, SYMLINE_AXIS_HORIZONTAL, 0, W, H);
    symline_i_linefilter_adapt(&p.filter, &cfg, &d.stats, 0u);
    ws = (uint8_t *)malloc(symline_i_pass_ws_size(&p, W, H));
    assert_int_equal(symline_i_pass_run(&d, &p, ws, ws + symline_i_pass_ws_size(&p, W, H)),
                     SYMLINE_OK);
    /* The bar: horizontal line segments on its centre row, points from 0 on. */
    assert_true(d.nseg >= 1u);
    assert_int_equal(d.prev_seg, d.nseg);
    assert_false(d.truncated);
    for (i = 0; i < d.nseg; i++) {
        assert_int_equal(segs[i].kind, SYMLINE_KIND_LINE);
        assert_int_equal(segs[i].axis, SYMLINE_AXIS_HORIZONTAL);
        assert_int_equal(segs[i].first, total);
        assert_true(segs[i].y0 >= 30 * 256 && segs[i].y0 <= 32 * 256);
        assert_true(segs[i].y1 >= 30 * 256 && segs[i].y1 <= 32 * 256);
        total += segs[i].count;
    }
    assert_int_equal(d.npts, total);
    assert_true(total >= W / 2u);
    /* The same pass again finds only what is already reported: nothing new. */
    assert_int_equal(symline_i_pass_run(&d, &p, ws, ws + symline_i_pass_ws_size(&p, W, H)),
                     SYMLINE_OK);
    assert_int_equal(d.nseg, d.prev_seg);
    assert_int_equal(d.npts, total);
    /* Too little workspace is an error, not an overrun. */
    assert_int_equal(symline_i_pass_run(&d, &p, ws, ws + 8), SYMLINE_ERR_BUFFER);
    free(ws);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(setup_from_config),
        cmocka_unit_test(one_pass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
